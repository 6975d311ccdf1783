//! Law 16, the goal kick.
//!
//! - **Law**: when the whole ball passes over the goal line, not as a goal, having last touched an
//!   attacker, the defending team restarts with a goal kick.
//! - **When it triggers**: |x| > 55.17 m outside the goal, last touch by the attacking team (or by
//!   nobody).
//! - **Restart**: ball at x = ±0.92·55 = ±50.6 m, y = 0 (docs/grf-compatibility.md#pitch-geometry); the
//!   goalkeeper takes it. Everyone else goes at once to his place in GRF's goal-kick shape
//!   (`set_piece_places`): the opponents back in a band round halfway, outside the penalty area.
//! - **GRF behaviour**: the same spot; game mode 2 until the keeper plays the ball.
//! - **Differences**: none known.

use glam::Vec2;

use super::Restart;
use crate::game::GameMode;
use crate::geometry::Side;
use crate::geometry::pitch::GOAL_KICK_X;

/// The goal kick for the team defending the goal the ball went past.
pub fn restart(defending: Side) -> Restart {
    Restart { mode: GameMode::GoalKick, side: defending, spot: Vec2::new(-defending.attack_sign() * GOAL_KICK_X, 0.0) }
}
