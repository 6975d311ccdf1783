//! Law 17: over the goal line, outside the goal, last touched by a defender: a corner kick for the
//! attackers from the corner on the side where the ball went out.

use glam::Vec3;
use touchline_engine::{GameMode, Side};

use super::{ball_out, ball_xy};

#[test]
fn right_defender_puts_it_behind_a_left_corner() {
    let env = ball_out(Vec3::new(54.9, 10.0, 0.11), Vec3::new(8.0, 1.0, 0.0), Side::Right);
    assert_eq!(env.info().game_mode, GameMode::Corner);
    let (x, y) = ball_xy(&env);
    assert!((x - 55.0).abs() < 1e-3 && (y - 36.0).abs() < 1e-3, "ball at ({x}, {y})");
    assert_eq!(env.game().owner().map(|o| o.0), Some(Side::Left));
}

#[test]
fn left_defender_puts_it_behind_a_right_corner_on_the_top_side() {
    let env = ball_out(Vec3::new(-54.9, -10.0, 0.11), Vec3::new(-8.0, -1.0, 0.0), Side::Left);
    assert_eq!(env.info().game_mode, GameMode::Corner);
    let (x, y) = ball_xy(&env);
    assert!((x + 55.0).abs() < 1e-3 && (y + 36.0).abs() < 1e-3, "ball at ({x}, {y})");
    assert_eq!(env.game().owner().map(|o| o.0), Some(Side::Right));
}
