//! Replays: one episode (or part of one) as a compact file that re-simulates bit for bit.
//!
//! A [`Replay`] holds what is needed to play the episode again, the scenario (whole, so that a
//! replay does not depend on the stdlib of the version that reads it), the env configuration, the
//! seed and episode index (or a [`Snapshot`] of the state where the recording started) and the
//! actions of every step, plus what is needed to check and show it without the engine: after
//! every step, a [`Frame`] (positions to the centimetre, score, mode, ball owner, controlled
//! players, and a hash of the exact state). A scenario with rhai scripts (reward terms, end
//! conditions, behaviours) carries their text ([`ScriptSource`]), so that the replay re-simulates
//! without the script files; and a recorder may attach named per-step numbers ([`StepValues`]:
//! a policy's value estimate, action probabilities) that viewers show beside each step.
//!
//! [`Replay::simulate`] plays the actions again in a fresh env and checks each step's state hash
//! and frame against the stored ones: a replay that does not reproduce is an error
//! ([`ReplayError::Diverged`]), never a silent difference. A scripted scenario needs the scripts'
//! hooks ([`Replay::simulate_with`]; `touchline_dsl::script::Scripts::from_sources` compiles them
//! from [`Replay::scripts`]).
//!
//! The file form ([`Replay::to_bytes`], [`Replay::from_bytes`]):
//!
//! | bytes | content |
//! |---|---|
//! | 0..8 | magic `TLREPLAY` |
//! | 8..10 | format version, u16 little-endian ([`FORMAT_VERSION`]) |
//! | 10..18 | length of the compressed payload, u64 LE |
//! | 18..26 | FNV-1a 64 checksum of the compressed payload, u64 LE |
//! | 26.. | payload: zlib(postcard([`Replay`])) |
//!
//! Reading checks, in order: magic, version, length (truncation), checksum (corruption), then
//! decompresses (at most 256 MiB), decodes and runs [`Replay::check`]. Every failure is a
//! [`ReplayError`] saying which check failed; no input makes the reader panic.

mod file;
mod recorder;

use serde::{Deserialize, Serialize};
use touchline_engine::{Action, Env, EnvConfig, GameMode, Hooks, Match, Scenario, Side, Snapshot};

pub use file::{FORMAT_VERSION, MAGIC, ReplayError};
pub use recorder::Recorder;

use crate::scene::{Scene, ScenePlayer};

/// Where the recording started.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Start {
    /// At the reset that starts 0-based episode `episode` of `seed`.
    Reset {
        /// The env's seed.
        seed: u64,
        /// 0-based episode index since seeding.
        episode: u64,
    },
    /// In the middle of an episode: the bytes of a [`Snapshot`] of the env there.
    Snapshot(Vec<u8>),
}

/// A player's fixed attributes, as drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct RosterEntry {
    /// Team.
    pub side: Side,
    /// Shirt number (1 + index in the team).
    pub number: u8,
    /// Goalkeepers wear their own colour.
    pub goalkeeper: bool,
}

/// The text of one script the scenario names, as it was when the episode was recorded.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ScriptSource {
    /// The path as the scenario writes it (`reward script "PATH"`).
    pub path: String,
    /// The script's rhai source.
    pub text: String,
}

/// Numbers a recorder attached to the steps under one name (for instance a policy's value
/// estimate), shown by viewers beside each step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StepValues {
    /// The name shown (unique within a replay).
    pub name: String,
    /// One value per step (`values[k]` belongs to step `k`, the step that leads to frame `k + 1`);
    /// NaN where the recorder gave none.
    pub values: Vec<f32>,
}

/// The state after one step, as stored: enough to draw it and to check a re-simulation.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Frame {
    /// Ball centre `[x, y, z]` (cm, engine frame).
    pub ball: [i16; 3],
    /// Players' positions `[x, y]` (cm), in roster order.
    pub players: Vec<[i16; 2]>,
    /// Bit `i` set when roster player `i` is still on the pitch.
    pub on_pitch: u32,
    /// Roster index of the ball owner, or `None`.
    pub owner: Option<u8>,
    /// Roster index of the player each controller drives.
    pub controlled: Vec<u8>,
    /// Goals `[left, right]`.
    pub score: [u16; 2],
    /// Game mode (GRF numbering 0..6).
    pub mode: u8,
    /// A 32-bit hash of the exact bits of the match state after the step (every player's
    /// position, velocity and facing; the ball's position, velocity and spin; score, mode, owner;
    /// see [`state_hash`]): re-simulation must give the same value.
    pub hash: u32,
}

