//! Runs the built `touchline` binary: output shapes, exit codes and diagnostics.

use std::process::{Command, Output};

/// Runs `touchline` with `args` in a fixed environment: no colour, no hyperlinks, no forced terminal
/// features, so that diagnostics render the same on every machine.
fn touchline(args: &[&str]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_touchline"));
    cmd.args(args);
    for var in ["FORCE_COLOR", "CLICOLOR_FORCE", "FORCE_HYPERLINK", "NO_GRAPHICS", "COLUMNS"] {
        cmd.env_remove(var);
    }
    cmd.env("NO_COLOR", "1");
    match cmd.output() {
        Ok(output) => output,
        Err(e) => panic!("cannot run {}: {e}", env!("CARGO_BIN_EXE_touchline")),
    }
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn run_json_reports_every_episode() {
    let output = touchline(&["run", "academy_empty_goal_close", "--episodes", "3", "--policy", "builtin", "--json"]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let report: serde_json::Value = serde_json::from_slice(&output.stdout).expect("stdout is one JSON document");
    let episodes = report["episodes"].as_array().expect("an `episodes` array");
    assert_eq!(episodes.len(), 3);
    for (i, episode) in episodes.iter().enumerate() {
        assert_eq!(episode["episode"].as_u64(), Some(i as u64));
        let steps = episode["steps"].as_u64().expect("steps");
        assert!((1..=401).contains(&steps), "episode {i}: {steps} steps");
        let ended = [&episode["terminated"], &episode["truncated"]];
        assert!(ended.iter().any(|flag| flag.as_bool() == Some(true)), "episode {i} did not end");
        assert_eq!(episode["score"].as_array().map(Vec::len), Some(2));
    }
    assert_eq!(report["summary"]["episodes"].as_u64(), Some(3));
    assert_eq!(report["policy"].as_str(), Some("builtin"));
    assert_eq!(report["action_set"].as_str(), Some("v2"));
}

#[test]
fn run_stats_prints_match_statistics_per_episode_and_on_average() {
    let output = touchline(&["run", "11_vs_11_easy_stochastic", "--episodes", "2", "--stats"]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let text = stdout(&output);
    for row in [
        "goals",
        "shots",
        "on target",
        "passes",
        "completed",
        "possession %",
        "fouls",
        "yellow cards",
        "red cards",
        "offsides",
        "corners",
        "throw-ins",
    ] {
        assert_eq!(text.lines().filter(|l| l.trim_start().starts_with(row)).count(), 3, "{row} in\n{text}");
    }
    assert!(text.contains("mean match statistics per episode"), "{text}");
    let json = touchline(&["run", "academy_empty_goal_close", "--episodes", "2", "--stats", "--json"]);
    let report: serde_json::Value = serde_json::from_slice(&json.stdout).expect("stdout is one JSON document");
    assert!(report["episodes"][0]["stats"]["passes"].is_array());
    assert!(report["summary"]["mean_stats"]["possession"].is_array());
}

#[test]
fn run_prints_episodes_and_summary() {
    let output =
        touchline(&["run", "academy_empty_goal_close", "--episodes", "2", "--policy", "random", "--seed", "4"]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let text = stdout(&output);
    let episode_lines =
        text.lines().filter(|l| l.trim_end().ends_with("terminated") || l.trim_end().ends_with("truncated")).count();
    assert_eq!(episode_lines, 2, "{text}");
    for key in ["episodes     2", "mean score", "total goals", "mean steps", "mean reward", "steps/s"] {
        assert!(text.contains(key), "missing `{key}` in\n{text}");
    }
}

#[test]
fn random_policy_is_reproducible() {
    let args = ["run", "academy_empty_goal", "--episodes", "2", "--policy", "random", "--seed", "11", "--json"];
    let episodes = |output: Output| {
        let report: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
        report["episodes"].clone()
    };
    assert_eq!(episodes(touchline(&args)), episodes(touchline(&args)));
}

#[test]
fn unknown_scenario_suggests_the_closest_name() {
    let output = touchline(&["run", "academy_empty_goal_clos"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(output.stdout.is_empty());
    let err = stderr(&output);
    assert!(err.contains("`academy_empty_goal_close`"), "{err}");
    insta::with_settings!({
        // Colour codes, should a terminal feature be forced anyway.
        filters => vec![(r"\x1b\[[0-9;]*m", "")],
    }, {
        insta::assert_snapshot!(err);
    });
}

#[test]
fn missing_json_file_exits_2() {
    let output = touchline(&["run", "no/such/dir/scenario.json"]);
    assert_eq!(output.status.code(), Some(2));
    let err = stderr(&output);
    assert!(err.contains("tl::E002") && err.contains("no/such/dir/scenario.json"), "{err}");
}

#[test]
fn too_many_agents_exits_2() {
    let output = touchline(&["run", "academy_empty_goal_close", "--left-agents", "5"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("controllable"), "{}", stderr(&output));
}

#[test]
fn bogus_policy_is_a_usage_error() {
    let output = touchline(&["run", "academy_empty_goal_close", "--policy", "bogus"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("bogus"));
}

#[test]
fn scenarios_lists_the_stdlib() {
    let output = touchline(&["scenarios"]);
    assert_eq!(output.status.code(), Some(0));
    let text = stdout(&output);
    assert!(text.lines().any(|l| l.starts_with("academy_empty_goal_close ")), "{text}");

    let names = stdout(&touchline(&["scenarios", "--names"]));
    let names: Vec<&str> = names.lines().collect();
    assert_eq!(names, touchline_dsl::stdlib::names());
}

#[test]
fn run_curriculum_shows_the_lessons() {
    // Every full window of 2 episodes meets `success_rate >= 0`: a new lesson every 2 episodes.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lessons.tl");
    std::fs::write(
        &path,
        "/// Two empty-goal lessons, then the run with a keeper.\nscenario lessons {\n  extends academy_empty_goal_close\n  \
         curriculum {\n    lesson close\n    lesson far extends academy_empty_goal\n    \
         lesson keeper extends academy_run_to_score_with_keeper\n    advance when success_rate >= 0 over 2 episodes\n  }\n}\n",
    )
    .unwrap();
    let path = path.to_str().unwrap();
    let output = touchline(&["run", path, "--curriculum", "--episodes", "5", "--policy", "builtin"]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let text = stdout(&output);
    assert!(text.contains("lesson   1 `close` -> 2/3 `far` after 2 episodes"), "{text}");
    assert!(text.contains("lesson   2 `far` -> 3/3 `keeper` after 2 episodes"), "{text}");
    assert!(text.contains("lessons (3 in the curriculum):"), "{text}");
    assert!(text.contains("advanced after episode 1"), "{text}");
    assert!(text.contains("advanced after episode 3"), "{text}");

    let output = touchline(&["run", path, "--curriculum", "--episodes", "5", "--policy", "idle", "--json"]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    let lessons: Vec<u64> =
        report["episodes"].as_array().unwrap().iter().map(|e| e["lesson"].as_u64().unwrap()).collect();
    assert_eq!(lessons, [0, 0, 1, 1, 2]);
    let rows = report["curriculum"]["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    assert_eq!(rows[0]["name"].as_str(), Some("close"));
    assert_eq!(rows[0]["episodes"].as_u64(), Some(2));
    assert_eq!(rows[0]["success_rate"].as_f64(), Some(0.0), "idling never scores");
    assert_eq!(rows[2]["advanced_after"], serde_json::Value::Null);
}

#[test]
fn run_curriculum_on_the_example_and_without_a_curriculum() {
    let output = touchline(&[
        "run",
        "../examples/scenarios/run_to_score_curriculum.tl",
        "--curriculum",
        "--episodes",
        "3",
        "--policy",
        "builtin",
    ]);
    assert_eq!(output.status.code(), Some(0), "stderr: {}", stderr(&output));
    assert!(stdout(&output).contains("1/3 close"), "{}", stdout(&output));
    let output = touchline(&["run", "academy_empty_goal_close", "--curriculum"]);
    assert_eq!(output.status.code(), Some(2), "stderr: {}", stderr(&output));
    assert!(stderr(&output).contains("has no curriculum"), "{}", stderr(&output));
}
