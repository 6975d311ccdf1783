//! Law 11, offside, modelled on GRF's `tests/offside_test` (docs/grf-compatibility.md#scenario-players,
//! #grf-tests test_offside): one team has a keeper near the centre spot and a winger far up the pitch, the
//! other two lazy players on the halfway line. The keeper's long pass to the winger is offside: an indirect
//! free kick for the defenders where the winger touched the ball. Not when the law is off, not when the winger
//! is behind the second-last defender, not when the defenders have a single active player.

use touchline_engine::rules::Stoppage;
use touchline_engine::{Action, Env, EnvConfig, GameMode, PlayerEntry, Role, Scenario, Side};

fn lazy(role: Role, x: f32, y: f32) -> PlayerEntry {
    PlayerEntry { lazy: true, ..PlayerEntry::new(role, x, y) }
}

/// GRF's offside_test teams: set A (keeper and winger) attacks, set B (two lazy players on the
/// halfway line) defends. `attacking` is the side set A plays on.
fn offside_scenario(attacking: Side) -> Scenario {
    let a = vec![PlayerEntry::new(Role::GK, -0.05, 0.0), PlayerEntry::new(Role::RM, 0.8, 0.0)];
    let b = vec![lazy(Role::GK, 0.0, 0.4), lazy(Role::RM, 0.0, -0.4)];
    let (left_team, right_team) = if attacking == Side::Left { (a, b) } else { (b, a) };
    Scenario {
        name: "offside_test".into(),
        game_duration: 50,
        deterministic: true,
        left_team,
        right_team,
        ..Scenario::default()
    }
}

/// Both set-A players are agent-controlled: the keeper walks onto the ball and plays a long pass
/// forward, the winger waits. Returns the env once play stopped or the episode ended.
fn long_pass(scenario: Scenario, attacking: Side) -> Env {
    let config = match attacking {
        Side::Left => EnvConfig { left_agents: 2, ..EnvConfig::default() },
        Side::Right => EnvConfig { left_agents: 0, right_agents: 2, ..EnvConfig::default() },
    };
    let mut env = Env::with_config(scenario, config, 0).unwrap();
    let mut passed = false;
    for _ in 0..50 {
        let has_ball = env.game().owner() == Some((attacking, 0));
        // In the controllers' own frame "right" is towards the opponents' goal.
        let keeper = if has_ball && !passed {
            passed = true;
            Action::LongPass
        } else if passed {
            Action::Idle
        } else {
            Action::Right
        };
        let out = env.step(&[keeper, Action::Idle]).unwrap();
        if env.game().last_stoppage().is_some() || out.terminated || out.truncated {
            break;
        }
    }
    assert!(passed, "the keeper never had the ball");
    env
}

#[test]
fn a_pass_to_a_player_beyond_the_defenders_is_offside() {
    for attacking in Side::BOTH {
        let env = long_pass(offside_scenario(attacking), attacking);
        let game = env.game();
        let Some(Stoppage::Offside { restart, offender }) = game.last_stoppage() else {
            panic!("{attacking:?}: no offside, stoppage {:?}", game.last_stoppage());
        };
        assert_eq!(offender, (attacking, 1));
        assert_eq!(restart.side, attacking.opponent());
        assert_eq!(restart.mode, GameMode::FreeKick);
        // The free kick is where the winger touched the ball, deep in the defenders' half.
        let winger = game.team(attacking)[1].position;
        assert!(restart.spot.x * attacking.attack_sign() > 30.0, "{attacking:?}: spot {}", restart.spot);
        assert!(restart.spot.distance(winger) < 12.0, "{attacking:?}: spot {} winger {winger}", restart.spot);
        assert_eq!(env.info().game_mode, GameMode::FreeKick);
        assert_eq!(game.owner().map(|o| o.0), Some(attacking.opponent()), "a defender takes the free kick");
        assert_eq!(game.stats().teams[attacking.index()].offsides, 1);
        // GRF's test_offside: the ball about 0.6 into the defenders' half in observations.
        let ball_x = env.observations()[0].ball[0];
        assert!((ball_x.abs() - 0.6).abs() < 0.4, "{attacking:?}: ball x {ball_x}");
    }
}

#[test]
fn no_offside_when_the_law_is_off() {
    let scenario = Scenario { offsides: false, ..offside_scenario(Side::Left) };
    let env = long_pass(scenario, Side::Left);
    assert!(!matches!(env.game().last_stoppage(), Some(Stoppage::Offside { .. })));
    assert_eq!(env.game().stats().teams[0].offsides, 0);
}

#[test]
fn no_offside_behind_the_second_last_defender() {
    let mut scenario = offside_scenario(Side::Left);
    // Both defenders (the keeper in goal) stand deeper than the winger.
    scenario.right_team = vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::CB, -0.9, 0.05)];
    let env = long_pass(scenario, Side::Left);
    assert!(!matches!(env.game().last_stoppage(), Some(Stoppage::Offside { .. })), "{:?}", env.game().last_stoppage());
}

#[test]
fn no_offside_against_a_single_defender() {
    let mut scenario = offside_scenario(Side::Left);
    scenario.right_team.truncate(1);
    let env = long_pass(scenario, Side::Left);
    assert!(!matches!(env.game().last_stoppage(), Some(Stoppage::Offside { .. })));
}
