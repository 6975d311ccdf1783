//! Player behaviours: what a player does instead of following the built-in AI (Scenic4RL's
//! behaviours). A behaviour is a list of [`Stage`]s: the player does the first stage's
//! [`Behaviour`] until its `until` condition holds (or, without one, until the behaviour finishes
//! by itself), then moves on to the next. After the last stage has finished the player keeps doing
//! it (a finished `move_to` stands on its point, a finished `pass_to` holds position).
//!
//! Points are in the frame of the player's team (own goal at x = -1, normalised units), as the
//! player's own position is written; players are absolute (see [`super::condition`]).

use serde::{Deserialize, Serialize};

use super::condition::{Condition, Target};

/// How a `pass_to` is played (grf.md §5.4's three passes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PassKind {
    /// Ground pass.
    Short,
    /// Driven, low lofted pass.
    Long,
    /// High lofted pass.
    High,
}

/// One native behaviour (or a script's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Behaviour {
    /// Stand still, facing the ball. Never finishes.
    Idle,
    /// Keep the place the player started the stage at, turning to face the ball; step back to it
    /// when pushed off. Never finishes.
    HoldPosition,
    /// Run after a target (the ball or a player), staying close. Never finishes.
    Follow(Target),
    /// Run to a point (team frame); finishes on arrival.
    MoveTo {
        /// Destination `[x, y]`, normalised units, team frame.
        point: [f32; 2],
    },
    /// Get the ball if needed and dribble it to a point (team frame); with `shoot`, shoot at the
    /// opponents' goal on arrival. Finishes on arrival (or after the shot).
    DribbleTo {
        /// Destination `[x, y]`, normalised units, team frame.
        point: [f32; 2],
        /// Shoot on arrival (`dribble_to(point) then shoot`).
        shoot: bool,
    },
    /// With the ball, pass it to a team-mate (index in the player's team list); without it, get
    /// it first. Finishes when the pass is played.
    PassTo {
        /// Team-mate index.
        player: usize,
        /// Kind of pass.
        kind: PassKind,
    },
    /// Stay goal-side of a player (an opponent), close enough to challenge. Never finishes.
    Mark(Target),
    /// Close down the ball carrier (or the loose ball) and tackle. Never finishes.
    Press,
    /// Hand the player to the built-in AI, optionally at its own difficulty θ ∈ [0, 1] instead of
    /// the team's. Never finishes.
    Builtin {
        /// Difficulty for this player; `None` keeps the team's.
        difficulty: Option<f32>,
    },
    /// A rhai script returning an action every env step (run through the env's hooks; path as
    /// written, relative to the scenario file). Never finishes.
    Script {
        /// Script path.
        path: String,
    },
}

/// One stage of a player's behaviour: `do BEHAVIOUR [until CONDITION]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Stage {
    /// What the player does.
    pub behaviour: Behaviour,
    /// When to move on to the next stage; `None`: when the behaviour finishes by itself (never,
    /// for behaviours that do not finish). `Condition::Done` inside it means the same.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub until: Option<Condition>,
}
