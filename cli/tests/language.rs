//! The language commands as a user runs them: `check`, `compile`, `fmt`, `list`, `run FILE.tl`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn touchline(args: &[&str]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_touchline"));
    cmd.args(args).env("NO_COLOR", "1");
    for var in ["FORCE_COLOR", "CLICOLOR_FORCE", "FORCE_HYPERLINK", "COLUMNS"] {
        cmd.env_remove(var);
    }
    cmd.output().unwrap_or_else(|e| panic!("cannot run touchline: {e}"))
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// A fresh directory under the target dir for one test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const DRILL: &str = "/// A randomised drill.\nscenario drill {\n  extends academy_empty_goal_close\n  ball at (0.7, uniform(-0.1, 0.1))\n}\n";
const BROKEN: &str = "scenario drill {\n  extends academy\n  game_durration 400\n  team left { GK at (-1, 0) CBB at (0.5, 0) }\n  team right { GK at (-1, 0) }\n}\n";

fn stdlib_files() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../stdlib-scenarios");
    let mut files = Vec::new();
    for dir in [root.clone(), root.join("tests")] {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "tl") {
                files.push(path.display().to_string());
            }
        }
    }
    files
}

#[test]
fn check_passes_on_every_stdlib_file() {
    let files = stdlib_files();
    assert_eq!(files.len(), 36, "35 scenarios and the prelude");
    let args: Vec<&str> = std::iter::once("check").chain(files.iter().map(String::as_str)).collect();
    let out = touchline(&args);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("checked 36 files: 36 ok, 0 errors"), "{}", text(&out.stdout));
}

#[test]
fn check_reports_every_error_and_exits_1() {
    let dir = scratch("check_errors");
    let file = dir.join("broken.tl");
    std::fs::write(&file, BROKEN).unwrap();
    let out = touchline(&["check", file.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    for needle in
        ["tl::E101", "did you mean `game_duration`?", "tl::E102", "did you mean `CB`?", "1 file: 0 ok, 2 errors"]
    {
        assert!(err.contains(needle), "{needle} missing in\n{err}");
    }
}

#[test]
fn compile_writes_json_that_loads_back_and_keeps_distributions() {
    let dir = scratch("compile");
    let file = dir.join("drill.tl");
    std::fs::write(&file, DRILL).unwrap();
    let json = dir.join("drill.json");
    let out = touchline(&["compile", file.to_str().unwrap(), "-o", json.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let written = std::fs::read_to_string(&json).unwrap();
    assert!(written.contains("\"uniform\""), "the distribution is kept:\n{written}");
    let back = touchline_dsl::load(json.to_str().unwrap()).unwrap();
    assert_eq!(back, touchline_dsl::load(file.to_str().unwrap()).unwrap());
    // A failed compile leaves the earlier output untouched.
    std::fs::write(&file, BROKEN).unwrap();
    let out = touchline(&["compile", file.to_str().unwrap(), "-o", json.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&json).unwrap(), written);
}

/// Issue 18: `compile --tl` writes an odd-episode ball placed from a player back as `.tl`, and that
/// text compiles to the same scenario.
#[test]
fn compile_tl_writes_a_relative_odd_ball_back() {
    let dir = scratch("compile_tl_odd_ball");
    let file = dir.join("odd.tl");
    let tl = "scenario odd {\n  extends academy\n  ball at (0.1, 0)\n  on odd episodes ball at near(left.CF + (1 m, 0), 2 m)\n  team left { GK at (-1, 0) CF at (uniform(0.2, 0.6), 0) }\n  team right { GK at (-1, 0) }\n}\n";
    std::fs::write(&file, tl).unwrap();
    let back = dir.join("back.tl");
    let out = touchline(&["compile", file.to_str().unwrap(), "--tl", "-o", back.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let written = std::fs::read_to_string(&back).unwrap();
    assert!(written.contains("on odd episodes ball at near(left[1] + (1 m, 0 m), 2 m)"), "{written}");
    let again = touchline_dsl::load(back.to_str().unwrap()).unwrap();
    assert_eq!(again, touchline_dsl::load(file.to_str().unwrap()).unwrap());
    assert!(again.odd_episode_ball_random.is_some());
}

#[test]
fn fmt_rewrites_then_is_a_fixed_point() {
    let dir = scratch("fmt");
    let file = dir.join("messy.tl");
    std::fs::write(&file, "scenario  s{extends academy_empty_goal // keep me\n ball at(0.1,0)}\n").unwrap();
    let path = file.to_str().unwrap();
    assert_eq!(touchline(&["fmt", "--check", path]).status.code(), Some(1));
    assert_eq!(touchline(&["fmt", path]).status.code(), Some(0));
    let formatted = std::fs::read_to_string(&file).unwrap();
    assert_eq!(formatted, "scenario s {\n  extends academy_empty_goal // keep me\n  ball at (0.1, 0)\n}\n");
    assert_eq!(touchline(&["fmt", "--check", path]).status.code(), Some(0));
    // A syntax error is reported and the file left as it was.
    std::fs::write(&file, "scenario s { ball at (0.1, }").unwrap();
    let out = touchline(&["fmt", path]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("tl::E100"), "{}", text(&out.stderr));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "scenario s { ball at (0.1, }");
}

#[test]
fn list_shows_descriptions() {
    let out = touchline(&["list"]);
    assert_eq!(out.status.code(), Some(0));
    let listing = text(&out.stdout);
    assert!(listing.contains("academy_empty_goal_close") && listing.contains("must score into an empty goal"));
    assert!(!listing.contains("tests/"));
    assert!(text(&touchline(&["list", "--tests"]).stdout).contains("tests/offside_test"));
}

#[test]
fn run_plays_a_tl_file() {
    let dir = scratch("run_tl");
    let file = dir.join("drill.tl");
    std::fs::write(&file, DRILL).unwrap();
    let out = touchline(&["run", file.to_str().unwrap(), "--episodes", "3", "--json"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(report["episodes"].as_array().map(Vec::len), Some(3));
}
