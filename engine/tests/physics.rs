//! Ball against the goal frame (rapier3d colliders): a post and the crossbar send the ball back, the
//! net stops it, and a ball in the net is a goal followed by a kickoff.

mod common;

use glam::{Vec2, Vec3};
use touchline_engine::geometry::pitch::{GOAL_DEPTH, GOAL_HALF_WIDTH, GOAL_LINE_OUT_X, HALF_LENGTH, POST_RADIUS};
use touchline_engine::rules::Stoppage;
use touchline_engine::{Env, GameMode, Match, Side};

fn empty_match() -> Env {
    Env::new(common::empty_pitch(400), 0).unwrap()
}

/// Ticks until the ball's x velocity turns negative; returns the ball then, or None.
fn rebound(game: &mut Match, ticks: usize) -> Option<Vec3> {
    for _ in 0..ticks {
        game.tick();
        if game.ball().velocity.x < 0.0 {
            return Some(game.ball().position);
        }
    }
    None
}

#[test]
fn the_ball_rebounds_off_a_post() {
    let mut env = empty_match();
    let game = env.game_mut();
    let post_y = GOAL_HALF_WIDTH + POST_RADIUS;
    game.place_ball(Vec3::new(48.0, post_y, 1.0), Vec3::new(25.0, 0.0, 1.5), Some((Side::Left, 1)));
    let at = rebound(game, 60).expect("the ball came back off the post");
    assert!((HALF_LENGTH - 0.5..HALF_LENGTH).contains(&at.x), "rebound at {at}");
    assert_eq!(game.score(), [0, 0]);
    // It keeps going back into the field.
    for _ in 0..20 {
        game.tick();
    }
    assert!(game.ball().position.x < HALF_LENGTH - 1.0);
    assert_eq!(game.score(), [0, 0]);
}

#[test]
fn the_ball_rebounds_off_the_crossbar() {
    let mut env = empty_match();
    let game = env.game_mut();
    // Centre level with the bar's axis, so it meets the bar head on.
    game.place_ball(Vec3::new(52.0, 0.5, 2.56), Vec3::new(18.0, 0.0, 1.2), None);
    let at = rebound(game, 40).expect("the ball came back off the bar");
    assert!(at.x < HALF_LENGTH && at.z > 2.0, "rebound at {at}");
    assert_eq!(game.score(), [0, 0]);
}

#[test]
fn a_ball_in_the_net_is_a_goal_stays_in_the_net_and_a_kickoff_follows() {
    let mut env = empty_match();
    let game = env.game_mut();
    game.place_ball(Vec3::new(45.0, 1.0, 0.5), Vec3::new(26.0, 0.5, 2.0), Some((Side::Left, 1)));
    let mut ticks = 0;
    while game.in_play() {
        game.tick();
        ticks += 1;
        assert!(ticks < 100, "no goal");
    }
    assert_eq!(game.score(), [1, 0]);
    assert_eq!(game.last_stoppage(), Some(Stoppage::Goal { scorer: Side::Left }));
    assert_eq!(game.mode(), GameMode::KickOff);
    // During the dead time the net holds the ball.
    let mut max_x: f32 = 0.0;
    let mut dead = 0;
    while !game.in_play() {
        game.tick();
        dead += 1;
        assert!(dead < 1000, "no kickoff");
        if !game.in_play() {
            let b = game.ball().position;
            max_x = max_x.max(b.x);
            assert!(b.y.abs() < GOAL_HALF_WIDTH + 0.2, "through the side netting: {b}");
        }
    }
    assert!(max_x > GOAL_LINE_OUT_X && max_x < HALF_LENGTH + GOAL_DEPTH, "through the back of the net: {max_x}");
    // Kickoff: ball on the centre spot, play on, every player in his own half, the conceding
    // (right) team's only player nearest to the ball.
    assert_eq!(game.mode(), GameMode::Normal);
    assert_eq!(game.ball().xy(), Vec2::ZERO);
    for p in game.players() {
        assert!(p.position.x * p.side.attack_sign() <= 1e-4, "{p:?} is in the opponents' half");
    }
}
