//! Reading a script file named by a scenario, which may name any path: only a regular file whose
//! name ends in `.rhai` is opened, and at most [`MAX_SCRIPT_BYTES`] of it read, so that
//! `reward script "/dev/zero"` cannot exhaust memory, a FIFO cannot block `touchline check`, and
//! `reward script "../../etc/passwd"` cannot show another file's lines in a diagnostic.

use std::io::{self, Read};
use std::path::Path;

/// Largest script file read, in bytes (256 KiB; the example scripts are under 4 KiB).
pub const MAX_SCRIPT_BYTES: u64 = 256 * 1024;

/// Why a script file is not read: an OS error, or a file that is not a script.
pub(crate) fn read_script(file: &Path) -> io::Result<String> {
    if !file.extension().is_some_and(|e| e.eq_ignore_ascii_case("rhai")) {
        return Err(refused("a script file's name ends in `.rhai`; other files are not read"));
    }
    // Checked before opening: opening a FIFO for reading blocks until a writer comes.
    if !std::fs::metadata(file)?.is_file() {
        return Err(refused("not a regular file (a folder, a device or a pipe); only files are read"));
    }
    let handle = std::fs::File::open(file)?;
    // Checked again on what was opened, in case the path changed in between.
    let meta = handle.metadata()?;
    if !meta.is_file() {
        return Err(refused("not a regular file (a folder, a device or a pipe); only files are read"));
    }
    if meta.len() > MAX_SCRIPT_BYTES {
        return Err(too_large(meta.len()));
    }
    let mut bytes = Vec::new();
    // `take` bounds the read even if the file grows after the check.
    handle.take(MAX_SCRIPT_BYTES + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_SCRIPT_BYTES {
        return Err(too_large(bytes.len() as u64));
    }
    String::from_utf8(bytes).map_err(|_| refused("not UTF-8 text; a script is a text file"))
}

fn refused(why: &str) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidInput, why)
}

fn too_large(bytes: u64) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!("{bytes} bytes, over the {} KiB a script may have", MAX_SCRIPT_BYTES / 1024),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_rhai_files_are_read() {
        let e = read_script(Path::new("/etc/passwd")).unwrap_err();
        assert!(e.to_string().contains(".rhai"), "{e}");
        let e = read_script(Path::new("/dev/zero")).unwrap_err();
        assert!(e.to_string().contains(".rhai"), "{e}");
    }
}
