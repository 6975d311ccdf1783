//! Player behaviours: what a player does instead of following the built-in AI (Scenic4RL's
//! behaviours). A behaviour is a list of [`Stage`]s: the player does the first stage's
//! [`Behaviour`] until its `until` condition holds (or, without one, until the behaviour finishes
//! by itself), then moves on to the next. After the last stage has finished the player keeps doing
//! it (a finished `move_to` stands on its point, a finished `pass_to` holds position).
//!
//! Points are in the frame of the player's team (own goal at x = -1, normalised units), as the
//! player's own position is written; players are absolute (see [`super::condition`]).

use serde::{Deserialize, Serialize};

use super::condition::{CheckContext, Condition, Target};

/// How a `pass_to` is played (docs/grf-compatibility.md#action-effects's three passes).
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

impl Stage {
    /// Checks a stage of `side`'s (0 left, 1 right) player `index`, whose team has `team`
    /// players: targets and points as [`Condition::check`], `pass_to` a team-mate other than
    /// himself, `mark` another player, θ in [0, 1], a script path.
    pub(crate) fn check(&self, side: usize, index: usize, team: usize, ctx: CheckContext) -> Result<(), String> {
        let himself = |t: &Target| match *t {
            Target::Me => true,
            Target::Left(i) => side == 0 && i == index,
            Target::Right(i) => side == 1 && i == index,
            _ => false,
        };
        match &self.behaviour {
            Behaviour::Follow(t) if himself(t) => return Err("a player cannot follow himself".into()),
            Behaviour::Follow(t) => t.check(ctx)?,
            Behaviour::Mark(t) if himself(t) => return Err("a player cannot mark himself".into()),
            Behaviour::Mark(t @ (Target::Left(_) | Target::Right(_))) => t.check(ctx)?,
            Behaviour::Mark(_) => return Err("mark needs a player".into()),
            Behaviour::MoveTo { point } | Behaviour::DribbleTo { point, .. } => Target::Point(*point).check(ctx)?,
            Behaviour::PassTo { player, .. } if *player == index => {
                return Err("a player cannot pass to himself".into());
            }
            Behaviour::PassTo { player, .. } if *player >= team => {
                return Err(format!("pass_to names team-mate {player}, who does not exist"));
            }
            Behaviour::Builtin { difficulty: Some(theta) } if !(0.0..=1.0).contains(theta) => {
                return Err(format!("builtin difficulty {theta} is outside [0, 1]"));
            }
            Behaviour::Script { path } if path.is_empty() => return Err("a behaviour script needs a path".into()),
            _ => {}
        }
        match &self.until {
            Some(c) => c.check(ctx),
            None => Ok(()),
        }
    }
}
