//! Hot reload (issue 5): a watched scenario follows edits of its script between episodes; a broken
//! edit is reported and never reaches a step; a save by rename is seen.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use touchline_dsl::script::ScriptOptions;
use touchline_dsl::watch::WatchEvent;
use touchline_dsl::{Watched, load};
use touchline_engine::scenario::{RewardKind, RewardTerm};
use touchline_engine::{Action, EnvConfig};

fn folder(test: &str) -> PathBuf {
    // One folder per test: the tests run in parallel threads of one process, and a folder shared
    // between them was removed under a running test's watcher.
    let dir = std::env::temp_dir().join(format!("touchline-watch-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn script(value: &str) -> String {
    format!("fn reward(s) {{ {value} }}\n")
}

/// Waits until `f` holds (the watcher works on its own thread), for at most 20 s.
fn eventually(what: &str, mut f: impl FnMut() -> bool) {
    let start = Instant::now();
    while !f() {
        assert!(start.elapsed() < Duration::from_secs(20), "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn write_atomically(path: &Path, text: &str) {
    // What many editors do: write a temporary file, then rename it over the original.
    let tmp = path.with_extension("rhai.swp");
    std::fs::write(&tmp, text).unwrap();
    std::fs::rename(&tmp, path).unwrap();
}

#[test]
fn the_env_follows_edits_and_keeps_the_last_good_version() {
    let dir = folder("edits");
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.rewards = vec![RewardTerm { reward: RewardKind::Script { path: "r.rhai".into() }, weight: 1.0 }];
    let spec = dir.join("scenario.json");
    std::fs::write(&spec, serde_json::to_string(&scenario).unwrap()).unwrap();
    let file = dir.join("r.rhai");
    std::fs::write(&file, script("1.0")).unwrap();

    let watched = Watched::new(spec.to_str().unwrap(), ScriptOptions::default()).unwrap();
    let failures = Arc::new(Mutex::new(Vec::new()));
    let seen = Arc::clone(&failures);
    watched.on_event(move |event| {
        if let WatchEvent::Failed(error) = event {
            seen.lock().unwrap().push(touchline_dsl::render_plain(*error));
        }
    });
    let mut env = watched.env(EnvConfig::default(), 0).unwrap();
    let reward = |env: &mut touchline_engine::Env| {
        env.step(&[Action::Idle]).unwrap();
        env.rewards()[0]
    };
    assert_eq!(reward(&mut env), 1.0);

    // An edit applies from the next reset, not in the middle of the episode.
    std::fs::write(&file, script("2.0")).unwrap();
    eventually("the edit to compile", || watched.generation() == 2);
    assert_eq!(reward(&mut env), 1.0, "the running episode keeps its version");
    env.reset().unwrap();
    assert_eq!(reward(&mut env), 2.0);

    // A broken edit is reported and the last good version keeps playing.
    std::fs::write(&file, "fn reward(s) { let = ; }").unwrap();
    eventually("the broken edit to be reported", || !failures.lock().unwrap().is_empty());
    assert!(failures.lock().unwrap()[0].contains("tl::S002"));
    env.reset().unwrap();
    assert_eq!(reward(&mut env), 2.0);
    assert_eq!(watched.generation(), 2);

    // Fixed by a save-by-rename (delete + re-create at the same path).
    write_atomically(&file, &script("3.0"));
    eventually("the fix to compile", || watched.generation() == 3);
    env.reset().unwrap();
    assert_eq!(reward(&mut env), 3.0);

    // The scenario file itself is watched too: a new weight.
    scenario.rewards[0].weight = 10.0;
    std::fs::write(&spec, serde_json::to_string(&scenario).unwrap()).unwrap();
    eventually("the scenario edit to compile", || watched.generation() == 4);
    env.reset().unwrap();
    assert_eq!(reward(&mut env), 30.0);
}

/// Counts what a watcher reports.
#[derive(Default)]
struct Reports {
    reloads: Vec<u64>,
    failures: Vec<String>,
}

fn watched_script(dir: &Path, text: &str) -> (Watched, PathBuf, Arc<Mutex<Reports>>) {
    let mut scenario = load("academy_empty_goal_close").unwrap();
    scenario.rewards = vec![RewardTerm { reward: RewardKind::Script { path: "r.rhai".into() }, weight: 1.0 }];
    let spec = dir.join("scenario.json");
    std::fs::write(&spec, serde_json::to_string(&scenario).unwrap()).unwrap();
    let file = dir.join("r.rhai");
    std::fs::write(&file, text).unwrap();
    let watched = Watched::new(spec.to_str().unwrap(), ScriptOptions::default()).unwrap();
    let reports = Arc::new(Mutex::new(Reports::default()));
    let seen = Arc::clone(&reports);
    watched.on_event(move |event| match event {
        WatchEvent::Reloaded { generation } => seen.lock().unwrap().reloads.push(*generation),
        WatchEvent::Failed(error) => seen.lock().unwrap().failures.push(touchline_dsl::render_plain(*error)),
        _ => {}
    });
    (watched, file, reports)
}

/// Reads the file (and the compile's own reads) for `secs`, as an editor or `cat` would.
fn keep_reading(file: &Path, secs: u64) {
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(secs) {
        let _ = std::fs::read_to_string(file).unwrap();
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Issue 17, item 10: before, the first edit started reloads that never stopped (3,120 in 90 s:
/// each compile's reads of the file were taken as changes), and a broken file was reported 10-40
/// times a second. Only content changes count now: reading, `touch`ing or saving the same text
/// reloads nothing, one edit is one reload, a broken edit is one report.
#[test]
fn only_content_changes_reload_and_each_failure_is_reported_once() {
    let dir = folder("once");
    std::fs::create_dir_all(&dir).unwrap();
    let (watched, file, reports) = watched_script(&dir, &script("1.0"));

    // Unchanged, read over and over, saved with the same text: nothing.
    keep_reading(&file, 2);
    std::fs::write(&file, script("1.0")).unwrap();
    keep_reading(&file, 2);
    assert_eq!(watched.generation(), 1);
    assert!(reports.lock().unwrap().reloads.is_empty(), "reloads: {:?}", reports.lock().unwrap().reloads);

    // One edit: one reload, and no more while the file is read.
    std::fs::write(&file, script("2.0")).unwrap();
    eventually("the edit to compile", || watched.generation() == 2);
    keep_reading(&file, 3);
    assert_eq!(reports.lock().unwrap().reloads, [2]);

    // A broken edit: one report, however often the file is read or saved unchanged.
    std::fs::write(&file, "fn reward(s) { let = ; }").unwrap();
    eventually("the broken edit to be reported", || !reports.lock().unwrap().failures.is_empty());
    keep_reading(&file, 2);
    std::fs::write(&file, "fn reward(s) { let = ; }").unwrap();
    keep_reading(&file, 2);
    let failures = reports.lock().unwrap().failures.len();
    assert_eq!(failures, 1, "{:?}", reports.lock().unwrap().failures);

    // Fixed: one reload again.
    std::fs::write(&file, script("3.0")).unwrap();
    eventually("the fix to compile", || watched.generation() == 3);
    keep_reading(&file, 1);
    assert_eq!(reports.lock().unwrap().reloads, [2, 3]);
    assert_eq!(reports.lock().unwrap().failures.len(), 1);
}

/// Issue 18, item 4: `env_playing` tells the version an env plays: the newest compiled only from
/// the env's next reset, and not a version the env refused (another number of controllable
/// players than its agents need).
#[test]
fn the_version_played_follows_resets_and_refusals() {
    let dir = std::env::temp_dir().join(format!("touchline-watch-playing-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let spec = dir.join("drill.tl");
    let drill = |ball: &str, right: &str| {
        format!(
            "scenario drill {{\n  extends academy_empty_goal_close\n  ball at ({ball})\n  team left {{\n    GK at (-1, 0)\n    CB at (0.5, 0)\n  }}\n  team right {{\n    GK at (-1, 0){right}\n  }}\n}}\n"
        )
    };
    std::fs::write(&spec, drill("0.5, 0", "")).unwrap();
    let watched = Watched::new(spec.to_str().unwrap(), ScriptOptions::default()).unwrap();
    // Two agents: the left CB and the right GK.
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let (mut env, playing) = watched.env_playing(config, 0).unwrap();
    assert_eq!(playing.generation(), 1);

    std::fs::write(&spec, drill("-0.2, 0", "")).unwrap();
    eventually("the edit to compile", || watched.generation() == 2);
    assert_eq!(playing.generation(), 1, "the episode under way keeps its version");
    env.reset().unwrap();
    assert_eq!(playing.generation(), 2);
    assert!((env.observations()[0].ball[0] + 0.2).abs() < 1e-3);

    // The right GK made not controllable: the right agent has no one to drive, the env refuses it.
    std::fs::write(&spec, drill("0.3, 0", " not controllable")).unwrap();
    eventually("the edit to compile", || watched.generation() == 3);
    let _ = env.reset();
    assert_eq!(playing.generation(), 2, "a refused version is not played");
}
