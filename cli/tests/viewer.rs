//! The replay viewer end to end in headless Chromium: the page written by `touchline view --html`
//! and the one served by `touchline view DIR` load a replay, show the requested step with the
//! controlled player's observation, play to the end, and draw the match (screenshot checked).
//!
//! Needs a Chromium (`chromium`, `chromium-browser` or `google-chrome` on the PATH, or
//! `TOUCHLINE_CHROMIUM`). `.ci/run` installs Debian's `chromium`; in CI (`CI` set) a missing
//! browser fails the test instead of skipping it.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use touchline_engine::{Action, Env, Scenario};

fn chromium() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("TOUCHLINE_CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    for dir in std::env::split_paths(&path) {
        for name in ["chromium", "chromium-browser", "google-chrome"] {
            let candidate = dir.join(name);
            if candidate.is_file() {
                return Some(candidate);
            }
        }
    }
    None
}

/// The browser, or `None` to skip (outside CI only).
fn browser_or_skip() -> Option<PathBuf> {
    let found = chromium();
    if found.is_none() {
        assert!(std::env::var_os("CI").is_none(), "CI must have Chromium for the viewer test (.ci/run installs it)");
        eprintln!("SKIPPED: no chromium on the PATH (set TOUCHLINE_CHROMIUM or install chromium)");
    }
    found
}

