//! `touchline view PATH`: watch replays in the browser.
//!
//! The viewer is one static page (`viewer.html`, embedded in the binary) that draws the match on a
//! canvas with play/pause, speed, step and scrub controls, and shows the observation of the
//! controlled player (controller 0) at every step: its Super Mini Map and the raw observation's
//! scalars. Per step it lists the action every controlled player took and its reward, and the
//! numbers the recorder attached (`record_values` in Python: a value estimate, action
//! probabilities). The pitch shows the step counter and the game mode, the ball's height (its
//! lift above its shadow, and in metres while in the air), and in a drill (a scenario that ends
//! when the ball goes out of play, as GRF's Academy) zooms to where the play happens. The data
//! comes from re-simulating each replay (so a replay that does not reproduce is refused), with the
//! scenario's scripts compiled from the text the replay carries.
//!
//! - `touchline view DIR` serves the page and the replays of `DIR` on `http://127.0.0.1:PORT/`
//!   (`/replays.json` lists them, `/replay/NAME.json` gives one).
//! - `touchline view PATH --html page.html` writes the page with the replays inside it: one file
//!   that opens in a browser from the disk, with no server.

use std::io::{BufRead, BufReader, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};

use clap::Args;
use serde::Serialize;
use touchline_engine::geometry::coords::{OBS_X_SCALE, OBS_Y_SCALE};
use touchline_engine::{Env, Side};
use touchline_render::replay::Replay;

use crate::CliError;
use crate::cmd::replay::load;

/// The viewer page.
const PAGE: &str = include_str!("viewer.html");
/// Where `--html` puts the data in the page.
const DATA_MARKER: &str = "<!--TOUCHLINE_DATA-->";

/// Arguments of `touchline view`.
#[derive(Debug, Args)]
pub(crate) struct ViewArgs {
    /// A folder of replays (`*.tlreplay`, as `touchline run --record` writes them) or one replay.
    path: PathBuf,

    /// Port to serve on (on 127.0.0.1 only); 0 picks a free one.
    #[arg(long, default_value_t = 8000)]
    port: u16,

    /// Write the viewer with the replays inside it to this HTML file instead of serving it.
    #[arg(long, value_name = "FILE")]
    html: Option<PathBuf>,
}

/// One replay as the page reads it: per-frame columns, positions in metres (engine frame).
#[derive(Debug, Serialize)]
struct ViewData {
    name: String,
    scenario: String,
    description: String,
    first_step: u32,
    steps: usize,
    /// Side of controller 0 (`"left"` or `"right"`), whose observation is shown.
    controller_side: &'static str,
    /// Metres per normalised unit in observations `[x, y]`, to draw the Super Mini Map.
    obs_scale: [f32; 2],
    /// `[side (0 left, 1 right), shirt number, goalkeeper (0/1)]` per player.
    roster: Vec<[u8; 3]>,
    /// Ball `[x, y, z]` per frame (m).
    ball: Vec<[f32; 3]>,
    /// Players' `[x, y]` per frame (m), roster order.
    players: Vec<Vec<[f32; 2]>>,
    /// Roster index of the ball owner per frame, -1 for none.
    owner: Vec<i32>,
    /// Roster indices of every controlled player per frame.
    controlled: Vec<Vec<u8>>,
    score: Vec<[u16; 2]>,
    /// Game mode name per frame (GRF's names).
    mode: Vec<&'static str>,
    /// Controller 0's observation per frame.
    obs: Vec<ObsRow>,
    /// Side of each controller (`"left"` / `"right"`), left controllers first.
    controller_sides: Vec<&'static str>,
    /// Per frame, the GRF name of the action each controller took in the step that led to it
    /// (empty for frame 0).
    actions: Vec<Vec<&'static str>>,
    /// Per frame, each controller's reward for the step that led to it (empty for frame 0).
    rewards: Vec<Vec<f32>>,
    /// The recorder's named per-step numbers; `values[k]` belongs to the step leading to frame
    /// `k + 1`, `null` where none was given.
    values: Vec<ViewValues>,
    /// The scenario is a drill (it ends when the ball goes out of play, as GRF's Academy): the
    /// page zooms to where the play happens.
    drill: bool,
}

