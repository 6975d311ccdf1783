//! `touchline run`: play episodes of a scenario with a simple policy.
//!
//! Prints one line per episode (index, score, steps, controller 0's return, how it ended) and a
//! summary; or, with `--json`, one JSON document ([`Report`]) and nothing else on stdout.

use std::io::{self, IsTerminal, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64Mcg;
use serde::Serialize;
use touchline_dsl::script::{ScriptOptions, Scripts};
use touchline_engine::{Action, ActionSet, EngineError, EnvConfig, Scenario};
use touchline_render::replay::{Recorder, Replay};

use super::lessons::LessonLog;
use super::stats::StatsLine;

use crate::CliError;

/// Arguments of `touchline run`.
#[derive(Debug, Args)]
pub(crate) struct RunArgs {
    /// A stdlib scenario name (see `touchline list`), a `.tl` scenario file, or a compiled
    /// `.json` scenario.
    scenario: String,

    /// Episodes to play; the first starts from the seed, each later one from `reset()`.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    episodes: u64,

    /// Seed of the environment (the random policy draws from its own generator seeded from it).
    #[arg(long, default_value_t = 0)]
    seed: u64,

    /// Who chooses the controlled players' actions.
    #[arg(long, value_enum, default_value_t = Policy::Builtin)]
    policy: Policy,

    /// Print one JSON document with every episode and the summary on stdout, and nothing else.
    #[arg(long)]
    json: bool,

    /// Left-team players the agents control.
    #[arg(long, default_value_t = 1)]
    left_agents: usize,

    /// Right-team players the agents control.
    #[arg(long, default_value_t = 0)]
    right_agents: usize,

    /// Add GRF's Checkpoint reward to the Scoring reward.
    #[arg(long)]
    checkpoints: bool,

    /// Print match statistics (goals, shots, passes, possession, fouls, cards, offsides, corners,
    /// ...) for every episode and on average; with `--json`, add them to each episode and the
    /// summary.
    #[arg(long)]
    stats: bool,

    /// Write replays of the episodes into this folder (`touchline replay` and `touchline view`
    /// read them): `<scenario>_seed<S>_ep<E>.tlreplay`.
    #[arg(long, value_name = "DIR")]
    record: Option<PathBuf>,

    /// With --record: keep every Nth episode (the first, the N+1th, …).
    #[arg(long, default_value_t = 1, value_name = "N", requires = "record", value_parser = clap::value_parser!(u64).range(1..))]
    record_every: u64,

    /// With --record: keep only clips round goals (the 100 steps before each goal and 1 after, as
    /// GRF's score dumps), `…_goal<STEP>.tlreplay`, instead of whole episodes.
    #[arg(long, requires = "record")]
    record_goals: bool,

    /// Show progress through the scenario's curriculum: a line when the env moves to the next
    /// lesson and a table of the lessons (episodes, the window's metrics, when each advanced);
    /// with `--json`, a `curriculum` object and each episode's lesson.
    #[arg(long)]
    curriculum: bool,
}

/// How actions are chosen for every controlled player.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Serialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum Policy {
    /// Always `idle`.
    Idle,
    /// Uniformly at random from the 19-action default set, every step.
    Random,
    /// The built-in AI plays the controlled players too (`builtin_ai` of the `v2` action set).
    Builtin,
}

impl Policy {
    fn name(self) -> &'static str {
        match self {
            Policy::Idle => "idle",
            Policy::Random => "random",
            Policy::Builtin => "builtin",
        }
    }

    pub(crate) fn action_set(self) -> ActionSet {
        match self {
            Policy::Builtin => ActionSet::V2,
            Policy::Idle | Policy::Random => ActionSet::Default,
        }
    }
}

/// Offset mixed into the seed of the random policy's generator, so that it does not share a seed
/// with the engine's own generator (the 64-bit golden ratio, a common seed-mixing constant).
const POLICY_SEED_OFFSET: u64 = 0x9E37_79B9_7F4A_7C15;

/// A policy with its state.
pub(crate) enum Agent {
    /// The same action every step.
    Fixed(Action),
    /// Uniform draws from `set`.
    Random { rng: Pcg64Mcg, set: ActionSet },
}