fn touchline(args: &[&str]) -> std::process::Output {
    let out = Command::new(env!("CARGO_BIN_EXE_touchline"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .unwrap_or_else(|e| panic!("cannot run touchline: {e}"));
    assert!(out.status.success(), "touchline {args:?}: {}", String::from_utf8_lossy(&out.stderr));
    out
}

/// Runs headless Chromium on `url` with `extra` arguments; returns stdout.
fn headless(browser: &Path, profile: &Path, extra: &[&str], url: &str) -> String {
    let out = Command::new(browser)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run"])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(["--window-size=1400,800", "--virtual-time-budget=5000"])
        .args(extra)
        .arg(url)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {}: {e}", browser.display()));
    assert!(out.status.success(), "chromium failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The text of the element with `id` in a dumped DOM.
fn text_of(dom: &str, id: &str) -> String {
    let open = format!("id=\"{id}\"");
    let at = dom.find(&open).unwrap_or_else(|| panic!("no #{id} in the page:\n{dom}")) + open.len();
    let start = at + dom[at..].find('>').unwrap_or(0) + 1;
    dom[start..].split('<').next().unwrap_or("").to_string()
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("touchline-viewer-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

const SCENARIO: &str = "academy_counterattack_easy";
const NAME: &str = "academy_counterattack_easy_seed0_ep0";

/// Records one episode of the scenario with the built-in policy into `dir`; returns its length
/// and the controlled player's raw observation after step 30 (computed here with the engine).
fn record(dir: &Path) -> (u32, touchline_engine::RawObservation) {
    touchline(&["run", SCENARIO, "--record", dir.to_str().expect("utf-8")]);
    let path = format!("{}/../stdlib-scenarios/{SCENARIO}.json", env!("CARGO_MANIFEST_DIR"));
    let scenario: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
    let config = touchline_engine::EnvConfig { action_set: touchline_engine::ActionSet::V2, ..Default::default() };
    let mut env = Env::with_config(scenario, config, 0).expect("env");
    let mut at_30 = None;
    loop {
        let out = env.step(&[Action::BuiltinAi]).expect("step");
        if env.info().steps == 30 {
            at_30 = Some(env.observations()[0].clone());
        }
        if out.terminated || out.truncated {
            break;
        }
    }
    (env.info().steps, at_30.expect("the episode lasts 30 steps"))
}

#[test]
fn viewer_page_from_file_shows_steps_plays_and_draws() {
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("file");
    let (steps, obs) = record(&dir);
    let page = dir.join("viewer.html");
    touchline(&["view", dir.to_str().expect("utf-8"), "--html", page.to_str().expect("utf-8")]);
    let url = format!("file://{}", page.display());
    let profile = dir.join("profile");

    // Step 30, with the observation the engine gives.
    let dom = headless(&browser, &profile, &["--dump-dom"], &format!("{url}?replay={NAME}&frame=30"));
    assert_eq!(text_of(&dom, "step-label"), format!("step 30 / {steps}"));
    assert_eq!(text_of(&dom, "obs-active"), obs.active.to_string());
    assert_eq!(text_of(&dom, "obs-steps-left"), obs.steps_left.to_string());
    assert_eq!(text_of(&dom, "obs-game-mode"), obs.game_mode.name());
    assert_eq!(text_of(&dom, "obs-action-taken"), "BuiltinAi");

    // Play at 16× from the start: the whole episode plays and stops at its end.
    let dom = headless(&browser, &profile, &["--dump-dom"], &format!("{url}?replay={NAME}&frame=0&play=1&speed=16"));
    assert_eq!(text_of(&dom, "step-label"), format!("step {steps} / {steps}"));
    assert_eq!(text_of(&dom, "play"), "play");

    // The screenshot shows a pitch with both teams, the ring of the controlled player, the ball,
    // and the Super Mini Map.
    let shot = dir.join("shot.png");
    headless(
        &browser,
        &profile,
        &[&format!("--screenshot={}", shot.display())],
        &format!("{url}?replay={NAME}&frame=30"),
    );
    let counts = colour_counts(&shot);
    let total = 1400 * 800;
    assert!(counts.grass > total / 5, "grass: {counts:?}");
    assert!(counts.red > 100 && counts.blue > 100, "both teams: {counts:?}");
    assert!(counts.yellow > 20, "controlled ring: {counts:?}");
    assert!(counts.white > 200, "lines and ball: {counts:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn viewer_served_by_touchline_view() {
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("served");
    let (steps, obs) = record(&dir);
    let mut server = Command::new(env!("CARGO_BIN_EXE_touchline"))
        .args(["view", dir.to_str().expect("utf-8"), "--port", "0"])
        .stdout(Stdio::piped())
        .spawn()
        .expect("start touchline view");
    let mut line = String::new();
    BufReader::new(server.stdout.take().expect("stdout")).read_line(&mut line).expect("server line");
    let url =
        line.split_whitespace().find(|w| w.starts_with("http://")).expect("the server prints its address").to_string();
    let dom = headless(&browser, &dir.join("profile"), &["--dump-dom"], &format!("{url}?replay={NAME}&frame=30"));
    let _ = server.kill();
    let _ = server.wait();
    assert_eq!(text_of(&dom, "step-label"), format!("step 30 / {steps}"));
    assert_eq!(text_of(&dom, "obs-active"), obs.active.to_string());
    let _ = std::fs::remove_dir_all(&dir);
}

#[derive(Debug, Default)]
struct Counts {
    grass: usize,
    red: usize,
    blue: usize,
    yellow: usize,
    white: usize,
}

/// Pixels of the screenshot near the page's colours.
fn colour_counts(path: &Path) -> Counts {
    let file = std::fs::File::open(path).expect("screenshot");
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file)).read_info().expect("png");
    let mut buf = vec![0; decoder.output_buffer_size().expect("size")];
    let info = decoder.next_frame(&mut buf).expect("frame");
    let step = info.color_type.samples();
    let mut c = Counts::default();
    let near = |p: &[u8], q: [u8; 3]| p.iter().zip(q).all(|(a, b)| a.abs_diff(b) <= 24);
    for p in buf[..info.buffer_size()].chunks_exact(step) {
        if near(p, [52, 128, 60]) || near(p, [60, 140, 68]) {
            c.grass += 1;
        } else if near(p, [214, 48, 40]) {
            c.red += 1;
        } else if near(p, [40, 96, 214]) {
            c.blue += 1;
        } else if near(p, [255, 230, 0]) {
            c.yellow += 1;
        } else if p[0] > 235 && p[1] > 235 && p[2] > 235 {
            c.white += 1;
        }
    }
    c
}

/// Issue 19: an agent's replay with per-step values (as Python's `record_values` attaches them):
/// the page lists each controlled player's action and reward and the values of the step shown,
/// and zooms to the drill.
#[test]
fn viewer_shows_each_steps_actions_rewards_and_recorded_values() {
    use touchline_render::replay::Recorder;
    let Some(browser) = browser_or_skip() else { return };
    let dir = scratch("values");
    let path = format!("{}/../stdlib-scenarios/academy_3_vs_1_with_keeper.json", env!("CARGO_MANIFEST_DIR"));
    let scenario: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("scenario")).expect("json");
    let config = touchline_engine::EnvConfig { left_agents: 2, ..Default::default() };
    let mut env = Env::with_config(scenario, config, 4).expect("env");
    let mut recorder = Recorder::start(&env);
    let plan = [[Action::Right, Action::TopRight], [Action::ShortPass, Action::Right], [Action::Sprint, Action::Shot]];
    let mut rewards = Vec::new();
    for (k, actions) in plan.iter().cycle().take(12).enumerate() {
        recorder.value("value", 0.125 * k as f32);
        if k == 4 {
            recorder.value("p_shot", 0.75);
        }
        let out = env.step(actions).expect("step");
        recorder.record(&env, actions);
        rewards.push(env.rewards().to_vec());
        if out.terminated || out.truncated {
            break;
        }
    }
    assert!(recorder.steps() >= 6, "the drill lasts 6 steps");
    recorder.finish().save(&dir.join("agent.tlreplay")).expect("save");
    let page = dir.join("viewer.html");
    touchline(&["view", dir.to_str().expect("utf-8"), "--html", page.to_str().expect("utf-8")]);
    let url = format!("file://{}?replay=agent&frame=5", page.display());
    let dom = headless(&browser, &dir.join("profile"), &["--dump-dom"], &url);
    // Frame 5 shows the state after step 5 (0-based 4, the plan's second pair): its actions,
    // rewards and values.
    assert_eq!(text_of(&dom, "step-action-0"), "short_pass");
    assert_eq!(text_of(&dom, "step-action-1"), "right");
    assert_eq!(text_of(&dom, "step-reward-0"), format!("{:.3}", rewards[4][0]));
    assert_eq!(text_of(&dom, "step-reward-1"), format!("{:.3}", rewards[4][1]));
    assert_eq!(text_of(&dom, "value-value"), "0.500");
    assert_eq!(text_of(&dom, "value-p_shot"), "0.750");
    assert!(dom.contains("class=\"bar\" style=\"width: 75px;\""), "a probability gets a bar: {dom}");
    let dom = headless(&browser, &dir.join("profile"), &["--dump-dom"], &url.replace("frame=5", "frame=3"));
    assert_eq!(text_of(&dom, "value-p_shot"), "\u{2014}", "no value given at that step");
    assert!(!dom.contains("id=\"zoom-control\" hidden"), "a drill offers the zoom");

    // Zoomed to the drill, the players are drawn larger than on the whole pitch: more team colour
    // (the scoreboard's team squares are the same size in both).
    let zoomed = dir.join("zoomed.png");
    let whole = dir.join("whole.png");
    headless(&browser, &dir.join("profile"), &[&format!("--screenshot={}", zoomed.display())], &url);
    headless(&browser, &dir.join("profile"), &[&format!("--screenshot={}", whole.display())], &format!("{url}&zoom=0"));
    let (z, w) = (colour_counts(&zoomed), colour_counts(&whole));
    assert!(2 * z.red > 3 * w.red, "zoomed {z:?}, whole pitch {w:?}");
    let _ = std::fs::remove_dir_all(&dir);
}
