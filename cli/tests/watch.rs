//! `touchline watch` (issue 17, item 10): an unchanged file reloads nothing, one edit reloads once,
//! a broken edit is reported once. Before, the first edit started reloads that never stopped
//! (3,120 in 90 s) and each failure was reported 10-40 times a second.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

const SCENARIO: &str = "scenario watched {\n  extends academy_empty_goal_close\n  reward script \"r.rhai\"\n}\n";

fn script(value: &str) -> String {
    format!("fn reward(s) {{ {value} }}\n")
}

/// `touchline watch` on `scenario`, its stderr collected as it comes.
struct Watching {
    child: Child,
    stderr: Arc<Mutex<String>>,
}

impl Watching {
    fn start(scenario: &Path) -> Watching {
        let mut child = Command::new(env!("CARGO_BIN_EXE_touchline"))
            .args(["watch", scenario.to_str().unwrap(), "--pause-ms", "20"])
            .env("NO_COLOR", "1")
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("touchline watch starts");
        let stderr = Arc::new(Mutex::new(String::new()));
        let mut pipe = child.stderr.take().unwrap();
        let sink = Arc::clone(&stderr);
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n) = pipe.read(&mut buf) {
                if n == 0 {
                    break;
                }
                sink.lock().unwrap().push_str(&String::from_utf8_lossy(&buf[..n]));
            }
        });
        Watching { child, stderr }
    }

    fn count(&self, what: &str) -> usize {
        self.stderr.lock().unwrap().matches(what).count()
    }

    fn wait_for(&self, what: &str, n: usize) {
        let start = Instant::now();
        while self.count(what) < n {
            assert!(start.elapsed() < Duration::from_secs(30), "no {what:?} in 30 s: {}", self.stderr.lock().unwrap());
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Watching {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn folder() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("touchline-cli-watch-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Reads `file` for `secs` seconds, as an editor looking at it would.
fn keep_reading(file: &Path, secs: u64) {
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(secs) {
        let _ = std::fs::read(file).unwrap();
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn watch_reloads_once_per_edit_and_reports_a_broken_file_once() {
    const RELOADED: &str = "reloaded: version";
    const FAILED: &str = "the last good version keeps playing";
    let dir = folder();
    let scenario = dir.join("watched.tl");
    std::fs::write(&scenario, SCENARIO).unwrap();
    let rhai = dir.join("r.rhai");
    std::fs::write(&rhai, script("1.0")).unwrap();
    let watching = Watching::start(&scenario);
    watching.wait_for("watching", 1);

    // Unchanged and read over and over: no reload.
    keep_reading(&rhai, 2);
    keep_reading(&scenario, 1);
    assert_eq!(watching.count(RELOADED), 0, "{}", watching.stderr.lock().unwrap());

    // One edit: one reload.
    std::fs::write(&rhai, script("2.0")).unwrap();
    watching.wait_for(RELOADED, 1);
    keep_reading(&rhai, 3);
    assert_eq!(watching.count(RELOADED), 1, "{}", watching.stderr.lock().unwrap());

    // A broken file: one message.
    std::fs::write(&rhai, "fn reward(s) { let = ; }\n").unwrap();
    watching.wait_for(FAILED, 1);
    keep_reading(&rhai, 3);
    assert_eq!(watching.count(FAILED), 1, "{}", watching.stderr.lock().unwrap());
    assert_eq!(watching.count("tl::S002"), 1, "{}", watching.stderr.lock().unwrap());
    assert_eq!(watching.count(RELOADED), 1);
}

/// Issue 17, item 2, in `touchline watch`: a script error on a line past column 65,535 is
/// reported like any other, where miette's renderer used to panic on the label.
#[test]
fn a_script_error_far_along_one_line_is_reported_not_a_panic() {
    const FAILED: &str = "the last good version keeps playing";
    // Its own folder: `folder()` clears the other test's, and `cargo test` runs both in one process.
    let dir = std::env::temp_dir().join(format!("touchline-cli-watch-long-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenario = dir.join("watched.tl");
    std::fs::write(&scenario, SCENARIO).unwrap();
    let rhai = dir.join("r.rhai");
    std::fs::write(&rhai, script("1.0")).unwrap();
    let watching = Watching::start(&scenario);
    watching.wait_for("watching", 1);
    // 70,000 spaces, then a syntax error, all on one line.
    std::fs::write(&rhai, format!("fn reward(s) {{{} let = ; }}\n", " ".repeat(70_000))).unwrap();
    watching.wait_for(FAILED, 1);
    let stderr = watching.stderr.lock().unwrap().clone();
    assert!(stderr.contains("tl::S002"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}
