//! Law 13, free kicks.
//!
//! - **Law**: a direct or indirect free kick is awarded to the opponents of a player who commits
//!   an offence (a foul, Law 12; offside, Law 11), from where the offence occurred. Opponents
//!   stay 9.15 m away until the ball is in play.
//! - **When it triggers**: a whistled foul outside the offender's penalty area (see
//!   [`super::fouls`]) or an offside (see [`super::offside`]).
//! - **Restart**: ball at the spot clamped into ±0.95·55 m × ±0.95·36 m (docs/grf-compatibility.md#pitch-geometry); the
//!   nearest outfield player of the awarded team takes it; keepers go back to their lines and
//!   opponents at least 9.15 m from the ball; game mode 3 until the taker plays the ball.
//! - **GRF behaviour**: the same spot clamping and game mode.
//! - **Differences**: no wall; direct and indirect free kicks are not told apart (an offside free
//!   kick may be scored directly).

use glam::Vec2;

use super::Restart;
use crate::game::GameMode;
use crate::geometry::Side;
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};

/// The free kick for `side` for an offence at `at` (m).
pub fn restart(side: Side, at: Vec2) -> Restart {
    let spot = Vec2::new(
        at.x.clamp(-0.95 * HALF_LENGTH, 0.95 * HALF_LENGTH),
        at.y.clamp(-0.95 * HALF_WIDTH, 0.95 * HALF_WIDTH),
    );
    Restart { mode: GameMode::FreeKick, side, spot }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spot_is_clamped_into_the_field() {
        let r = restart(Side::Left, Vec2::new(58.0, -37.0));
        assert_eq!(r.mode, GameMode::FreeKick);
        assert_eq!(r.spot, Vec2::new(0.95 * 55.0, -0.95 * 36.0));
    }
}
