//! Script files a scenario names (issue 17, item 9): only regular `.rhai` files of at most
//! 256 KiB are read; another file's content never shows in a diagnostic, a FIFO never blocks and
//! a device is never read.

use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use touchline_dsl::script::{MAX_SCRIPT_BYTES, ScriptOptions, Scripts};
use touchline_engine::Scenario;
use touchline_engine::scenario::{RewardKind, RewardTerm};

fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("touchline-script-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Compiles a scenario whose reward script is `path` (relative to `dir`) on another thread, and
/// returns its rendered error; fails if it takes over 10 s (a blocked or endless read).
fn compile_error(path: &str, dir: &Path) -> String {
    let scenario = Scenario {
        rewards: vec![RewardTerm { reward: RewardKind::Script { path: path.into() }, weight: 1.0 }],
        ..Scenario::default()
    };
    let dir = dir.to_path_buf();
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let result = Scripts::compile(&scenario, &dir, ScriptOptions::default());
        let _ = tx.send(result.err().map(|e| touchline_dsl::render_plain(&e)));
    });
    match rx.recv_timeout(Duration::from_secs(10)) {
        Ok(Some(message)) => message,
        Ok(None) => panic!("{path}: compiled"),
        Err(_) => panic!("{path}: still reading after 10 s"),
    }
}

#[test]
fn another_files_content_is_never_shown() {
    let dir = folder("passwd");
    let up = "../".repeat(dir.components().count() + 2);
    let message = compile_error(&format!("{up}etc/passwd"), &dir);
    assert!(message.contains("tl::S001") && message.contains(".rhai"), "{message}");
    let passwd = std::fs::read_to_string("/etc/passwd").unwrap_or_default();
    for line in passwd.lines().filter(|l| l.len() > 8) {
        assert!(!message.contains(line), "the diagnostic shows /etc/passwd: {message}");
    }
    assert!(!message.contains("root:"), "{message}");
}

#[test]
fn a_fifo_does_not_block() {
    let dir = folder("fifo");
    let status = std::process::Command::new("mkfifo").arg(dir.join("pipe.rhai")).status().unwrap();
    assert!(status.success());
    let message = compile_error("pipe.rhai", &dir);
    assert!(message.contains("tl::S001") && message.contains("not a regular file"), "{message}");
}

#[test]
fn a_device_is_not_read() {
    let dir = folder("device");
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.rhai")).unwrap();
    let message = compile_error("zero.rhai", &dir);
    assert!(message.contains("tl::S001") && message.contains("not a regular file"), "{message}");
    let message = compile_error("/dev/zero", &dir);
    assert!(message.contains("tl::S001"), "{message}");
}

#[test]
fn a_script_over_the_size_cap_is_refused_and_one_under_it_compiles() {
    let dir = folder("size");
    let body = "fn reward(s) { 0 }\n";
    let pad = "// padding padding padding padding padding padding padding padding padding padding\n";
    let big = format!("{body}{}", pad.repeat(MAX_SCRIPT_BYTES as usize / pad.len() + 1));
    std::fs::write(dir.join("big.rhai"), &big).unwrap();
    let message = compile_error("big.rhai", &dir);
    assert!(message.contains("tl::S001") && message.contains("256 KiB"), "{message}");
    let small = format!("{body}{}", pad.repeat(100));
    std::fs::write(dir.join("small.rhai"), small).unwrap();
    let scenario = Scenario {
        rewards: vec![RewardTerm { reward: RewardKind::Script { path: "small.rhai".into() }, weight: 1.0 }],
        ..Scenario::default()
    };
    Scripts::compile(&scenario, &dir, ScriptOptions::default()).unwrap();
}

#[test]
fn binary_files_are_refused_without_echo() {
    let dir = folder("binary");
    std::fs::write(dir.join("bin.rhai"), [0xff_u8, 0xfe, 0x00, 0x41, 0x42]).unwrap();
    let message = compile_error("bin.rhai", &dir);
    assert!(message.contains("tl::S001") && message.contains("UTF-8"), "{message}");
}

/// Runs `f` on another thread; fails if it takes over 10 s (a blocked or endless read).
fn within_10_s<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(Duration::from_secs(10)).unwrap_or_else(|_| panic!("{what}: still reading after 10 s"))
}

/// A rendered diagnostic on one line (miette wraps long messages).
fn flat(message: &str) -> String {
    message.split_whitespace().filter(|w| *w != "│").collect::<Vec<_>>().join(" ")
}

/// The other files a scenario names are read the same careful way: a FIFO or a device as an
/// import, a `start from` state, a `.tl` or `.json` scenario is an error, at once.
#[test]
fn scenario_files_that_are_pipes_or_devices_are_errors() {
    let dir = folder("sources");
    let fifo = dir.join("pipe.tl");
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let json_fifo = dir.join("pipe.json");
    assert!(std::process::Command::new("mkfifo").arg(&json_fifo).status().unwrap().success());
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.state")).unwrap();
    let main = dir.join("main.tl");
    std::fs::write(
        &main,
        "import \"pipe.tl\"\nscenario s {\n  extends academy_empty_goal_close\n}\n\
         scenario t {\n  extends academy_empty_goal_close\n  start from \"zero.state\"\n}\n",
    )
    .unwrap();
    let message = within_10_s("an import that is a FIFO", move || {
        touchline_dsl::compile_file(&main).err().map(|d| d.render_plain()).unwrap_or_default()
    });
    assert!(flat(&message).contains("not a regular file"), "{message}");
    let message = within_10_s("a .tl that is a FIFO", move || {
        touchline_dsl::compile_file(&fifo).err().map(|d| d.render_plain()).unwrap_or_default()
    });
    assert!(flat(&message).contains("not a regular file"), "{message}");
    let message = within_10_s("a .json that is a FIFO", move || {
        touchline_dsl::load_file(&json_fifo).err().map(|e| touchline_dsl::render_plain(&e)).unwrap_or_default()
    });
    assert!(message.contains("tl::E002"), "{message}");
    let start = dir.join("start.tl");
    std::fs::write(&start, "scenario t {\n  extends academy_empty_goal_close\n  start from \"zero.state\"\n}\n")
        .unwrap();
    let message = within_10_s("start from /dev/zero", move || {
        touchline_dsl::compile_file(&start).err().map(|d| d.render_plain()).unwrap_or_default()
    });
    assert!(message.contains("tl::E121") && flat(&message).contains("not a regular file"), "{message}");
}
