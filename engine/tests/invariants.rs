//! Properties over random action sequences (proptest): whatever agents do, positions and velocities
//! stay finite and inside the rim, the score only grows, and play never stays stopped at a set
//! piece for more than 30 steps (GRF's anti-stalling rule plus the AI's takers).

mod common;

use proptest::prelude::*;
use touchline_engine::{ActionSet, Env, EnvConfig, GameMode};

const SCENARIOS: [&str; 4] = ["11_vs_11_stochastic", "academy_corner", "academy_counterattack_hard", "5_vs_5"];

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn random_play_stays_sane(
        scenario in 0..SCENARIOS.len(),
        seed in 0u64..1_000,
        right_agent in any::<bool>(),
        actions in proptest::collection::vec((0u32..20, 0u32..20), 50..400),
    ) {
        let config = EnvConfig { right_agents: usize::from(right_agent), action_set: ActionSet::V2, ..EnvConfig::default() };
        let mut env = Env::with_config(common::scenario(SCENARIOS[scenario]), config, seed).unwrap();
        let mut stopped = 0;
        let mut score = [0, 0];
        for (a, b) in actions {
            let chosen = [a, b];
            let out = env.step_indices(&chosen[..env.num_controllers()]).unwrap();
            let game = env.game();
            for p in game.players() {
                prop_assert!(p.position.is_finite() && p.velocity.is_finite());
                prop_assert!(p.position.x.abs() <= 60.0 + 1e-3 && p.position.y.abs() <= 40.0 + 1e-3, "{:?}", p);
            }
            let ball = game.ball();
            prop_assert!(ball.position.is_finite() && ball.velocity.is_finite());
            prop_assert!(ball.position.x.abs() <= 60.0 + 1e-3 && ball.position.y.abs() <= 40.0 + 1e-3);
            let now = env.info().score;
            prop_assert!(now[0] >= score[0] && now[1] >= score[1]);
            score = now;
            stopped = if env.info().game_mode == GameMode::Normal { 0 } else { stopped + 1 };
            prop_assert!(stopped <= 30, "stuck at {:?}", env.info().game_mode);
            if out.terminated || out.truncated {
                env.reset().unwrap();
                score = [0, 0];
                stopped = 0;
            }
        }
    }
}
