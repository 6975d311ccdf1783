//! `touchline check FILE...`: compile `.tl` files and report every diagnostic.

use std::io::{self, Write};
use std::path::PathBuf;

use clap::Args;
use touchline_dsl::script::Scripts;
use touchline_engine::{EngineError, EnvConfig, Scenario};

use crate::CliError;

/// Arguments of `touchline check`.
#[derive(Debug, Args)]
pub(crate) struct CheckArgs {
    /// `.tl` files to check.
    #[arg(required = true)]
    files: Vec<PathBuf>,
}

/// Compiles each file and prints its diagnostics (errors and warnings) to stderr, then a summary
/// line; a file that compiles has its scripts compiled, and their `reset` hooks run once. Fails
/// with [`CliError::Check`] (exit 1) when any file has an error.
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
        if diagnostics.has_errors() {
            continue;
        }
        let Ok(compiled) = touchline_dsl::compile_file(file) else { continue };
        // The scenario compiles: its scripts must too (`tl::S001` … `tl::S004`, `tl::S008`,
        // `tl::S010`), and their `reset` hooks must run.
        let dir = touchline_dsl::script_dir(&file.to_string_lossy());
        match Scripts::compile(&compiled.scenario, &dir, Default::default()) {
            Err(script_errors) => {
                failed += 1;
                for e in script_errors.errors {
                    errors += 1;
                    let _ = writeln!(stderr.lock(), "{:?}", miette::Report::new(e));
                }
            }
            Ok(scripts) => {
                if let Some(message) = first_reset(&scripts, compiled.scenario) {
                    failed += 1;
                    errors += 1;
                    // Rendered already, as `touchline run` prints it.
                    let _ = writeln!(stderr.lock(), "{}\n", message.trim_end());
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

/// Plays the scenario's first reset with its scripts attached, as `touchline run` does, with the
/// scenario's seed (`game_engine_random_seed`) and at most one left agent: the rendered diagnostic
/// of a `reset` hook that fails (`tl::S005`, `tl::S006`), if one does. What the env refuses for
/// other reasons depends on the agents asked for, which are `touchline run`'s to check.
fn first_reset(scripts: &Scripts, scenario: Scenario) -> Option<String> {
    if scripts.is_empty() {
        return None;
    }
    let first = scenario.curriculum.as_ref().and_then(|c| c.lessons.first()).map_or(&scenario, |l| &l.scenario);
    let left_agents = first.controllable_every_episode()[0].min(1);
    let config = EnvConfig { left_agents, right_agents: 0, ..EnvConfig::default() };
    let seed = scenario.game_engine_random_seed;
    match touchline_dsl::attach(scripts, scenario, config, seed) {
        Err(EngineError::Script { message, .. }) => Some(message),
        _ => None,
    }
}