impl Agent {
    pub(crate) fn new(policy: Policy, seed: u64) -> Agent {
        match policy {
            Policy::Idle => Agent::Fixed(Action::Idle),
            Policy::Builtin => Agent::Fixed(Action::BuiltinAi),
            Policy::Random => Agent::Random {
                rng: Pcg64Mcg::seed_from_u64(seed.wrapping_add(POLICY_SEED_OFFSET)),
                set: policy.action_set(),
            },
        }
    }

    /// Writes one action per controller into `actions`.
    pub(crate) fn act(&mut self, actions: &mut [Action]) {
        match self {
            Agent::Fixed(action) => actions.fill(*action),
            Agent::Random { rng, set } => {
                let choices = set.actions();
                for a in actions {
                    *a = choices[rng.random_range(0..choices.len())];
                }
            }
        }
    }
}

/// What `--json` prints.
#[derive(Debug, Serialize)]
struct Report<'a> {
    /// The scenario as given on the command line.
    scenario: &'a str,
    seed: u64,
    policy: Policy,
    /// `"default"` (19 actions) or `"v2"` (20, with `builtin_ai`).
    action_set: &'static str,
    left_agents: usize,
    right_agents: usize,
    checkpoints: bool,
    episodes: Vec<EpisodeRecord>,
    summary: Summary,
    /// Progress through the lessons, with `--curriculum`.
    #[serde(skip_serializing_if = "Option::is_none")]
    curriculum: Option<LessonLog>,
}

/// One played episode.
#[derive(Debug, Serialize)]
struct EpisodeRecord {
    /// 0-based episode index (the engine's `StepInfo::episode`).
    episode: u64,
    /// Goals `[left, right]`.
    score: [u32; 2],
    /// Env steps played (at most `game_duration + 1`).
    steps: u32,
    /// Sum of controller 0's rewards over the episode (0 when no player is controlled).
    reward: f64,
    /// The scenario's end conditions held at the last step.
    terminated: bool,
    /// The time limit was reached at the last step.
    truncated: bool,
    /// Match statistics, with `--stats`.
    #[serde(skip_serializing_if = "Option::is_none")]
    stats: Option<StatsLine>,
    /// 0-based lesson the episode was played in, with `--curriculum`.
    #[serde(skip_serializing_if = "Option::is_none")]
    lesson: Option<usize>,
}

impl EpisodeRecord {
    /// How the episode ended, in one word (`terminated` wins when both flags are set).
    fn ended(&self) -> &'static str {
        if self.terminated { "terminated" } else { "truncated" }
    }
}

/// Totals and means over all episodes.
#[derive(Debug, Serialize)]
struct Summary {
    episodes: u64,
    /// Mean goals per episode `[left, right]`.
    mean_score: [f64; 2],
    /// Goals by both teams over all episodes.
    total_goals: u64,
    total_steps: u64,
    mean_steps: f64,
    /// Mean of the episodes' `reward`.
    mean_reward: f64,
    /// Wall-clock seconds spent stepping and resetting (not loading).
    wall_seconds: f64,
    /// `total_steps / wall_seconds`; `null` when too little time passed to measure.
    steps_per_second: Option<f64>,
    /// Mean match statistics per episode, with `--stats`.
    #[serde(skip_serializing_if = "Option::is_none")]
    mean_stats: Option<StatsLine>,
}

impl Summary {
    fn new(records: &[EpisodeRecord], elapsed: Duration) -> Summary {
        let n = records.len().max(1) as f64;
        let goals = |side: usize| records.iter().map(|r| u64::from(r.score[side])).sum::<u64>();
        let total_steps: u64 = records.iter().map(|r| u64::from(r.steps)).sum();
        let wall_seconds = elapsed.as_secs_f64();
        Summary {
            episodes: records.len() as u64,
            mean_score: [goals(0) as f64 / n, goals(1) as f64 / n],
            total_goals: goals(0) + goals(1),
            total_steps,
            mean_steps: total_steps as f64 / n,
            mean_reward: records.iter().map(|r| r.reward).sum::<f64>() / n,
            wall_seconds,
            steps_per_second: (wall_seconds > 0.0).then(|| total_steps as f64 / wall_seconds),
            mean_stats: StatsLine::mean(records.iter().filter_map(|r| r.stats.as_ref())),
        }
    }
}