/// A recorded episode; see the module documentation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Replay {
    /// The scenario, whole.
    pub scenario: Scenario,
    /// The env configuration (agents per side, action set, rewards).
    pub config: EnvConfig,
    /// Where the recording started.
    pub start: Start,
    /// Env steps played before the first frame (0 for a recording from a reset).
    pub first_step: u32,
    /// Every player of the match.
    pub roster: Vec<RosterEntry>,
    /// Actions of every step, step-major: `controllers` actions per step.
    pub actions: Vec<Action>,
    /// Number of controllers (actions per step).
    pub controllers: usize,
    /// `frames[0]` is the state at the start, `frames[k]` the state after step `k`.
    pub frames: Vec<Frame>,
    /// The text of every script the scenario runs (empty for a scenario without scripts).
    pub scripts: Vec<ScriptSource>,
    /// Named per-step numbers given by the recorder (empty when none were given).
    pub values: Vec<StepValues>,
}

/// Centimetres, saturating at ±327 m (far outside the pitch's 60 m rim).
fn centimetres(m: f32) -> i16 {
    (m * 100.0).round().clamp(f32::from(i16::MIN), f32::from(i16::MAX)) as i16
}

impl Frame {
    /// The frame of `env`'s current state (reuses `self`'s buffers).
    pub fn capture(&mut self, env: &Env) {
        let game = env.game();
        let b = game.ball().position;
        self.ball = [centimetres(b.x), centimetres(b.y), centimetres(b.z)];
        self.players.clear();
        self.players.extend(game.players().iter().map(|p| [centimetres(p.position.x), centimetres(p.position.y)]));
        self.on_pitch = game.players().iter().enumerate().filter(|(_, p)| p.active).fold(0, |m, (i, _)| m | 1 << i);
        self.owner = game.owner().map(|(side, i)| game.global_index(side, i) as u8);
        self.controlled.clear();
        self.controlled
            .extend(env.controller_sides().zip(env.controlled_players()).map(|(s, &i)| game.global_index(s, i) as u8));
        let score = game.score();
        self.score = [score[0].min(u32::from(u16::MAX)) as u16, score[1].min(u32::from(u16::MAX)) as u16];
        self.mode = game.mode() as u8;
        self.hash = state_hash(game);
    }
}

