//! The RL episode around a [`Match`]: controllers, sticky actions, 10 ticks per step, rewards,
//! end conditions and observations, with GRF's semantics (docs/grf-compatibility.md#actions, #rewards,
//! #time-base, #episode-length).

mod config;
mod control;
mod end;
mod hooks;
mod lessons;
mod restore_check;
mod snapshot;
mod step;
mod sticky;

use glam::Vec2;
use serde::{Deserialize, Serialize};

pub use config::EnvConfig;
pub use hooks::{HookOutcome, HookView, Hooks};
use snapshot::EnvState;
pub use snapshot::Snapshot;
pub use sticky::{Press, StickyState};

use crate::error::EngineError;
use crate::game::{Action, ActionSet, GameMode, Kick, KickTarget, Match, PlayerInput};
use crate::geometry::Side;
use crate::obs::RawObservation;
use crate::player::{DRIBBLE_SPEED, WALK_SPEED};
use crate::reward::{CheckpointTracker, EventProgress, EventRewards, RewardPlan, Viewpoint, scoring_reward};
use crate::scenario::{Curriculum, Metric, Scenario};
use end::EndTracker;
use lessons::LessonProgress;

/// Ticks of play per env step: 10 × 10 ms = 0.1 s (GRF `physics_steps_per_frame`, docs/grf-compatibility.md#time-base).
pub const TICKS_PER_STEP: u32 = 10;
/// Most ticks one step may simulate (play plus dead time), a guard against a stuck restart.
const MAX_TICKS_PER_STEP: u32 = 2_000;

/// How a step ended.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct StepOutcome {
    /// The scenario's end conditions hold (goal, out of play, possession change).
    pub terminated: bool,
    /// The time limit was reached (`game_duration + 1` steps).
    pub truncated: bool,
}

/// Per-step information, as GRF's `info` plus the per-term rewards.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StepInfo {
    /// Goals `[left, right]`.
    pub score: [u32; 2],
    /// Steps left (`game_duration + 1` at reset).
    pub steps_left: u32,
    /// Game mode after the step.
    pub game_mode: GameMode,
    /// The left team's scoring reward this step (+1, -1 or 0; GRF `score_reward`).
    pub score_reward: f32,
    /// Checkpoint reward paid this step, summed over controllers.
    pub checkpoint_reward: f32,
    /// Reward paid this step by the hooks' script terms, summed over controllers.
    pub script_reward: f32,
    /// Reward paid this step by the event terms (`reward on …`), summed over controllers.
    #[serde(default)]
    pub event_reward: f32,
    /// Script failures absorbed this episode under the "warn" policy (each paid zero).
    pub script_errors: u32,
    /// Steps taken this episode.
    pub steps: u32,
    /// 0-based episode index since the last seeding.
    pub episode: u64,
    /// 0-based index of the curriculum lesson played (0 without a curriculum).
    #[serde(default)]
    pub lesson: usize,
}

/// Where an env stands in its curriculum ([`Env::curriculum_progress`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CurriculumProgress {
    /// The lesson played, 0-based.
    pub lesson: usize,
    /// Number of lessons.
    pub lessons: usize,
    /// Episodes finished in this lesson.
    pub episodes: u64,
    /// Finished episodes the lesson's criterion is judged over now (at most its window).
    pub window: usize,
}

/// One agent controller: its side and its virtual gamepad (the player it drives is in
/// `EnvState::controlled`).
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
struct Controller {
    side: Side,
    sticky: StickyState,
}

