//! `touchline compile FILE [-o OUT.json]`: a scenario (`.tl`, stdlib name, `.json`) to its
//! compiled JSON form.

use std::io::{self, Write};
use std::path::PathBuf;

use clap::Args;

use crate::CliError;

/// Arguments of `touchline compile`.
#[derive(Debug, Args)]
pub(crate) struct CompileArgs {
    /// A `.tl` file, a stdlib scenario name or a compiled `.json`.
    scenario: String,

    /// Where to write the JSON (default: stdout). Written atomically: a failed compile or write
    /// leaves any existing file untouched.
    #[arg(short, long)]
    output: Option<PathBuf>,

    /// Write `.tl` source instead of JSON (turns any compiled scenario back into text).
    #[arg(long)]
    tl: bool,
}

/// Compiles and writes.
pub(crate) fn run(args: &CompileArgs) -> Result<(), CliError> {
    let scenario = touchline_dsl::load(&args.scenario)?;
    let text = if args.tl {
        touchline_dsl::scenario_to_tl(&scenario)
    } else {
        let mut json = serde_json::to_string_pretty(&scenario).map_err(io::Error::other)?;
        json.push('\n');
        json
    };
    match &args.output {
        None => io::stdout().lock().write_all(text.as_bytes())?,
        Some(path) => super::write_atomically(path, &text)?,
    }
    Ok(())
}
