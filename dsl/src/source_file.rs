//! Reading the files a scenario names (`.tl` sources and their imports, compiled `.json`,
//! `start from` states): only regular files, and at most [`MAX_SOURCE_BYTES`], so that a FIFO
//! cannot block `touchline check` and `/dev/zero` cannot exhaust memory. Scripts have their own,
//! stricter reader (`script::file`).

use std::io::{self, Read};
use std::path::Path;

/// Largest scenario source, compiled scenario or saved state read, in bytes (64 MiB).
pub(crate) const MAX_SOURCE_BYTES: u64 = 64 * 1024 * 1024;

/// The bytes of the regular file at `path`, at most `max` of them.
///
/// # Errors
/// The OS's error, or `InvalidInput` for a folder, device or pipe (checked before opening: opening
/// a FIFO blocks until a writer comes) and for a file over `max` bytes.
pub(crate) fn read_regular(path: &Path, max: u64) -> io::Result<Vec<u8>> {
    let not_a_file =
        || io::Error::new(io::ErrorKind::InvalidInput, "not a regular file (a folder, a device or a pipe)");
    if !std::fs::metadata(path)?.is_file() {
        return Err(not_a_file());
    }
    let handle = std::fs::File::open(path)?;
    if !handle.metadata()?.is_file() {
        return Err(not_a_file());
    }
    let mut bytes = Vec::new();
    // `take` bounds the read even if the file grows after the check.
    handle.take(max + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > max {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, format!("over the {} MiB a file may have", max >> 20)));
    }
    Ok(bytes)
}

/// As [`read_regular`], as UTF-8 text, at most [`MAX_SOURCE_BYTES`].
///
/// # Errors
/// As [`read_regular`], and `InvalidData` for text that is not UTF-8.
pub(crate) fn read_text(path: &Path) -> io::Result<String> {
    String::from_utf8(read_regular(path, MAX_SOURCE_BYTES)?).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        io::Error::new(
            io::ErrorKind::InvalidData,
            format!("it is not UTF-8 text: byte {at} is 0x{:02x} (a binary file?)", e.as_bytes()[at]),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_and_folders_are_not_read() {
        assert!(read_text(Path::new("/dev/zero")).unwrap_err().to_string().contains("not a regular file"));
        assert!(read_text(Path::new("/tmp")).unwrap_err().to_string().contains("not a regular file"));
    }
}
