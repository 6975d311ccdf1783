//! `touchline`: play touchline scenarios from the command line.
//!
//! ```text
//! touchline run academy_empty_goal_close --episodes 10
//! touchline run 11_vs_11_easy_stochastic --policy random --seed 7 --json
//! touchline run 11_vs_11_stochastic --episodes 20 --stats
//! touchline run drills/my_drill.tl
//! touchline check drills/*.tl
//! touchline compile drills/my_drill.tl -o my_drill.json
//! touchline fmt drills/my_drill.tl
//! touchline list
//! touchline run 11_vs_11_easy_stochastic --record replays/
//! touchline replay replays/11_vs_11_easy_stochastic_seed0_ep0.tlreplay -o match.gif
//! touchline view replays/
//! touchline play academy_empty_goal_close --port 8000
//! ```
//!
//! Exit codes: 0 on success; 1 when `check` finds an error, `fmt --check` finds an unformatted
//! file, the engine fails or the output cannot be written; 2 for bad input (usage errors, an
//! unknown scenario, an unreadable, invalid or non-compiling scenario file, an agent configuration
//! the scenario cannot take, an unreadable, damaged or non-reproducing replay). Errors are printed to stderr as miette diagnostics.

mod cmd;

use std::io;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use miette::Diagnostic;
use thiserror::Error;
use touchline_dsl::LoadError;
use touchline_engine::EngineError;

/// touchline: a fast football environment for reinforcement learning.
#[derive(Debug, Parser)]
#[command(name = "touchline", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Play episodes of a scenario with a simple policy and report scores, rewards and speed.
    Run(cmd::run::RunArgs),
    /// Compile `.tl` files and print every error and warning (exit 1 on any error).
    Check(cmd::check::CheckArgs),
    /// Compile a scenario to JSON (or back to `.tl` with --tl).
    Compile(cmd::compile::CompileArgs),
    /// Rewrite `.tl` files in the canonical layout (comments kept).
    Fmt(cmd::fmt::FmtArgs),
    /// List the stdlib scenarios with their descriptions.
    #[command(alias = "scenarios")]
    List(cmd::list::ListArgs),
    /// Draw a replay into a video (MP4 with ffmpeg, animated GIF, or PNG frames).
    Replay(cmd::replay::ReplayArgs),
    /// Watch replays in the browser: serves a viewer page on localhost, or writes it as one
    /// self-contained HTML file.
    View(cmd::view::ViewArgs),
    /// Play a scenario yourself in the browser (keyboard or gamepad) against the built-in AI; each
    /// match is recorded as a replay.
    Play(cmd::play::PlayArgs),
    /// Play a scenario over and over, recompiling it and its scripts whenever a file changes.
    Watch(cmd::watch::WatchArgs),
}

