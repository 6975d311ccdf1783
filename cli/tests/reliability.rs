//! Input that used to abort the `touchline` process (issue 17): deep nesting (item 1, SIGABRT) and
//! a label past column 65,535 (item 2, exit 101). Each is now a diagnostic and the command's
//! status for bad input: 1 for `check`, 2 for a scenario `run` cannot load.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn touchline(args: &[&str]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_touchline"));
    cmd.args(args).env("NO_COLOR", "1");
    for var in ["FORCE_COLOR", "CLICOLOR_FORCE", "FORCE_HYPERLINK", "COLUMNS"] {
        cmd.env_remove(var);
    }
    cmd.output().expect("the touchline binary runs")
}

fn scratch(name: &str, text: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("reliability");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn assert_diagnostic(output: &Output, code: &str, status: i32) {
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(status), "stderr: {stderr}");
    assert!(stderr.contains(code), "stderr: {stderr}");
    assert!(!stderr.contains("panicked"), "stderr: {stderr}");
}

#[test]
fn deep_nesting_is_a_diagnostic_not_an_abort() {
    let cond = format!("{}steps >= 5{}", "(".repeat(1000), ")".repeat(1000));
    let path =
        scratch("deep.tl", &format!("scenario deep {{\n  extends academy_empty_goal_close\n  end when {cond}\n}}\n"));
    let path = path.to_str().unwrap();
    assert_diagnostic(&touchline(&["check", path]), "tl::E148", 1);
    let nots = "not ".repeat(10_000);
    let path = scratch(
        "nots.tl",
        &format!("scenario deep {{\n  extends academy_empty_goal_close\n  end when {nots} steps >= 5\n}}\n"),
    );
    assert_diagnostic(&touchline(&["run", path.to_str().unwrap(), "--episodes", "1"]), "tl::E148", 2);
}

#[test]
fn labels_past_column_65535_render() {
    let text = format!("scenario s {{ extends academy_empty_goal_close {} game_duraton 400 }}\n", " ".repeat(100_000));
    let path = scratch("long.tl", &text);
    let output = touchline(&["check", path.to_str().unwrap()]);
    assert_diagnostic(&output, "tl::E101", 1);
    assert!(output.stderr.len() < 4_000, "{} bytes of stderr", output.stderr.len());
    let json = format!("{{\"description\": \"{}\", \"game_duration\": \"long\"}}", "d".repeat(70_000));
    let path = scratch("long.json", &json);
    assert_diagnostic(&touchline(&["run", path.to_str().unwrap(), "--episodes", "1"]), "tl::E003", 2);
}