/// One named series of per-step numbers, as the page reads it.
#[derive(Debug, Serialize)]
struct ViewValues {
    name: String,
    /// NaN becomes `null` in JSON.
    values: Vec<f32>,
}

/// The scalars of controller 0's raw observation after a frame, and what led to it.
#[derive(Debug, Serialize)]
struct ObsRow {
    /// The action taken in the step that led to this frame (`""` for frame 0).
    action: String,
    reward: f32,
    active: i32,
    designated: i32,
    ball_owned_team: i32,
    ball_owned_player: i32,
    /// Sticky actions as 10 digits: 8 directions, sprint, dribble.
    sticky: String,
    steps_left: u32,
    game_mode: &'static str,
}

/// Re-simulates `replay` (checking it) and collects what the page shows.
fn view_data(name: &str, path: &Path, replay: &Replay) -> Result<ViewData, CliError> {
    let m = |cm: i16| f32::from(cm) / 100.0;
    let mut obs = Vec::with_capacity(replay.frames.len());
    let mut rewards = Vec::with_capacity(replay.frames.len());
    let mut sides = Vec::new();
    let mut side = Side::Left;
    replay
        .simulate_with(crate::cmd::replay::hooks(replay)?, |env: &Env, k| {
            side = env.controller_sides().next().unwrap_or(Side::Left);
            if k == 0 {
                sides = env.controller_sides().map(Side::name).collect();
            }
            rewards.push(if k == 0 { Vec::new() } else { env.rewards().to_vec() });
            let o = &env.observations()[0];
            obs.push(ObsRow {
                action: if k == 0 { String::new() } else { format!("{:?}", replay.step_actions(k - 1)[0]) },
                reward: if k == 0 { 0.0 } else { env.rewards()[0] },
                active: o.active,
                designated: o.designated,
                ball_owned_team: o.ball_owned_team,
                ball_owned_player: o.ball_owned_player,
                sticky: o.sticky_actions.iter().map(|b| char::from(b'0' + b.min(&9))).collect(),
                steps_left: o.steps_left,
                game_mode: o.game_mode.name(),
            });
        })
        .map_err(|source| CliError::Replay { path: path.to_path_buf(), source })?;
    Ok(ViewData {
        name: name.to_string(),
        scenario: replay.scenario.name.clone(),
        description: replay.scenario.description.clone(),
        first_step: replay.first_step,
        steps: replay.steps(),
        controller_side: side.name(),
        obs_scale: [OBS_X_SCALE, OBS_Y_SCALE],
        roster: replay.roster.iter().map(|r| [r.side as u8, r.number, u8::from(r.goalkeeper)]).collect(),
        ball: replay.frames.iter().map(|f| [m(f.ball[0]), m(f.ball[1]), m(f.ball[2])]).collect(),
        players: replay.frames.iter().map(|f| f.players.iter().map(|p| [m(p[0]), m(p[1])]).collect()).collect(),
        owner: replay.frames.iter().map(|f| f.owner.map_or(-1, i32::from)).collect(),
        controlled: replay.frames.iter().map(|f| f.controlled.clone()).collect(),
        score: replay.frames.iter().map(|f| f.score).collect(),
        mode: replay
            .frames
            .iter()
            .map(|f| touchline_engine::GameMode::ALL.get(usize::from(f.mode)).copied().unwrap_or_default().name())
            .collect(),
        obs,
        controller_sides: sides,
        actions: (0..=replay.steps())
            .map(|k| if k == 0 { Vec::new() } else { replay.step_actions(k - 1).iter().map(|a| a.name()).collect() })
            .collect(),
        rewards,
        values: replay.values.iter().map(|v| ViewValues { name: v.name.clone(), values: v.values.clone() }).collect(),
        drill: replay.scenario.end_episode_on_out_of_play,
    })
}

