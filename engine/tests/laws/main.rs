//! One module per law, driven through `Env` as a user would see them, modelled on GRF's test
//! scenarios (docs/grf-compatibility.md#scenario-players, #grf-tests) where GRF has one.

#[path = "../common/mod.rs"]
mod common;

mod cards;
mod corner_kick;
mod fouls;
mod goal;
mod goal_kick;
mod half_time;
mod kickoff;
mod offside;
mod penalty_kick;
mod throw_in;

use glam::Vec3;
use touchline_engine::{Env, Side};

/// An 11-v-11 match at its start, with the ball about to cross a line at `at` moving with
/// `velocity`, last touched by `last_touch`; returns the env after one step (dead time included).
pub fn ball_out(at: Vec3, velocity: Vec3, last_touch: Side) -> Env {
    let mut env = Env::new(common::scenario("11_vs_11_stochastic"), 1).unwrap();
    env.game_mut().place_ball(at, velocity, Some((last_touch, 5)));
    env.step(&[touchline_engine::Action::Idle]).unwrap();
    env
}

/// The observation's ball (x, y) in metres for controller 0 (left team: global frame).
pub fn ball_xy(env: &Env) -> (f32, f32) {
    let b = env.observations()[0].ball;
    (b[0] * 54.4, b[1] * 83.6)
}