/// A reinforcement-learning environment over one [`Scenario`].
#[derive(Clone, Debug)]
pub struct Env {
    /// The scenario played: the current lesson's when there is a curriculum.
    scenario: Scenario,
    /// The lessons, when the env was built on a scenario with a curriculum.
    curriculum: Option<Box<Curriculum>>,
    config: EnvConfig,
    /// Every player controllable on a side has an agent: control never switches.
    fixed_control: [bool; 2],
    /// The reward terms paid each step.
    reward_plan: RewardPlan,
    /// The event terms (`reward on …`) paid each step.
    event_rewards: EventRewards,
    /// The saved match every episode starts from (the scenario's `start_state`).
    start: Option<Box<Match>>,
    /// Identifies scenario and configuration, so that snapshots restore only where they belong.
    fingerprint: u64,
    /// Everything that changes while the env plays (what a [`Snapshot`] saves).
    state: EnvState,
    /// Script reward terms and end conditions, run outside the engine.
    hooks: Option<Box<dyn Hooks>>,
    /// Scratch: the actions taken in the last step (after anti-stalling), one per controller.
    taken: Vec<Action>,
    /// Scratch: the hooks' rewards of the last step, one per controller.
    hook_rewards: Vec<f32>,
}

/// The input a gamepad in state `sticky` gives `player` in a step where `press` was pressed
/// (agents' and scripted players' actions alike); `on_ball`: he may play the ball
/// (`Match::may_play_ball`).
fn sticky_input(sticky: &StickyState, press: Press, player: &crate::player::Player, on_ball: bool) -> PlayerInput {
    let dir = sticky.direction_action().and_then(Action::direction_vector).unwrap_or(Vec2::ZERO);
    let speed = if sticky.dribble {
        DRIBBLE_SPEED
    } else if sticky.sprint {
        player.max_speed
    } else {
        WALK_SPEED
    };
    let aim = if dir == Vec2::ZERO { player.facing } else { dir };
    // A pass or shot button held down, its kick not yet asked for: the man on the ball runs on.
    let buffered = on_ball && sticky.held.is_some_and(|held| !held.fired);
    let velocity = if buffered { buffered_run(player) } else { dir * speed };
    PlayerInput {
        velocity,
        look: player.facing,
        dribble: sticky.dribble,
        kick: match press {
            Press::Kick(kind, power) => Some(Kick { kind, target: KickTarget::Direction(aim), height: 0.6, power }),
            _ => None,
        },
        slide: press == Press::Slide,
        first_time: None,
    }
}

/// The run of a man on the ball while his pass or shot button is held down and the kick is still
/// to come, GRF 2.10's human controller with a kick buffered: the stick no longer steers him. A
/// player on the move runs on along his facing at his present pace; one standing stays where he
/// is. GRF asks its ball control for his pace times ((1 + facing · stick) / 2)^1.5 × 0.8 + 0.2,
/// times 0.9, but that control runs him at least as fast as it takes to stay on the ball he has
/// touched ahead of him, which is about his pace, so a braking stick changes nothing. Once the
/// kick is asked for, the wind-up keeps his run too (`Match::move_players`). So a shot held to
/// fill its gauge is struck on the run: measured in GRF 2.10.2 (academy_empty_goal, shot held
/// from the first step, engine seeds 100-101), our centre back reached the ball at about 3 m/s,
/// ran on at 3.8-5.3 m/s while the gauge filled and struck the ball at 34-35 m/s; touchline's
/// stood still and struck it at about 31 m/s before this, 33.6 after (the fidelity harness's
/// probe shot_every_step; docs/grf-compatibility.md, "a carrier holding pass or shot runs on").
fn buffered_run(player: &crate::player::Player) -> Vec2 {
    let pace = player.velocity.length();
    if pace < crate::game::kick::STANDING_RUN { Vec2::ZERO } else { player.facing * pace }
}

impl Env {
    /// An environment with the default configuration (one left agent, scoring reward, 19
    /// actions), reset to its first episode with `seed`.
    ///
    /// # Errors
    /// [`EngineError::InvalidScenario`] when the scenario fails [`Scenario::validate`].
    pub fn new(scenario: Scenario, seed: u64) -> Result<Env, EngineError> {
        Env::with_config(scenario, EnvConfig::default(), seed)
    }

