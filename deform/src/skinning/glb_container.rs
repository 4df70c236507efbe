//! The binary glTF container (`.glb`) as read: its 12-byte header checked before the `gltf`
//! crate trusts it, and the JSON chunk alone for a caller that needs no buffer.

use std::io::Read;
use std::path::Path;

/// The magic of a binary glTF file.
const MAGIC: &[u8; 4] = b"glTF";

/// The bytes of a binary glTF header, and of a chunk header.
const HEADER: usize = 12;
const CHUNK_HEADER: usize = 8;

/// For bytes that begin with the binary glTF magic, checks the header: version 2, and a
/// stated length equal to the file's (the `gltf` crate subtracts the header's size from it
/// unchecked, which panics in a debug build when it is below 12, and it ignores bytes past
/// it). Other bytes (a `.gltf` JSON document) pass unchanged.
///
/// # Errors
/// The reason, in words.
pub(crate) fn check_glb_header(bytes: &[u8]) -> Result<(), String> {
    if !bytes.starts_with(MAGIC) {
        return Ok(());
    }
    if bytes.len() < HEADER {
        return Err(format!(
            "a binary glTF header is {HEADER} bytes; the file ends after {}",
            bytes.len()
        ));
    }
    let word =
        |at: usize| u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    let version = word(4);
    if version != 2 {
        return Err(format!(
            "binary glTF version {version}; only version 2 is read"
        ));
    }
    let stated = word(8) as usize;
    if stated != bytes.len() {
        let what = if stated < bytes.len() {
            "bytes follow its stated end"
        } else {
            "the file is truncated"
        };
        return Err(format!(
            "the binary glTF header gives the file's length as {stated} bytes, but it has {} ({what})",
            bytes.len()
        ));
    }
    Ok(())
}

/// The JSON of a glTF model at `path` without its binary chunk: the whole file for a `.gltf`
/// document, the header and the JSON chunk of a `.glb` (so that a large model's buffer is
/// not read for it). `None` when the file cannot be read, holds more than
/// [`crate::mesh::io::MAX_FILE_BYTES`], or its JSON chunk's header is missing or cut short
/// (the full read reports why; the version and stated length are its to check).
pub(crate) fn read_json_only(path: &Path) -> Option<Vec<u8>> {
    let mut file = std::fs::File::open(path).ok()?;
    let mut head = [0u8; HEADER + CHUNK_HEADER];
    let mut got = 0;
    while got < head.len() {
        match file.read(&mut head[got..]) {
            Ok(0) => break,
            Ok(n) => got += n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(_) => return None,
        }
    }
    if !head[..got].starts_with(MAGIC) {
        let mut bytes = head[..got].to_vec();
        let limit = crate::mesh::io::MAX_FILE_BYTES;
        file.take(limit + 1).read_to_end(&mut bytes).ok()?;
        return (bytes.len() as u64 <= limit).then_some(bytes);
    }
    if got < head.len() || &head[16..20] != b"JSON" {
        return None;
    }
    let length = u32::from_le_bytes([head[12], head[13], head[14], head[15]]) as u64;
    let mut json = Vec::new();
    file.take(length).read_to_end(&mut json).ok()?;
    (json.len() as u64 == length).then_some(json)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn glb(version: u32, stated: u32, json: &[u8]) -> Vec<u8> {
        let mut out = b"glTF".to_vec();
        out.extend_from_slice(&version.to_le_bytes());
        out.extend_from_slice(&stated.to_le_bytes());
        out.extend_from_slice(&(json.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(json);
        out
    }

    #[test]
    fn headers_are_checked() {
        let json = br#"{"asset":{"version":"2.0"}}    "#;
        let len = (20 + json.len()) as u32;
        assert!(check_glb_header(&glb(2, len, json)).is_ok());
        assert!(check_glb_header(json).is_ok(), "JSON passes");
        for (bytes, words) in [
            (glb(2, 0, json), "0 bytes"),
            (glb(2, 11, json), "follow its stated end"),
            (glb(2, len + 1, json), "truncated"),
            (glb(1, len, json), "version 1"),
            (b"glTF\x02\0".to_vec(), "ends after 6"),
        ] {
            let e = check_glb_header(&bytes).expect_err(words);
            assert!(e.contains(words), "{e}");
        }
    }

    #[test]
    fn the_json_chunk_is_read_alone() {
        let dir = std::env::temp_dir().join(format!("glb-json-only-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let json = br#"{"asset":{"version":"2.0"}}    "#;
        let mut bytes = glb(2, 0, json);
        bytes.extend_from_slice(&8u32.to_le_bytes());
        bytes.extend_from_slice(b"BIN\0abcdefgh");
        let path = dir.join("m.glb");
        std::fs::write(&path, &bytes).unwrap();
        assert_eq!(read_json_only(&path).as_deref(), Some(&json[..]));
        std::fs::write(&path, &bytes[..30]).unwrap();
        assert_eq!(read_json_only(&path), None, "a JSON chunk cut short");
        let text = dir.join("m.gltf");
        std::fs::write(&text, json).unwrap();
        assert_eq!(read_json_only(&text).as_deref(), Some(&json[..]));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
