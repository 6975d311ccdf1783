//! Shared fixtures: the stdlib scenarios' compiled JSON, read from the repository, and policies.
#![allow(dead_code, unreachable_pub)]

use touchline_engine::{Action, ActionSet, Env, EnvConfig, PlayerEntry, Role, Scenario};

/// A stdlib scenario by name (from `stdlib-scenarios/<name>.json`).
pub fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Every stdlib scenario name.
pub fn names() -> Vec<String> {
    let dir = format!("{}/../stdlib-scenarios", env!("CARGO_MANIFEST_DIR"));
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok()?.strip_suffix(".json").map(str::to_owned))
        .collect();
    names.sort();
    names
}

/// An env on a stdlib scenario with the default configuration.
pub fn env(name: &str, seed: u64) -> Env {
    Env::new(scenario(name), seed).unwrap()
}

/// An env with the Checkpoint reward on.
pub fn env_with_checkpoints(name: &str, seed: u64) -> Env {
    Env::with_config(scenario(name), EnvConfig { checkpoints: true, ..EnvConfig::default() }, seed).unwrap()
}

/// An env where the agents' players are driven by the built-in AI (`builtin_ai`, v2 set).
pub fn builtin_env(name: &str, seed: u64) -> Env {
    let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    Env::with_config(scenario(name), config, seed).unwrap()
}

/// Two goalkeepers and one left outfield player, everyone lazy but the outfield player; the right
/// keeper stands in the left goal so that the right goal is empty (like academy_empty_goal).
pub fn empty_pitch(duration: u32) -> Scenario {
    let mut gk = PlayerEntry::new(Role::GK, -1.0, 0.0);
    gk.lazy = true;
    let mut right_gk = PlayerEntry::new(Role::GK, 1.0, 0.0);
    right_gk.lazy = true;
    Scenario {
        name: "empty_pitch".into(),
        game_duration: duration,
        left_team: vec![gk, PlayerEntry::new(Role::CB, -0.5, 0.3)],
        right_team: vec![right_gk],
        ball_position: [-0.5, 0.35],
        ..Scenario::default()
    }
}

/// Steps with `policy(step, env)` until the episode ends; returns (steps, summed reward of
/// controller 0).
pub fn play(env: &mut Env, mut policy: impl FnMut(u32, &Env) -> Action) -> (u32, f32) {
    let mut total = 0.0;
    let mut k = 0;
    loop {
        let actions = vec![policy(k, env); env.num_controllers()];
        let out = env.step(&actions).unwrap();
        total += env.rewards().first().copied().unwrap_or(0.0);
        k += 1;
        if out.terminated || out.truncated {
            return (k, total);
        }
    }
}

/// A tiny seeded generator for random policies (xorshift64*).
pub struct RandomPolicy(u64);

impl RandomPolicy {
    pub fn new(seed: u64) -> RandomPolicy {
        RandomPolicy(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    pub fn index(&mut self, n: usize) -> usize {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 33) as usize % n
    }

    pub fn action(&mut self, set: ActionSet) -> Action {
        set.actions()[self.index(set.len())]
    }
}

/// A three-lesson curriculum over stdlib drills: `close` (academy_empty_goal_close), `far`
/// (academy_empty_goal), `keeper` (academy_run_to_score_with_keeper); each lesson advances once
/// `window` episodes have `success_rate >= threshold`.
pub fn curriculum(window: u32, threshold: f64) -> Scenario {
    use touchline_engine::scenario::{Criterion, Curriculum, Lesson, Metric, Threshold};
    let advance = Criterion {
        window,
        min_episodes: window,
        thresholds: vec![Threshold { metric: Metric::SuccessRate, at_least: true, value: threshold }],
    };
    let lesson = |name: &str, scenario: &str| Lesson {
        name: name.into(),
        scenario: self::scenario(scenario),
        advance: Some(advance.clone()),
    };
    Scenario {
        curriculum: Some(Box::new(Curriculum {
            lessons: vec![
                lesson("close", "academy_empty_goal_close"),
                lesson("far", "academy_empty_goal"),
                lesson("keeper", "academy_run_to_score_with_keeper"),
            ],
        })),
        ..scenario("academy_empty_goal_close")
    }
}
