//! Rewards never become inf or NaN from finite inputs (issue 17, item 8): weights are bounded when
//! a scenario compiles (`tl::E149`, or `tl::E004` for a compiled scenario), and a script term whose
//! weighted value is not finite fails the step naming the script (`tl::S009`).

use std::path::PathBuf;

use touchline_dsl::script::{ErrorPolicy, ScriptOptions};
use touchline_dsl::{build_env_with, compile, load, load_json};
use touchline_engine::scenario::{RewardKind, RewardTerm};
use touchline_engine::{Action, EngineError, EnvConfig};

#[test]
fn four_huge_scoring_weights_are_refused_at_their_span() {
    let source = "scenario huge {\n  extends academy_empty_goal_close\n  reward scoring weight 1e38\n  \
                  reward scoring weight 1e38\n  reward scoring weight 1e38\n  reward scoring weight 1e38\n}\n";
    let Err(diagnostics) = compile(source, "huge.tl") else { panic!("four weights of 1e38 compile") };
    let errors: Vec<_> = diagnostics.items.iter().filter(|d| d.code.as_str() == "tl::E149").collect();
    assert_eq!(errors.len(), 4, "{diagnostics:?}");
    let at = errors[0].labels[0].0;
    assert_eq!(&source[at.start..at.end], "1e38");
    // In range: compiles.
    compile(&source.replace("1e38", "1e6"), "ok.tl").unwrap();
    // Event rewards and checkpoint values too.
    for (text, bad) in [
        ("reward on shot 1e9", "1e9"),
        ("reward checkpoint(count: 10, value: 1e30)", "1e30"),
        ("reward scoring weight -2e6", "2e6"),
    ] {
        let source = format!("scenario s {{\n  extends academy_empty_goal_close\n  {text}\n}}\n");
        let Err(d) = compile(&source, "s.tl") else { panic!("{text} compiles") };
        let e = d.items.iter().find(|d| d.code.as_str() == "tl::E149").unwrap_or_else(|| panic!("{text}: {d:?}"));
        assert!(source[e.labels[0].0.start..e.labels[0].0.end].contains(bad), "{text}: {d:?}");
    }
}

#[test]
fn a_compiled_scenario_with_a_huge_weight_is_refused() {
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.rewards = vec![RewardTerm { reward: RewardKind::Scoring, weight: 1e38 }; 4];
    let json = serde_json::to_string(&scenario).unwrap();
    let e = load_json(&json, "huge.json").unwrap_err();
    let text = touchline_dsl::render_plain(&e);
    assert!(text.contains("tl::E004") && text.contains("reward weight"), "{text}");
}

fn folder(files: &[(&str, &str)]) -> PathBuf {
    let name = files.iter().map(|(_, t)| t.len()).sum::<usize>();
    let dir = std::env::temp_dir().join(format!("touchline-overflow-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

/// A script returning 3e38 with `weight 10`: before, the env paid inf; now the step fails naming
/// the script, or under the warn policy the term pays zero and the error is counted.
#[test]
fn a_script_term_that_overflows_is_an_error_naming_it() {
    let dir = folder(&[("big.rhai", "fn reward(s) { 3e38 }"), ("one.rhai", "fn reward(s) { 1.0 }")]);
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.rewards = vec![
        RewardTerm { reward: RewardKind::Script { path: "one.rhai".into() }, weight: 1.0 },
        RewardTerm { reward: RewardKind::Script { path: "big.rhai".into() }, weight: 10.0 },
    ];
    let options = ScriptOptions { on_error: ErrorPolicy::Raise, ..ScriptOptions::default() };
    let mut env = build_env_with(scenario.clone(), &dir, EnvConfig::default(), 0, options).unwrap();
    match env.step(&[Action::Idle]) {
        Err(EngineError::Script { message, .. }) => {
            assert!(message.contains("tl::S009") && message.contains("big.rhai"), "{message}");
        }
        other => panic!("paid {:?}: {other:?}", env.rewards()),
    }

    let options = ScriptOptions { on_error: ErrorPolicy::Warn, ..ScriptOptions::default() };
    let mut env = build_env_with(scenario, &dir, EnvConfig::default(), 0, options).unwrap();
    env.step(&[Action::Idle]).unwrap();
    assert_eq!(env.rewards(), [1.0], "the overflowing term pays zero");
    assert_eq!(env.info().script_errors, 1);
    assert!(env.hook_log().iter().any(|l| l.contains("tl::S009")), "{:?}", env.hook_log());
}

/// Two terms each finite whose sum is not: the second one is named.
#[test]
fn a_sum_that_overflows_names_the_term_that_made_it() {
    let dir = folder(&[("a.rhai", "fn reward(s) { 3e38 }"), ("b.rhai", "fn reward(s) { 3.0e38 }")]);
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.rewards = vec![
        RewardTerm { reward: RewardKind::Script { path: "a.rhai".into() }, weight: 1.0 },
        RewardTerm { reward: RewardKind::Script { path: "b.rhai".into() }, weight: 1.0 },
    ];
    let mut env = build_env_with(scenario, &dir, EnvConfig::default(), 0, ScriptOptions::default()).unwrap();
    let Err(EngineError::Script { message, .. }) = env.step(&[Action::Idle]) else {
        panic!("paid {:?}", env.rewards())
    };
    assert!(message.contains("tl::S009") && message.contains("b.rhai"), "{message}");
}