    /// An environment with `config`, reset to its first episode with `seed`.
    ///
    /// # Errors
    /// [`EngineError::InvalidScenario`] for a bad scenario; [`EngineError::InvalidConfig`] when
    /// more players are to be controlled than a side has controllable players.
    pub fn with_config(scenario: Scenario, config: EnvConfig, seed: u64) -> Result<Env, EngineError> {
        Env::build(scenario, config, seed, None)
    }

    /// An environment whose scenario's script terms (`RewardKind::Script`,
    /// `EndCondition::Script`) run through `hooks`, reset to its first episode with `seed`.
    /// `touchline_dsl::build_env` builds the rhai hooks of a scenario and calls this.
    ///
    /// # Errors
    /// As [`Env::with_config`], and any error of the hooks' first [`Hooks::reset`].
    pub fn with_hooks(
        scenario: Scenario,
        config: EnvConfig,
        seed: u64,
        hooks: Box<dyn Hooks>,
    ) -> Result<Env, EngineError> {
        Env::build(scenario, config, seed, Some(hooks))
    }

    fn build(
        mut scenario: Scenario,
        config: EnvConfig,
        seed: u64,
        hooks: Option<Box<dyn Hooks>>,
    ) -> Result<Env, EngineError> {
        scenario.validate()?;
        let curriculum = scenario.curriculum.take();
        if let Some(c) = &curriculum {
            lesson_agents(c, &config, hooks.is_some())?;
            scenario = c.lessons[0].scenario.clone();
        }
        let agents = agents_for(&scenario, &config)?;
        let controllers: Vec<Controller> = (0..agents[0])
            .map(|_| Controller { side: Side::Left, sticky: StickyState::default() })
            .chain((0..agents[1]).map(|_| Controller { side: Side::Right, sticky: StickyState::default() }))
            .collect();
        let n = controllers.len();
        let game = Match::new(&scenario, 0, seed);
        let reward_plan = RewardPlan::new(&scenario, &config, hooks.is_some())?;
        let event_rewards = EventRewards::new(&scenario);
        let start = match &scenario.start_state {
            Some(bytes) => Some(Box::new(snapshot::start_match(&scenario, bytes)?)),
            None => None,
        };
        if hooks.is_none()
            && let Some(path) = scenario.script_behaviours().next()
        {
            return Err(EngineError::InvalidScenario {
                reason: format!(
                    "the behaviour script \"{path}\" needs script hooks; build the env through \
                     touchline_dsl, which runs scripts"
                ),
            });
        }
        if hooks.is_none()
            && let Some(crate::scenario::EndCondition::Script { path }) =
                scenario.end_when.iter().find(|c| matches!(c, crate::scenario::EndCondition::Script { .. }))
        {
            return Err(EngineError::InvalidScenario {
                reason: format!(
                    "the end-condition script \"{path}\" needs script hooks; build the env through \
                     touchline_dsl, which runs scripts"
                ),
            });
        }
        let progress = LessonProgress::new(curriculum.as_ref().map_or(0, |c| c.max_window()));
        let mut env = Env {
            curriculum,
            hooks,
            taken: vec![Action::Idle; n],
            hook_rewards: vec![0.0; n],
            reward_plan,
            start,
            state: EnvState {
                seed,
                episode: 0,
                fresh: true,
                game,
                controllers,
                controlled: vec![0; n],
                observations: vec![RawObservation::default(); n],
                rewards: vec![0.0; n],
                checkpoints: vec![CheckpointTracker::default(); n],
                events: vec![EventProgress::default(); n * event_rewards.len()],
                previous_ball: vec![[0.0; 2]; n],
                end: EndTracker::default(),
                info: StepInfo::default(),
                steps: 0,
                done: false,
                score_diff: 0,
                waiting_for_game: 0,
                hook_error: None,
                lessons: progress,
            },
            event_rewards,
            fixed_control: fixed_control(&scenario, agents),
            scenario,
            config,
            fingerprint: 0,
        };
        env.fingerprint = env.compute_fingerprint();
        env.begin(0)?;
        Ok(env)
    }

