//! Issue 7, must show (small version; `cargo run --release -p touchline-engine --example strength`
//! plays 50 matches per pairing): the built-in AI's strength follows θ. Full 11-v-11 matches with
//! the built-in AI on all 22 players and fixed seeds, so the figures are fixed too.

mod common;

use touchline_engine::{Action, ActionSet, Env, EnvConfig, MatchStats, Side};

/// Matches per pairing: with 10 the fixed sample of equal sides scored 0.9 a match against 1.44 over
/// 50 (the example), so a bound on the mean failed on the luck of the draw after unrelated changes.
const MATCHES: u64 = 30;

fn matches(left: f32, right: f32) -> Vec<MatchStats> {
    (0..MATCHES)
        .map(|seed| {
            let mut scenario = common::scenario("11_vs_11_stochastic");
            scenario.left_team_difficulty = left;
            scenario.right_team_difficulty = right;
            // The two formations differ: alternate them between the sides, as GRF's odd episodes do.
            if seed % 2 == 1 {
                std::mem::swap(&mut scenario.left_team, &mut scenario.right_team);
            }
            let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
            let mut env = Env::with_config(scenario, config, 100 + seed).unwrap();
            loop {
                let out = env.step(&[Action::BuiltinAi]).unwrap();
                if out.truncated || out.terminated {
                    return *env.game().stats();
                }
            }
        })
        .collect()
}

fn mean(stats: &[MatchStats], f: impl Fn(&MatchStats) -> f64) -> f64 {
    stats.iter().map(f).sum::<f64>() / stats.len() as f64
}

fn goal_difference(s: &MatchStats) -> f64 {
    f64::from(s.teams[0].goals) - f64::from(s.teams[1].goals)
}

#[test]
fn the_stronger_side_wins_by_more_against_weaker_opponents() {
    let easy = mean(&matches(1.0, 0.05), goal_difference);
    let hard = mean(&matches(1.0, 0.95), goal_difference);
    eprintln!("θ=1 vs 0.05: {easy:+.2}; θ=1 vs 0.95: {hard:+.2}");
    assert!(easy > 1.5, "θ=1 should beat θ=0.05 clearly: {easy:+.2}");
    assert!(easy > hard + 1.0, "vs 0.05 {easy:+.2}, vs 0.95 {hard:+.2}");
}

#[test]
fn equal_sides_are_level_and_play_football() {
    let stats = matches(0.6, 0.6);
    let gd = mean(&stats, goal_difference);
    let possession = mean(&stats, |s| s.possession_percent(Side::Left));
    let goals = mean(&stats, |s| f64::from(s.teams[0].goals + s.teams[1].goals));
    let completed = mean(&stats, |s| f64::from(s.teams[0].passes_completed + s.teams[1].passes_completed));
    let out_of_play =
        mean(&stats, |s| f64::from(s.teams.iter().map(|t| t.throw_ins + t.corners + t.goal_kicks).sum::<u32>()));
    eprintln!("GD {gd:+.2}, possession {possession:.1} %, goals {goals:.2}, completed passes {completed:.1}");
    assert!(gd.abs() < 1.0, "mean goal difference {gd:+.2}");
    assert!((40.0..60.0).contains(&possession), "possession {possession:.1} %");
    assert!((1.0..6.0).contains(&goals), "goals per match {goals:.2}");
    // GRF's built-in AI completes about 50 passes a match (python/bench/grf_reference.json,
    // the texture cases): a side that passes at all, not a number tuned to ours.
    assert!(completed > 40.0, "completed passes per match {completed:.1}");
    assert!(out_of_play > 1.0, "restarts from the ball going out per match {out_of_play:.2}");
    // The AI slides and fouls (issue 15): GRF gives about 4 free kicks a match, touchline's
    // AI commits 1.0-1.5 fouls a match in this sample (fewer since the chaser meets a loose ball
    // just in time; docs/grf-compatibility.md, "how fast a player goes for a loose ball"; 1.0
    // since passes leave at GRF's touch caps, with 2.8 free kicks).
    let fouls = mean(&stats, |s| f64::from(s.teams[0].fouls + s.teams[1].fouls));
    let free_kicks = mean(&stats, |s| f64::from(s.teams[0].free_kicks + s.teams[1].free_kicks));
    eprintln!("fouls {fouls:.2}, free kicks {free_kicks:.2} per match");
    assert!(fouls >= 1.0, "fouls per match {fouls:.2}");
}
