//! Law 16: over the goal line, outside the goal, last touched by an attacker: a goal kick taken by
//! the defending keeper from 0.92 of the half length.

use glam::Vec3;
use touchline_engine::{GameMode, Role, Side};

use super::{ball_out, ball_xy};

#[test]
fn left_attack_wide_of_the_right_goal_is_a_right_goal_kick() {
    let env = ball_out(Vec3::new(54.9, 12.0, 0.11), Vec3::new(8.0, 0.0, 0.0), Side::Left);
    assert_eq!(env.info().game_mode, GameMode::GoalKick);
    let (x, y) = ball_xy(&env);
    assert!((x - 50.6).abs() < 1e-3 && y.abs() < 1e-3, "ball at ({x}, {y})");
    let (side, i) = env.game().owner().unwrap();
    assert_eq!(side, Side::Right);
    assert_eq!(env.game().team(side)[i].role, Role::GK);
}

#[test]
fn right_attack_over_the_left_goal_line_is_a_left_goal_kick() {
    let env = ball_out(Vec3::new(-54.9, -20.0, 0.11), Vec3::new(-8.0, 0.0, 0.0), Side::Right);
    assert_eq!(env.info().game_mode, GameMode::GoalKick);
    let (x, _) = ball_xy(&env);
    assert!((x + 50.6).abs() < 1e-3);
    assert_eq!(env.game().owner().map(|o| o.0), Some(Side::Left));
}

#[test]
fn over_the_bar_is_not_a_goal() {
    let env = ball_out(Vec3::new(54.9, 0.0, 3.0), Vec3::new(8.0, 0.0, 0.0), Side::Left);
    assert_eq!(env.info().game_mode, GameMode::GoalKick);
    assert_eq!(env.info().score, [0, 0]);
}
