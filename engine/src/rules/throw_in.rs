//! Law 15, the throw-in.
//!
//! - **Law**: when the whole ball passes over a touchline, play restarts with a throw-in for the
//!   opponents of the player who last touched it, from where it left the field.
//! - **When it triggers**: |y| > 36.17 m (touchline 36 m + 0.06 m + ball radius).
//! - **Restart**: ball on the touchline at x clamped to ±54.4 m (docs/grf-compatibility.md#pitch-geometry); the nearest
//!   outfield player of the throwing team takes it and must pass.
//! - **GRF behaviour**: the same spot and team; game mode 5 until the taker plays the ball.
//! - **Differences**: the throw is modelled as a pass from the ground.

use glam::{Vec2, Vec3};

use super::Restart;
use crate::game::GameMode;
use crate::geometry::Side;
use crate::geometry::pitch::{HALF_WIDTH, THROW_IN_MAX_X};

/// The throw-in for `side` after the ball went out at `at` (m).
pub fn restart(side: Side, at: Vec3) -> Restart {
    let spot = Vec2::new(at.x.clamp(-THROW_IN_MAX_X, THROW_IN_MAX_X), HALF_WIDTH.copysign(at.y));
    Restart { mode: GameMode::ThrowIn, side, spot }
}