/// Runs `touchline run`.
pub(crate) fn run(args: &RunArgs) -> Result<(), CliError> {
    let scenario = touchline_dsl::load(&args.scenario)?;
    if args.curriculum && scenario.curriculum.is_none() {
        return Err(CliError::NoCurriculum { scenario: args.scenario.clone() });
    }
    let config = EnvConfig {
        left_agents: args.left_agents,
        right_agents: args.right_agents,
        action_set: args.policy.action_set(),
        checkpoints: args.checkpoints,
    };
    let first = scenario.curriculum.as_ref().and_then(|c| c.lessons.first()).map_or(&scenario, |l| &l.scenario);
    // With the odd-episode swap a side plays either list: what it can control in every episode.
    let controllable = first.controllable_every_episode();
    let expected_steps = u64::from(first.game_duration) + 1;
    let dir = touchline_dsl::script_dir(&args.scenario);
    let scripts = Scripts::compile(&scenario, &dir, ScriptOptions::default())
        .map_err(|e| CliError::Build(touchline_dsl::BuildError::Scripts(e)))?;
    // Replays carry the scripts' text, so that they re-simulate without the files.
    let script_sources: Vec<(String, String)> =
        scripts.sources().map(|(path, text)| (path.to_owned(), text.to_owned())).collect();
    let mut env = touchline_dsl::attach(&scripts, scenario, config, args.seed).map_err(|e| match e {
        // A script failing at the first reset is the script's error, not the configuration's.
        EngineError::Script { message, .. } => CliError::Script { episode: 0, message },
        source => CliError::Config {
            scenario: args.scenario.clone(),
            help: format!(
                "this scenario has {} controllable left and {} controllable right players; \
                 pass --left-agents and --right-agents within those numbers",
                controllable[0], controllable[1]
            ),
            source,
        },
    })?;

    let mut out = io::stdout().lock();
    let bar = progress_bar(args, expected_steps);
    if !args.json {
        bar.suspend(|| write_header(&mut out, args, env.scenario(), env.num_controllers()))?;
    }

    let mut lessons = if args.curriculum { LessonLog::new(&env) } else { None };
    let mut agent = Agent::new(args.policy, args.seed);
    let mut actions = vec![Action::Idle; env.num_controllers()];
    let mut records = Vec::new();
    let mut writer: Option<ReplayWriter> = None;
    if let Some(dir) = &args.record {
        std::fs::create_dir_all(dir).map_err(|source| CliError::Write { path: dir.clone(), source })?;
    }
    let start = Instant::now();
    for i in 0..args.episodes {
        if i > 0 {
            env.reset().map_err(|source| CliError::step(env.info(), source))?;
            if let Some(line) = lessons.as_mut().and_then(|l| l.after_reset(&env, i))
                && !args.json
            {
                bar.suspend(|| writeln!(out, "{line}"))?;
            }
        }
        let mut recorder = (args.record.is_some() && i % args.record_every == 0)
            .then(|| Recorder::start(&env).with_scripts(script_sources.iter().cloned()));
        let mut reward = 0.0_f64;
        let outcome = loop {
            agent.act(&mut actions);
            let outcome = env.step(&actions).map_err(|source| CliError::step(env.info(), source))?;
            if let Some(r) = &mut recorder {
                r.record(&env, &actions);
            }
            reward += f64::from(env.rewards().first().copied().unwrap_or(0.0));
            bar.inc(1);
            if outcome.terminated || outcome.truncated {
                break outcome;
            }
        };
        if let (Some(dir), Some(recorder)) = (&args.record, recorder) {
            // Compressing and writing happen on another thread while the next episode plays (at
            // most one replay in flight), so recording costs the stepping thread only the frames.
            let previous = writer.take();
            let (dir, replay, goals) = (dir.clone(), recorder.finish(), args.record_goals);
            writer = Some(std::thread::spawn(move || save_replays(&dir, &replay, goals)));
            if let Some(done) = previous {
                let written = joined(done, args)?;
                if !args.json {
                    for path in written {
                        bar.suspend(|| writeln!(out, "replay   {}", path.display()))?;
                    }
                }
            }
        }
        let info = env.info();
        let record = EpisodeRecord {
            episode: info.episode,
            score: info.score,
            steps: info.steps,
            reward,
            terminated: outcome.terminated,
            truncated: outcome.truncated,
            stats: args.stats.then(|| StatsLine::from(env.game().stats())),
            lesson: lessons.as_ref().map(|_| info.lesson),
        };
        if let Some(log) = lessons.as_mut() {
            log.episode_done(&env);
        }
        // The bar's length assumed every episode runs to the time limit: drop what was not played.
        bar.set_length(bar.length().unwrap_or(0).saturating_sub(expected_steps.saturating_sub(u64::from(info.steps))));
        if !args.json {
            bar.suspend(|| {
                writeln!(
                    out,
                    "{:>7}  {:>5}  {:>5}  {:>7.3}  {}",
                    record.episode,
                    format!("{}-{}", record.score[0], record.score[1]),
                    record.steps,
                    record.reward,
                    record.ended()
                )?;
                if let Some(stats) = &record.stats {
                    stats.write(&mut out, "")?;
                }
                Ok::<(), io::Error>(())
            })?;
        }
        records.push(record);
    }
    let elapsed = start.elapsed();
    bar.finish_and_clear();
    if let Some(done) = writer.take() {
        let written = joined(done, args)?;
        if !args.json {
            for path in written {
                writeln!(out, "replay   {}", path.display())?;
            }
        }
    }

    let summary = Summary::new(&records, elapsed);
    if args.json {
        let report = Report {
            scenario: &args.scenario,
            seed: args.seed,
            policy: args.policy,
            action_set: env.action_set().name(),
            left_agents: args.left_agents,
            right_agents: args.right_agents,
            checkpoints: args.checkpoints,
            episodes: records,
            summary,
            curriculum: lessons,
        };
        serde_json::to_writer_pretty(&mut out, &report).map_err(io::Error::from)?;
        writeln!(out)?;
    } else {
        write_summary(&mut out, &summary)?;
        if let Some(log) = &lessons {
            log.write(&mut out)?;
        }
    }
    out.flush()?;
    Ok(())
}

