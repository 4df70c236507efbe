//! Basis blades as bitmaps over the basis vectors, their names and signs.
//!
//! Blade `k` of an algebra with basis `v_0 .. v_{n-1}` is the outer product of the basis vectors
//! whose bits are set in `k`, taken in ascending basis order. Names concatenate the basis names
//! after one `e` (`eo`, `e1` -> `eo1`); the scalar is `s` (`1` is accepted when parsing).

/// A basis blade: the set of basis vectors in its outer product, as a bitmap.
pub type Bitmap = u32;

/// Which grades of `e_a e_b` a product keeps: the products of the generic references (dense
/// and sparse) differ only by it.
#[derive(Clone, Copy)]
pub(crate) enum Keep {
    /// Every grade: the geometric product.
    All,
    /// Grade `ga + gb`: the outer product.
    Outer,
    /// Grade `gb - ga`: the left contraction.
    Left,
    /// Grade `ga - gb`: the right contraction.
    Right,
    /// Grade 0: the scalar product.
    Scalar,
}

impl Keep {
    /// Whether grade `gk` of the product of blades of grades `ga`, `gb` is kept.
    pub(crate) fn keeps(self, ga: u32, gb: u32, gk: u32) -> bool {
        match self {
            Keep::All => true,
            Keep::Outer => gk == ga + gb,
            Keep::Left => gb >= ga && gk == gb - ga,
            Keep::Right => ga >= gb && gk == ga - gb,
            Keep::Scalar => gk == 0,
        }
    }
}

/// Number of basis vectors in the blade.
pub(crate) fn grade(b: Bitmap) -> u32 {
    b.count_ones()
}

/// Sign of reordering `a ^ b` (both in ascending order) into ascending order:
/// `e_a ^ e_b = sign * e_(a|b)` when `a & b == 0`.
pub(crate) fn reorder_sign(a: Bitmap, b: Bitmap) -> i32 {
    let mut a = a >> 1;
    let mut swaps = 0;
    while a != 0 {
        swaps += (a & b).count_ones();
        a >>= 1;
    }
    if swaps % 2 == 0 {
        1
    } else {
        -1
    }
}

/// Sign of the reverse of a grade-`k` blade: `(-1)^(k(k-1)/2)`.
pub(crate) fn reverse_sign(b: Bitmap) -> i32 {
    let k = grade(b);
    if (k * k.saturating_sub(1) / 2).is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// Sign of the grade involution of a grade-`k` blade: `(-1)^k`.
pub(crate) fn involute_sign(b: Bitmap) -> i32 {
    if grade(b).is_multiple_of(2) {
        1
    } else {
        -1
    }
}

/// The suffix of a basis name after its leading `e` (`eo` -> `o`, `e1` -> `1`).
pub(crate) fn suffix(basis_name: &str) -> &str {
    basis_name.strip_prefix('e').unwrap_or(basis_name)
}

/// Canonical name of a blade: `s` for the scalar, else `e` followed by the basis suffixes in
/// basis order. Bits past `basis` are ignored (and names past the 32 a [`Bitmap`] holds).
pub(crate) fn blade_name(b: Bitmap, basis: &[String]) -> String {
    if b == 0 {
        return "s".to_string();
    }
    let mut s = String::from("e");
    for (i, name) in basis.iter().take(Bitmap::BITS as usize).enumerate() {
        if b & (1 << i) != 0 {
            s.push_str(suffix(name));
        }
    }
    s
}

/// Why a blade name could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum BladeNameError {
    /// The name does not split into basis suffixes.
    Unknown,
    /// The name splits in more than one way.
    Ambiguous,
    /// A basis vector appears twice (`e11`).
    Repeated,
}

/// Parse a blade name written with basis suffixes in any order (`e31`, `eo1`, `e1o`).
/// Returns the bitmap and the sign relating the written order to the canonical one:
/// the written blade equals `sign * canonical`.
///
/// Linear in the length of the name times the size of the basis: the ways to split each
/// tail of the name are counted once (capped at two), from the end, instead of by
/// backtracking. The bases of a [`crate::runtime::metric::Metric`] are prefix-free, so there is at most one
/// way; other bases may give [`BladeNameError::Ambiguous`]. A name that uses a basis vector
/// past the 32 a [`Bitmap`] holds is [`BladeNameError::Unknown`].
pub(crate) fn parse_blade(name: &str, basis: &[String]) -> Result<(Bitmap, i32), BladeNameError> {
    if name == "s" || name == "1" {
        return Ok((0, 1));
    }
    let rest = name.strip_prefix('e').ok_or(BladeNameError::Unknown)?;
    if rest.is_empty() {
        return Err(BladeNameError::Unknown);
    }
    let suffixes: Vec<&str> = basis.iter().map(|b| suffix(b)).collect();
    let len = rest.len();
    // ways[p]: number of splits of rest[p..] (0, 1 or 2 meaning "two or more");
    // next[p]: the basis index that starts the split when there is exactly one.
    let mut ways = vec![0u8; len + 1];
    let mut next = vec![usize::MAX; len + 1];
    ways[len] = 1;
    for p in (0..len).rev() {
        if !rest.is_char_boundary(p) {
            continue;
        }
        for (i, s) in suffixes.iter().enumerate() {
            if !s.is_empty() && rest[p..].starts_with(s) && ways[p + s.len()] > 0 {
                ways[p] = (ways[p] + ways[p + s.len()]).min(2);
                next[p] = i;
            }
        }
    }
    match ways[0] {
        0 => Err(BladeNameError::Unknown),
        1 => {
            let mut bitmap: Bitmap = 0;
            let mut sign = 1;
            let mut p = 0;
            while p < len {
                let i = next[p];
                let bit = u32::try_from(i)
                    .ok()
                    .and_then(|i| Bitmap::from(1u8).checked_shl(i))
                    .ok_or(BladeNameError::Unknown)?;
                if bitmap & bit != 0 {
                    return Err(BladeNameError::Repeated);
                }
                sign *= reorder_sign(bitmap, bit);
                bitmap |= bit;
                p += suffixes[i].len();
            }
            Ok((bitmap, sign))
        }
        _ => Err(BladeNameError::Ambiguous),
    }
}

