//! What a player is told to do in one tick. Agents (through sticky actions) and the built-in AI
//! both produce a [`PlayerInput`]; a player driven by an agent and one driven by the AI differ only
//! in who filled it in.

use glam::Vec2;

/// The kinds of kick a player can make (docs/grf-compatibility.md#action-effects).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum KickKind {
    /// Ground pass to a team-mate.
    ShortPass,
    /// Long pass: GRF's long pass, struck as a ground pass is but to a point led a fifth of its
    /// length forward of the receiver; the touch's cap makes a long one bounce.
    LongPass,
    /// High lofted pass.
    HighPass,
    /// Shot at the opponents' goal.
    Shot,
}

/// Where a kick goes.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum KickTarget {
    /// A point on the pitch (m, global frame); for shots a point on the goal line. The AI aims so.
    Point(Vec2),
    /// A direction (unit, global frame): passes go to the best team-mate that way and shots at
    /// the goal, chosen when the kick is made. Agents' buttons aim so (docs/grf-compatibility.md#action-effects).
    Direction(Vec2),
}

/// A kick request: a kind, an aim and a power in [0, 1] (from the button gauge for agents).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Kick {
    /// Pass or shot.
    pub kind: KickKind,
    /// Where the ball should go.
    pub target: KickTarget,
    /// Shot aim height at the goal line (m); ignored for passes.
    pub height: f32,
    /// Power in [0, 1].
    pub power: f32,
}

/// One tick's instruction for one player.
#[derive(Clone, Copy, Debug, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct PlayerInput {
    /// Desired velocity (m/s, global frame). The player accelerates towards it within his limits.
    pub velocity: Vec2,
    /// Direction to face when standing (unit or zero: keep facing).
    pub look: Vec2,
    /// Dribble button: slower, closer control.
    pub dribble: bool,
    /// A kick to make when (or as soon as) the player has the ball.
    pub kick: Option<Kick>,
    /// Start a sliding tackle in the movement direction (a goalkeeper in his area dives instead).
    pub slide: bool,
    /// A kick to strike on the first touch of the loose ball he is going for, without first
    /// taking it under control: GRF's AI queues its on-the-ball command while still running to the
    /// ball, so the touch is the kick and the player never shows as its owner. Held while set.
    #[serde(default)]
    pub first_time: Option<Kick>,
}
