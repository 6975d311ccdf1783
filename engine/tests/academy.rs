//! The Academy drills and benchmarks play out from their scenarios, and the simplest drill is
//! solved by the obvious policy.

mod common;

use touchline_engine::{Action, ActionSet, Env, EnvConfig};

#[test]
fn run_right_and_shoot_scores_in_the_empty_goal_within_40_steps() {
    for seed in 0..20 {
        let mut env = common::env("academy_empty_goal_close", seed);
        let (steps, reward) = common::play(&mut env, |k, _| if k % 4 == 3 { Action::Shot } else { Action::Right });
        assert!(steps <= 40, "seed {seed}: {steps} steps");
        assert_eq!(reward, 1.0, "seed {seed}");
        assert_eq!(env.info().score, [1, 0]);
    }
}

#[test]
fn every_stdlib_scenario_plays_out_with_random_and_builtin_agents() {
    for name in common::names() {
        let scenario = common::scenario(&name);
        let duration = scenario.game_duration;
        for (policy_seed, builtin) in [(1u64, false), (2, true)] {
            let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
            let mut env = Env::with_config(scenario.clone(), config, policy_seed).unwrap();
            let mut policy = common::RandomPolicy::new(policy_seed);
            let (steps, _) =
                common::play(&mut env, |_, e| if builtin { Action::BuiltinAi } else { policy.action(e.action_set()) });
            assert!(steps <= duration + 1, "{name}: {steps} steps");
            for p in env.game().players() {
                assert!(p.position.is_finite(), "{name}: {p:?}");
            }
        }
    }
}

#[test]
fn academy_drills_end_early_on_their_conditions() {
    // Random play in a drill mostly ends by a goal, the ball going out or losing it, not the clock.
    let mut early = 0;
    for seed in 0..20 {
        let mut env = common::env("academy_run_to_score_with_keeper", seed);
        let mut policy = common::RandomPolicy::new(seed);
        let (steps, _) = common::play(&mut env, |_, e| policy.action(e.action_set()));
        if steps < 401 {
            early += 1;
        }
    }
    assert!(early >= 15, "only {early} of 20 episodes ended early");
}
