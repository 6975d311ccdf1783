//! One module per subcommand: its clap arguments and its `run` function.

pub(crate) mod check;
pub(crate) mod compile;
pub(crate) mod fmt;
pub(crate) mod lessons;
pub(crate) mod list;
pub(crate) mod play;
pub(crate) mod replay;
pub(crate) mod run;
pub(crate) mod stats;
pub(crate) mod view;
pub(crate) mod watch;

use std::io::{self, Write};
use std::path::Path;

/// Writes `text` to `path` through a temporary file in the same directory, renamed into place:
/// readers never see a half-written file, and a failure leaves the old file as it was.
pub(crate) fn write_atomically(path: &Path, text: &str) -> io::Result<()> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let mut file = tempfile::NamedTempFile::new_in(dir)?;
    file.write_all(text.as_bytes())?;
    file.as_file().sync_all()?;
    file.persist(path).map_err(|e| e.error)?;
    Ok(())
}
