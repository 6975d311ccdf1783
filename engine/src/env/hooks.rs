//! Hooks: code outside the engine that an [`Env`](super::Env) calls at every reset and after every
//! step, for the scenario's script reward terms and script end conditions. The engine knows
//! nothing of the scripting language: `touchline_dsl` implements [`Hooks`] with rhai scripts
//! (`reward script "x.rhai"`, `end when script "y.rhai"`) and attaches them with
//! [`Env::with_hooks`](super::Env::with_hooks).
//!
//! Behaviour scripts (`Behaviour::Script`) are asked first: before the step's ticks, once per
//! scripted player ([`Hooks::behaviour_action`]).
//!
//! Order within a step: the match plays its ticks, controls and observations are refreshed, the
//! built-in rewards (scoring, checkpoints) are computed, then [`Hooks::step`] runs and its rewards
//! are added; the episode terminates when a built-in condition or a hook says so.

use std::fmt;

use crate::error::EngineError;
use crate::game::{Action, Match};
use crate::obs::RawObservation;
use crate::scenario::Scenario;

/// What hooks see after a reset or a step: borrowed views of the env's state, built without
/// allocation.
#[derive(Clone, Copy, Debug)]
pub struct HookView<'a> {
    /// The match (global frame, SI units).
    pub game: &'a Match,
    /// One raw observation per controller (left controllers first), each in its controller's
    /// own frame: GRF-normalised coordinates, the viewer's team attacking +x.
    pub observations: &'a [RawObservation],
    /// How many of the controllers (the first ones) play for the left team; the rest play right.
    pub left_controllers: usize,
    /// The actions just taken, one per controller, in each controller's own frame, after GRF's
    /// anti-stalling rule; empty at reset.
    pub actions: &'a [Action],
    /// The built-in rewards of the step (weighted scoring + checkpoints), one per controller;
    /// zeros at reset.
    pub rewards: &'a [f32],
    /// Steps taken this episode (0 at reset).
    pub steps: u32,
    /// Steps left (`game_duration + 1` at reset).
    pub steps_left: u32,
    /// 0-based episode index since the last seeding.
    pub episode: u64,
    /// The env's seed, for hooks that offer seeded randomness.
    pub seed: u64,
}

/// What the hooks decided about a step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HookOutcome {
    /// A hook ends the episode (it terminates, as a built-in end condition).
    pub end: bool,
    /// Hook failures absorbed this step (a policy that pays zero and warns instead of failing);
    /// counted in [`StepInfo::script_errors`](super::StepInfo::script_errors).
    pub errors: u32,
}

/// Reward terms and end conditions run by code outside the engine.
///
/// Implementations must be deterministic given the views they are shown (and their own saved
/// state), so that seeding and snapshots keep their guarantees.
pub trait Hooks: Send + Sync + fmt::Debug {
    /// Starts an episode: forget per-episode state (the scripts' `memory`) and look at the first
    /// observation.
    ///
    /// # Errors
    /// A hook that fails; [`Env::reset`](super::Env::reset) returns it, the episode is over
    /// (stepping it returns the same error) and the next reset starts the following episode.
    fn reset(&mut self, view: &HookView<'_>) -> Result<(), EngineError>;

    /// Runs after a step: adds each controller's hook reward into `rewards` (one slot per
    /// controller, left controllers first, zeroed before the call) and says whether the episode
    /// ends.
    ///
    /// # Errors
    /// A hook that fails (a script runtime error or exhausted limit, under the error policy); the
    /// step then fails and the episode is over.
    fn step(&mut self, view: &HookView<'_>, rewards: &mut [f32]) -> Result<HookOutcome, EngineError>;

    /// The action of `side`'s player `player` (index in his team), whose behaviour stage is
    /// `script "path"`, for the step about to be played; asked once per scripted player before
    /// the step's ticks, in player order (left team first). The action is in the player's own
    /// frame (his team attacking +x, as an agent's) and is applied as an agent's, with a sticky
    /// gamepad of his own. `view` shows the state before the step (`steps` taken so far,
    /// `actions` the agents' actions for this step).
    ///
    /// # Errors
    /// A hook that fails; the step then fails and the episode is over. Hooks without behaviour
    /// scripts keep this default, which refuses.
    fn behaviour_action(
        &mut self,
        _view: &HookView<'_>,
        side: crate::geometry::Side,
        player: usize,
        path: &str,
    ) -> Result<Action, EngineError> {
        Err(EngineError::InvalidScenario {
            reason: format!("these hooks run no behaviour scripts (\"{path}\" for {} player {player})", side.name()),
        })
    }

    /// Messages of the last reset or step: lines the scripts printed and absorbed errors.
    fn log(&self) -> &[String] {
        &[]
    }

    /// The hooks' per-episode state as bytes, for [`Env::snapshot`](super::Env::snapshot).
    fn save(&self) -> Vec<u8>;

    /// Puts back state saved by [`Hooks::save`].
    ///
    /// # Errors
    /// [`EngineError::InvalidSnapshot`] for bytes these hooks cannot read.
    fn load(&mut self, bytes: &[u8]) -> Result<(), EngineError>;

    /// Asked at each reset, before the episode starts: a new scenario to play from now on (a
    /// watched source that was edited), with the hooks already switched to its scripts. `None`
    /// keeps the current one.
    fn poll_scenario(&mut self) -> Option<Scenario> {
        None
    }

    /// Called when the env refused the scenario from [`Hooks::poll_scenario`] (it keeps playing
    /// the previous one), so that a watcher can report it.
    fn scenario_refused(&mut self, _error: &EngineError) {}

    /// A copy with the same scripts and state (what cloning an env does).
    fn clone_box(&self) -> Box<dyn Hooks>;
}

impl Clone for Box<dyn Hooks> {
    fn clone(&self) -> Box<dyn Hooks> {
        self.clone_box()
    }
}
