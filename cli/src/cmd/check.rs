//! `touchline check FILE...`: compile `.tl` files and report every diagnostic.

use std::io::{self, Write};
use std::path::PathBuf;

use clap::Args;

use crate::CliError;

/// Arguments of `touchline check`.
#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    /// `.tl` files to check.
    #[arg(required = true)]
    files: Vec<PathBuf>,
}

/// Compiles each file and prints its diagnostics (errors and warnings) to stderr, then a summary
/// line. Fails with [`CliError::Check`] (exit 1) when any file has an error.
pub(crate) fn run(args: &CheckArgs) -> Result<(), CliError> {
    let (mut errors, mut warnings, mut failed) = (0usize, 0usize, 0usize);
    let stderr = io::stderr();
    for file in &args.files {
        let diagnostics = touchline_dsl::check_file(file);
        failed += usize::from(diagnostics.has_errors());
        for d in &diagnostics.items {
            if d.code.is_warning() {
                warnings += 1;
            } else {
                errors += 1;
            }
            let _ = writeln!(stderr.lock(), "{:?}", miette::Report::new(d.clone()));
        }
        if !diagnostics.has_errors() {
            // The scenario compiles: its scripts must too (`tl::S001` … `tl::S004`).
            let dir = touchline_dsl::script_dir(&file.to_string_lossy());
            let scripts = touchline_dsl::compile_file(file)
                .map(|c| touchline_dsl::script::Scripts::compile(&c.scenario, &dir, Default::default()).err());
            if let Ok(Some(script_errors)) = scripts {
                failed += 1;
                for e in script_errors.errors {
                    errors += 1;
                    let _ = writeln!(stderr.lock(), "{:?}", miette::Report::new(e));
                }
            }
        }
    }
    let n = args.files.len();
    let summary = format!(
        "checked {n} file{}: {} ok, {errors} error{}, {warnings} warning{}",
        if n == 1 { "" } else { "s" },
        n - failed,
        if errors == 1 { "" } else { "s" },
        if warnings == 1 { "" } else { "s" }
    );
    if failed > 0 {
        return Err(CliError::Check { summary });
    }
    writeln!(io::stdout().lock(), "{summary}")?;
    Ok(())
}