/// Everything a command can fail with.
#[derive(Debug, Error, Diagnostic)]
pub(crate) enum CliError {
    /// The scenario could not be loaded (the dsl's diagnostics, `tl::E001` …).
    #[error(transparent)]
    #[diagnostic(transparent)]
    Load(#[from] LoadError),

    /// The scenario loaded, but the environment cannot be built with the requested agents.
    #[error("cannot play `{scenario}` with this configuration")]
    #[diagnostic(code(tl::cli::config))]
    Config {
        /// The scenario as given on the command line.
        scenario: String,
        /// What to change.
        #[help]
        help: String,
        /// The engine's reason.
        #[source]
        source: EngineError,
    },

    /// `--curriculum` on a scenario without one.
    #[error("`{scenario}` has no curriculum")]
    #[diagnostic(
        code(tl::cli::curriculum),
        help(
            "add `curriculum {{ lesson … advance when … }}` to the scenario (grammar/README.md, Curricula), or drop --curriculum"
        )
    )]
    NoCurriculum {
        /// The scenario as given on the command line.
        scenario: String,
    },

    /// The engine refused a step it should have accepted: a bug.
    #[error("the engine failed in episode {episode} after {steps} steps")]
    #[diagnostic(
        code(tl::cli::engine),
        help("this is a bug in touchline; please report it with the command line that caused it")
    )]
    Engine {
        /// 0-based episode index.
        episode: u64,
        /// Steps played in that episode before the failure.
        steps: u32,
        /// The engine's error.
        #[source]
        source: EngineError,
    },

    /// `touchline check` found errors (already printed).
    #[error("{summary}")]
    #[diagnostic(code(tl::cli::check))]
    Check {
        /// The summary line.
        summary: String,
    },

    /// A `.tl` file has a syntax error (`touchline fmt`).
    #[error(transparent)]
    #[diagnostic(transparent)]
    Syntax(Box<touchline_dsl::Diagnostic>),

    /// A file to format could not be read.
    #[error("cannot read `{path}`")]
    #[diagnostic(code(tl::cli::read))]
    Read {
        /// The path.
        path: String,
        /// The operating system's error.
        #[source]
        source: io::Error,
    },

    /// `touchline fmt --check` found files that are not formatted.
    #[error("not formatted: {files}")]
    #[diagnostic(code(tl::cli::fmt), help("run `touchline fmt` on them"))]
    Unformatted {
        /// The files, comma-separated.
        files: String,
    },

    /// A file or folder could not be written.
    #[error("cannot write {}", path.display())]
    #[diagnostic(code(tl::cli::write))]
    Write {
        /// The file.
        path: std::path::PathBuf,
        /// Why.
        #[source]
        source: io::Error,
    },

    /// A replay file is damaged, from another version, or does not reproduce.
    #[error("cannot use the replay {}", path.display())]
    #[diagnostic(
        code(tl::cli::replay),
        help("replays are written by `touchline run --record DIR` and by Python's `touchline.RecordReplay`")
    )]
    Replay {
        /// The file.
        path: std::path::PathBuf,
        /// The reason.
        #[source]
        source: touchline_render::replay::ReplayError,
    },

    /// A video or image could not be made.
    #[error("cannot write the video {}: {reason}", path.display())]
    #[diagnostic(code(tl::cli::video))]
    Video {
        /// The output.
        path: std::path::PathBuf,
        /// Why.
        reason: String,
    },

    /// The viewer or the play page could not serve.
    #[error("cannot serve the page: {reason}")]
    #[diagnostic(code(tl::cli::view))]
    Serve {
        /// Why.
        reason: String,
    },

    /// The scenario's scripts do not load (`tl::S001` …).
    #[error(transparent)]
    #[diagnostic(transparent)]
    Build(touchline_dsl::BuildError),

    /// A scenario script failed while playing (its rendered diagnostic, `tl::S005`/`tl::S006`, is
    /// printed as it is, above this one: nesting it in miette's frame wrapped its lines twice).
    #[error("the run stopped in episode {episode}: a scenario script failed (above)")]
    #[diagnostic(code(tl::cli::script))]
    Script {
        /// 0-based episode index.
        episode: u64,
        /// The script's diagnostic, rendered; it names the step.
        message: String,
    },

    /// `touchline watch` could not start.
    #[error(transparent)]
    #[diagnostic(transparent)]
    Watch(#[from] touchline_dsl::watch::WatchError),

    /// Writing to stdout failed.
    #[error("cannot write the output")]
    #[diagnostic(code(tl::cli::output))]
    Output(#[from] io::Error),
}

impl CliError {
    /// 2 for bad input, 1 for failures while running.
    fn exit_code(&self) -> u8 {
        match self {
            CliError::Load(_)
            | CliError::Config { .. }
            | CliError::Syntax(_)
            | CliError::Read { .. }
            | CliError::Replay { .. }
            | CliError::Build(_)
            | CliError::NoCurriculum { .. }
            | CliError::Watch(_) => 2,
            CliError::Check { .. }
            | CliError::Unformatted { .. }
            | CliError::Engine { .. }
            | CliError::Script { .. }
            | CliError::Output(_)
            | CliError::Write { .. }
            | CliError::Video { .. }
            | CliError::Serve { .. } => 1,
        }
    }

    /// The error of a failed step: a script's diagnostic, or an engine bug.
    pub(crate) fn step(info: &touchline_engine::StepInfo, source: EngineError) -> CliError {
        match source {
            EngineError::Script { message, .. } => CliError::Script { episode: info.episode, message },
            source => CliError::Engine { episode: info.episode, steps: info.steps, source },
        }
    }
}

/// miette's handler, given every diagnostic through [`touchline_dsl::excerpt::Clipped`]: a label
/// past column 65,535 (a one-line JSON over 64 KiB) would panic it.
struct ClippedHandler(miette::MietteHandler);

impl miette::ReportHandler for ClippedHandler {
    fn debug(&self, diagnostic: &dyn miette::Diagnostic, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.0.debug(&touchline_dsl::excerpt::Clipped::new(diagnostic), f)
    }
}

fn main() -> ExitCode {
    // Usage errors print clap's message and exit with status 2; `--help` and `--version` exit 0.
    let cli = Cli::parse();
    // The fancy graphical handler: colour and unicode when stderr is a terminal that supports them;
    // excerpts clipped on very long lines, where miette's padding would panic.
    let _ = miette::set_hook(Box::new(|_| Box::new(ClippedHandler(miette::MietteHandlerOpts::new().build()))));

    let result = match cli.command {
        Command::Run(args) => cmd::run::run(&args),
        Command::Check(args) => cmd::check::run(&args),
        Command::Compile(args) => cmd::compile::run(&args),
        Command::Fmt(args) => cmd::fmt::run(&args),
        Command::List(args) => cmd::list::run(&args),
        Command::Replay(args) => cmd::replay::run(&args),
        Command::View(args) => cmd::view::run(&args),
        Command::Watch(args) => cmd::watch::run(&args),
        Command::Play(args) => cmd::play::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // A closed pipe (`touchline scenarios | head`) is not an error worth reporting.
        Err(CliError::Output(e)) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(err) => {
            let code = err.exit_code();
            report(err);
            ExitCode::from(code)
        }
    }
}

/// A one-line summary after a list of diagnostics.
#[derive(Debug, Error, Diagnostic)]
#[error("{0}")]
#[diagnostic(code(tl::cli::summary))]
struct Summary(String);

/// Prints `err` to stderr. A list of diagnostics (a scenario that does not compile, scripts that do
/// not load) is printed one diagnostic at a time and then, if there are several, counted: as one
/// miette report, the first was printed twice (as the report's own message and again as the
/// first related diagnostic).
fn report(err: CliError) {
    match err {
        CliError::Load(LoadError::Compile(diags)) => {
            let errors = diags.errors().count();
            for d in &diags.items {
                eprintln!("{:?}", miette::Report::new(d.clone()));
            }
            let origin = diags.items.first().map(|d| d.source.name().to_owned()).unwrap_or_default();
            let (n, warnings) = (errors, diags.items.len() - errors);
            let plural = |k: usize, word: &str| format!("{k} {word}{}", if k == 1 { "" } else { "s" });
            let line = format!("`{origin}` does not compile: {}, {}", plural(n, "error"), plural(warnings, "warning"));
            if diags.items.len() > 1 {
                eprintln!("{:?}", miette::Report::new(Summary(line)));
            }
        }
        CliError::Build(touchline_dsl::BuildError::Scripts(errors)) => {
            let n = errors.errors.len();
            for e in errors.errors {
                eprintln!("{:?}", miette::Report::new(e));
            }
            if n > 1 {
                eprintln!(
                    "{:?}",
                    miette::Report::new(Summary(format!("the scenario's scripts do not load: {n} errors")))
                );
            }
        }
        CliError::Script { ref message, .. } => {
            eprintln!("{}", message.trim_end());
            eprintln!();
            eprintln!("{:?}", miette::Report::new(err));
        }
        err => eprintln!("{:?}", miette::Report::new(err)),
    }
}
