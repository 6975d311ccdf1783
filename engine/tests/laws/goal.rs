//! Law 10, a goal, modelled on GRF's `tests/goal_test` (docs/grf-compatibility.md#scenario-players,
//! #grf-tests test_goal): two lone keepers, the one on the ball runs it into the empty goal; the goal counts
//! for his team and play restarts from the centre spot.

use touchline_engine::{Action, Env, EnvConfig, Event, PlayerEntry, Role, Scenario, Side};

#[test]
fn grf_goal_test() {
    for (episode_ball, scorer) in [(0.5f32, Side::Left), (-0.5, Side::Right)] {
        let scenario = Scenario {
            name: "goal_test".into(),
            game_duration: 65,
            deterministic: true,
            ball_position: [episode_ball, 0.0],
            left_team: vec![PlayerEntry::new(Role::GK, 0.5, 0.0)],
            right_team: vec![PlayerEntry::new(Role::GK, 0.5, 0.0)],
            ..Scenario::default()
        };
        let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
        let mut env = Env::with_config(scenario, config, 0).unwrap();
        loop {
            let out = env.step(&[Action::Right, Action::Right]).unwrap();
            if env.info().score != [0, 0] {
                assert!(env.game().events().iter().any(|e| matches!(e, Event::Goal { side, .. } if *side == scorer)));
                break;
            }
            assert!(!(out.terminated || out.truncated), "{scorer:?}: no goal in 65 steps");
        }
        let mut expected = [0, 0];
        expected[scorer.index()] = 1;
        assert_eq!(env.info().score, expected);
        assert!(env.observations()[0].ball[0].abs() < 0.1, "back on the centre spot");
        assert_eq!(env.game().stats().teams[scorer.index()].goals, 1);
    }
}
