//! The graded table of the peer harness: every side's timings and outputs read back, each
//! output element compared with ours, each row's ratio graded against issue 47's target.

use crate::{N, PASSES};
use benches::grade::{Spread, Target};
use std::collections::BTreeMap;
use std::io::Read;
use std::path::Path;

/// One line of the table: label, our key, the peer, its key, the target ratio.
const ROWS: [(&str, &str, &str, &str, f64); 14] = [
    (
        "PGA f32: motor on point, one motor per point",
        "pga.motor_point",
        "klein",
        "pga.motor_point",
        0.85,
    ),
    (
        "PGA f32: one motor on 10,000 points (`point_matrix().apply` / klein's batch call)",
        "pga.batch",
        "klein",
        "pga.batch",
        1.0,
    ),
    (
        "PGA f32: same, `sandwich` in a plain loop / klein's batch call",
        "pga.batch_sandwich",
        "klein",
        "pga.batch",
        1.3,
    ),
    (
        "PGA f32: motor * motor",
        "pga.motor_motor",
        "klein",
        "pga.motor_motor",
        1.0,
    ),
    (
        "PGA f32: rotor * rotor",
        "pga.rotor_rotor",
        "klein",
        "pga.rotor_rotor",
        1.0,
    ),
    ("PGA f32: exp(line)", "pga.exp", "klein", "pga.exp", 1.0),
    ("PGA f32: log(motor)", "pga.log", "klein", "pga.log", 1.0),
    (
        "PGA f32: motor to matrix (`point_matrix` / `as_mat4x4`)",
        "pga.motor_matrix",
        "klein",
        "pga.motor_matrix",
        1.0,
    ),
    (
        "CGA f64: vector * vector",
        "cga.vector_vector",
        "gatl",
        "cga.vector_vector",
        1.0,
    ),
    (
        "CGA f64: bivector * bivector",
        "cga.bivector_bivector",
        "gatl",
        "cga.bivector_bivector",
        1.0,
    ),
    (
        "CGA f64: motor * motor",
        "cga.motor_motor",
        "gatl",
        "cga.motor_motor",
        1.0,
    ),
    (
        "CGA f64: motor on point (`sandwich` / `M P ~M`)",
        "cga.motor_point",
        "gatl",
        "cga.motor_point",
        1.0,
    ),
    (
        "CGA f64: ga-benchmark inverse kinematics, 5 joints (Taylor expp)",
        "cga.ik_taylor",
        "gatl",
        "cga.ik_taylor",
        0.8,
    ),
    (
        "CGA f64: ga-benchmark inverse kinematics, 5 joints (closed-form exp / GATL's `exp`)",
        "cga.ik_exp",
        "gatl",
        "cga.ik_exp",
        0.8,
    ),
];

/// [`ROWS`], their PGA f64 twins (no target: an infinite one) and the operation rows of
/// `ops.rs` (target 1.0 each).
fn rows() -> Vec<(String, String, &'static str, String, f64)> {
    let mut rows: Vec<_> = ROWS
        .iter()
        .map(|&(l, k, p, pk, t)| (l.to_string(), k.to_string(), p, pk.to_string(), t))
        .collect();
    // PGA in f64 beside klein's f32: no target.
    for &(label, key, peer, pkey, _) in ROWS.iter().filter(|r| r.1.starts_with("pga.")) {
        rows.push((
            label.replacen("PGA f32", "PGA f64 (beside klein's f32)", 1),
            key.replacen("pga.", "pga64.", 1),
            peer,
            pkey.to_string(),
            f64::INFINITY,
        ));
    }
    for (ga, gb, pair) in crate::ops::pairs() {
        for op in crate::ops::products(ga, gb) {
            let key = format!("ops.{pair}.{op}");
            let label = format!(
                "CGA f64 op, grades ({ga}, {gb}) blades: {} product",
                crate::ops::product_name(op)
            );
            rows.push((label, key.clone(), "gatl", key, 1.0));
        }
    }
    for g in 0..=5 {
        for op in crate::ops::UNARY {
            let key = format!("un.{g}.{op}");
            let label = format!(
                "CGA f64 op, grade {g} blade: {}",
                crate::ops::unary_name(op)
            );
            rows.push((label, key.clone(), "gatl", key, 1.0));
        }
    }
    rows
}

