//! PLY output: binary little-endian PLY 1.0 with double-precision positions and triangles
//! (`vertex_indices` as a `uchar` count and `int` indices), which MeshLab, Blender and
//! most mesh tools read. There is no PLY reader: tests parse the header and the layout.

use crate::mesh::Mesh;
use crate::mesh::MeshError;
use crate::mesh::Result;
use std::io::Write;
use std::path::Path;

/// The header of a binary PLY file for `vertices` vertices and `faces` triangles.
#[must_use]
pub fn ply_header(vertices: usize, faces: usize) -> String {
    format!(
        "ply\nformat binary_little_endian 1.0\ncomment written by cga-deform\n\
         element vertex {vertices}\nproperty double x\nproperty double y\nproperty double z\n\
         element face {faces}\nproperty list uchar int vertex_indices\nend_header\n"
    )
}

/// Writes `mesh` as binary little-endian PLY: the header, then `x y z` as `f64` per vertex,
/// then `3 i j k` (`u8`, then `i32`) per triangle; vertex order and count as given.
///
/// # Errors
/// A vertex index beyond `i32::MAX` (PLY's `int`) is [`std::io::ErrorKind::InvalidInput`];
/// otherwise the writer's errors.
pub fn write_ply_to(mesh: &Mesh, mut w: impl Write) -> std::io::Result<()> {
    if mesh.positions.len() > i32::MAX as usize {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "PLY indices are 32-bit signed: too many vertices",
        ));
    }
    let mut buf = std::io::BufWriter::new(&mut w);
    buf.write_all(ply_header(mesh.positions.len(), mesh.triangles.len()).as_bytes())?;
    for p in &mesh.positions {
        for c in [p.x, p.y, p.z] {
            buf.write_all(&c.to_le_bytes())?;
        }
    }
    for t in &mesh.triangles {
        buf.write_all(&[3])?;
        for &i in t {
            let i = i32::try_from(i).map_err(|_| {
                std::io::Error::new(std::io::ErrorKind::InvalidInput, "index beyond i32")
            })?;
            buf.write_all(&i.to_le_bytes())?;
        }
    }
    buf.flush()
}

/// Writes a PLY file.
pub fn write_ply(mesh: &Mesh, path: impl AsRef<Path>) -> Result<()> {
    let path = path.as_ref();
    let io = |source| MeshError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::create(path).map_err(io)?;
    write_ply_to(mesh, file).map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn header_counts_and_binary_layout() {
        let mesh = Mesh::new(
            vec![DVec3::ZERO, DVec3::X, DVec3::new(0.5, -2.25, 1e-300)],
            vec![[0, 1, 2], [2, 1, 0]],
        );
        let mut bytes = Vec::new();
        write_ply_to(&mesh, &mut bytes).unwrap();
        let end = b"end_header\n";
        let at = bytes.windows(end.len()).position(|w| w == end).unwrap() + end.len();
        let header = std::str::from_utf8(&bytes[..at]).unwrap();
        assert!(header.starts_with("ply\nformat binary_little_endian 1.0\n"));
        assert!(header.contains("element vertex 3\n"), "{header}");
        assert!(header.contains("element face 2\n"), "{header}");
        let body = &bytes[at..];
        assert_eq!(body.len(), 3 * 24 + 2 * 13);
        // Reading it back as the header says gives the mesh, bit for bit.
        let f = |k: usize| f64::from_le_bytes(body[8 * k..8 * k + 8].try_into().unwrap());
        let back: Vec<DVec3> = (0..3)
            .map(|v| DVec3::new(f(3 * v), f(3 * v + 1), f(3 * v + 2)))
            .collect();
        assert_eq!(back, mesh.positions);
        let faces = &body[72..];
        for (t, tri) in mesh.triangles.iter().enumerate() {
            let rec = &faces[13 * t..13 * t + 13];
            assert_eq!(rec[0], 3);
            let idx: Vec<u32> = (0..3)
                .map(|k| i32::from_le_bytes(rec[1 + 4 * k..5 + 4 * k].try_into().unwrap()) as u32)
                .collect();
            assert_eq!(idx, tri.to_vec());
        }
    }
}
