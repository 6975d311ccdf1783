//! `touchline fmt FILE...`: rewrite `.tl` files in the canonical layout.

use std::io::{self, Write};
use std::path::PathBuf;

use clap::Args;

use crate::CliError;

/// Arguments of `touchline fmt`.
#[derive(Debug, Args)]
pub(crate) struct FmtArgs {
    /// `.tl` files to format in place.
    #[arg(required = true)]
    files: Vec<PathBuf>,

    /// Change nothing; list the files that are not formatted and fail (exit 1) if there are any.
    #[arg(long)]
    check: bool,

    /// Print the formatted text to stdout instead of rewriting the file.
    #[arg(long, conflicts_with = "check")]
    stdout: bool,
}

/// Formats each file; a file with a syntax error is reported and left untouched.
pub(crate) fn run(args: &FmtArgs) -> Result<(), CliError> {
    let mut unformatted = Vec::new();
    for file in &args.files {
        let origin = file.display().to_string();
        let text = std::fs::read_to_string(file).map_err(|source| CliError::Read { path: origin.clone(), source })?;
        let formatted = touchline_dsl::format_source(&text, &origin).map_err(CliError::Syntax)?;
        if args.stdout {
            io::stdout().lock().write_all(formatted.as_bytes())?;
        } else if formatted != text {
            if args.check {
                unformatted.push(origin);
            } else {
                super::write_atomically(file, &formatted)?;
                writeln!(io::stdout().lock(), "formatted {origin}")?;
            }
        }
    }
    if !unformatted.is_empty() {
        return Err(CliError::Unformatted { files: unformatted.join(", ") });
    }
    Ok(())
}
