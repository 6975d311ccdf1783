//! A random agent on `academy_empty_goal`: the smallest complete touchline program.
//!
//! It loads a stdlib scenario by name, builds an [`Env`] with the default configuration (one
//! controlled left player, the Scoring reward, GRF's 19-action default set), and plays episodes
//! with actions drawn uniformly from the action set, printing each episode's return.
//!
//! ```text
//! cargo run -p touchline-examples --example random_agent
//! ```

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64Mcg;
use touchline_engine::{ActionSet, Env};

/// Episodes to play.
const EPISODES: u32 = 5;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A stdlib name, or the path of a compiled `.json` scenario. On failure, print the diagnostic
    // the way the `touchline` command does (code, message, help).
    let scenario = match touchline_dsl::load("academy_empty_goal") {
        Ok(scenario) => scenario,
        Err(err) => {
            eprintln!("{}", touchline_dsl::render_plain(&err));
            std::process::exit(2);
        }
    };

    // The environment owns all of the simulation's randomness; seed 0 makes runs repeatable.
    let mut env = Env::new(scenario, 0)?;
    // The agent's own generator, also seeded.
    let mut rng = Pcg64Mcg::seed_from_u64(1);
    let n_actions = ActionSet::Default.len() as u32;

    for episode in 0..EPISODES {
        if episode > 0 {
            env.reset()?;
        }
        let mut episode_return = 0.0_f32;
        loop {
            // One action index per controlled player (here exactly one), in 0..19.
            let actions: Vec<u32> = (0..env.num_controllers()).map(|_| rng.random_range(0..n_actions)).collect();
            let outcome = env.step_indices(&actions)?;
            episode_return += env.rewards()[0];
            // `terminated`: a goal, the ball out of play or lost; `truncated`: 401 steps played.
            if outcome.terminated || outcome.truncated {
                break;
            }
        }
        let info = env.info();
        println!(
            "episode {episode}: return {episode_return:+.1}, score {}-{}, {} steps",
            info.score[0], info.score[1], info.steps
        );
    }
    Ok(())
}
