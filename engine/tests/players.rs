//! Issue 7, players: per-slot attributes (the same for both teams, docs/grf-compatibility.md#player-stats)
//! and fatigue that grows with running, slows players down, is observed as `tired_factor` and is restored at
//! half-time (docs/grf-compatibility.md#half-time).

mod common;

use touchline_engine::{Action, ActionSet, Env, EnvConfig, Side};

#[test]
fn both_teams_get_the_same_slot_profiles() {
    let env = common::env("11_vs_11_stochastic", 0);
    let game = env.game();
    for i in 0..11 {
        assert_eq!(game.team(Side::Left)[i].attributes, game.team(Side::Right)[i].attributes, "slot {i}");
    }
    let speeds: Vec<f32> = game.team(Side::Left).iter().map(|p| p.fresh_speed).collect();
    assert!(speeds.iter().any(|&s| (s - speeds[0]).abs() > 0.01), "slots differ: {speeds:?}");
}

#[test]
fn running_tires_players_and_half_time_restores_them() {
    let mut scenario = common::scenario("11_vs_11_stochastic");
    scenario.second_half = 1500;
    let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario, config, 4).unwrap();
    for _ in 0..1500 {
        env.step(&[Action::BuiltinAi]).unwrap();
    }
    let o = &env.observations()[0];
    let outfield: Vec<f32> = o.left_team_tired_factor[1..].to_vec();
    let mean = outfield.iter().sum::<f32>() / outfield.len() as f32;
    assert!(outfield.iter().all(|&t| t > 0.02 && t < 0.99), "{outfield:?}");
    assert!(o.left_team_tired_factor[0] < mean, "the keeper runs least: {:?}", o.left_team_tired_factor);
    for p in env.game().players().iter().filter(|p| !p.is_keeper()) {
        assert!(p.max_speed < p.fresh_speed, "a tired player is slower: {p:?}");
    }
    // GRF counts the half-time step one later (docs/grf-compatibility.md#episode-length, #half-time).
    env.step(&[Action::BuiltinAi]).unwrap();
    env.step(&[Action::BuiltinAi]).unwrap();
    let o = &env.observations()[0];
    assert!(o.left_team_tired_factor.iter().chain(&o.right_team_tired_factor).all(|&t| t < 0.01), "{o:?}");
}
