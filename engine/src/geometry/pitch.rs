//! Pitch dimensions in metres. Sources: docs/grf-compatibility.md#coordinates, #pitch-geometry (GRF's engine
//! values), which follow the Laws of the Game (Law 1) with GRF's 110 m × 72 m pitch.
//!
//! Engine frame: origin at the centre spot, x towards the right team's goal, y across the pitch
//! (positive towards the bottom of the screen, as GRF's observation y), z up.

/// Half the pitch length, goal line to centre (m).
pub const HALF_LENGTH: f32 = 55.0;
/// Half the pitch width, touchline to centre (m).
pub const HALF_WIDTH: f32 = 36.0;
/// Half width of the painted lines (m); the ball is out when wholly over the line.
pub const LINE_HALF_WIDTH: f32 = 0.06;
/// Ball radius (m); a ball at rest on the grass has z = this.
pub const BALL_RADIUS: f32 = 0.11;
/// |x| beyond which the ball is wholly over a goal line (55 + 0.06 + 0.11 m, docs/grf-compatibility.md#pitch-geometry).
pub const GOAL_LINE_OUT_X: f32 = HALF_LENGTH + LINE_HALF_WIDTH + BALL_RADIUS;
/// |y| beyond which the ball is wholly over a touchline (36.17 m).
pub const TOUCH_LINE_OUT_Y: f32 = HALF_WIDTH + LINE_HALF_WIDTH + BALL_RADIUS;
/// Half the distance between the posts (m, GRF: 3.7).
pub const GOAL_HALF_WIDTH: f32 = 3.7;
/// Height of the crossbar's underside (m, GRF: 2.5).
pub const GOAL_HEIGHT: f32 = 2.5;
/// Depth of the net behind the goal line (m).
pub const GOAL_DEPTH: f32 = 2.55;
/// Radius of posts and crossbar (m; Law 1 allows up to 12 cm width).
pub const POST_RADIUS: f32 = 0.06;
/// Depth of the penalty area from the goal line (m, Law 1: 16.5).
pub const PENALTY_AREA_DEPTH: f32 = 16.5;
/// Half width of the penalty area (m, GRF: 20.15).
pub const PENALTY_AREA_HALF_WIDTH: f32 = 20.15;
/// Distance of the penalty mark from the goal line (m, Law 1: 11).
pub const PENALTY_MARK_DISTANCE: f32 = 11.0;
/// Radius of the centre circle and the distance opponents keep at restarts (m, Law 1: 9.15).
pub const CENTRE_CIRCLE_RADIUS: f32 = 9.15;
/// Players may run off the pitch up to the rim (GRF: 60 m × 40 m half sizes).
pub const RIM_HALF_LENGTH: f32 = 60.0;
/// Half width including the rim (m).
pub const RIM_HALF_WIDTH: f32 = 40.0;
/// Goal-kick spot: 0.92 of the half length from the centre (50.6 m, docs/grf-compatibility.md#pitch-geometry).
pub const GOAL_KICK_X: f32 = 0.92 * HALF_LENGTH;
/// Where throw-ins are taken along the touchline, at most this far from the centre in x (54.4 m).
pub const THROW_IN_MAX_X: f32 = 54.4;
/// Standard gravity (m/s²).
pub const GRAVITY: f32 = 9.81;

/// Whether a point (m) lies in the penalty area defended by the team whose goal is at
/// `goal_sign * HALF_LENGTH` (`goal_sign` = -1 for the left team's goal).
pub fn in_penalty_area(x: f32, y: f32, goal_sign: f32) -> bool {
    let from_line = HALF_LENGTH - x * goal_sign;
    (0.0..=PENALTY_AREA_DEPTH).contains(&from_line) && y.abs() <= PENALTY_AREA_HALF_WIDTH
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn penalty_areas() {
        assert!(in_penalty_area(-50.0, 5.0, -1.0));
        assert!(!in_penalty_area(-50.0, 5.0, 1.0));
        assert!(in_penalty_area(40.0, -20.0, 1.0));
        assert!(!in_penalty_area(37.0, 0.0, 1.0));
    }
}
