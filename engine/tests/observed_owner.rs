//! Who the observation shows with the ball (`ball_owned_team`, `ball_owned_player`): GRF 2.10
//! reports its last toucher while he still has possession by its test (the ball low, within a
//! metre of the point just ahead of him and moving within 6 m/s of him), so a ball knocked a
//! short way off its carrier shows as the knocker's for a moment, and a ball in flight as no one's.
//! A ball placed for a restart is no one's until it is played, a thrown-in ball its thrower's.

mod common;

use glam::{Vec2, Vec3};
use touchline_engine::{Action, GameMode, Match, PlayerEntry, Role, Scenario, Side};

/// Our centre back at the centre spot facing the right team's goal, an opponent's centre forward
/// 10 m away, both keepers.
fn game() -> Match {
    let s = Scenario {
        left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CB, 0.0, 0.0)],
        right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CF, -0.2, 0.0)],
        game_duration: 400,
        ..Scenario::default()
    };
    s.validate().unwrap();
    let mut game = Match::new(&s, 0, 7);
    game.place_player(Side::Left, 1, Vec2::ZERO);
    game
}

#[test]
fn a_ball_just_off_its_last_toucher_shows_as_his() {
    let mut game = game();
    // Knocked 0.6 m ahead of him, rolling on at 4 m/s: still his in the observation.
    game.place_ball(Vec3::new(0.6, 0.0, 0.11), Vec3::new(4.0, 0.0, 0.0), Some((Side::Left, 1)));
    assert_eq!(game.owner(), None, "nobody has it at his feet");
    assert_eq!(game.observed_owner(), Some((Side::Left, 1)));
}

#[test]
fn a_ball_out_of_reach_too_fast_or_too_high_shows_as_no_ones() {
    let mut game = game();
    let cases = [
        ("1.5 m off", Vec3::new(1.5, 0.0, 0.11), Vec3::new(1.0, 0.0, 0.0)),
        ("at 8 m/s", Vec3::new(0.6, 0.0, 0.11), Vec3::new(8.0, 0.0, 0.0)),
        ("in the air", Vec3::new(0.6, 0.0, 0.9), Vec3::new(2.0, 0.0, 0.0)),
    ];
    for (what, position, velocity) in cases {
        game.place_ball(position, velocity, Some((Side::Left, 1)));
        assert_eq!(game.observed_owner(), None, "{what}");
    }
    // Near his feet, but last touched by nobody (a ball as placed): no one's either.
    game.place_ball(Vec3::new(0.6, 0.0, 0.11), Vec3::ZERO, None);
    assert_eq!(game.observed_owner(), None, "untouched");
}

#[test]
fn the_owner_at_his_feet_is_the_observed_owner() {
    let mut game = game();
    game.place_ball(Vec3::new(0.4, 0.0, 0.11), Vec3::ZERO, Some((Side::Left, 1)));
    for _ in 0..30 {
        game.tick();
        if game.owner().is_some() {
            break;
        }
    }
    assert_eq!(game.owner(), Some((Side::Left, 1)), "he steps onto the ball");
    assert_eq!(game.observed_owner(), game.owner());
}

/// GRF 2.10.2, 11_vs_11_stochastic with the built-in AI on both sides (engine seeds 3 and 5, every
/// step of every restart): `ball_owned_team` is −1 throughout goal kicks and free kicks, and the
/// thrower's team at a throw-in. touchline's taker holds the ball at his feet at every restart;
/// the observation shows it as GRF does.
#[test]
fn a_ball_placed_for_a_restart_is_no_ones_until_played_and_a_throw_in_is_the_throwers() {
    let mut env = common::builtin_env("11_vs_11_stochastic", 3);
    let mut seen = [0u32; 7];
    for _ in 0..3000 {
        let out = env.step(&[Action::BuiltinAi]).unwrap();
        let obs = &env.observations()[0];
        let mode = obs.game_mode;
        seen[mode as usize] += 1;
        match mode {
            GameMode::GoalKick | GameMode::Corner | GameMode::FreeKick | GameMode::Penalty => {
                assert_eq!((obs.ball_owned_team, obs.ball_owned_player), (-1, -1), "{mode:?}");
            }
            GameMode::ThrowIn => assert!(obs.ball_owned_team >= 0, "the thrower holds the ball"),
            GameMode::Normal | GameMode::KickOff => {}
        }
        if out.terminated || out.truncated {
            break;
        }
    }
    let count = |m: GameMode| seen[m as usize];
    assert!(count(GameMode::GoalKick) > 0 && count(GameMode::ThrowIn) > 0, "restarts seen: {seen:?}");
}
