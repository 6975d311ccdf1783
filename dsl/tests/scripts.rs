//! Scenario scripts (issue 5): the example scripts, the sandbox, error reporting and policy,
//! determinism and snapshots.

use std::path::{Path, PathBuf};

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use touchline_dsl::script::{ErrorPolicy, ScriptError, ScriptOptions, Scripts};
use touchline_dsl::{BuildError, build_env, build_env_with, load};
use touchline_engine::scenario::{EndCondition, RewardKind, RewardTerm};
use touchline_engine::{Action, ActionSet, EngineError, Env, EnvConfig, Scenario};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/rewards")
}

fn with_reward(mut scenario: Scenario, path: &str, weight: f32) -> Scenario {
    scenario.rewards =
        vec![RewardTerm::scoring(), RewardTerm { reward: RewardKind::Script { path: path.into() }, weight }];
    scenario
}

/// A scratch folder holding `files` (name, text).
fn folder(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("touchline-scripts-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

fn env_with(text: &str, policy: ErrorPolicy) -> Result<Env, BuildError> {
    let dir = folder(&format!("{:x}", fnv(text)), &[("s.rhai", text)]);
    let scenario = with_reward(load("academy_empty_goal_close").unwrap(), "s.rhai", 1.0);
    let options = ScriptOptions { on_error: policy, ..ScriptOptions::default() };
    build_env_with(scenario, &dir, EnvConfig::default(), 0, options)
}

fn fnv(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

fn script_error(e: BuildError) -> ScriptError {
    match e {
        BuildError::Scripts(mut errors) => errors.errors.remove(0),
        other => panic!("expected a script error, got {other:?}"),
    }
}

fn random_actions(rng: &mut Pcg64, n: usize) -> Vec<Action> {
    let set = ActionSet::Default.actions();
    (0..n).map(|_| set[rng.random_range(0..set.len())]).collect()
}

/// The Checkpoint reward in rhai pays exactly what the built-in one pays, step by step, over
/// 1,000 random-policy episodes of each scenario (both run in the same env: built-in terms in
/// `info.checkpoint_reward`, the script's in `info.script_reward`).
#[test]
fn rhai_checkpoints_equal_the_builtin_reward() {
    for name in ["academy_empty_goal", "academy_run_to_score"] {
        let mut scenario = with_reward(load(name).unwrap(), "checkpoints.rhai", 1.0);
        scenario.rewards.push(RewardTerm { reward: RewardKind::Checkpoints { count: 10, value: 0.1 }, weight: 1.0 });
        let mut env = build_env(scenario, &examples(), EnvConfig::default(), 7).unwrap();
        let mut rng = Pcg64::seed_from_u64(11);
        let (mut paid, mut steps) = (0.0_f64, 0_u64);
        for episode in 0..1_000 {
            if episode > 0 {
                env.reset().unwrap();
            }
            loop {
                let actions = random_actions(&mut rng, 1);
                let outcome = env.step(&actions).unwrap();
                let info = *env.info();
                assert_eq!(
                    info.script_reward, info.checkpoint_reward,
                    "{name}, episode {episode}, step {}: the script and the built-in reward differ",
                    info.steps
                );
                paid += f64::from(info.checkpoint_reward);
                steps += 1;
                if outcome.terminated || outcome.truncated {
                    break;
                }
            }
        }
        assert!(paid > 10.0, "{name}: the random policy collected checkpoints ({paid} over {steps} steps)");
    }
}

#[test]
fn every_example_loads_and_runs() {
    let scenario = load("academy_run_to_score_with_keeper").unwrap();
    for script in ["possession.rhai", "pass_completion.rhai", "distance_to_goal.rhai", "checkpoints.rhai"] {
        let s = with_reward(scenario.clone(), script, 1.0);
        let mut env = build_env(s, &examples(), EnvConfig { left_agents: 2, ..EnvConfig::default() }, 3).unwrap();
        let mut rng = Pcg64::seed_from_u64(5);
        for _ in 0..100 {
            let actions = random_actions(&mut rng, 2);
            if env.is_done() {
                env.reset().unwrap();
            }
            env.step(&actions).unwrap_or_else(|e| panic!("{script}: {e}"));
            assert!(env.rewards().iter().all(|r| r.is_finite()));
        }
    }
}

#[test]
fn possession_pays_while_we_have_the_ball() {
    let scenario = with_reward(load("academy_empty_goal_close").unwrap(), "possession.rhai", 1.0);
    let mut env = build_env(scenario, &examples(), EnvConfig::default(), 0).unwrap();
    let mut paid = 0.0;
    for _ in 0..5 {
        env.step(&[Action::Right]).unwrap();
        paid += env.info().script_reward;
    }
    assert!(paid > 0.0, "the attacker starts on the ball");
}

#[test]
fn end_script_ends_the_episode_when_the_ball_enters_our_half() {
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.end_when = vec![EndCondition::Script { path: "ends/ball_in_our_half.rhai".into() }];
    scenario.end_episode_on_score = false;
    scenario.end_episode_on_out_of_play = false;
    let mut env = build_env(scenario.clone(), &examples(), EnvConfig::default(), 0).unwrap();
    let outcome = env.step(&[Action::Idle]).unwrap();
    assert!(!outcome.terminated, "the ball starts in the opponents' half");
    // Put the ball in our half.
    env.game_mut().place_ball(glam::Vec3::new(-10.0, 0.0, 0.11), glam::Vec3::ZERO, None);
    let outcome = env.step(&[Action::Idle]).unwrap();
    assert!(outcome.terminated && !outcome.truncated);
}

#[test]
fn per_agent_rewards_and_memory() {
    let text = r#"
fn reset(s) { memory.n = 0; }
fn reward(s) {
    memory.n += 1;
    print(`step ${s.steps}`);
    [memory.n, 10 * memory.n]
}
"#;
    let dir = folder("per-agent", &[("r.rhai", text)]);
    let scenario = with_reward(load("academy_run_to_score_with_keeper").unwrap(), "r.rhai", 0.5);
    let mut env = build_env(scenario, &dir, EnvConfig { left_agents: 2, ..EnvConfig::default() }, 0).unwrap();
    env.step(&[Action::Idle, Action::Idle]).unwrap();
    env.step(&[Action::Idle, Action::Idle]).unwrap();
    assert_eq!(env.rewards(), &[1.0, 10.0], "weight 0.5 × [2, 20]");
    assert_eq!(env.hook_log(), &["step 2".to_owned()]);
    env.reset().unwrap();
    env.step(&[Action::Idle, Action::Idle]).unwrap();
    assert_eq!(env.rewards(), &[0.5, 5.0], "memory starts again at each episode");
}

#[test]
fn snapshots_keep_the_scripts_memory() {
    let text = "fn reward(s) { if memory.n == () { memory.n = 0; } memory.n += 1; memory.n }";
    let mut env = env_with(text, ErrorPolicy::Raise).unwrap();
    for _ in 0..3 {
        env.step(&[Action::Idle]).unwrap();
    }
    let bytes = env.snapshot().to_bytes();
    let later: Vec<f32> = (0..3).map(|_| env.step(&[Action::Idle]).map(|_| env.rewards()[0]).unwrap()).collect();
    assert_eq!(later, [4.0, 5.0, 6.0]);
    env.restore(&touchline_engine::Snapshot::from_bytes(&bytes).unwrap()).unwrap();
    let again: Vec<f32> = (0..3).map(|_| env.step(&[Action::Idle]).map(|_| env.rewards()[0]).unwrap()).collect();
    assert_eq!(again, later);
}

#[test]
fn same_seed_same_rewards() {
    let text = "fn reward(s) { s.ball[0] * 0.1 + s.left_team[1][1] }";
    let run = || {
        let mut env = env_with(text, ErrorPolicy::Raise).unwrap();
        let mut rng = Pcg64::seed_from_u64(1);
        // Up to 50 steps, or to the end of the episode (a random agent may lose the ball sooner).
        let mut rewards = Vec::new();
        while rewards.len() < 50 && !env.is_done() {
            env.step(&random_actions(&mut rng, 1)).unwrap();
            rewards.push(env.rewards()[0]);
        }
        assert!(rewards.len() >= 5, "the episode lasted {} steps", rewards.len());
        rewards
    };
    assert_eq!(run(), run());
}

#[test]
fn an_endless_loop_is_stopped_by_the_operation_limit() {
    let mut env = env_with("fn reward(s) { let x = 0; loop { x += 1; } }", ErrorPolicy::Raise).unwrap();
    let Err(EngineError::Script { message, .. }) = env.step(&[Action::Idle]) else { panic!("the loop must fail") };
    assert!(message.contains("tl::S005") && message.contains("operation limit"), "{message}");
    assert!(message.contains("fn reward"), "points at the hook: {message}");
    assert!(env.is_done());
}

#[test]
fn huge_strings_and_arrays_are_refused() {
    for text in [r#"fn reward(s) { let x = "ab"; loop { x += x; } }"#, "fn reward(s) { let a = [1]; loop { a += a; } }"]
    {
        let mut env = env_with(text, ErrorPolicy::Raise).unwrap();
        let Err(EngineError::Script { message, .. }) = env.step(&[Action::Idle]) else { panic!("{text} must fail") };
        assert!(message.contains("tl::S005") && message.contains("is over its"), "{text}: {message}");
    }
}

#[test]
fn no_file_access_no_modules_no_eval_no_clock() {
    // Compile-time refusals.
    for text in ["import \"x\" as x; fn reward(s) { 0 }", "fn reward(s) { eval(\"1\") }"] {
        let e = script_error(env_with(text, ErrorPolicy::Raise).unwrap_err());
        assert!(matches!(e, ScriptError::Syntax { .. } | ScriptError::TopLevel { .. }), "{text}: {e:?}");
    }
    // No such functions at run time.
    // (A clock or `sleep` is refused when the script compiles: tests/sandbox.rs.)
    for text in ["fn reward(s) { open(\"/etc/passwd\") }", "fn reward(s) { rand() }"] {
        let mut env = env_with(text, ErrorPolicy::Raise).unwrap();
        let Err(EngineError::Script { message, .. }) = env.step(&[Action::Idle]) else { panic!("{text} must fail") };
        assert!(message.contains("Function not found"), "{text}: {message}");
    }
}

#[test]
fn syntax_errors_point_at_line_and_column() {
    let e = script_error(env_with("fn reward(s) {\n    let x = ;\n}\n", ErrorPolicy::Raise).unwrap_err());
    let ScriptError::Syntax { span, .. } = &e else { panic!("{e:?}") };
    assert_eq!(span.offset(), "fn reward(s) {\n    let x = ".len());
    let text = touchline_dsl::render_plain(&e);
    assert!(text.contains("tl::S002") && text.contains("s.rhai:2:13"), "{text}");
}

#[test]
fn undefined_variables_are_compile_errors() {
    let e = script_error(env_with("fn reward(s) { undefined + 1 }", ErrorPolicy::Raise).unwrap_err());
    assert!(matches!(e, ScriptError::Syntax { .. }), "{e:?}");
}

#[test]
fn missing_or_wrong_hooks() {
    let e = script_error(env_with("fn rewards(s) { 0 }", ErrorPolicy::Raise).unwrap_err());
    assert!(matches!(e, ScriptError::MissingHook { hook: "reward", .. }), "{e:?}");
    let e = script_error(env_with("fn reward(s, t) { 0 }", ErrorPolicy::Raise).unwrap_err());
    assert!(touchline_dsl::render_plain(&e).contains("takes 2 parameters"), "{e:?}");
    let e = script_error(env_with("let total = 0; fn reward(s) { 0 }", ErrorPolicy::Raise).unwrap_err());
    assert!(matches!(e, ScriptError::TopLevel { .. }), "{e:?}");
    let e = script_error(
        build_env(
            with_reward(Scenario::default(), "missing.rhai", 1.0),
            Path::new("/nonexistent"),
            EnvConfig::default(),
            0,
        )
        .unwrap_err(),
    );
    assert!(matches!(e, ScriptError::Unreadable { .. }), "{e:?}");
}

#[test]
fn wrong_return_types_fail_the_step() {
    for (text, expected) in [
        (r#"fn reward(s) { "a lot" }"#, "tl::S006"),
        ("fn reward(s) { [1.0, 2.0] }", "1 agent(s)"),
        ("fn reward(s) { 1.0 / 0.0 }", "tl::S006"),
    ] {
        let mut env = env_with(text, ErrorPolicy::Raise).unwrap();
        let Err(EngineError::Script { message, .. }) = env.step(&[Action::Idle]) else { panic!("{text} must fail") };
        assert!(message.contains(expected), "{text}: {message}");
    }
}

#[test]
fn warn_policy_pays_zero_and_counts() {
    let mut env = env_with("fn reward(s) { if s.steps == 2 { throw \"bad\" } 1.0 }", ErrorPolicy::Warn).unwrap();
    env.step(&[Action::Idle]).unwrap();
    assert_eq!(env.info().script_reward, 1.0);
    env.step(&[Action::Idle]).unwrap();
    assert_eq!((env.info().script_reward, env.info().script_errors), (0.0, 1));
    assert!(env.hook_log()[0].contains("tl::S005"), "{:?}", env.hook_log());
    env.step(&[Action::Idle]).unwrap();
    assert_eq!((env.info().script_reward, env.info().script_errors), (1.0, 1));
}

#[test]
fn memory_is_not_visible_in_helpers_and_the_message_says_so() {
    let text = "fn helper() { memory.x = 1; 0 } fn reward(s) { helper() }";
    let mut env = env_with(text, ErrorPolicy::Raise).unwrap();
    let Err(EngineError::Script { message, .. }) = env.step(&[Action::Idle]) else { panic!() };
    assert!(message.contains("helper"), "{message}");
}

#[test]
fn from_text_compiles_without_files() {
    let scripts = Scripts::from_text("x.rhai", "fn end(s) { s.steps >= 3 }", None, ScriptOptions::default()).unwrap();
    assert!(!scripts.is_empty());
}

/// A scenario whose left forward is played by `examples/behaviours/run_and_shoot.rhai` (or
/// `path` in `dir`), no agents, the right keeper lazy.
fn scripted_forward(path: &str) -> Scenario {
    use touchline_engine::scenario::{Behaviour, Stage};
    use touchline_engine::{PlayerEntry, Role};
    let mut forward = PlayerEntry::new(Role::CF, 0.1, 0.1);
    forward.behaviour = vec![Stage { behaviour: Behaviour::Script { path: path.into() }, until: None }];
    Scenario {
        left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), forward],
        right_team: vec![PlayerEntry { lazy: true, ..PlayerEntry::new(Role::GK, -1.0, 0.0) }],
        ball_position: [0.3, -0.1],
        game_duration: 300,
        ..Scenario::default()
    }
}

fn behaviours_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/behaviours")
}

/// The example behaviour script runs at the ball, carries it forward and shoots; the same seed
/// plays the same game.
#[test]
fn a_behaviour_script_runs_at_the_ball_and_shoots() {
    let config = EnvConfig { left_agents: 0, ..EnvConfig::default() };
    let play = || {
        let mut env = build_env(scripted_forward("run_and_shoot.rhai"), &behaviours_dir(), config, 3).unwrap();
        let (mut shot, mut owned, mut hashes) = (false, false, Vec::new());
        for _ in 0..200 {
            let out = env.step(&[]).unwrap();
            hashes.push(env.game().state_hash());
            owned |= env.game().owner() == Some((touchline_engine::Side::Left, 1));
            shot |= env.game().events().iter().any(|e| {
                matches!(e, touchline_engine::Event::Shot { side: touchline_engine::Side::Left, player: 1, .. })
            });
            if shot || out.terminated || out.truncated {
                break;
            }
        }
        (owned, shot, hashes)
    };
    let (owned, shot, first) = play();
    assert!(owned && shot, "owned the ball: {owned}, shot: {shot}");
    assert_eq!(first, play().2);
}

/// Behaviour scripts are checked at load (`fn act(s, me)`, `tl::S003`), and a bad return value
/// is a return-type diagnostic under the error policy: fails the step, or, with `warn`, the
/// player idles and the error is counted.
#[test]
fn behaviour_script_errors_follow_the_policy() {
    let config = EnvConfig { left_agents: 0, ..EnvConfig::default() };
    let dir = folder("act", &[("one.rhai", "fn act(s) { \"shot\" }"), ("bad.rhai", "fn act(s, me) { \"jump\" }")]);
    let e = script_error(build_env(scripted_forward("one.rhai"), &dir, config, 0).unwrap_err());
    assert!(matches!(e, ScriptError::MissingHook { hook: "act", .. }), "{e:?}");
    assert!(touchline_dsl::render_plain(&e).contains("fn act(s, me)"), "{e:?}");
    let mut env = build_env(scripted_forward("bad.rhai"), &dir, config, 0).unwrap();
    let err = env.step(&[]).unwrap_err().to_string();
    assert!(err.contains("tl::S006") && err.contains("`jump`"), "{err}");
    let warn = ScriptOptions { on_error: ErrorPolicy::Warn, ..ScriptOptions::default() };
    let mut env = build_env_with(scripted_forward("bad.rhai"), &dir, config, 0, warn).unwrap();
    for k in 1..=3 {
        env.step(&[]).unwrap();
        assert_eq!(env.info().script_errors, k);
        assert!(env.hook_log().iter().any(|l| l.contains("jump")));
    }
}