/// All blades of an `n`-dimensional algebra in the canonical order: by grade, then by
/// ascending basis indices (shortlex): `2^n` of them.
///
/// # Panics
/// For `n >= 32` (a [`Bitmap`] holds 31 and fewer dimensions here).
#[cfg(any(feature = "codegen", test))]
pub(crate) fn canonical_order(n: usize) -> Vec<Bitmap> {
    assert!(n < 32, "{n} dimensions: a blade bitmap holds fewer than 32");
    let mut all: Vec<Bitmap> = (0..(1u32 << n)).collect();
    all.sort_by_key(|&b| {
        let idx: Vec<u32> = (0..n as u32).filter(|i| b & (1 << i) != 0).collect();
        (grade(b), idx)
    });
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bases of more than 32 names: the names past a bitmap's 32 bits are unknown, not a
    /// shift overflow.
    #[test]
    fn bases_past_32_names_do_not_overflow() {
        // Two-letter suffixes: prefix-free.
        let names: Vec<String> = (0..40u8)
            .map(|i| format!("e{}{}", (b'a' + i / 26) as char, (b'a' + i % 26) as char))
            .collect();
        assert_eq!(blade_name(1, &names), "eaa");
        assert_eq!(blade_name(u32::MAX, &names).len(), 1 + 2 * 32);
        let past = format!("e{}", suffix(&names[35]));
        assert_eq!(parse_blade(&past, &names), Err(BladeNameError::Unknown));
        assert_eq!(parse_blade("eaaab", &names), Ok((3, 1)));
    }

    fn basis() -> Vec<String> {
        ["eo", "e1", "e2", "e3", "ei"]
            .iter()
            .map(|s| s.to_string())
            .collect()
    }

    #[test]
    fn names_round_trip() {
        let b = basis();
        for bm in 0..32 {
            let n = blade_name(bm, &b);
            assert_eq!(parse_blade(&n, &b), Ok((bm, 1)));
        }
        assert_eq!(blade_name(0b10001, &b), "eoi");
    }

    #[test]
    fn written_order_gives_sign() {
        let b = basis();
        assert_eq!(parse_blade("e31", &b), Ok((0b01010, -1)));
        assert_eq!(parse_blade("e1o", &b), Ok((0b00011, -1)));
        assert_eq!(parse_blade("e321", &b), Ok((0b01110, -1)));
        assert_eq!(parse_blade("e11", &b), Err(BladeNameError::Repeated));
        assert_eq!(parse_blade("e4", &b), Err(BladeNameError::Unknown));
    }

    #[test]
    fn reorder_sign_counts_swaps() {
        assert_eq!(reorder_sign(0b10, 0b01), -1);
        assert_eq!(reorder_sign(0b01, 0b10), 1);
        assert_eq!(reorder_sign(0b110, 0b001), 1);
    }

    #[test]
    fn parsing_is_linear_on_prefix_bases() {
        // Basis suffixes `1` and `11`: a long run of ones has exponentially many splits.
        let b: Vec<String> = vec!["e1".into(), "e11".into()];
        let long = format!("e{}x", "1".repeat(5000));
        let start = std::time::Instant::now();
        assert_eq!(parse_blade(&long, &b), Err(BladeNameError::Unknown));
        assert_eq!(
            parse_blade(&format!("e{}", "1".repeat(5000)), &b),
            Err(BladeNameError::Ambiguous)
        );
        assert!(start.elapsed().as_secs_f64() < 1.0);
        assert_eq!(parse_blade("e111", &b), Err(BladeNameError::Ambiguous));
        assert_eq!(parse_blade("e11", &b), Err(BladeNameError::Ambiguous));
        assert_eq!(parse_blade("e1", &b), Ok((0b01, 1)));
        // Multi-character suffixes and any order.
        let b: Vec<String> = vec!["exy".into(), "ez".into()];
        assert_eq!(parse_blade("ezxy", &b), Ok((0b11, -1)));
        assert_eq!(parse_blade("exyz", &b), Ok((0b11, 1)));
        assert_eq!(parse_blade("exy", &b), Ok((0b01, 1)));
        assert_eq!(parse_blade("ex", &b), Err(BladeNameError::Unknown));
        assert_eq!(parse_blade("eé", &b), Err(BladeNameError::Unknown));
    }
}
