//! Reading a file that weft or an engine was pointed at, safely: only a
//! regular file (never a FIFO, socket or device, whose read can block for
//! ever or never end), and never more than a stated number of bytes (a
//! file's size is checked before anything is allocated).
//!
//! Shared by the compiler (material, include, scene, texture, cache and
//! shard files) and the runtime (metadata and the files it lists), so both
//! refuse the same things with the same words.

use std::fs::File;
use std::io::{self, Read};
use std::path::Path;

/// The largest text file weft reads as input (a material, an include, a
/// scene, a metadata file): far above any real one (the shipped library's
/// largest metadata file is under 2 MiB).
pub const MAX_TEXT_BYTES: u64 = 64 << 20;

/// The largest binary file weft reads (a texture PNG, a baked table, a
/// compiled shader, a cache blob): a 4096² RGBA16F table is 128 MiB.
pub const MAX_BINARY_BYTES: u64 = 256 << 20;

/// Reads `path` whole if it is a regular file (symbolic links followed) of
/// at most `max_bytes`. The type is checked before the file is opened, so a
/// FIFO is refused instead of blocking, and again on the open file.
pub fn read_regular(path: &Path, max_bytes: u64) -> io::Result<Vec<u8>> {
    check_regular(&std::fs::metadata(path)?, max_bytes)?;
    let file = File::open(path)?;
    let len = check_regular(&file.metadata()?, max_bytes)?;
    let mut bytes = Vec::with_capacity(len as usize);
    // `take` bounds the read even if the file grows while it is read.
    file.take(max_bytes + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_large(max_bytes));
    }
    Ok(bytes)
}

/// [`read_regular`] for UTF-8 text.
pub fn read_regular_string(path: &Path, max_bytes: u64) -> io::Result<String> {
    String::from_utf8(read_regular(path, max_bytes)?)
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidData, "it is not UTF-8 text"))
}

/// Whether `path` (symbolic links followed) is a regular file; an error
/// saying what it is otherwise.
pub fn require_regular(path: &Path) -> io::Result<()> {
    check_regular(&std::fs::metadata(path)?, u64::MAX).map(|_| ())
}

fn check_regular(meta: &std::fs::Metadata, max_bytes: u64) -> io::Result<u64> {
    if !meta.is_file() {
        let what = if meta.is_dir() {
            "a folder"
        } else {
            special_kind(meta)
        };
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("it is {what}, not a regular file; weft reads only regular files"),
        ));
    }
    if meta.len() > max_bytes {
        return Err(too_large(max_bytes));
    }
    Ok(meta.len())
}

fn too_large(max_bytes: u64) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidData,
        format!(
            "it is larger than {} MiB, the most weft reads for a file of this kind",
            max_bytes >> 20
        ),
    )
}

#[cfg(unix)]
fn special_kind(meta: &std::fs::Metadata) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    let t = meta.file_type();
    if t.is_fifo() {
        "a FIFO (named pipe)"
    } else if t.is_socket() {
        "a socket"
    } else if t.is_char_device() || t.is_block_device() {
        "a device"
    } else {
        "not a regular file"
    }
}

#[cfg(not(unix))]
fn special_kind(_: &std::fs::Metadata) -> &'static str {
    "a special file"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_regular_files_within_the_bound() {
        let dir = std::env::temp_dir().join(format!("weft-files-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("a.txt");
        std::fs::write(&f, "hello").unwrap();
        assert_eq!(read_regular_string(&f, 5).unwrap(), "hello");
        let e = read_regular(&f, 4).unwrap_err().to_string();
        assert!(e.contains("larger than"), "{e}");
        let e = read_regular(&dir, 100).unwrap_err().to_string();
        assert!(e.contains("a folder"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn refuses_devices_without_reading() {
        // /dev/zero never ends: reading it would fill memory.
        let e = read_regular(Path::new("/dev/zero"), MAX_BINARY_BYTES)
            .unwrap_err()
            .to_string();
        assert!(e.contains("a device"), "{e}");
    }
}
