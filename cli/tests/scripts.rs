//! Scenario scripts as a user meets them in the command (issue 18): `check` runs a script's
//! compile-time checks, and `run` reports a failing hook as the script's own diagnostic.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the command in `dir`, so that the paths it prints are the relative ones given.
fn touchline(dir: &Path, args: &[&str]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_touchline"));
    cmd.args(args).current_dir(dir).env("NO_COLOR", "1");
    for var in ["FORCE_COLOR", "CLICOLOR_FORCE", "FORCE_HYPERLINK", "COLUMNS"] {
        cmd.env_remove(var);
    }
    cmd.output().unwrap_or_else(|e| panic!("cannot run touchline: {e}"))
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// A fresh folder holding `drill.tl` (a reward script term naming `script.rhai`) and the script.
fn drill(name: &str, script: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("scripts-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let tl =
        "scenario drill {\n  extends academy_empty_goal_close\n  reward scoring\n  reward script \"script.rhai\"\n}\n";
    std::fs::write(dir.join("drill.tl"), tl).unwrap();
    std::fs::write(dir.join("script.rhai"), script).unwrap();
    dir
}

fn snapshot(name: &str, stderr: &str) {
    insta::with_settings!({ filters => vec![(r"\x1b\[[0-9;]*m", "")], omit_expression => true }, {
        insta::assert_snapshot!(name, stderr);
    });
}

#[test]
fn check_reports_an_unknown_property_with_the_real_ones() {
    let dir = drill("unknown-property", "fn reward(s) {\n    if s.ball_owner == 0 { 0.001 } else { 0.0 }\n}\n");
    let out = touchline(&dir, &["check", "drill.tl"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("tl::S010") && err.contains("did you mean one of `ball_owned_team`"), "{err}");
    snapshot("check_reports_an_unknown_property_with_the_real_ones", &err);
}

/// A `loop {}` in `fn reset` is the script's `tl::S005`, labelled on the loop; it was reported as
/// "cannot play with this configuration" with advice about agent counts.
#[test]
fn an_endless_reset_is_the_scripts_error_not_the_configurations() {
    let dir = drill("endless-reset", "fn reset(s) {\n    loop {}\n}\n\nfn reward(s) {\n    0.0\n}\n");
    let out = touchline(&dir, &["run", "drill.tl"]);
    assert_eq!(out.status.code(), Some(1), "a failing run, not bad input");
    let err = text(&out.stderr);
    assert!(err.contains("tl::S005") && err.contains("loop {}"), "{err}");
    assert!(!err.contains("tl::cli::config") && !err.contains("--left-agents"), "{err}");
    snapshot("an_endless_reset_is_the_scripts_error_not_the_configurations", &err);
}

/// Issue 18, item 5: a script failing in a step is printed as the script's own diagnostic, not
/// nested in a frame that wrapped each of its lines twice, and the step it names is the one the
/// env counts (it said "at step 0" around "failed at step 1").
#[test]
fn a_script_failing_in_a_step_is_printed_whole_and_names_its_step() {
    let dir = drill("throws", "fn reward(s) {\n    if s.steps == 3 { throw \"no\"; }\n    0.0\n}\n");
    let out = touchline(&dir, &["run", "drill.tl"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("`reward` failed in step 3") && err.contains("in episode 0"), "{err}");
    assert!(!err.contains("at step"), "{err}");
    assert!(err.lines().all(|l| l.chars().count() <= 80), "no line wider than the renderer's 80 columns:\n{err}");
    snapshot("a_script_failing_in_a_step_is_printed_whole_and_names_its_step", &err);
}

/// Issue 18, item 5: `run` printed the first compile error twice (as the report's message and as
/// its first related diagnostic).
#[test]
fn run_prints_each_compile_error_once() {
    let dir = drill("broken", "fn reward(s) { 0.0 }\n");
    let broken = "scenario d {\n  extends academy\n  game_durration 400\n  team left { GK at (-1, 0) CBB at (0.5, 0) }\n  team right { GK at (-1, 0) }\n}\n";
    std::fs::write(dir.join("drill.tl"), broken).unwrap();
    let out = touchline(&dir, &["run", "drill.tl"]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert_eq!(err.matches("unknown key `game_durration`").count(), 1, "{err}");
    assert_eq!(err.matches("unknown role `CBB`").count(), 1, "{err}");
    assert!(err.contains("`drill.tl` does not compile: 2 errors, 0 warnings"), "{err}");
    snapshot("run_prints_each_compile_error_once", &err);
    // And a script that does not compile, once.
    let dir = drill("broken-script", "fn reward(s) { let x = ; }\n");
    let err = text(&touchline(&dir, &["run", "drill.tl"]).stderr);
    assert_eq!(err.matches("Unexpected ';'").count(), 1, "{err}");
}

/// Issue 18, item 5: a main file that is not text is `tl::E150`; it was `tl::E112`, the code of an
/// import that cannot be read.
#[test]
fn a_binary_scenario_file_is_e150() {
    let dir = drill("binary", "fn reward(s) { 0.0 }\n");
    std::fs::write(dir.join("drill.tl"), [0x82_u8, 0xff, 0x00, 0x13, 0x9f]).unwrap();
    let check = touchline(&dir, &["check", "drill.tl"]);
    let run = touchline(&dir, &["run", "drill.tl"]);
    assert_eq!((check.status.code(), run.status.code()), (Some(1), Some(2)));
    for err in [text(&check.stderr), text(&run.stderr)] {
        assert!(err.contains("tl::E150") && err.contains("not UTF-8 text: byte 0 is 0x82"), "{err}");
        assert!(!err.contains("tl::E112"), "{err}");
    }
}

/// Issue 18: `check` runs a script's `reset` hook once, with the scenario's seed, so an error
/// raised there is reported with its code at check time (exit 1); a reset that runs is fine.
#[test]
fn check_runs_the_reset_hook_once() {
    let dir = drill("reset-throws", "fn reset(s) {\n    throw \"no goal here\";\n}\n\nfn reward(s) {\n    0.0\n}\n");
    let out = touchline(&dir, &["check", "drill.tl"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let err = text(&out.stderr);
    assert!(err.contains("tl::S005") && err.contains("no goal here") && err.contains("reset"), "{err}");
    assert!(err.contains("checked 1 file: 0 ok, 1 error, 0 warnings"), "{err}");
    snapshot("check_runs_the_reset_hook_once", &err);
    let dir = drill("reset-runs", "fn reset(s) {\n    memory.start = s.steps;\n}\n\nfn reward(s) {\n    0.0\n}\n");
    let out = touchline(&dir, &["check", "drill.tl"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("1 ok, 0 errors"), "{}", text(&out.stdout));
}
