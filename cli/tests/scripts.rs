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