    /// Starts the next episode (the same one again if no step was taken since the last start).
    ///
    /// # Errors
    /// A hook that fails at the episode's start ([`Hooks::reset`], e.g. a script's `fn reset`
    /// throwing; [`EngineError::Script`] with its diagnostic). The episode is then over before
    /// it began: stepping it returns the same error, and the next reset starts the episode after
    /// it (it is never replayed in a loop).
    pub fn reset(&mut self) -> Result<(), EngineError> {
        let episode = if self.state.fresh { self.state.episode } else { self.state.episode + 1 };
        self.begin(episode)
    }

    /// Reseeds and starts episode 0 of the new seed (Gymnasium's `reset(seed=…)`).
    ///
    /// # Errors
    /// As [`Env::reset`].
    pub fn reset_with_seed(&mut self, seed: u64) -> Result<(), EngineError> {
        self.state.seed = seed;
        self.begin(0)
    }

    /// Reseeds and starts 0-based episode `episode` of `seed`: the state the `episode`-th reset
    /// after [`Env::reset_with_seed`] would give (episodes do not depend on earlier ones). Replays
    /// use it to start where a recording started.
    ///
    /// # Errors
    /// As [`Env::reset`].
    pub fn reset_to_episode(&mut self, seed: u64, episode: u64) -> Result<(), EngineError> {
        self.state.seed = seed;
        self.begin(episode)
    }

    /// The seed of the current episodes (set at construction or by the last reseeding reset).
    pub fn seed(&self) -> u64 {
        self.state.seed
    }

    fn begin(&mut self, episode: u64) -> Result<(), EngineError> {
        if let Some(hooks) = self.hooks.as_mut()
            && let Some(scenario) = hooks.poll_scenario()
            && let Err(e) = self.swap_scenario(scenario)
            && let Some(hooks) = self.hooks.as_mut()
        {
            hooks.scenario_refused(&e);
        }
        self.advance_lesson();
        self.state.lessons.start_episode();
        self.state.episode = episode;
        self.state.fresh = true;
        self.state.game = match &self.start {
            Some(saved) => saved.restarted(&self.scenario, episode, self.state.seed),
            None => Match::new(&self.scenario, episode, self.state.seed),
        };
        self.state.steps = 0;
        self.state.done = false;
        self.state.score_diff = 0;
        self.state.waiting_for_game = 0;
        for c in &mut self.state.controllers {
            c.sticky = StickyState::default();
        }
        for t in &mut self.state.checkpoints {
            *t = CheckpointTracker::default();
        }
        self.state.events.fill(EventProgress::default());
        for side in Side::BOTH {
            let (start, len) = self.controller_span(side);
            control::initial(&self.state.game, side, &mut self.state.controlled[start..start + len]);
        }
        self.state.rewards.fill(0.0);
        self.refresh_observations();
        self.state.end.reset(self.state.game.observed_owner().map(|o| o.0), self.state.game.mode());
        self.state.info = StepInfo {
            score: [0, 0],
            steps_left: self.steps_left(),
            game_mode: self.state.game.mode(),
            score_reward: 0.0,
            checkpoint_reward: 0.0,
            event_reward: 0.0,
            script_reward: 0.0,
            script_errors: 0,
            steps: 0,
            episode,
            lesson: self.state.lessons.lesson,
        };
        self.state.hook_error = None;
        if let Some(hooks) = self.hooks.as_mut() {
            let view = hook_view(&self.state, &self.scenario, &[]);
            if let Err(e) = hooks.reset(&view) {
                // The episode is spent: not fresh, so the next reset moves on to the next one
                // instead of replaying this failure for ever; over, so it cannot be stepped.
                self.state.fresh = false;
                self.state.done = true;
                self.state.hook_error = Some(e.clone());
                return Err(e);
            }
        }
        Ok(())
    }