/// A replay being written on its own thread.
type ReplayWriter = std::thread::JoinHandle<Result<Vec<PathBuf>, CliError>>;

/// Waits for a replay writer; returns the files it wrote.
fn joined(writer: ReplayWriter, args: &RunArgs) -> Result<Vec<PathBuf>, CliError> {
    writer.join().unwrap_or_else(|_| {
        Err(CliError::Write {
            path: args.record.clone().unwrap_or_default(),
            source: io::Error::other("the replay writer stopped unexpectedly"),
        })
    })
}

/// Writes `replay` into `dir`, whole or as clips round its goals; returns the files written.
fn save_replays(dir: &std::path::Path, replay: &Replay, goals_only: bool) -> Result<Vec<PathBuf>, CliError> {
    let (seed, episode) = match &replay.start {
        touchline_render::replay::Start::Reset { seed, episode } => (*seed, *episode),
        touchline_render::replay::Start::Snapshot(_) => (0, 0),
    };
    let name = if replay.scenario.name.is_empty() { "scenario" } else { replay.scenario.name.as_str() };
    let stem = format!("{name}_seed{seed}_ep{episode}");
    let mut parts = Vec::new();
    if goals_only {
        for g in replay.goal_frames() {
            let clip = crate::cmd::replay::hooks(replay).and_then(|hooks| {
                replay
                    .clip_with(hooks, g.saturating_sub(100), (g + 1).min(replay.steps()))
                    .map_err(|source| CliError::Replay { path: dir.join(&stem), source })
            })?;
            parts.push((dir.join(format!("{stem}_goal{g}.tlreplay")), clip));
        }
    }
    let mut written = Vec::new();
    let whole = (!goals_only).then(|| (dir.join(format!("{stem}.tlreplay")), replay));
    for (path, part) in parts.iter().map(|(p, r)| (p.clone(), r)).chain(whole) {
        part.save(&path).map_err(|source| CliError::Write { path: path.clone(), source })?;
        written.push(path);
    }
    Ok(written)
}

