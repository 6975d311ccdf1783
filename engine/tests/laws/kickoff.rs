//! Law 8: after a goal, the conceding team kicks off from the centre spot with everyone in his own
//! half; the kickoff formation goes to the conceding team.

use glam::{Vec2, Vec3};
use touchline_engine::{Action, GameMode, Side};

use super::common;

#[test]
fn the_conceding_team_kicks_off() {
    for (scorer, x) in [(Side::Left, 50.0f32), (Side::Right, -50.0)] {
        let mut env = touchline_engine::Env::new(common::scenario("11_vs_11_stochastic"), 3).unwrap();
        // Clear the keepers out of the way and roll the ball into the goal.
        for side in Side::BOTH {
            env.game_mut().place_player(side, 0, Vec2::new(0.0, side.attack_sign() * 30.0));
        }
        env.game_mut().place_ball(Vec3::new(x, 0.0, 0.11), Vec3::new(x.signum() * 20.0, 0.0, 0.0), Some((scorer, 5)));
        for _ in 0..10 {
            env.step(&[Action::Idle]).unwrap();
            if env.info().score != [0, 0] {
                break;
            }
        }
        let mut expected = [0, 0];
        expected[scorer.index()] = 1;
        assert_eq!(env.info().score, expected);
        assert_eq!(env.info().game_mode, GameMode::Normal, "the kickoff counts as taken at once");
        let game = env.game();
        assert!(game.ball().xy().length() < 1.0, "ball at {}", game.ball().xy());
        let nearest = game.players().iter().min_by(|a, b| a.position.length().total_cmp(&b.position.length())).unwrap();
        assert_eq!(nearest.side, scorer.opponent(), "the conceding team stands at the ball");
        for p in game.players() {
            assert!(p.position.x * p.side.attack_sign() <= 1.0, "{p:?} is in the opponents' half");
        }
    }
}

/// GRF's `tests/kickoff_for_goal_loosing_team_test` (docs/grf-compatibility.md#scenario-semantics,
/// #scenario-players): both keepers stand in the right goal, so the right team, which starts at the ball,
/// walks it into the empty left goal; then the left team kicks off in the kickoff formation (its winger on
/// the centre spot).
#[test]
fn grf_kickoff_for_goal_loosing_team_test() {
    use touchline_engine::{Env, PlayerEntry, Role, Scenario};
    let scenario = Scenario {
        name: "kickoff_for_goal_loosing_team_test".into(),
        game_duration: 400,
        deterministic: true,
        left_team: vec![PlayerEntry::new(Role::GK, 1.0, 0.0), PlayerEntry::new(Role::RM, 0.8, 0.0)],
        right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::RM, 0.0, 0.02)],
        ..Scenario::default()
    };
    let mut env = Env::new(scenario, 0).unwrap();
    for _ in 0..400 {
        env.step(&[Action::Idle]).unwrap();
        if env.info().score != [0, 0] {
            break;
        }
    }
    assert_eq!(env.info().score, [0, 1], "the right team scores into the empty goal");
    let game = env.game();
    let winger = game.team(Side::Left)[1].position;
    assert!(winger.length() < 2.5, "the conceding team's winger is at the ball: {winger}");
    let nearest = game.players().iter().min_by(|a, b| a.position.length().total_cmp(&b.position.length())).unwrap();
    assert_eq!(nearest.side, Side::Left);
}
