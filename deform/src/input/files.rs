//! Reading the program's documents from files: any text document of bounded size, and a
//! selection by its extension (`.dmat`, libigl's; `.json`, ours).

use super::selection::{parse_selection_json, selection_from_dmat, Selection};
use super::InputError;
use std::path::Path;

/// The largest JSON document (motors, keys, selections, animations) read: 1 GiB, room for a
/// selection of every vertex of a 50-million-vertex mesh. A file or pipe that gives more is
/// refused before it fills memory.
pub const MAX_DOCUMENT_BYTES: u64 = 1 << 30;

/// Read a text file (or pipe) of at most [`MAX_DOCUMENT_BYTES`].
///
/// # Errors
/// An [`InputError`] naming the file: it cannot be read, is larger, or is not UTF-8.
pub fn read_document(path: &Path) -> Result<String, InputError> {
    let name = path.display().to_string();
    let bytes = crate::mesh::io::read_limited(path, MAX_DOCUMENT_BYTES)
        .map_err(|e| InputError::new(&name, "file", format!("cannot read ({e})")))?;
    String::from_utf8(bytes)
        .map_err(|e| InputError::new(&name, "file", format!("not UTF-8 text ({e})")))
}

/// Read a selection of a mesh of `vertex_count` vertices by the file's extension: `.dmat`
/// (libigl: -1 free, k >= 0 group k) or `.json` (`{"k": [vertices]}`).
///
/// ```
/// let dir = std::env::temp_dir().join(format!("deform-sel-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("sel.json");
/// std::fs::write(&path, r#"{"0": [0, 1], "1": [3]}"#).unwrap();
/// let sel = deform::input::read_selection(&path, 4).unwrap();
/// assert_eq!(sel.groups, vec![vec![0, 1], vec![3]]);
/// assert!(deform::input::read_selection(&dir.join("sel.txt"), 4).is_err());
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
///
/// # Errors
/// An [`InputError`] naming the file and the item: another extension, a file that cannot be
/// read, an index out of range, a vertex in two groups.
pub fn read_selection(path: &Path, vertex_count: usize) -> Result<Selection, InputError> {
    let name = path.display().to_string();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("dmat") => {
            let m = crate::mesh::io::read_dmat(path)
                .map_err(|e| InputError::new(&name, "DMAT", e.to_string()))?;
            selection_from_dmat(&m, vertex_count, &name)
        }
        Some("json") => parse_selection_json(&read_document(path)?, vertex_count, &name),
        _ => Err(InputError::new(
            &name,
            "file",
            "a selection is a .dmat (libigl) or .json file",
        )),
    }
}
