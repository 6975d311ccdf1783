//! Law 10, determining the outcome of a match: a goal.
//!
//! - **Law**: a goal is scored when the whole ball passes over the goal line, between the posts
//!   and under the crossbar.
//! - **When it triggers**: the ball's centre crosses the plane |x| = 55.17 m (goal line 55 m +
//!   line half width 0.06 m + ball radius 0.11 m) during a tick, with |y| ≤ 3.7 m and z ≤ 2.5 m at
//!   the crossing point.
//! - **Restart**: kickoff by the team that conceded (see [`super::kickoff`]).
//! - **GRF behaviour**: the same test on the segment between two ticks
//!   (docs/grf-compatibility.md#pitch-geometry); entering through the side netting is rejected.
//! - **Differences**: none known. Own goals count for the team whose goal was not breached, as in
//!   GRF.

use glam::Vec3;

use crate::geometry::Side;
use crate::geometry::pitch::{GOAL_HALF_WIDTH, GOAL_HEIGHT, GOAL_LINE_OUT_X};

/// The team credited with a goal if the ball moving from `before` to `after` (m) went in.
pub fn scored(before: Vec3, after: Vec3) -> Option<Side> {
    for sign in [1.0f32, -1.0] {
        let (b, a) = (before.x * sign, after.x * sign);
        if b <= GOAL_LINE_OUT_X && a > GOAL_LINE_OUT_X {
            let t = (GOAL_LINE_OUT_X - b) / (a - b);
            let at = before + (after - before) * t;
            if at.y.abs() <= GOAL_HALF_WIDTH && at.z <= GOAL_HEIGHT {
                // A ball into the right goal (+x) scores for the left team.
                return Some(if sign > 0.0 { Side::Left } else { Side::Right });
            }
        }
    }
    None
}

/// Whether `ball`, just struck, is heading into a goal: its predicted path (2 s, no players)
/// crosses a goal line between the posts and under the bar. Used to count shots on target.
pub fn on_target(ball: &crate::physics::Ball) -> bool {
    let path = crate::ai::BallPath::predict(ball);
    let mut before = ball.position;
    for &after in path.at() {
        if scored(before, after).is_some() {
            return true;
        }
        before = after;
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn over_the_bar_or_wide_is_no_goal() {
        assert_eq!(scored(Vec3::new(55.0, 0.0, 2.6), Vec3::new(55.5, 0.0, 2.6)), None);
        assert_eq!(scored(Vec3::new(55.0, 3.9, 1.0), Vec3::new(55.5, 3.9, 1.0)), None);
        assert_eq!(scored(Vec3::new(55.0, -3.6, 2.4), Vec3::new(55.5, -3.6, 2.4)), Some(Side::Left));
        // Already behind the line: nothing new.
        assert_eq!(scored(Vec3::new(56.0, 0.0, 0.1), Vec3::new(56.5, 0.0, 0.1)), None);
    }
}
