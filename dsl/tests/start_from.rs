//! `start from "moment.state"`: a moment saved from a match (a snapshot's bytes, as Python's
//! `env.unwrapped.get_state()` gives them) becomes a drill that every episode starts from.

use std::path::Path;

use touchline_engine::{Action, Env};

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_saved_moment_starts_every_episode() {
    let dir = scratch("start_from");
    // Play 150 steps of a full match and save the moment.
    let mut env = Env::new(touchline_dsl::load("11_vs_11_stochastic").unwrap(), 5).unwrap();
    for _ in 0..150 {
        env.step(&[Action::Idle]).unwrap();
    }
    std::fs::write(dir.join("moment.state"), env.snapshot().to_bytes()).unwrap();
    let saved = env.observations()[0].clone();

    let drill = dir.join("moment.tl");
    std::fs::write(
        &drill,
        "/// From a saved moment.\nscenario moment {\n  extends 11_vs_11_stochastic\n  game_duration 100\n  start from \"moment.state\"\n}\n",
    )
    .unwrap();
    let scenario =
        touchline_dsl::load(drill.to_str().unwrap()).unwrap_or_else(|e| panic!("{}", touchline_dsl::render_plain(&e)));
    assert!(scenario.start_state.is_some());
    let mut drill_env = Env::new(scenario.clone(), 9).unwrap();
    for episode in 0..3 {
        let obs = &drill_env.observations()[0];
        assert_eq!(obs.left_team, saved.left_team, "episode {episode}");
        assert_eq!(obs.right_team, saved.right_team, "episode {episode}");
        assert_eq!(obs.ball, saved.ball, "episode {episode}");
        assert_eq!(obs.score, [0, 0]);
        assert_eq!(obs.steps_left, 101);
        for _ in 0..20 {
            drill_env.step(&[Action::Idle]).unwrap();
        }
        drill_env.reset().unwrap();
    }
    // The compiled JSON carries the state, so the drill loads without the state file.
    let json = serde_json::to_string(&scenario).unwrap();
    std::fs::remove_file(dir.join("moment.state")).unwrap();
    let back = touchline_dsl::load_json(&json, "moment.json").unwrap();
    assert_eq!(back.start_state, scenario.start_state);
}

#[test]
fn a_missing_or_mismatched_state_is_a_diagnostic() {
    let dir = scratch("start_from_errors");
    let drill = dir.join("drill.tl");
    std::fs::write(&drill, "scenario d {\n  extends academy_empty_goal\n  start from \"nowhere.state\"\n}\n").unwrap();
    let err = touchline_dsl::compile_file(&drill).unwrap_err();
    assert_eq!(err.errors().next().unwrap().code, touchline_dsl::Code::StartState);

    // A state saved from an 11 v 11 match cannot start a 2 v 1 drill.
    let env = Env::new(touchline_dsl::load("11_vs_11_stochastic").unwrap(), 0).unwrap();
    std::fs::write(dir.join("big.state"), env.snapshot().to_bytes()).unwrap();
    std::fs::write(&drill, "scenario d {\n  extends academy_empty_goal\n  start from \"big.state\"\n}\n").unwrap();
    let err = touchline_dsl::compile_file(&drill).unwrap_err();
    let first = err.errors().next().unwrap();
    assert_eq!(first.code, touchline_dsl::Code::StartState);
    assert!(first.message.contains("11v11"), "{}", first.message);

    // Garbage bytes are refused with the snapshot's own reason.
    std::fs::write(dir.join("big.state"), b"not a state").unwrap();
    let err = touchline_dsl::compile_file(&drill).unwrap_err();
    assert!(err.errors().next().unwrap().message.contains("snapshot"), "{}", err.render_plain());
}

/// Issue 17, item 12: `start from` takes what Python's `get_state()` returns — a snapshot with the
/// frame stacks as extra bytes — as well as a bare snapshot.
#[test]
fn a_state_with_extra_bytes_starts_a_drill() {
    let dir = scratch("start_from_get_state");
    let mut env = Env::new(touchline_dsl::load("academy_corner").unwrap(), 2).unwrap();
    for _ in 0..10 {
        env.step(&[Action::Idle]).unwrap();
    }
    let stacks = vec![7u8; 1848];
    std::fs::write(dir.join("moment.state"), env.snapshot().to_bytes_with(&stacks)).unwrap();
    let drill = dir.join("moment.tl");
    std::fs::write(&drill, "scenario moment {\n  extends academy_corner\n  start from \"moment.state\"\n}\n").unwrap();
    let scenario = touchline_dsl::compile_file(&drill).unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    let drill_env = Env::new(scenario, 0).unwrap();
    assert_eq!(drill_env.observations()[0].left_team, env.observations()[0].left_team);
}