/// The replays under `path`: the file itself, or the `*.tlreplay` files of the folder by name.
fn replay_files(path: &Path) -> Result<Vec<(String, PathBuf)>, CliError> {
    let name_of = |p: &Path| p.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
    if !path.is_dir() {
        if !path.exists() {
            return Err(CliError::Read {
                path: path.display().to_string(),
                source: std::io::Error::new(std::io::ErrorKind::NotFound, "no such file or folder"),
            });
        }
        return Ok(vec![(name_of(path), path.to_path_buf())]);
    }
    let entries =
        std::fs::read_dir(path).map_err(|source| CliError::Read { path: path.display().to_string(), source })?;
    let mut files: Vec<(String, PathBuf)> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "tlreplay"))
        .map(|p| (name_of(&p), p))
        .collect();
    files.sort();
    Ok(files)
}

/// JSON safe to put inside a `<script>` element (`</` cannot close it).
fn script_json(value: &impl Serialize) -> String {
    serde_json::to_string(value).unwrap_or_else(|_| "null".into()).replace("</", "<\\/")
}

/// Runs `touchline view`.
pub(crate) fn run(args: &ViewArgs) -> Result<(), CliError> {
    let files = replay_files(&args.path)?;
    if let Some(out) = &args.html {
        let mut all = Vec::new();
        for (name, path) in &files {
            all.push(view_data(name, path, &load(path)?)?);
        }
        let script = format!("<script>window.TOUCHLINE_DATA = {{\"replays\": {}}};</script>", script_json(&all));
        let page = PAGE.replacen(DATA_MARKER, &script, 1);
        std::fs::write(out, page).map_err(|source| CliError::Write { path: out.clone(), source })?;
        println!("wrote {} ({} replay{})", out.display(), all.len(), if all.len() == 1 { "" } else { "s" });
        return Ok(());
    }
    let listener = TcpListener::bind(("127.0.0.1", args.port))
        .map_err(|e| CliError::Serve { reason: format!("port {}: {e}", args.port) })?;
    let port = listener.local_addr().map_err(|e| CliError::Serve { reason: e.to_string() })?.port();
    println!(
        "serving {} replay{} at http://127.0.0.1:{port}/ (Ctrl-C to stop)",
        files.len(),
        if files.len() == 1 { "" } else { "s" }
    );
    std::io::stdout().flush()?;
    // One bad connection does not stop the viewer.
    for stream in listener.incoming().flatten() {
        let _ = answer(stream, &files);
    }
    Ok(())
}

/// Answers one HTTP request.
fn answer(mut stream: TcpStream, files: &[(String, PathBuf)]) -> std::io::Result<()> {
    let mut line = String::new();
    let mut reader = BufReader::new(stream.try_clone()?);
    reader.read_line(&mut line)?;
    // Skip the headers.
    let mut header = String::new();
    while reader.read_line(&mut header)? > 2 {
        header.clear();
    }
    let target = line.split_whitespace().nth(1).unwrap_or("/");
    let path = target.split('?').next().unwrap_or("/");
    let (status, kind, body) = match path {
        "/" | "/index.html" => ("200 OK", "text/html; charset=utf-8", PAGE.to_string()),
        "/replays.json" => {
            let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
            ("200 OK", "application/json", script_json(&names))
        }
        _ => match path.strip_prefix("/replay/").and_then(|p| p.strip_suffix(".json")) {
            Some(name) => match files.iter().find(|(n, _)| n == name) {
                Some((n, p)) => match load(p).and_then(|r| view_data(n, p, &r)) {
                    Ok(data) => ("200 OK", "application/json", script_json(&data)),
                    Err(e) => (
                        "500 Internal Server Error",
                        "text/plain; charset=utf-8",
                        format!("{:?}", miette::Report::new(e)),
                    ),
                },
                None => ("404 Not Found", "text/plain; charset=utf-8", format!("no replay named {name}")),
            },
            None => ("404 Not Found", "text/plain; charset=utf-8", "not found".to_string()),
        },
    };
    write!(
        stream,
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n",
        body.len()
    )?;
    stream.write_all(body.as_bytes())?;
    stream.flush()
}
