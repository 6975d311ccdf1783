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

/// GRF's `tests/corner_test` (docs/grf-compatibility.md#scenario-players, #grf-tests test_corner), first
/// episode: a left winger runs the ball over his own goal line; the right team's corner at (−1.011, 0.43)
/// with its winger at the flag and both keepers on their lines.
#[test]
fn grf_corner_test() {
    use touchline_engine::{Action, Env, EnvConfig, PlayerEntry, Role, Scenario};
    let lazy = |role, x, y| PlayerEntry { lazy: true, ..PlayerEntry::new(role, x, y) };
    let scenario = Scenario {
        name: "corner_test".into(),
        game_duration: 30,
        ball_position: [-0.9, 0.3],
        left_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, -0.85, 0.3), lazy(Role::RM, 0.0, 0.0)],
        right_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, -0.85, 0.3)],
        ..Scenario::default()
    };
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario, config, 0).unwrap();
    let mut saw_corner = false;
    loop {
        let out = env.step(&[Action::Left, Action::Left]).unwrap();
        saw_corner |= env.info().game_mode == GameMode::Corner;
        if out.terminated || out.truncated {
            break;
        }
    }
    assert!(saw_corner);
    assert_eq!(env.game().stats().teams[1].corners, 1);
    let o = &env.observations()[0];
    assert!((o.ball[0] + 0.95).abs() < 0.1 && (o.ball[1] - 0.4).abs() < 0.1, "ball {:?}", o.ball);
    assert!((o.right_team[0][0] - 1.0).abs() < 0.1, "right keeper {:?}", o.right_team[0]);
    assert!((o.right_team[1][0] + 0.95).abs() < 0.1, "right taker {:?}", o.right_team[1]);
    assert!((o.left_team[0][0] + 0.95).abs() < 0.1, "left keeper {:?}", o.left_team[0]);
    assert!((o.left_team[1][0] + 0.9).abs() < 0.2, "left winger {:?}", o.left_team[1]);
}