/// A progress bar over the expected total of steps, on stderr; hidden with `--json`, when stderr
/// is not a terminal, or for a single short episode.
fn progress_bar(args: &RunArgs, expected_steps: u64) -> ProgressBar {
    let total = expected_steps.saturating_mul(args.episodes);
    let worth_it = args.episodes > 1 || total > 1000;
    if args.json || !worth_it || !io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let style = ProgressStyle::with_template(
        "{spinner} [{elapsed_precise}] {wide_bar} {human_pos}/{human_len} steps, eta {eta}",
    )
    .unwrap_or_else(|_| ProgressStyle::default_bar());
    ProgressBar::new(total).with_style(style)
}

fn write_header(out: &mut impl Write, args: &RunArgs, scenario: &Scenario, controllers: usize) -> io::Result<()> {
    let name = if scenario.name.is_empty() { args.scenario.as_str() } else { scenario.name.as_str() };
    writeln!(
        out,
        "{name}: {} episode{}, seed {}, policy {}, {controllers} controlled player{} ({} left, {} right)",
        args.episodes,
        if args.episodes == 1 { "" } else { "s" },
        args.seed,
        args.policy.name(),
        if controllers == 1 { "" } else { "s" },
        args.left_agents,
        args.right_agents,
    )?;
    writeln!(out, "episode  score  steps   reward  ended")
}

fn write_summary(out: &mut impl Write, s: &Summary) -> io::Result<()> {
    writeln!(out)?;
    writeln!(out, "episodes     {}", s.episodes)?;
    writeln!(out, "mean score   {:.2} - {:.2}", s.mean_score[0], s.mean_score[1])?;
    writeln!(out, "total goals  {}", s.total_goals)?;
    writeln!(out, "mean steps   {:.1}", s.mean_steps)?;
    writeln!(out, "mean reward  {:.3}", s.mean_reward)?;
    if let Some(stats) = &s.mean_stats {
        writeln!(out, "mean match statistics per episode (left / right):")?;
        stats.write(out, "")?;
    }
    match s.steps_per_second {
        Some(rate) => writeln!(out, "steps/s      {rate:.0} ({} steps in {:.3} s)", s.total_steps, s.wall_seconds),
        None => writeln!(out, "steps/s      - ({} steps, too fast to time)", s.total_steps),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn random_policy_draws_every_action_of_the_set() {
        let mut agent = Agent::new(Policy::Random, 3);
        let mut seen = [false; 19];
        let mut actions = [Action::Idle; 4];
        for _ in 0..500 {
            agent.act(&mut actions);
            for a in actions {
                let index = ActionSet::Default.encode(a).expect("drawn from the default set");
                seen[index as usize] = true;
            }
        }
        assert!(seen.iter().all(|s| *s));
    }

    #[test]
    fn random_policy_is_seeded() {
        let draw = |seed| {
            let mut agent = Agent::new(Policy::Random, seed);
            let mut actions = [Action::Idle; 16];
            agent.act(&mut actions);
            actions
        };
        assert_eq!(draw(1), draw(1));
        assert_ne!(draw(1), draw(2));
    }

    #[test]
    fn summary_means() {
        let record = |score: [u32; 2], steps, reward| EpisodeRecord {
            episode: 0,
            score,
            steps,
            reward,
            terminated: true,
            truncated: false,
            stats: None,
            lesson: None,
        };
        let s = Summary::new(&[record([1, 0], 10, 1.0), record([0, 2], 30, -1.0)], Duration::from_secs(2));
        assert_eq!(s.mean_score, [0.5, 1.0]);
        assert_eq!(s.total_goals, 3);
        assert_eq!(s.total_steps, 40);
        assert_eq!(s.mean_steps, 20.0);
        assert_eq!(s.mean_reward, 0.0);
        assert_eq!(s.steps_per_second, Some(20.0));
        assert_eq!(Summary::new(&[], Duration::ZERO).steps_per_second, None);
    }
}
