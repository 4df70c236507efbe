//! libigl's dense matrix files (`.dmat`), ASCII and binary.
//!
//! The first line holds `cols rows`, then the values in column-major order. A first line of
//! `0 0` marks a binary file: a second line holds `cols rows`, then raw little-endian `f64`s.

use super::{capacity, read_bytes, Ctx};
use crate::mesh::MeshError;
use crate::mesh::Result;
use std::io::Write;
use std::path::Path;

/// A dense matrix stored column-major.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Dmat {
    /// Number of rows.
    pub rows: usize,
    /// Number of columns.
    pub cols: usize,
    /// Values, column after column (`data[c * rows + r]`).
    pub data: Vec<f64>,
}

impl Dmat {
    /// Entry `(r, c)`.
    ///
    /// # Panics
    /// If `r` or `c` is out of range.
    pub fn get(&self, r: usize, c: usize) -> f64 {
        assert!(r < self.rows && c < self.cols, "index out of range");
        self.data[c * self.rows + r]
    }

    /// Column `c` as a slice.
    ///
    /// # Panics
    /// If `c` is out of range.
    pub fn column(&self, c: usize) -> &[f64] {
        &self.data[c * self.rows..(c + 1) * self.rows]
    }

    /// Rows of a one-column selection whose value is `group`, e.g. libigl tutorial selections
    /// (`-1` free, `0, 1, 2..` handle groups). Values are compared after rounding.
    ///
    /// Errors: [`MeshError::DimensionMismatch`] unless the matrix has exactly one column (a
    /// `5x0` matrix, read from `0 5`, is not a selection) holding `rows` values.
    pub fn rows_equal_to(&self, group: i64) -> Result<Vec<u32>> {
        if self.cols != 1 {
            return Err(MeshError::DimensionMismatch {
                what: "columns of a selection matrix",
                expected: 1,
                got: self.cols,
            });
        }
        if self.data.len() != self.rows || self.rows > u32::MAX as usize {
            return Err(MeshError::DimensionMismatch {
                what: "values of a selection matrix",
                expected: self.rows,
                got: self.data.len(),
            });
        }
        Ok((0..self.rows as u32)
            .filter(|&r| self.data[r as usize].round() as i64 == group)
            .collect())
    }
}

/// Reads a DMAT file (ASCII or binary).
pub fn read_dmat(path: impl AsRef<Path>) -> Result<Dmat> {
    let path = path.as_ref();
    parse_dmat(&read_bytes(path)?, &path.display().to_string())
}

fn header(bytes: &[u8], at: usize, ctx: Ctx) -> Result<(usize, usize, usize)> {
    let end = bytes[at..]
        .iter()
        .position(|&b| b == b'\n')
        .map_or(bytes.len(), |p| at + p);
    let line = std::str::from_utf8(&bytes[at..end]).map_err(|_| ctx.err("header is not text"))?;
    let mut t = line.split_ascii_whitespace();
    let cols = ctx.usize(t.next(), "column count")?;
    let rows = ctx.usize(t.next(), "row count")?;
    Ok((cols, rows, (end + 1).min(bytes.len())))
}

/// Parses DMAT bytes (ASCII or binary). Every value must be finite; a matrix with zero rows
/// or columns (e.g. `0 5`) parses, with no values.
///
/// ```
/// let m = deform::mesh::io::parse_dmat(b"2 3\n1 2 3\n4 5 6\n", "m").unwrap();
/// assert_eq!((m.rows, m.cols, m.get(2, 1)), (3, 2, 6.0));
/// ```
pub fn parse_dmat(bytes: &[u8], name: &str) -> Result<Dmat> {
    let mut ctx = Ctx { name, line: 1 };
    let (cols, rows, next) = header(bytes, 0, ctx)?;
    let len = cols
        .checked_mul(rows)
        .ok_or_else(|| ctx.err("matrix size overflows"))?;
    if cols == 0 && rows == 0 && next < bytes.len() {
        // Binary: a second header, then little-endian doubles.
        ctx.line = 2;
        let (cols, rows, start) = header(bytes, next, ctx)?;
        let len = cols
            .checked_mul(rows)
            .and_then(|l| l.checked_mul(8))
            .ok_or_else(|| ctx.err("matrix size overflows"))?;
        let body = &bytes[start..];
        if body.len() != len {
            return Err(ctx.err(format!(
                "binary body has {} bytes, expected {len} for {rows}x{cols}",
                body.len()
            )));
        }
        let data: Vec<f64> = body
            .chunks_exact(8)
            .map(|c| f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]))
            .collect();
        if let Some(k) = data.iter().position(|x| !x.is_finite()) {
            return Err(ctx.err(format!(
                "binary value {k} (row {}, column {}) is not finite",
                k % rows.max(1),
                k / rows.max(1)
            )));
        }
        return Ok(Dmat { rows, cols, data });
    }
    let text = std::str::from_utf8(&bytes[next..]).map_err(|_| ctx.err("body is not text"))?;
    let mut data = Vec::with_capacity(capacity(len, bytes.len()));
    for (ln, line) in text.lines().enumerate() {
        ctx.line = ln + 2;
        for tok in line.split_ascii_whitespace() {
            if data.len() == len {
                return Err(ctx.err(format!("more than {len} values")));
            }
            data.push(ctx.f64(Some(tok), "value")?);
        }
    }
    if data.len() != len {
        return Err(MeshError::Parse {
            path: name.to_string(),
            line: 0,
            message: format!("{} values, expected {len} for {rows}x{cols}", data.len()),
        });
    }
    Ok(Dmat { rows, cols, data })
}

/// Writes an ASCII DMAT file.
pub fn write_dmat(m: &Dmat, path: impl AsRef<Path>) -> Result<()> {
    let path = path.as_ref();
    let io = |source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut w = std::io::BufWriter::new(std::fs::File::create(path).map_err(io)?);
    writeln!(w, "{} {}", m.cols, m.rows).map_err(io)?;
    for v in &m.data {
        writeln!(w, "{v}").map_err(io)?;
    }
    w.flush().map_err(io)
}
