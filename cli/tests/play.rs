//! `touchline play` end to end in headless Chromium (issue 19): the test starts the server, opens
//! its page, presses real keys (Chrome DevTools Protocol `Input.dispatchKeyEvent`, the path a
//! keyboard's events take) and reads what the page shows (`window.playState`, the state it drew).
//! It checks that the player moves, that a pass is played, and that a scripted key sequence scores
//! in academy_empty_goal_close and is recorded as a replay that re-simulates.
//!
//! The DevTools Protocol runs over `--remote-debugging-pipe` (file descriptors 3 and 4 of the
//! browser, given to it by `bash`), so the test needs no WebSocket client.
//!
//! Needs a Chromium, found as cli/tests/viewer.rs finds it; in CI (`CI` set) a missing browser
//! fails the test instead of skipping it.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("TOUCHLINE_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .flat_map(|dir| ["chromium", "chromium-browser", "google-chrome"].map(|name| dir.join(name)))
        .find(|candidate| candidate.is_file())
}

/// The browser, or `None` to skip (outside CI only).
fn browser_or_skip() -> Option<PathBuf> {
    let found = chromium();
    if found.is_none() {
        assert!(std::env::var_os("CI").is_none(), "CI must have Chromium for the play test (.ci/run installs it)");
        eprintln!("SKIPPED: no chromium on the PATH (set TOUCHLINE_CHROMIUM or install chromium)");
    }
    found
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("touchline-play-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

/// A running `touchline play`, stopped when dropped.
struct Server {
    child: Child,
    url: String,
    /// The rest of its stdout.
    lines: BufReader<std::process::ChildStdout>,
}

impl Server {
    fn start(scenario: &str, record: &Path) -> Server {
        Server::start_with(scenario, record, &[])
    }

    fn start_with(scenario: &str, record: &Path, extra: &[&str]) -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_touchline"))
            .args(["play", scenario, "--port", "0", "--record", record.to_str().expect("utf-8")])
            .args(extra)
            .stdout(Stdio::piped())
            .spawn()
            .expect("start touchline play");
        let mut line = String::new();
        let mut lines = BufReader::new(child.stdout.take().expect("stdout"));
        lines.read_line(&mut line).expect("server line");
        let url = line.split_whitespace().find(|w| w.starts_with("http://")).expect("the address").to_string();
        Server { child, url, lines }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Headless Chromium driven over the DevTools Protocol; one page.
struct Browser {
    child: Child,
    commands: ChildStdin,
    replies: Receiver<Value>,
    next_id: u64,
    session: Option<String>,
}

impl Browser {
    fn launch(browser: &Path, profile: &Path) -> Browser {
        // bash hands the browser our pipes as its fds 3 (commands in) and 4 (replies out).
        let mut child = Command::new("bash")
            .arg("-c")
            .arg(r#"exec "$0" "$@" 3<&0 4>&1 0</dev/null 1>/dev/null"#)
            .arg(browser)
            .args(["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--window-size=1400,800"])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg("--remote-debugging-pipe")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|e| panic!("cannot run {}: {e}", browser.display()));
        let commands = child.stdin.take().expect("stdin");
        let mut out = child.stdout.take().expect("stdout");
        let (send, replies) = channel();
        // Messages are JSON texts, each ended by a NUL byte.
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            let mut chunk = [0u8; 65536];
            while let Ok(n) = out.read(&mut chunk) {
                if n == 0 {
                    break;
                }
                buf.extend_from_slice(&chunk[..n]);
                while let Some(end) = buf.iter().position(|&b| b == 0) {
                    let message: Vec<u8> = buf.drain(..=end).collect();
                    if let Ok(v) = serde_json::from_slice::<Value>(&message[..end])
                        && send.send(v).is_err()
                    {
                        return;
                    }
                }
            }
        });
        Browser { child, commands, replies, next_id: 0, session: None }
    }

    /// Sends a command (to the page once one is open) and waits for its result.
    fn call(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let mut message = json!({ "id": id, "method": method, "params": params });
        if let Some(s) = &self.session {
            message["sessionId"] = json!(s);
        }
        let mut bytes = serde_json::to_vec(&message).expect("json");
        bytes.push(0);
        self.commands.write_all(&bytes).expect("write to the browser");
        self.commands.flush().expect("flush");
        let deadline = Instant::now() + Duration::from_secs(30);
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            let reply = self.replies.recv_timeout(left).unwrap_or_else(|_| panic!("no reply to {method}"));
            if reply["id"] == json!(id) {
                assert!(reply.get("error").is_none(), "{method}: {reply}");
                return reply["result"].clone();
            }
        }
    }

    fn open(&mut self, url: &str) {
        let target = self.call("Target.createTarget", json!({ "url": url }));
        let attached = self.call("Target.attachToTarget", json!({ "targetId": target["targetId"], "flatten": true }));
        self.session = Some(attached["sessionId"].as_str().expect("session").to_string());
        // The page believes it has the focus, as a window a person types into.
        self.call("Emulation.setFocusEmulationEnabled", json!({ "enabled": true }));
    }

    fn eval(&mut self, expression: &str) -> Value {
        let r = self.call("Runtime.evaluate", json!({ "expression": expression, "returnByValue": true }));
        r["result"]["value"].clone()
    }

    /// The state the page last drew (`null` before the first).
    fn state(&mut self) -> Value {
        self.eval("window.playState")
    }

    /// Waits until the page's state satisfies `ready`; returns it.
    fn wait_for(&mut self, what: &str, ready: impl Fn(&Value) -> bool) -> Value {
        let deadline = Instant::now() + Duration::from_secs(20);
        loop {
            let s = self.state();
            if ready(&s) {
                return s;
            }
            assert!(Instant::now() < deadline, "timed out waiting for {what}; the page shows {s}");
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// A key going down or up: `code` as `KeyboardEvent.code`, `key` as `.key`, `vk` its Windows
    /// virtual key code.
    fn key(&mut self, (code, key, vk): (&str, &str, u32), down: bool) {
        let kind = if down { "rawKeyDown" } else { "keyUp" };
        self.call(
            "Input.dispatchKeyEvent",
            json!({ "type": kind, "code": code, "key": key, "windowsVirtualKeyCode": vk, "nativeVirtualKeyCode": vk }),
        );
    }

    /// Presses a key for `ms` milliseconds.
    fn tap(&mut self, key: (&str, &str, u32), ms: u64) {
        self.key(key, true);
        std::thread::sleep(Duration::from_millis(ms));
        self.key(key, false);
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

const RIGHT: (&str, &str, u32) = ("ArrowRight", "ArrowRight", 39);
const D: (&str, &str, u32) = ("KeyD", "d", 68);
const SHORT_PASS: (&str, &str, u32) = ("KeyJ", "j", 74);
const SHOT: (&str, &str, u32) = ("KeyL", "l", 76);

/// Decodes standard base64 (the screenshot's encoding).
fn base64(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        _ => 63,
    };
    let digits: Vec<u8> = text.bytes().filter(|&c| c != b'=').map(value).collect();
    let mut out = Vec::with_capacity(digits.len() * 3 / 4);
    for chunk in digits.chunks(4) {
        let n = chunk.iter().enumerate().fold(0u32, |n, (i, &d)| n | u32::from(d) << (18 - 6 * i));
        out.extend_from_slice(&n.to_be_bytes()[1..chunk.len()]);
    }
    out
}

/// `[x, y]` of roster player `i` in a state.
fn position(s: &Value, i: usize) -> (f64, f64) {
    let p = &s["players"][i];
    (p[0].as_f64().expect("x"), p[1].as_f64().expect("y"))
}

fn controlled(s: &Value) -> usize {
    s["controlled"][0].as_u64().expect("a controlled player") as usize
}

#[test]
fn keys_move_the_player_and_play_a_pass() {
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("pass");
    let server = Server::start("academy_3_vs_1_with_keeper", &dir.join("replays"));
    let mut page = Browser::launch(&browser, &dir.join("profile"));
    page.open(&server.url);
    let start = page.wait_for("the kick-off", |s| s["phase"] == "kick_off");
    // The key map is on the page.
    let keymap = page.eval("document.getElementById('keymap').textContent").as_str().unwrap_or("").to_string();
    for what in ["short pass", "long pass", "high pass", "shot", "sprint", "dribble", "sliding", "AI", "pause"] {
        assert!(keymap.contains(what), "the key map names {what}: {keymap}");
    }

    // D (WASD's right) held until the player has the ball (it lies a metre to his right): he runs to it, the match
    // under way.
    let player = controlled(&start);
    let (x0, y0) = position(&start, player);
    page.key(D, true);
    let on_ball = page.wait_for("the player on the ball", |s| {
        s["step"].as_u64().unwrap_or(0) >= 3 && s["owner"].as_i64() == Some(player as i64)
    });
    page.key(D, false);
    assert_eq!(on_ball["phase"], "playing");
    let (x1, y1) = position(&on_ball, player);
    assert!(x1 - x0 > 0.2 && (y1 - y0).abs() < 0.2, "moved from ({x0}, {y0}) to ({x1}, {y1})");

    // J: a short pass, by the person's player.
    page.tap(SHORT_PASS, 60);
    let passed = page.wait_for("a pass", |s| s["passes"].as_u64().unwrap_or(0) >= 1);
    let events = passed["events"].to_string();
    assert!(events.contains(&format!("pass by left #{}", player + 1)), "{events}");

    // `TOUCHLINE_PLAY_SCREENSHOT=docs/play.png` keeps a picture of the page (README's).
    if let Some(path) = std::env::var_os("TOUCHLINE_PLAY_SCREENSHOT") {
        page.call(
            "Emulation.setDeviceMetricsOverride",
            json!({ "width": 1440, "height": 760, "deviceScaleFactor": 1, "mobile": false }),
        );
        let shot = page.call("Page.captureScreenshot", json!({ "format": "png" }));
        let png = base64(shot["data"].as_str().expect("data"));
        std::fs::write(path, png).expect("write the screenshot");
    }
    drop(page);
    drop(server);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_scripted_key_sequence_scores_in_academy_empty_goal_close_and_is_recorded() {
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("goal");
    let replays = dir.join("replays");
    let server = Server::start("academy_empty_goal_close", &replays);
    let mut page = Browser::launch(&browser, &dir.join("profile"));
    page.open(&server.url);
    let start = page.wait_for("the kick-off", |s| s["phase"] == "kick_off");
    let player = controlled(&start);
    let (x0, _) = position(&start, player);

    // Run right for six steps, then hold the shot for two more while still running. The keys
    // follow the steps the page shows, not a wall clock, so a loaded machine plays the same script
    // (the unit test `running_right_and_shooting_scores_…` shows it scores for 3-11 steps of
    // running and a shot held 1-4 steps).
    page.key(RIGHT, true);
    let running = page.wait_for("six steps", |s| s["step"].as_u64().unwrap_or(0) >= 6);
    let pressed_at = running["step"].as_u64().unwrap_or(0);
    page.key(SHOT, true);
    page.wait_for("two steps of the shot", |s| s["step"].as_u64().unwrap_or(0) >= pressed_at + 2);
    page.key(SHOT, false);
    page.key(RIGHT, false);
    let (x1, _) = position(&running, player);
    assert!(x1 - x0 > 1.0, "ran from x = {x0} to {x1}");

    let end = page.wait_for("full time", |s| s["phase"] == "full_time");
    assert_eq!(end["score"], json!([1, 0]), "{end}");
    assert!(end["shots"].as_u64().unwrap_or(0) >= 1, "{end}");
    let saved = PathBuf::from(end["saved"].as_str().expect("the match was recorded"));
    assert!(saved.starts_with(&replays) && saved.is_file(), "{}", saved.display());
    drop(page);
    drop(server);

    // The replay re-simulates (the viewer refuses one that does not) and shows the goal.
    let html = dir.join("view.html");
    let out = Command::new(env!("CARGO_BIN_EXE_touchline"))
        .args(["view", saved.to_str().expect("utf-8"), "--html", html.to_str().expect("utf-8")])
        .output()
        .expect("touchline view");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 19: two people, one per team, on one keyboard (W A S D and the arrows) and in two tabs
/// (`?player=1` gives the second the whole key map).
#[test]
fn two_people_play_on_one_keyboard_and_in_two_tabs() {
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("two");
    let server = Server::start_with("academy_3_vs_1_with_keeper", &dir.join("replays"), &["--players", "2"]);
    let mut page = Browser::launch(&browser, &dir.join("profile"));
    page.open(&server.url);
    let start = page.wait_for("the kick-off", |s| s["phase"] == "kick_off");
    let (left, right) = (controlled(&start), start["controlled"][1].as_u64().expect("two people") as usize);
    let keymap = page.eval("document.getElementById('keymap').textContent").as_str().unwrap_or("").to_string();
    assert!(keymap.contains("left (red)") && keymap.contains("right (blue)"), "{keymap}");

    // W for the left person, ↓ for the right one, together (for ten steps: the left player, a
    // metre from the loose ball, first steps towards it).
    const W: (&str, &str, u32) = ("KeyW", "w", 87);
    const DOWN: (&str, &str, u32) = ("ArrowDown", "ArrowDown", 40);
    page.key(W, true);
    page.key(DOWN, true);
    let moved = page.wait_for("ten steps", |s| s["step"].as_u64().unwrap_or(0) >= 10);
    page.key(W, false);
    page.key(DOWN, false);
    let (l0, r0) = (position(&start, left), position(&start, right));
    let (l1, r1) = (position(&moved, left), position(&moved, right));
    assert!(l1.1 < l0.1 - 0.5, "the left player ran up: {l0:?} -> {l1:?}");
    assert!(r1.1 > r0.1 + 0.5, "the right player ran down: {r0:?} -> {r1:?}");

    // A second tab for the right person: S (down in the whole key map) moves the right player.
    // Judged over ten steps of open play in one episode: a set piece (his player standing at the
    // ball to take it) or a new episode in between says nothing about the keys, so the ten steps
    // are tried again, up to three times.
    let mut tab = Browser::launch(&browser, &dir.join("profile-2"));
    tab.open(&format!("{}?player=1", server.url));
    const S: (&str, &str, u32) = ("KeyS", "s", 83);
    let mut judged = None;
    for _ in 0..3 {
        let before = tab.wait_for("open play", |s| s["step"].as_u64().unwrap_or(0) >= 5 && s["mode"] == "Normal");
        let right = before["controlled"][1].as_u64().expect("two people") as usize;
        tab.key(S, true);
        let step = before["step"].as_u64().unwrap_or(0);
        let after = tab.wait_for("ten more steps", |s| {
            s["step"].as_u64().unwrap_or(0) >= step + 10 || s["episode"] != before["episode"]
        });
        tab.key(S, false);
        if after["episode"] == before["episode"] && after["mode"] == "Normal" {
            judged = Some((position(&before, right), position(&after, right)));
            break;
        }
    }
    let (b, a) = judged.expect("ten steps of open play in three tries");
    assert!(a.1 > b.1 + 0.5, "the right player ran down: {b:?} -> {a:?}");
    drop((page, tab, server));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 19: a program plays the opponent over the local socket (as examples/python/play_policy.py
/// does with a saved SB3 policy): it gets the right player's `simple115v2` observation after every
/// step and its answer, `bottom` in that player's own frame, runs him up the screen.
#[test]
fn a_policy_on_the_socket_plays_the_opponent() {
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("policy");
    let mut server = Server::start_with("academy_3_vs_1_with_keeper", &dir.join("replays"), &["--opponent-port", "0"]);
    let mut line = String::new();
    server.lines.read_line(&mut line).expect("the opponent's line");
    let address = line.split_whitespace().find(|w| w.starts_with("127.0.0.1:")).expect("the port").to_string();
    let stream = std::net::TcpStream::connect(&address).expect("connect");
    let mut answers = stream.try_clone().expect("clone");
    let observed = std::thread::spawn(move || {
        let mut sizes = Vec::new();
        for line in BufReader::new(stream).lines() {
            let Ok(line) = line else { break };
            let message: Value = serde_json::from_str(&line).expect("json");
            sizes.push(message["observation"].as_array().map_or(0, Vec::len));
            assert_eq!(message["side"], "right");
            let reply = json!({ "turn": message["turn"], "action": 7 }).to_string() + "\n";
            if answers.write_all(reply.as_bytes()).is_err() || sizes.len() >= 12 {
                break;
            }
        }
        sizes
    });
    let mut page = Browser::launch(&browser, &dir.join("profile"));
    page.open(&server.url);
    let start = page.wait_for("the policy", |s| s["policy_connected"] == json!(true));
    assert_eq!(start["controllers"].as_array().map(Vec::len), Some(1), "one person");
    // The policy's player: the second controlled one (env controllers are left team first).
    let right = start["controlled"][1].as_u64().expect("the policy's player") as usize;
    assert_eq!(start["roster"][right][0], 1, "on the right team");
    page.tap(D, 100);
    let later = page.wait_for("ten steps", |s| s["step"].as_u64().unwrap_or(0) >= 10);
    let (b, a) = (position(&start, right), position(&later, right));
    assert!(a.1 < b.1 - 0.5, "the policy ran its player up the screen: {b:?} -> {a:?}");
    let sizes = observed.join().expect("the policy thread");
    assert!(sizes.len() >= 10 && sizes.iter().all(|&n| n == 115), "{sizes:?}");
    drop((page, server));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_arguments_fail_with_a_clear_error_and_no_panic() {
    let dir = scratch("bad");
    // Each run must end by itself: a server that started by mistake is killed and fails the test.
    let touchline = |args: &[&str]| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_touchline"))
            .args(args)
            .env("NO_COLOR", "1")
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("run");
        let deadline = Instant::now() + Duration::from_secs(30);
        while child.try_wait().expect("wait").is_none() {
            if Instant::now() > deadline {
                let _ = child.kill();
                panic!("touchline {args:?} did not stop");
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let out = child.wait_with_output().expect("output");
        (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
    };
    let (code, err) = touchline(&["play", "no_such_scenario", "--port", "0"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    let (code, err) = touchline(&["play", "academy_empty_goal_close", "--theta", "1.5"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("outside [0, 1]"), "{err}");
    let (code, err) = touchline(&["play", "academy_empty_goal_close", "--side", "middle"]);
    assert_eq!(code, Some(2), "{err}");
    let (code, err) = touchline(&["play", "academy_empty_goal_close", "--players", "3"]);
    assert_eq!(code, Some(2), "{err}");
    let broken = dir.join("broken.tl");
    std::fs::write(&broken, "scenario broken { ball at (").expect("write");
    let (code, err) = touchline(&["play", broken.to_str().expect("utf-8"), "--port", "0"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    // A port that is taken.
    let taken = std::net::TcpListener::bind("127.0.0.1:0").expect("bind");
    let port = taken.local_addr().expect("addr").port().to_string();
    let (code, err) = touchline(&["play", "academy_empty_goal_close", "--port", &port]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("cannot serve the page"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
