//! Handle selections: a libigl DMAT with one value per vertex (`-1` free, `k >= 0` group `k`),
//! or JSON `{"k": [vertex indices]}`.

use super::InputError;
use crate::mesh::io::Dmat;
use serde_json::Value;
use std::collections::BTreeMap;

/// Vertex groups `0 .. len()`, each a sorted list of distinct vertices; no vertex is in two
/// groups.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Selection {
    /// `groups[k]` are the vertices of group `k`.
    pub groups: Vec<Vec<u32>>,
}

impl Selection {
    /// The groups as slices.
    pub fn sets(&self) -> Vec<&[u32]> {
        self.groups.iter().map(Vec::as_slice).collect()
    }

    /// The first and last groups (a spline's ends, H_1 and H_n); `name` names the file in
    /// the error for fewer than two groups.
    pub fn ends(&self, name: &str) -> Result<(&[u32], &[u32]), InputError> {
        match self.groups.as_slice() {
            [first, .., last] => Ok((first, last)),
            _ => Err(InputError::new(
                name,
                "groups",
                format!(
                    "a spline needs at least two groups (0 = H_1, highest = H_n), found {}",
                    self.groups.len()
                ),
            )),
        }
    }

    /// Check ranges, duplicates and empty groups.
    fn checked(groups: Vec<Vec<u32>>, vertex_count: usize, name: &str) -> Result<Self, InputError> {
        let mut owner = vec![usize::MAX; vertex_count];
        for (g, vs) in groups.iter().enumerate() {
            if vs.is_empty() {
                return Err(InputError::new(
                    name,
                    format!("group {g}"),
                    "empty group (groups must be numbered 0, 1, 2, ... without gaps)",
                ));
            }
            for &v in vs {
                let slot = owner.get_mut(v as usize).ok_or_else(|| {
                    InputError::new(
                        name,
                        format!("group {g}"),
                        format!("vertex {v} does not exist (the mesh has {vertex_count})"),
                    )
                })?;
                if *slot != usize::MAX {
                    return Err(InputError::new(
                        name,
                        format!("group {g}"),
                        format!("vertex {v} is also in group {}", *slot),
                    ));
                }
                *slot = g;
            }
        }
        Ok(Selection { groups })
    }
}

/// A selection from a libigl DMAT: one row per vertex, `-1` free, `k >= 0` the group.
///
/// # Errors
/// [`InputError`] for a matrix that is not `vertex_count x 1`, a value that is not an
/// integer `>= -1`, or groups with gaps.
pub fn selection_from_dmat(
    m: &Dmat,
    vertex_count: usize,
    name: &str,
) -> Result<Selection, InputError> {
    if m.cols != 1 || m.rows != vertex_count {
        return Err(InputError::new(
            name,
            "DMAT",
            format!(
                "expected {vertex_count} x 1 (one value per vertex), got {} x {}",
                m.rows, m.cols
            ),
        ));
    }
    let mut groups: Vec<Vec<u32>> = Vec::new();
    for (v, &x) in m.data.iter().enumerate() {
        if x.fract() != 0.0 || !(-1.0..=1e6).contains(&x) {
            return Err(InputError::new(
                name,
                format!("vertex {v}"),
                format!("{x} is not -1 or a group number"),
            ));
        }
        if x >= 0.0 {
            let g = x as usize;
            if groups.len() <= g {
                groups.resize(g + 1, Vec::new());
            }
            groups[g].push(v as u32);
        }
    }
    Selection::checked(groups, vertex_count, name)
}

/// A selection from JSON `{"0": [indices], "1": [...]}`.
///
/// # Errors
/// [`InputError`] for a file of the wrong shape, a key that is not a group number, an index
/// that is not a vertex, a vertex in two groups, or groups with gaps.
pub fn parse_selection_json(
    text: &str,
    vertex_count: usize,
    name: &str,
) -> Result<Selection, InputError> {
    let value: Value = super::json::parse_json(text, name)?;
    let object: BTreeMap<String, Value> = serde_json::from_value(value).map_err(|_| {
        InputError::new(
            name,
            "JSON",
            "expected an object from group numbers to vertex lists",
        )
    })?;
    let mut groups: Vec<Vec<u32>> = Vec::new();
    for (key, list) in &object {
        let item = format!("group {key:?}");
        let g: usize = key
            .parse()
            .ok()
            .filter(|&g| g < 1 << 16)
            .ok_or_else(|| InputError::new(name, item.clone(), "not a group number"))?;
        let vs = list.as_array().ok_or_else(|| {
            InputError::new(name, item.clone(), "expected an array of vertex indices")
        })?;
        let mut out = Vec::with_capacity(vs.len());
        for x in vs {
            let v = x.as_u64().filter(|&v| v < u32::MAX as u64).ok_or_else(|| {
                InputError::new(name, item.clone(), format!("{x} is not a vertex index"))
            })?;
            out.push(v as u32);
        }
        out.sort_unstable();
        if let Some(w) = out.windows(2).find(|w| w[0] == w[1]) {
            return Err(InputError::new(
                name,
                item,
                format!("vertex {} listed twice", w[0]),
            ));
        }
        if groups.len() <= g {
            groups.resize(g + 1, Vec::new());
        }
        groups[g] = out;
    }
    Selection::checked(groups, vertex_count, name)
}