/// A hash of the exact bits of `game`'s dynamic state, for checking re-simulations: a
/// multiply-xorshift mix over 32-bit words (one multiplication per word, so that recording stays
/// cheap), folded to 32 bits. Equal states give equal hashes on every platform.
pub fn state_hash(game: &Match) -> u32 {
    let mut h: u64 = 0x243F_6A88_85A3_08D3;
    let mut feed = |w: u32| {
        h = (h ^ u64::from(w)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        h ^= h >> 29;
    };
    for p in game.players() {
        for v in [p.position.x, p.position.y, p.velocity.x, p.velocity.y, p.facing.x, p.facing.y] {
            feed(v.to_bits());
        }
    }
    let b = game.ball();
    for v in b.position.to_array().into_iter().chain(b.velocity.to_array()).chain(b.spin.to_array()) {
        feed(v.to_bits());
    }
    let score = game.score();
    feed(score[0]);
    feed(score[1]);
    feed(game.mode() as u32);
    feed(game.owner().map_or(u32::MAX, |(side, i)| game.global_index(side, i) as u32));
    (h ^ (h >> 32)) as u32
}

impl Replay {
    /// Env steps recorded.
    pub fn steps(&self) -> usize {
        self.frames.len().saturating_sub(1)
    }

    /// The actions of step `k` (0-based within the replay), one per controller.
    pub fn step_actions(&self, k: usize) -> &[Action] {
        &self.actions[k * self.controllers..(k + 1) * self.controllers]
    }

    /// Writes frame `k` into `scene` (reusing its buffer). `k` beyond the last frame shows the
    /// last one.
    pub fn scene(&self, k: usize, scene: &mut Scene) {
        let Some(frame) = self.frames.get(k.min(self.steps())) else { return };
        let m = |cm: i16| f32::from(cm) / 100.0;
        scene.players.clear();
        scene.players.extend(self.roster.iter().zip(&frame.players).enumerate().map(|(i, (r, p))| ScenePlayer {
            side: r.side,
            number: r.number,
            goalkeeper: r.goalkeeper,
            position: [m(p[0]), m(p[1])],
            controlled: frame.controlled.contains(&(i as u8)),
            has_ball: frame.owner == Some(i as u8),
            on_pitch: i >= 32 || frame.on_pitch & (1 << i) != 0,
        }));
        scene.ball = [m(frame.ball[0]), m(frame.ball[1]), m(frame.ball[2])];
        scene.score = [u32::from(frame.score[0]), u32::from(frame.score[1])];
        scene.steps = self.first_step + k as u32;
        scene.mode = GameMode::ALL.get(usize::from(frame.mode)).copied().unwrap_or_default();
    }

    /// Builds the env where the recording started (a scenario without scripts).
    ///
    /// # Errors
    /// [`ReplayError::Engine`] when the scenario or configuration is refused (a scripted scenario
    /// needs [`Replay::start_env_with`]);
    /// [`ReplayError::Start`] when the start snapshot does not load or belongs elsewhere.
    pub fn start_env(&self) -> Result<Env, ReplayError> {
        self.start_env_with(None)
    }

    /// Builds the env where the recording started, with `hooks` running the scenario's scripts
    /// (fresh hooks, for instance compiled from [`Replay::scripts`]; `None` for a scenario
    /// without scripts).
    ///
    /// # Errors
    /// As [`Replay::start_env`].
    pub fn start_env_with(&self, hooks: Option<Box<dyn Hooks>>) -> Result<Env, ReplayError> {
        let build = |seed: u64, hooks: Option<Box<dyn Hooks>>| match hooks {
            Some(h) => Env::with_hooks(self.scenario.clone(), self.config, seed, h),
            None => Env::with_config(self.scenario.clone(), self.config, seed),
        };
        match &self.start {
            Start::Reset { seed, episode } => {
                let mut env = build(*seed, hooks)?;
                if *episode != 0 {
                    env.reset_to_episode(*seed, *episode)?;
                }
                Ok(env)
            }
            Start::Snapshot(bytes) => {
                let snapshot = Snapshot::from_bytes(bytes).map_err(ReplayError::Start)?;
                let mut env = build(0, hooks)?;
                env.restore(&snapshot).map_err(ReplayError::Start)?;
                Ok(env)
            }
        }
    }

    /// Plays the replay again: builds the start env, checks it against frame 0, then for each
    /// step applies the stored actions and checks the new state against the stored frame (exact
    /// state hash and every stored field). `visit(env, k)` sees the env at frame `k` = 0, 1, …,
    /// after the check. Returns the final env.
    ///
    /// # Errors
    /// As [`Replay::start_env`]; [`ReplayError::Engine`] when a step is refused (the episode
    /// ended early); [`ReplayError::Diverged`] at the first frame that differs.
    pub fn simulate(&self, visit: impl FnMut(&Env, usize)) -> Result<Env, ReplayError> {
        self.simulate_with(None, visit)
    }

    /// [`Replay::simulate`] with `hooks` running the scenario's scripts (see
    /// [`Replay::start_env_with`]).
    ///
    /// # Errors
    /// As [`Replay::simulate`].
    pub fn simulate_with(
        &self,
        hooks: Option<Box<dyn Hooks>>,
        mut visit: impl FnMut(&Env, usize),
    ) -> Result<Env, ReplayError> {
        let mut env = self.start_env_with(hooks)?;
        let mut frame = Frame::default();
        for k in 0..self.frames.len() {
            if k > 0 {
                env.step(self.step_actions(k - 1))?;
            }
            frame.capture(&env);
            let stored = &self.frames[k];
            if frame != *stored {
                return Err(ReplayError::Diverged { frame: k, stored: stored.hash, replayed: frame.hash });
            }
            visit(&env, k);
        }
        Ok(env)
    }

    /// The part of the replay from frame `first` to frame `last` (inclusive), for instance the
    /// moments round a goal (GRF's `score` dumps keep the 100 steps before a goal and 1 after,
    /// docs/grf-compatibility.md#replays). The clip starts from a snapshot taken by re-simulating up to `first`, so it
    /// re-simulates on its own.
    ///
    /// # Errors
    /// [`ReplayError::Inconsistent`] for an empty or out-of-range span; the errors of
    /// [`Replay::simulate`] while reaching `first`.
    pub fn clip(&self, first: usize, last: usize) -> Result<Replay, ReplayError> {
        self.clip_with(None, first, last)
    }

    /// [`Replay::clip`] with `hooks` running the scenario's scripts (see
    /// [`Replay::start_env_with`]).
    ///
    /// # Errors
    /// As [`Replay::clip`].
    pub fn clip_with(&self, hooks: Option<Box<dyn Hooks>>, first: usize, last: usize) -> Result<Replay, ReplayError> {
        if first > last || last > self.steps() {
            return Err(ReplayError::Inconsistent {
                reason: format!("frames {first}..={last} are not inside 0..={}", self.steps()),
            });
        }
        let mut env = self.start_env_with(hooks)?;
        for k in 0..first {
            env.step(self.step_actions(k))?;
        }
        let mut check = Frame::default();
        check.capture(&env);
        if check != self.frames[first] {
            return Err(ReplayError::Diverged { frame: first, stored: self.frames[first].hash, replayed: check.hash });
        }
        let start = if first == 0 { self.start.clone() } else { Start::Snapshot(env.snapshot().to_bytes()) };
        Ok(Replay {
            scenario: self.scenario.clone(),
            config: self.config,
            start,
            first_step: self.first_step + first as u32,
            roster: self.roster.clone(),
            actions: self.actions[first * self.controllers..last * self.controllers].to_vec(),
            controllers: self.controllers,
            frames: self.frames[first..=last].to_vec(),
            scripts: self.scripts.clone(),
            values: self
                .values
                .iter()
                .map(|v| StepValues { name: v.name.clone(), values: v.values[first..last].to_vec() })
                .collect(),
        })
    }

    /// Frames (after frame 0) at which a goal was scored: the score differs from the frame
    /// before.
    pub fn goal_frames(&self) -> Vec<usize> {
        (1..self.frames.len()).filter(|&k| self.frames[k].score != self.frames[k - 1].score).collect()
    }

    /// Checks that the parts agree with one another: action and frame counts, roster and frame
    /// sizes. [`Replay::from_bytes`] runs it, so a decoded replay can be indexed freely.
    ///
    /// # Errors
    /// [`ReplayError::Inconsistent`] naming the first disagreement.
    pub fn check(&self) -> Result<(), ReplayError> {
        let bad = |reason: String| Err(ReplayError::Inconsistent { reason });
        if self.frames.is_empty() {
            return bad("it has no frames".into());
        }
        if self.controllers == 0 || self.controllers > 22 {
            return bad(format!("{} controllers (1 to 22 expected)", self.controllers));
        }
        if self.actions.len() != self.steps() * self.controllers {
            return bad(format!(
                "{} actions for {} steps of {} controllers",
                self.actions.len(),
                self.steps(),
                self.controllers
            ));
        }
        if self.roster.len() > 2 * touchline_engine::MAX_PLAYERS_PER_TEAM {
            return bad(format!("{} players", self.roster.len()));
        }
        for (i, v) in self.values.iter().enumerate() {
            if v.values.len() != self.steps() {
                return bad(format!(
                    "the values {:?} hold {} numbers for {} steps",
                    v.name,
                    v.values.len(),
                    self.steps()
                ));
            }
            if self.values[..i].iter().any(|w| w.name == v.name) {
                return bad(format!("two series of values are named {:?}", v.name));
            }
        }
        for (k, f) in self.frames.iter().enumerate() {
            if f.players.len() != self.roster.len() {
                return bad(format!("frame {k} has {} players, the roster {}", f.players.len(), self.roster.len()));
            }
            if f.controlled.len() != self.controllers
                || f.controlled.iter().any(|&i| usize::from(i) >= self.roster.len())
            {
                return bad(format!("frame {k} names controlled players that do not exist"));
            }
            if f.owner.is_some_and(|i| usize::from(i) >= self.roster.len())
                || usize::from(f.mode) >= GameMode::ALL.len()
            {
                return bad(format!("frame {k} has an owner or game mode out of range"));
            }
        }
        Ok(())
    }
}
