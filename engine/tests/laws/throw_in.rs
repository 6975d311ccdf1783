//! Law 15: over a touchline, a throw-in to the other team where the ball left the field.

use glam::Vec3;
use touchline_engine::{GameMode, Side};

use super::{ball_out, ball_xy};

#[test]
fn over_the_bottom_touchline_last_touched_by_left_is_a_right_throw_in() {
    let env = ball_out(Vec3::new(10.0, 35.8, 0.11), Vec3::new(1.0, 6.0, 0.0), Side::Left);
    assert_eq!(env.info().game_mode, GameMode::ThrowIn);
    let (x, y) = ball_xy(&env);
    assert!((x - 10.5).abs() < 1.0 && (y - 36.0).abs() < 1e-3, "ball at ({x}, {y})");
    let (side, _) = env.game().owner().expect("the taker holds the ball");
    assert_eq!(side, Side::Right);
}

#[test]
fn over_the_top_touchline_last_touched_by_right_is_a_left_throw_in() {
    let env = ball_out(Vec3::new(-30.0, -35.8, 0.11), Vec3::new(0.0, -6.0, 0.0), Side::Right);
    assert_eq!(env.info().game_mode, GameMode::ThrowIn);
    let (_, y) = ball_xy(&env);
    assert!((y + 36.0).abs() < 1e-3);
    assert_eq!(env.game().owner().map(|o| o.0), Some(Side::Left));
    // The left team's agent sees a throw-in it can take: the taker is the controlled player.
    let obs = &env.observations()[0];
    assert_eq!(obs.ball_owned_team, 0);
    assert_eq!(obs.active, obs.ball_owned_player);
}

#[test]
fn the_spot_is_clamped_near_the_corners() {
    let env = ball_out(Vec3::new(54.9, 35.9, 0.11), Vec3::new(0.5, 6.0, 0.0), Side::Left);
    assert_eq!(env.info().game_mode, GameMode::ThrowIn);
    let (x, _) = ball_xy(&env);
    assert!((x - 54.4).abs() < 1e-3, "x = {x}");
}
