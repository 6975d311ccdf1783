//! `touchline list` (alias `scenarios`): the stdlib scenarios, one a line, with their size,
//! length and description; `--tests` adds GRF's test scenarios.

use std::io::{self, Write};

use clap::Args;

use crate::CliError;

/// Arguments of `touchline scenarios`.
#[derive(Debug, Args)]
pub(crate) struct ListArgs {
    /// Print only the names, one a line (for scripts).
    #[arg(long)]
    names: bool,

    /// Also list GRF's test scenarios (`tests/corner_test`, …).
    #[arg(long)]
    tests: bool,
}

/// Runs `touchline list`.
pub(crate) fn run(args: &ListArgs) -> Result<(), CliError> {
    let mut names: Vec<&str> = touchline_dsl::stdlib::names().to_vec();
    if args.tests {
        names.extend(touchline_dsl::stdlib::test_names());
    }
    let mut out = io::stdout().lock();
    if args.names {
        for name in names {
            writeln!(out, "{name}")?;
        }
        return Ok(out.flush()?);
    }
    let width = names.iter().map(|n| n.len()).max().unwrap_or(0);
    writeln!(out, "{:width$}  players  steps  description", "scenario")?;
    for name in names {
        // Embedded scenarios are tested to parse; print the bare name should one ever fail.
        match touchline_dsl::load(name).ok() {
            Some(s) => writeln!(
                out,
                "{name:width$}  {:>7}  {:>5}  {}",
                format!("{}v{}", s.left_team.len(), s.right_team.len()),
                s.game_duration,
                s.description
            )?,
            None => writeln!(out, "{name}")?,
        }
    }
    Ok(out.flush()?)
}