    /// Moves to the next lesson when the current one's criterion holds over its window (the
    /// last lesson stays).
    fn advance_lesson(&mut self) {
        let Some(c) = &self.curriculum else { return };
        let i = self.state.lessons.lesson;
        let Some(next) = c.lessons.get(i + 1) else { return };
        if !c.lessons[i].advance.as_ref().is_some_and(|crit| self.state.lessons.met(crit)) {
            return;
        }
        let scenario = next.scenario.clone();
        // Every lesson was checked against the env when it was built, so this cannot fail; if
        // it did, the env would stay on the lesson it plays.
        if self.switch_to(scenario).is_ok() {
            self.state.lessons.advance();
        }
    }

    /// Switches to `scenario` (from a watched source) for the episodes to come; refused, leaving
    /// the env as it was, when it is invalid or gives a different number of controllers. A
    /// scenario with a curriculum replaces the lessons and plays the lesson of the same index.
    fn swap_scenario(&mut self, mut scenario: Scenario) -> Result<(), EngineError> {
        scenario.validate()?;
        let Some(c) = scenario.curriculum.take() else {
            let old = self.curriculum.take();
            if let Err(e) = self.switch_to(scenario) {
                self.curriculum = old;
                return Err(e);
            }
            self.state.lessons = LessonProgress::new(0);
            return Ok(());
        };
        lesson_agents(&c, &self.config, self.hooks.is_some())?;
        let lesson = self.state.lessons.lesson.min(c.lessons.len() - 1);
        let first = c.lessons[lesson].scenario.clone();
        let capacity = c.max_window();
        let old = self.curriculum.replace(c);
        if let Err(e) = self.switch_to(first) {
            self.curriculum = old;
            return Err(e);
        }
        self.state.lessons.resize(capacity);
        self.state.lessons.lesson = lesson;
        Ok(())
    }

    /// Plays `scenario` from the next episode on (a lesson, or a scenario without curriculum);
    /// refused when it gives another number of controllers than the env has.
    fn switch_to(&mut self, scenario: Scenario) -> Result<(), EngineError> {
        scenario.validate()?;
        let controllable = scenario.controllable_players();
        let agents = agents_for(&scenario, &self.config).unwrap_or([usize::MAX, usize::MAX]);
        let (left, n) = (self.controller_span(Side::Left).1, self.state.controllers.len());
        if agents[0] != left || agents[0].saturating_add(agents[1]) != n {
            return Err(EngineError::InvalidScenario {
                reason: format!(
                    "the edited scenario gives {} left and {} right controllers, the env has {left} and {}; \
                     restart to change the number of agents",
                    agents[0].min(controllable[0]),
                    agents[1].min(controllable[1]),
                    n - left
                ),
            });
        }
        let reward_plan = RewardPlan::new(&scenario, &self.config, self.hooks.is_some())?;
        let start = match &scenario.start_state {
            Some(bytes) => Some(Box::new(snapshot::start_match(&scenario, bytes)?)),
            None => None,
        };
        self.reward_plan = reward_plan;
        self.event_rewards = EventRewards::new(&scenario);
        // Sized here, once per accepted edit, so that stepping never allocates.
        self.state.events = vec![EventProgress::default(); n * self.event_rewards.len()];
        self.start = start;
        self.fixed_control = fixed_control(&scenario, agents);
        self.scenario = scenario;
        self.fingerprint = self.compute_fingerprint();
        Ok(())
    }

    /// First controller index and number of controllers of `side`.
    fn controller_span(&self, side: Side) -> (usize, usize) {
        let left = self.state.controllers.iter().filter(|c| c.side == Side::Left).count();
        match side {
            Side::Left => (0, left),
            Side::Right => (left, self.state.controllers.len() - left),
        }
    }

    fn steps_left(&self) -> u32 {
        (self.scenario.game_duration + 1).saturating_sub(self.state.steps)
    }

