//! Every scenario the checks accept plays (issue 17, item 3): random valid scenarios — team sizes,
//! roles, flags, the odd-episode swap, ball starts, end rules, agents a side — are built into envs
//! and played over several resets, with random actions. An env either refuses its configuration
//! when it is built, with an error, or plays: never a panic at some later reset.
//!
//! The case count is modest for CI; set `PROPTEST_CASES` for a longer run.

use proptest::prelude::*;
use touchline_engine::{EngineError, Env, EnvConfig, PlayerEntry, Role, Scenario};

const ROLES: [Role; 9] = [Role::CB, Role::LB, Role::RB, Role::DM, Role::CM, Role::LM, Role::RM, Role::AM, Role::CF];

/// One player: role (a GK or an outfield role), place, `lazy`, `controllable`.
fn player(keeper: bool) -> impl Strategy<Value = PlayerEntry> {
    (0..ROLES.len(), -1.0f32..1.0, -0.42f32..0.42, any::<bool>(), prop::bool::weighted(0.8)).prop_map(
        move |(role, x, y, lazy, controllable)| {
            let mut p = PlayerEntry::new(if keeper { Role::GK } else { ROLES[role] }, x, y);
            p.lazy = lazy;
            p.controllable = controllable;
            p
        },
    )
}

/// A team of 1 to 11 players, one of them the keeper (at a random place in the list).
fn team() -> impl Strategy<Value = Vec<PlayerEntry>> {
    (prop::collection::vec(player(false), 0..=10), player(true), any::<prop::sample::Index>()).prop_map(
        |(mut outfield, keeper, at)| {
            let i = at.index(outfield.len() + 1);
            outfield.insert(i, keeper);
            outfield
        },
    )
}

prop_compose! {
    fn scenario()(
        left in team(),
        right in team(),
        flags in prop::collection::vec(any::<bool>(), 8),
        ball in (-1.0f32..1.0, -0.42f32..0.42),
        odd_ball in prop::option::of((-1.0f32..1.0, -0.42f32..0.42)),
        difficulty in (0.0f32..=1.0, 0.0f32..=1.0),
        duration in 5u32..120,
    ) -> Scenario {
        Scenario {
            name: "random".into(),
            game_duration: duration,
            deterministic: flags[0],
            offsides: flags[1],
            end_episode_on_score: flags[2],
            end_episode_on_out_of_play: flags[3],
            end_episode_on_possession_change: flags[4],
            control_all_players: flags[5],
            swap_teams_on_odd_episodes: flags[6],
            left_team_difficulty: difficulty.0,
            right_team_difficulty: difficulty.1,
            ball_position: [ball.0, ball.1],
            odd_episode_ball_position: odd_ball.map(|(x, y)| [x, y]),
            left_team: left,
            right_team: right,
            ..Scenario::default()
        }
    }
}

/// Builds and plays `scenario` under `config`: 3 episodes of up to 40 steps with the actions
/// drawn from `actions`, checking that observations and rewards stay finite.
fn play(scenario: Scenario, config: EnvConfig, seed: u64, actions: &[u32]) -> Result<(), TestCaseError> {
    scenario.validate().map_err(|e| TestCaseError::reject(e.to_string()))?;
    let mut env = match Env::with_config(scenario, config, seed) {
        Ok(env) => env,
        // Refused when built, with a reason: what the scenario checks let through is playable
        // by some configuration, just not this one.
        Err(EngineError::InvalidConfig { .. }) => return Ok(()),
        Err(e) => return Err(TestCaseError::fail(format!("unexpected error building the env: {e}"))),
    };
    let mut a = actions.iter().cycle();
    for _ in 0..3 {
        for _ in 0..40 {
            let step: Vec<u32> = (0..env.num_controllers()).map(|_| *a.next().unwrap_or(&0)).collect();
            let out = env.step_indices(&step).map_err(|e| TestCaseError::fail(e.to_string()))?;
            prop_assert!(env.observations().iter().all(|o| o.ball.iter().all(|v| v.is_finite())));
            prop_assert!(env.rewards().iter().all(|r| r.is_finite()));
            if out.terminated || out.truncated {
                break;
            }
        }
        env.reset().unwrap();
    }
    Ok(())
}

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(64)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_valid_scenarios_play_through_resets(
        scenario in scenario(),
        agents in (0usize..=3, 0usize..=2),
        seed in any::<u64>(),
        actions in prop::collection::vec(0u32..19, 1..64),
    ) {
        let config = EnvConfig { left_agents: agents.0, right_agents: agents.1, ..EnvConfig::default() };
        play(scenario, config, seed, &actions)?;
    }
}

/// The case the issue found: 5_vs_5 with a right team of one keeper nobody controls. With the
/// odd-episode swap the left agent would have no player at the second reset; the env now says
/// so when it is built, and plays with no left agent.
#[test]
fn a_swap_onto_a_team_without_controllable_players_is_refused_when_built() {
    let path = format!("{}/../stdlib-scenarios/5_vs_5.json", env!("CARGO_MANIFEST_DIR"));
    let mut scenario: Scenario = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut keeper = PlayerEntry::new(Role::GK, -1.0, 0.0);
    keeper.controllable = false;
    scenario.right_team = vec![keeper];
    scenario.validate().unwrap();
    let Err(err) = Env::new(scenario.clone(), 0) else { panic!("one left agent cannot play odd episodes") };
    assert!(matches!(err, EngineError::InvalidConfig { .. }), "{err}");
    assert!(err.to_string().contains("swap"), "{err}");
    let config = EnvConfig { left_agents: 0, ..EnvConfig::default() };
    play(scenario, config, 0, &[0]).unwrap();
}
