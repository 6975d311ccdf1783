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

/// GRF's `tests/keeper_test` (docs/grf-compatibility.md#scenario-players, #grf-tests test_keeper_ball), first
/// episode: a left winger runs the ball over the right goal line; the right keeper holds it for the goal kick at
/// x ≈ 1.0.
#[test]
fn grf_keeper_test() {
    use touchline_engine::{Action, Env, EnvConfig, PlayerEntry, Scenario};
    let lazy = |role, x, y| PlayerEntry { lazy: true, ..PlayerEntry::new(role, x, y) };
    let scenario = Scenario {
        name: "keeper_test".into(),
        game_duration: 30,
        ball_position: [0.9, 0.3],
        left_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, 0.85, 0.3), lazy(Role::RM, 0.0, 0.0)],
        right_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, 0.85, 0.3)],
        ..Scenario::default()
    };
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario, config, 0).unwrap();
    let mut saw_goal_kick = false;
    loop {
        let out = env.step(&[Action::Right, Action::Right]).unwrap();
        saw_goal_kick |= env.info().game_mode == GameMode::GoalKick;
        if saw_goal_kick || out.terminated || out.truncated {
            break;
        }
    }
    assert!(saw_goal_kick);
    let o = &env.observations()[0];
    assert!((o.ball[0] - 1.0).abs() < 0.1 && o.ball[1].abs() < 0.1, "ball {:?}", o.ball);
    assert_eq!(env.game().owner(), Some((Side::Right, 0)), "the keeper holds the ball");
    assert!((o.right_team[0][0] - 1.0).abs() < 0.1, "right keeper {:?}", o.right_team[0]);
    assert!((o.left_team[0][0] + 0.9).abs() < 0.1, "left keeper {:?}", o.left_team[0]);
}
