//! `touchline watch FILE`: play episodes of a scenario file over and over while it is edited.
//!
//! The scenario (`.tl` or compiled `.json`), its imports and every script it names are
//! watched ([`touchline_dsl::Watched`]); each change of their content is recompiled at once and
//! its diagnostics are shown on stderr, once (reading a file or saving it unchanged does nothing);
//! the next episode plays the new version, or the last good one if the change did not compile. A
//! script failing while it plays is shown once per version. One line per episode on stdout.

use std::io::{self, Write};
use std::time::Duration;

use clap::Args;
use miette::{Diagnostic, GraphicalReportHandler};
use touchline_dsl::Watched;
use touchline_dsl::script::{ErrorPolicy, ScriptOptions};
use touchline_dsl::watch::WatchEvent;
use touchline_engine::{Action, EngineError, EnvConfig};

use super::run::{Agent, Policy};
use crate::CliError;

/// Arguments of `touchline watch`.
#[derive(Debug, Args)]
pub(crate) struct WatchArgs {
    /// The scenario file: a compiled `.json` scenario (or a `.tl` source).
    scenario: String,

    /// Stop after this many episodes (default: play until interrupted).
    #[arg(long)]
    episodes: Option<u64>,

    /// Seed of the environment and of the random policy.
    #[arg(long, default_value_t = 0)]
    seed: u64,

    /// Who chooses the controlled players' actions.
    #[arg(long, value_enum, default_value_t = Policy::Random)]
    policy: Policy,

    /// Left-team players the agents control.
    #[arg(long, default_value_t = 1)]
    left_agents: usize,

    /// Right-team players the agents control.
    #[arg(long, default_value_t = 0)]
    right_agents: usize,

    /// Pause between episodes, in milliseconds.
    #[arg(long, default_value_t = 0)]
    pause_ms: u64,

    /// A script failing during a step pays zero and is counted, instead of ending the episode.
    #[arg(long)]
    warn_script_errors: bool,
}

/// Renders through [`touchline_dsl::excerpt::Clipped`]: a label past column 65,535 (a script's
/// diagnostic on a very long line) would make miette's renderer panic (issue 17, item 2).
fn render(diagnostic: &dyn Diagnostic) -> String {
    let mut out = String::new();
    let clipped = touchline_dsl::excerpt::Clipped::new(diagnostic);
    if GraphicalReportHandler::new().render_report(&mut out, &clipped).is_err() {
        out = diagnostic.to_string();
    }
    out
}

/// Runs `touchline watch`.
pub(crate) fn run(args: &WatchArgs) -> Result<(), CliError> {
    let on_error = if args.warn_script_errors { ErrorPolicy::Warn } else { ErrorPolicy::Raise };
    let watched = Watched::new(&args.scenario, ScriptOptions { on_error, ..ScriptOptions::default() })?;
    watched.on_event(|event| match event {
        WatchEvent::Reloaded { generation } => {
            eprintln!("reloaded: version {generation} plays from the next episode");
        }
        WatchEvent::Failed(error) => {
            eprintln!("{}\nthe last good version keeps playing", render(*error));
        }
        WatchEvent::Refused(error) => eprintln!("not applied: {error}"),
        _ => {}
    });
    let config = EnvConfig {
        left_agents: args.left_agents,
        right_agents: args.right_agents,
        action_set: args.policy.action_set(),
        checkpoints: false,
    };
    let (mut env, playing) = watched.env_playing(config, args.seed).map_err(|source| CliError::Config {
        scenario: args.scenario.clone(),
        help: "pass --left-agents and --right-agents within the scenario's controllable players".into(),
        source,
    })?;
    eprintln!("watching {} and its scripts; edit them and save", args.scenario);
    let mut agent = Agent::new(args.policy, args.seed);
    let mut actions = vec![Action::Idle; env.num_controllers()];
    let mut out = io::stdout().lock();
    let mut episode = 0_u64;
    // The last script failure shown in full, with the version it came from: the same failure in
    // the same version is shown once, then only counted in the episode lines.
    let mut shown: Option<(u64, String)> = None;
    while args.episodes.is_none_or(|n| episode < n) {
        if episode > 0
            && let Err(e) = env.reset()
        {
            // A script's `reset` failed: this episode is spent; the next reset moves on.
            writeln!(
                out,
                "episode {episode} (version {}): a script failed at the episode's reset",
                playing.generation()
            )?;
            show_once(&mut shown, playing.generation(), &e.to_string());
            std::thread::sleep(Duration::from_millis(500));
            episode += 1;
            continue;
        }
        // The version this episode plays (taken up at its reset), not the newest compiled.
        let generation = playing.generation();
        let mut reward = 0.0_f64;
        let failed = loop {
            agent.act(&mut actions);
            match env.step(&actions) {
                Ok(outcome) => {
                    reward += f64::from(env.rewards()[0]);
                    for line in env.hook_log() {
                        eprintln!("{line}");
                    }
                    if outcome.terminated || outcome.truncated {
                        break None;
                    }
                }
                Err(EngineError::Script { message, .. }) => break Some(message),
                Err(source) => return Err(CliError::step(env.info(), source)),
            }
        };
        let info = env.info();
        match failed {
            None => writeln!(
                out,
                "episode {episode} (version {generation}): score {}-{}, {} steps, return {reward:.3}, {} script errors",
                info.score[0], info.score[1], info.steps, info.script_errors
            )?,
            Some(message) => {
                // The step under way when it failed: the script's diagnostic counts the same way.
                writeln!(out, "episode {episode} (version {generation}): a script failed in step {}", info.steps + 1)?;
                show_once(&mut shown, generation, &message);
                // Give the user time to fix it rather than failing thousands of times a second.
                std::thread::sleep(Duration::from_millis(500));
            }
        }
        out.flush()?;
        if args.pause_ms > 0 {
            std::thread::sleep(Duration::from_millis(args.pause_ms));
        }
        episode += 1;
    }
    Ok(())
}

/// Prints a script failure unless the same one, from the same version, was the last shown.
fn show_once(shown: &mut Option<(u64, String)>, generation: u64, message: &str) {
    if shown.as_ref().is_some_and(|(g, m)| *g == generation && m == message) {
        return;
    }
    eprintln!("{message}");
    *shown = Some((generation, message.to_owned()));
}
