//! `touchline run --record`, `touchline replay` and their errors, through the built binary.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn touchline(args: &[&str]) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_touchline"));
    cmd.args(args).env("NO_COLOR", "1");
    cmd.output().unwrap_or_else(|e| panic!("cannot run touchline: {e}"))
}

/// A fresh folder under the system's temporary folder.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("touchline-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch folder");
    dir
}

fn files(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("read folder")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Stderr with miette's box drawing removed and lines joined, so that a message wrapped over lines
/// can be searched.
fn flat(stderr: &[u8]) -> String {
    let text = String::from_utf8_lossy(stderr).replace(['│', '×', '╰', '─', '▶'], " ");
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

#[test]
fn record_every_second_episode_then_draw_gif_and_pngs() {
    let dir = scratch("record");
    let out = touchline(&[
        "run",
        "academy_counterattack_easy",
        "--episodes",
        "3",
        "--record",
        s(&dir),
        "--record-every",
        "2",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(
        files(&dir),
        ["academy_counterattack_easy_seed0_ep0.tlreplay", "academy_counterattack_easy_seed0_ep2.tlreplay"]
    );
    let replay = dir.join("academy_counterattack_easy_seed0_ep0.tlreplay");

    let gif = dir.join("ep0.gif");
    let out = touchline(&["replay", s(&replay), "-o", s(&gif), "--width", "160", "--height", "120", "--every", "5"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let bytes = std::fs::read(&gif).expect("gif written");
    assert!(bytes.starts_with(b"GIF89a"));

    let frames = dir.join("frames");
    let out = touchline(&["replay", s(&replay), "-o", s(&frames), "--width", "64", "--height", "48", "--every", "20"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let pngs = files(&frames);
    assert!(pngs.len() >= 2 && pngs[0] == "frame_00000.png", "{pngs:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn goal_clips_hold_the_goal() {
    let dir = scratch("goals");
    let out = touchline(&["run", "academy_empty_goal_close", "--episodes", "2", "--record", s(&dir), "--record-goals"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let clips = files(&dir);
    assert!(!clips.is_empty() && clips.iter().all(|c| c.contains("_goal")), "{clips:?}");
    let out =
        touchline(&["replay", s(&dir.join(&clips[0])), "-o", s(&dir.join("f")), "--width", "32", "--height", "24"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn damaged_replays_exit_2_with_the_reason() {
    let dir = scratch("damaged");
    let out = touchline(&["run", "academy_empty_goal_close", "--record", s(&dir)]);
    assert!(out.status.success());
    let good = dir.join("academy_empty_goal_close_seed0_ep0.tlreplay");
    let bytes = std::fs::read(&good).expect("replay");

    let cases: [(&str, Vec<u8>, &str); 4] = [
        ("truncated", bytes[..bytes.len() / 2].to_vec(), "truncated"),
        (
            "corrupted",
            {
                let mut b = bytes.clone();
                let n = b.len() - 3;
                b[n] ^= 0xFF;
                b
            },
            "corrupted",
        ),
        ("foreign", b"GIF89a not a replay".to_vec(), "not a touchline replay"),
        ("empty", Vec::new(), "not a touchline replay"),
    ];
    for (name, content, reason) in cases {
        let path = dir.join(format!("{name}.tlreplay"));
        std::fs::write(&path, content).expect("write");
        let out = touchline(&["replay", s(&path), "-o", s(&dir.join("x.gif"))]);
        let err = flat(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains(reason) && !err.contains("panicked"), "{name}: {err}");
    }
    let out = touchline(&["replay", s(&dir.join("missing.tlreplay")), "-o", s(&dir.join("x.gif"))]);
    assert_eq!(out.status.code(), Some(2));
    let out = touchline(&["replay", s(&good), "-o", s(&dir.join("x.avi"))]);
    assert!(flat(&out.stderr).contains("unknown video type"), "{}", flat(&out.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn mp4_through_ffmpeg_when_installed() {
    let has_ffmpeg = Command::new("ffmpeg").arg("-version").output().is_ok_and(|o| o.status.success());
    let dir = scratch("mp4");
    let out = touchline(&["run", "academy_empty_goal_close", "--record", s(&dir)]);
    assert!(out.status.success());
    let replay = dir.join("academy_empty_goal_close_seed0_ep0.tlreplay");
    let mp4 = dir.join("ep0.mp4");
    let out = touchline(&["replay", s(&replay), "-o", s(&mp4), "--width", "160", "--height", "90"]);
    if has_ffmpeg {
        assert!(out.status.success(), "{}", flat(&out.stderr));
        assert!(std::fs::metadata(&mp4).expect("mp4 written").len() > 500);
    } else {
        // Without ffmpeg the command says how to get it or what to write instead.
        assert_eq!(out.status.code(), Some(1));
        assert!(flat(&out.stderr).contains("ffmpeg"), "{}", flat(&out.stderr));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 19: the replay of a scenario with a reward script carries the script's text, so that
/// `replay` and `view` re-simulate it (they refused it before: "needs script hooks"), even with
/// the script file gone.
#[test]
fn replays_of_scripted_scenarios_draw_and_view_without_the_script_files() {
    let dir = scratch("scripted");
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    // A copy of the example and its script, removed once recorded.
    std::fs::create_dir_all(dir.join("scenarios")).expect("dir");
    std::fs::create_dir_all(dir.join("rewards")).expect("dir");
    for f in ["scenarios/run_to_score_shaped.tl", "rewards/distance_to_goal.rhai"] {
        std::fs::copy(root.join("examples").join(f), dir.join(f)).expect("copy");
    }
    let record = dir.join("record");
    let scenario = dir.join("scenarios/run_to_score_shaped.tl");
    let out = touchline(&["run", s(&scenario), "--episodes", "2", "--policy", "random", "--record", s(&record)]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    std::fs::remove_file(dir.join("rewards/distance_to_goal.rhai")).expect("remove the script");
    let replay = record.join("run_to_score_shaped_seed0_ep1.tlreplay");
    let out = touchline(&["replay", s(&replay), "-o", s(&dir.join("frames")), "--width", "32", "--height", "24"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let page = dir.join("view.html");
    let out = touchline(&["view", s(&record), "--html", s(&page)]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let html = std::fs::read_to_string(&page).expect("page");
    assert!(html.contains("run_to_score_shaped_seed0_ep1"));
    // The goal clips of a scripted scenario re-simulate too (`--record-goals` cuts them).
    let goals = dir.join("goals");
    std::fs::copy(root.join("examples/rewards/distance_to_goal.rhai"), dir.join("rewards/distance_to_goal.rhai"))
        .expect("copy");
    let out = touchline(&[
        "run",
        s(&scenario),
        "--episodes",
        "3",
        "--policy",
        "builtin",
        "--record",
        s(&goals),
        "--record-goals",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let clips = files(&goals);
    assert!(!clips.is_empty(), "the built-in AI scores in run to score");
    let out = touchline(&[
        "replay",
        s(&goals.join(&clips[0])),
        "-o",
        s(&dir.join("clip")),
        "--width",
        "32",
        "--height",
        "24",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}
