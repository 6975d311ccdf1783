//! Law 17, the corner kick.
//!
//! - **Law**: when the whole ball passes over the goal line, not as a goal, having last touched a
//!   defender, the attacking team restarts with a corner kick.
//! - **When it triggers**: |x| > 55.17 m outside the goal, last touch by the defending team.
//! - **Restart**: ball in the corner arc on the side where it went out, (±55, ±36) m
//!   (docs/grf-compatibility.md#pitch-geometry); the nearest outfield attacker takes it.
//! - **GRF behaviour**: the same spot; game mode 4 until the taker plays the ball.
//! - **Differences**: none known.

use glam::{Vec2, Vec3};

use super::Restart;
use crate::game::GameMode;
use crate::geometry::Side;
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};

/// The corner for `attacking` after the ball went out at `at` (m).
pub fn restart(attacking: Side, at: Vec3) -> Restart {
    let spot = Vec2::new(attacking.attack_sign() * HALF_LENGTH, HALF_WIDTH.copysign(at.y));
    Restart { mode: GameMode::Corner, side: attacking, spot }
}