fn read_times(path: &Path) -> Option<BTreeMap<String, f64>> {
    let text = std::fs::read_to_string(path).ok()?;
    Some(
        text.lines()
            .filter_map(|l| {
                let (k, v) = l.split_once(' ')?;
                Some((k.to_string(), v.trim().parse().ok()?))
            })
            .collect(),
    )
}

fn read_outputs(path: &Path) -> Option<BTreeMap<String, Vec<f64>>> {
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .ok()?
        .read_to_end(&mut bytes)
        .ok()?;
    let mut out = BTreeMap::new();
    let mut at = 0;
    let take = |at: &mut usize, k: usize| {
        let s = &bytes[*at..*at + k];
        *at += k;
        s
    };
    while at < bytes.len() {
        let len = u32::from_le_bytes(take(&mut at, 4).try_into().ok()?) as usize;
        let key = String::from_utf8(take(&mut at, len).to_vec()).ok()?;
        let count = u64::from_le_bytes(take(&mut at, 8).try_into().ok()?) as usize;
        let v = take(&mut at, count * 8)
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
            .collect();
        out.insert(key, v);
    }
    Some(out)
}

/// The largest difference between two outputs, relative to `max(1, |ours|)`; infinite when the
/// lengths differ.
fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    a.iter()
        .zip(b)
        .map(|(x, y)| {
            let d = (x - y).abs() / x.abs().max(1.0);
            if d.is_nan() {
                f64::INFINITY
            } else {
                d
            }
        })
        .fold(0.0, f64::max)
}

/// A peer's name as printed.
fn shown(peer: &str) -> &str {
    if peer == "gatl" {
        "GATL"
    } else {
        peer
    }
}

/// Prints the table; returns the exit code (1 when outputs disagree or a side is missing).
pub(crate) fn report(dir: &Path, rounds: usize) -> i32 {
    let times = |side: &str| -> Vec<BTreeMap<String, f64>> {
        (1..=rounds)
            .filter_map(|r| read_times(&dir.join(format!("{side}.{r}.times"))))
            .collect()
    };
    let ours = times("ours");
    let peers: BTreeMap<&str, _> = [("klein", times("klein")), ("gatl", times("gatl"))].into();
    let out_ours = read_outputs(&dir.join("ours.out")).unwrap_or_default();
    let outs: BTreeMap<&str, _> = ["klein", "gatl"]
        .map(|p| {
            (
                p,
                read_outputs(&dir.join(format!("{p}.out"))).unwrap_or_default(),
            )
        })
        .into();
    let median = |runs: &[BTreeMap<String, f64>], key: &str| {
        let mut v: Vec<f64> = runs.iter().filter_map(|m| m.get(key).copied()).collect();
        (!v.is_empty()).then(|| Spread::median_of(&mut v))
    };

    println!(
        "ns per op over {N} operands, median of {rounds} alternating rounds (each round: the median of {PASSES} passes)\n"
    );
    println!(
        "| op | ours ns | peer ns | ours / peer (range over rounds) | target | grade | max diff |"
    );
    println!("|---|---|---|---|---|---|---|");
    let (mut pass, mut miss, mut bad) = (0, 0, 0);
    // The ga-benchmark operation rows' ratios, for the summary below the table.
    let mut set: Vec<(String, String, f64)> = Vec::new();
    for (label, key, peer, pkey, target) in rows() {
        let (key, pkey) = (key.as_str(), pkey.as_str());
        let o = median(&ours, key);
        let p = median(&peers[peer], pkey);
        let tol = if key.starts_with("pga") { 1e-4 } else { 1e-10 };
        let diff = match (out_ours.get(key), outs[peer].get(pkey)) {
            (Some(a), Some(b)) => Some(max_diff(a, b)),
            _ => None,
        };
        let diff_text = match diff {
            Some(d) if d <= tol => format!("{d:.1e}"),
            Some(d) => {
                bad += 1;
                format!("**{d:.1e} DIFFER**")
            }
            None => "-".into(),
        };
        let (o_text, p_text, ratio_text, grade) = match (o, p) {
            (Some(o), Some(p)) => {
                // Ratio of the medians; the range is that of the per-round ratios.
                let mut per_round: Vec<f64> = ours
                    .iter()
                    .zip(&peers[peer])
                    .filter_map(|(a, b)| Some(a.get(key)? / b.get(pkey)?))
                    .collect();
                let r = Spread {
                    value: o.value / p.value,
                    ..Spread::median_of(&mut per_round)
                };
                let met = Target::AtMost(target).reached_by(r.value);
                if key.starts_with("ops.") || key.starts_with("un.") {
                    set.push((key.to_string(), label.clone(), r.value));
                }
                let grade = if target.is_infinite() {
                    "no target"
                } else if met {
                    pass += 1;
                    "PASS"
                } else {
                    miss += 1;
                    "**MISS**"
                };
                (
                    format!("{:.2}", o.value),
                    format!("{} {:.2}", shown(peer), p.value),
                    format!("{:.2} ({:.2}-{:.2})", r.value, r.low, r.high),
                    grade.to_string(),
                )
            }
            (o, _) => {
                // A peer that ran but lacks the row, or our side lacking a row the peer has:
                // the two sides list different rows.
                if !peers[peer].is_empty() {
                    bad += 1;
                }
                (
                    o.map_or("-".into(), |o| format!("{:.2}", o.value)),
                    format!("{} not run", shown(peer)),
                    "-".into(),
                    "-".into(),
                )
            }
        };
        let target = if target.is_infinite() {
            "-".to_string()
        } else {
            format!("<= {target:.2}")
        };
        println!(
            "| {label} | {o_text} | {p_text} | {ratio_text} | {target} | {grade} | {diff_text} |"
        );
    }
    println!("\n{pass} targets met, {miss} missed; outputs compared element by element (relative to max(1, |ours|); tolerance 1e-4 f32, 1e-10 f64): {bad} rows differ");
    ops_summary(&mut set);
    if ours.is_empty() || bad > 0 {
        1
    } else {
        0
    }
}

