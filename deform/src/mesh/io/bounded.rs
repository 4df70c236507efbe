//! Reading an input file with a limit on its size, so that a file or a pipe far larger than
//! any model (a sparse file, `yes` behind a process substitution, a video named `.obj`) is a
//! clear error before it fills memory.

use std::io::{Error, ErrorKind, Read};
use std::path::Path;

/// The largest file the readers of this crate take: 4 GiB. A `.glb` cannot be larger (its
/// length field has 32 bits), and an OBJ of this size holds about 50 million vertices.
pub const MAX_FILE_BYTES: u64 = 1 << 32;

/// The bytes of `path`, a file or a pipe, when there are at most `limit` of them; more is an
/// error of kind [`ErrorKind::FileTooLarge`] that names the limit. A regular file is refused
/// by its length before it is read; a pipe is read until it passes the limit; a device
/// ([`is_device`]: `/dev/zero`, a disk) is refused unread ([`ErrorKind::InvalidInput`]).
///
/// ```
/// let dir = std::env::temp_dir().join(format!("read-limited-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let file = dir.join("five.txt");
/// std::fs::write(&file, b"12345").unwrap();
/// assert_eq!(deform::mesh::io::read_limited(&file, 5).unwrap(), b"12345");
/// let e = deform::mesh::io::read_limited(&file, 4).unwrap_err();
/// assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn read_limited(path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
    let file = std::fs::File::open(path)?;
    let mut bytes = Vec::new();
    let meta = file.metadata()?;
    if is_device(&meta.file_type()) {
        return Err(Error::new(
            ErrorKind::InvalidInput,
            "a device, not a file: refusing to read it",
        ));
    }
    if meta.is_file() {
        if meta.len() > limit {
            return Err(too_large(limit));
        }
        // The length is a hint only (a file may grow, and /proc files say 0).
        bytes.reserve(meta.len() as usize);
    }
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(too_large(limit));
    }
    Ok(bytes)
}

/// A character or block device, or a socket (Unix; nothing elsewhere): not an input file,
/// whatever its name says (a link to `/dev/zero` named `x.obj` never ends).
pub fn is_device(t: &std::fs::FileType) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        t.is_char_device() || t.is_block_device() || t.is_socket()
    }
    #[cfg(not(unix))]
    {
        let _ = t;
        false
    }
}

fn too_large(limit: u64) -> Error {
    Error::new(
        ErrorKind::FileTooLarge,
        format!("more than {} bytes, the most this reader takes", limit),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file whose length says 0 but that holds more than the limit (as a pipe does): the
    /// read stops past the limit and says so.
    #[cfg(target_os = "linux")]
    #[test]
    fn a_stream_past_the_limit_is_refused() {
        let status = Path::new("/proc/self/status");
        let all = read_limited(status, MAX_FILE_BYTES).unwrap();
        assert!(all.len() > 64, "{} bytes", all.len());
        let e = read_limited(status, 64).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::FileTooLarge);
        assert!(e.to_string().contains("more than 64 bytes"), "{e}");
    }

    /// A device is refused before anything is read from it.
    #[cfg(unix)]
    #[test]
    fn a_device_is_refused_unread() {
        let e = read_limited(Path::new("/dev/zero"), MAX_FILE_BYTES).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::InvalidInput);
        assert!(e.to_string().contains("a device"), "{e}");
    }

    /// A sparse file one byte past the limit is refused by its length, unread.
    #[test]
    fn a_file_past_the_limit_is_refused_by_its_length() {
        let dir = std::env::temp_dir().join(format!("read-limited-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("huge.obj");
        let file = std::fs::File::create(&path).unwrap();
        file.set_len(MAX_FILE_BYTES + 1).unwrap();
        let e = read_limited(&path, MAX_FILE_BYTES).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::FileTooLarge);
        let m = crate::mesh::io::read_mesh(&path).unwrap_err();
        assert!(
            m.to_string()
                .contains("huge.obj: more than 4294967296 bytes"),
            "{m}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
