//! # touchline-engine
//!
//! The touchline match engine: a football (soccer) simulation for reinforcement learning that does
//! the job of Google Research Football (GRF) with GRF's conventions, far faster.
//!
//! - [`Scenario`] is the only input: plain serde data (the scenario language compiles to it).
//! - [`Match`] is the world (ball, two teams, referee, built-in AI); [`Match::tick`] advances it
//!   10 ms.
//! - [`Env`] is the RL episode: one [`Env::step`] is 10 ticks (0.1 s of play, GRF's time base),
//!   with sticky actions, Scoring and Checkpoint rewards, GRF's termination rules and the raw
//!   observation ([`RawObservation`]) per controlled player.
//!
//! Units: SI inside the engine (metres, seconds, m/s); GRF's normalised coordinates at the
//! boundary (observations, scenarios), converted only in [`geometry::coords`].
//!
//! ```
//! use touchline_engine::{Env, Scenario, PlayerEntry, Role, Action};
//! let scenario = Scenario {
//!     left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CB, 0.75, 0.0)],
//!     right_team: vec![PlayerEntry::new(Role::GK, 1.0, 0.0)],
//!     ball_position: [0.77, 0.0],
//!     game_duration: 400,
//!     end_episode_on_score: true,
//!     ..Scenario::default()
//! };
//! let mut env = Env::new(scenario, 0).unwrap();
//! let outcome = env.step(&[Action::Right]).unwrap();
//! assert!(!outcome.truncated);
//! assert_eq!(env.info().steps_left, 400);
//! ```

#![deny(missing_docs)]

pub mod ai;
pub mod behaviour;
pub mod env;
mod error;
pub mod game;
pub mod geometry;
pub mod obs;
pub mod physics;
pub mod player;
pub mod reward;
mod rng;
pub mod rules;
pub mod scenario;
pub mod stats;

pub use env::{CurriculumProgress, Env, EnvConfig, HookOutcome, HookView, Hooks, Snapshot, StepInfo, StepOutcome};
pub use error::EngineError;
pub use game::{Action, ActionSet, GameMode, Match};
pub use geometry::Side;
pub use obs::RawObservation;
pub use player::Role;
pub use scenario::{MAX_PLAYERS_PER_TEAM, PlayerEntry, SCENARIO_FORMAT_VERSION, Scenario};
pub use stats::{Event, MatchStats, TeamStats};

/// The names most programs need.
pub mod prelude {
    pub use crate::{Action, ActionSet, Env, EnvConfig, GameMode, PlayerEntry, RawObservation, Role, Scenario, Side};
}