    fn refresh_observations(&mut self) {
        let steps_left = self.steps_left();
        for i in 0..self.state.controllers.len() {
            let c = self.state.controllers[i];
            let active = Some(self.state.controlled[i]);
            let designated = if self.fixed_control[c.side.index()] || self.controller_span(c.side).1 > 1 {
                control::designated(&self.state.game, c.side, &control::LazyPath::new())
            } else {
                active
            };
            self.state.observations[i].fill(
                &self.state.game,
                c.side,
                active,
                designated,
                c.sticky.bits(c.side == Side::Right),
                steps_left,
            );
        }
    }

    /// Observations after the last reset or step, one per controller (left controllers first).
    pub fn observations(&self) -> &[RawObservation] {
        &self.state.observations
    }

    /// Rewards of the last step, one per controller (scoring + checkpoints + event terms +
    /// script terms).
    pub fn rewards(&self) -> &[f32] {
        &self.state.rewards
    }

    /// Messages of the hooks from the last reset or step (lines scripts printed, absorbed script
    /// errors); empty without hooks.
    pub fn hook_log(&self) -> &[String] {
        self.hooks.as_ref().map_or(&[], |h| h.log())
    }

    /// Whether script hooks are attached.
    pub fn has_hooks(&self) -> bool {
        self.hooks.is_some()
    }

    /// Information about the last step.
    pub fn info(&self) -> &StepInfo {
        &self.state.info
    }

    /// Number of agent controllers (the length of actions, observations and rewards).
    pub fn num_controllers(&self) -> usize {
        self.state.controllers.len()
    }

    /// Side of each controller, in order.
    pub fn controller_sides(&self) -> impl Iterator<Item = Side> + '_ {
        self.state.controllers.iter().map(|c| c.side)
    }

    /// Player (index in his team) each controller drives, in order.
    pub fn controlled_players(&self) -> &[usize] {
        &self.state.controlled
    }

    /// Whether the episode has ended (step now fails until reset).
    pub fn is_done(&self) -> bool {
        self.state.done
    }

    /// The scenario played (with a curriculum: the current lesson's).
    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    /// The curriculum the env plays, if its scenario has one.
    pub fn curriculum(&self) -> Option<&Curriculum> {
        self.curriculum.as_deref()
    }

    /// The lesson played: its 0-based index and name; `None` without a curriculum. Lessons
    /// change at [`Env::reset`], when the lesson's criterion holds.
    pub fn lesson(&self) -> Option<(usize, &str)> {
        let c = self.curriculum.as_ref()?;
        let i = self.state.lessons.lesson;
        Some((i, c.lessons[i].name.as_str()))
    }

    /// Where the env stands in its curriculum; `None` without one.
    pub fn curriculum_progress(&self) -> Option<CurriculumProgress> {
        let c = self.curriculum.as_ref()?;
        let p = &self.state.lessons;
        let window = c.lessons[p.lesson].advance.as_ref().map_or(0, |a| p.window(a.window as usize).count());
        Some(CurriculumProgress { lesson: p.lesson, lessons: c.lessons.len(), episodes: p.episodes, window })
    }

    /// The mean of `metric` over the current lesson's window (its criterion's, or every
    /// recorded episode when it has none); `None` without a curriculum or before any episode
    /// of the lesson finished.
    pub fn lesson_metric(&self, metric: Metric) -> Option<f64> {
        let c = self.curriculum.as_ref()?;
        let p = &self.state.lessons;
        let window = c.lessons[p.lesson].advance.as_ref().map_or(usize::MAX, |a| a.window as usize);
        let results = p.window(window);
        let n = results.clone().count();
        (n > 0).then(|| {
            results
                .map(|r| match metric {
                    Metric::MeanReward => f64::from(r.reward),
                    Metric::MeanScore => f64::from(r.score_diff),
                    Metric::SuccessRate => f64::from(u8::from(r.score_diff > 0)),
                })
                .sum::<f64>()
                / n as f64
        })
    }

    /// The configuration.
    pub fn config(&self) -> &EnvConfig {
        &self.config
    }

    /// The action set agents use.
    pub fn action_set(&self) -> ActionSet {
        self.config.action_set
    }

    /// The match (read-only).
    pub fn game(&self) -> &Match {
        &self.state.game
    }

    /// The match, for tests and tools that set up situations by hand.
    pub fn game_mut(&mut self) -> &mut Match {
        &mut self.state.game
    }
}