/// The ga-benchmark operation set in brief: the ratios as two grids (grade pairs by product,
/// grades by unary operation; `-` where a product is identically zero), how many rows are at or
/// below 1.0x GATL, and every row above.
fn ops_summary(set: &mut [(String, String, f64)]) {
    if set.is_empty() {
        return;
    }
    let ratio: BTreeMap<&str, f64> = set.iter().map(|(k, _, r)| (k.as_str(), *r)).collect();
    let cell = |key: String| {
        ratio
            .get(key.as_str())
            .map_or("-".into(), |r| format!("{r:.2}"))
    };
    let products = [
        "gp", "op", "lc", "rc", "sp", "dot", "hip", "cp", "rp", "igp",
    ];
    println!("\nga-benchmark's binary operations, ours / GATL by grade pair:\n");
    println!("| grades | {} |", products.join(" | "));
    println!("|---{}|", "|---".repeat(products.len()));
    for (ga, gb, pair) in crate::ops::pairs() {
        let cells: Vec<String> = products
            .iter()
            .map(|p| cell(format!("ops.{pair}.{p}")))
            .collect();
        println!("| ({ga}, {gb}) | {} |", cells.join(" | "));
    }
    println!("\nga-benchmark's unary operations, ours / GATL by grade:\n");
    println!("| grade | {} |", crate::ops::UNARY.join(" | "));
    println!("|---{}|", "|---".repeat(crate::ops::UNARY.len()));
    for g in 0..=5 {
        let cells: Vec<String> = crate::ops::UNARY
            .iter()
            .map(|u| cell(format!("un.{g}.{u}")))
            .collect();
        println!("| {g} | {} |", cells.join(" | "));
    }
    set.sort_by(|a, b| a.2.total_cmp(&b.2));
    let at_most = set.iter().filter(|(_, _, r)| *r <= 1.0).count();
    let mid = set[set.len() / 2].2;
    println!(
        "\nga-benchmark operation set: {at_most} of {} rows <= 1.0x GATL (ratios {:.2} to {:.2}, median {mid:.2}); above 1.0x:",
        set.len(),
        set[0].2,
        set[set.len() - 1].2
    );
    for (_, label, r) in set.iter().filter(|(_, _, r)| *r > 1.0) {
        println!("- {label}: {r:.2}");
    }
}