/// Agents a side for `scenario` under `config` (`control_all_players` turns one agent into one
/// per controllable player).
///
/// # Errors
/// [`EngineError::InvalidConfig`] when more agents are asked for than a side has controllable
/// players.
fn agents_for(scenario: &Scenario, config: &EnvConfig) -> Result<[usize; 2], EngineError> {
    // With the odd-episode swap a side plays either list: it needs its agents in both.
    let controllable = scenario.controllable_every_episode();
    let swapped =
        if scenario.swap_teams_on_odd_episodes { " in every episode (the teams swap on odd episodes)" } else { "" };
    let mut agents = [config.left_agents, config.right_agents];
    for side in 0..2 {
        if scenario.control_all_players && agents[side] == 1 {
            agents[side] = controllable[side];
        }
        if agents[side] > controllable[side] {
            return Err(EngineError::InvalidConfig {
                reason: format!(
                    "{} agents asked for the {} team, which has {} controllable players{swapped}",
                    agents[side],
                    Side::from_index(side).name(),
                    controllable[side]
                ),
            });
        }
    }
    Ok(agents)
}

/// Whether each side's agents drive all its controllable players in every episode (control
/// then never moves); with the odd-episode swap, in both lists.
fn fixed_control(scenario: &Scenario, agents: [usize; 2]) -> [bool; 2] {
    let n = scenario.controllable_players();
    let fixed = |side: usize| {
        if scenario.swap_teams_on_odd_episodes {
            agents[side] == n[0] && agents[side] == n[1]
        } else {
            agents[side] == n[side]
        }
    };
    [fixed(0), fixed(1)]
}

/// Checks that every lesson of `c` gives the same agents under `config` and pays rewards the
/// env can pay, so that moving between lessons never fails; returns the agents a side.
///
/// # Errors
/// [`EngineError::InvalidConfig`] naming the first lesson that differs from the first lesson.
fn lesson_agents(c: &Curriculum, config: &EnvConfig, hooks: bool) -> Result<[usize; 2], EngineError> {
    let first = &c.lessons[0];
    let agents = agents_for(&first.scenario, config)
        .map_err(|e| EngineError::InvalidConfig { reason: format!("lesson `{}`: {e}", first.name) })?;
    for l in &c.lessons {
        let theirs = agents_for(&l.scenario, config)
            .map_err(|e| EngineError::InvalidConfig { reason: format!("lesson `{}`: {e}", l.name) })?;
        if theirs != agents {
            return Err(EngineError::InvalidConfig {
                reason: format!(
                    "lesson `{}` gives {} left and {} right controllers, lesson `{}` {} and {}; every lesson \
                     must give the same",
                    l.name, theirs[0], theirs[1], first.name, agents[0], agents[1]
                ),
            });
        }
        RewardPlan::new(&l.scenario, config, hooks)
            .map_err(|e| EngineError::InvalidConfig { reason: format!("lesson `{}`: {e}", l.name) })?;
        if let Some(bytes) = &l.scenario.start_state {
            snapshot::start_match(&l.scenario, bytes)?;
        }
    }
    Ok(agents)
}

/// What the hooks see of the env after its last reset (`actions` empty) or step.
fn hook_view<'a>(state: &'a EnvState, scenario: &Scenario, actions: &'a [Action]) -> HookView<'a> {
    HookView {
        game: &state.game,
        observations: &state.observations,
        left_controllers: state.controllers.iter().filter(|c| c.side == Side::Left).count(),
        actions,
        rewards: &state.rewards,
        steps: state.steps,
        steps_left: (scenario.game_duration + 1).saturating_sub(state.steps),
        episode: state.episode,
        seed: state.seed,
    }
}
