//! `touchline play SCENARIO`: a person plays a scenario live in the browser.
//!
//! The engine runs here, in the `touchline` process; the page (`page.html`, embedded in the
//! binary) only draws and sends buttons. A clock thread plays one env step every 100 ms (GRF's
//! pace: 10 steps per second of play) while the match is on; the HTTP server (tiny_http, a thread
//! per request so that a waiting long poll blocks no one) serves:
//!
//! - `GET /`: the page;
//! - `GET /state?after=V`: the state after the latest step, as soon as its version is past `V`
//!   (at most 5 s later);
//! - `POST /input`: the buttons held and pressed (see docs/play-protocol.md).
//!
//! The person controls one player of `--side` (the env's usual active player, who switches to
//! whoever is nearest the ball), against the built-in AI at the scenario's θ or `--theta`; with
//! `--players 2` two people play, one per team, on one keyboard or in two tabs. Every finished
//! episode is written as a `.tlreplay` into `--record`.

mod controller;
mod live;
mod policy;

use std::io::{Read, Write};
use std::path::PathBuf;
use std::sync::{Arc, Condvar, Mutex, MutexGuard, PoisonError};
use std::time::{Duration, Instant};

use clap::{Args, ValueEnum};
use touchline_dsl::script::{ScriptOptions, Scripts};
use touchline_engine::{ActionSet, EngineError, EnvConfig, Scenario};

use crate::CliError;
use live::{InputMessage, LiveMatch};

/// The page.
const PAGE: &str = include_str!("page.html");
/// One env step of play: GRF's 10 steps per second.
const STEP: Duration = Duration::from_millis(100);
/// How long a long poll waits for a new state before answering with the current one.
const POLL_WAIT: Duration = Duration::from_secs(5);
/// The largest input message read (a message lists a dozen names).
const MAX_MESSAGE: u64 = 16 * 1024;

/// Arguments of `touchline play`.
#[derive(Debug, Args)]
pub(crate) struct PlayArgs {
    /// A stdlib scenario name (see `touchline list`), a `.tl` scenario file, or a compiled
    /// `.json` scenario.
    scenario: String,

    /// Port to serve on (on 127.0.0.1 only); 0 picks a free one.
    #[arg(long, default_value_t = 8000)]
    port: u16,

    /// The team the person plays.
    #[arg(long, value_enum, default_value_t = PlaySide::Left)]
    side: PlaySide,

    /// People at the match: 1, or 2 (one per team: the left team's on the page's left-hand keys
    /// or at `/?player=0`, the right team's on the right-hand keys or at `/?player=1`).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=2), conflicts_with = "side")]
    players: u8,

    /// Let a program (a Python policy: examples/python/play_policy.py) play the other team's
    /// active player, connecting to 127.0.0.1 on this port (0: any free one); the built-in AI
    /// plays him until it connects. docs/play-protocol.md has the protocol.
    #[arg(long, value_name = "PORT", conflicts_with = "players")]
    opponent_port: Option<u16>,

    /// Difficulty θ in [0, 1] of the built-in AI on the other team, or with `--players 2` of
    /// both teams' AI players (default: the scenario's).
    #[arg(long, value_name = "T", value_parser = theta)]
    theta: Option<f32>,

    /// Folder the matches are written into as they end (`touchline view` and `touchline replay`
    /// read them): `play_<scenario>_seed<S>_ep<E>.tlreplay`. Default: `touchline-plays` in the
    /// system's temporary folder (GRF's `play_game` dumps there too).
    #[arg(long, value_name = "DIR")]
    record: Option<PathBuf>,

    /// Seed of the environment.
    #[arg(long, default_value_t = 0)]
    seed: u64,
}

/// The team a person plays.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub(crate) enum PlaySide {
    Left,
    Right,
}

/// Parses `--theta`: a number in [0, 1].
fn theta(text: &str) -> Result<f32, String> {
    let t: f32 = text.parse().map_err(|_| format!("`{text}` is not a number"))?;
    if (0.0..=1.0).contains(&t) { Ok(t) } else { Err(format!("{t} is outside [0, 1]")) }
}

/// Sets the difficulty of the AI teams (the one without a person), in the scenario and its
/// lessons.
fn set_ai_theta(scenario: &mut Scenario, [left, right]: [bool; 2], t: f32) {
    let set = |s: &mut Scenario| {
        if left {
            s.left_team_difficulty = t;
        }
        if right {
            s.right_team_difficulty = t;
        }
    };
    set(scenario);
    if let Some(c) = &mut scenario.curriculum {
        c.lessons.iter_mut().for_each(|l| set(&mut l.scenario));
    }
}

/// The match and the condition its waiting readers sleep on.
struct Shared {
    live: Mutex<LiveMatch>,
    changed: Condvar,
}

impl Shared {
    /// The match, also after a thread panicked holding it (the state stays usable for the page).
    fn lock(&self) -> MutexGuard<'_, LiveMatch> {
        self.live.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

/// Runs `touchline play`.
pub(crate) fn run(args: &PlayArgs) -> Result<(), CliError> {
    let mut scenario = touchline_dsl::load(&args.scenario)?;
    let policy = args.opponent_port.is_some();
    let (left, right) = match (args.players, args.side) {
        (2, _) => (1, 1),
        (_, _) if policy => (1, 1),
        (_, PlaySide::Left) => (1, 0),
        (_, PlaySide::Right) => (0, 1),
    };
    if let Some(t) = args.theta {
        // θ is the AI's: the other team's with one person, both teams' AI players with two.
        let ai = match args.side {
            _ if args.players == 2 => [true, true],
            PlaySide::Left => [false, true],
            PlaySide::Right => [true, false],
        };
        set_ai_theta(&mut scenario, ai, t);
    }
    // `v2` for `builtin_ai`: the person can hand the player to the AI.
    let config = EnvConfig { left_agents: left, right_agents: right, action_set: ActionSet::V2, checkpoints: false };
    let scripts = Scripts::compile(&scenario, &touchline_dsl::script_dir(&args.scenario), ScriptOptions::default())
        .map_err(|e| CliError::Build(touchline_dsl::BuildError::Scripts(e)))?;
    // The replays carry the scripts' text, so that they re-simulate without the files.
    let sources: Vec<(String, String)> = scripts.sources().map(|(p, t)| (p.to_owned(), t.to_owned())).collect();
    let controllable = scenario.controllable_every_episode();
    let env = touchline_dsl::attach(&scripts, scenario, config, args.seed).map_err(|e| match e {
        EngineError::Script { message, .. } => CliError::Script { episode: 0, message },
        source => CliError::Config {
            scenario: args.scenario.clone(),
            help: format!(
                "this scenario has {} controllable left and {} controllable right players; \
                 play a side with one (--side left or --side right; --players 2 and --opponent-port need one on each)",
                controllable[0], controllable[1]
            ),
            source,
        },
    })?;
    let record = args.record.clone().unwrap_or_else(|| std::env::temp_dir().join("touchline-plays"));
    let name = env.scenario().name.clone();
    // The opponent's seat: env controllers are ordered left team first.
    let opponent = match args.opponent_port {
        Some(port) => {
            let seat = usize::from(args.side == PlaySide::Left);
            let (socket, port) = policy::PolicySocket::listen(port, seat)
                .map_err(|e| CliError::Serve { reason: format!("opponent port {port}: {e}") })?;
            Some((socket, port))
        }
        None => None,
    };
    let opponent_port = opponent.as_ref().map(|(_, port)| *port);
    let live = LiveMatch::new(env, sources, record, name, opponent.map(|(socket, _)| socket));
    let shared = Arc::new(Shared { live: Mutex::new(live), changed: Condvar::new() });

    let server = tiny_http::Server::http(("127.0.0.1", args.port))
        .map_err(|e| CliError::Serve { reason: format!("port {}: {e}", args.port) })?;
    let port = server.server_addr().to_ip().map_or(args.port, |a| a.port());
    println!("play {} at http://127.0.0.1:{port}/ (Ctrl-C to stop)", args.scenario);
    if let Some(p) = opponent_port {
        println!("opponent: waiting for a policy on 127.0.0.1:{p} (the built-in AI plays until one connects)");
    }
    std::io::stdout().flush()?;

    let clock = Arc::clone(&shared);
    std::thread::spawn(move || play_clock(&clock));
    for request in server.incoming_requests() {
        let shared = Arc::clone(&shared);
        std::thread::spawn(move || answer(request, &shared));
    }
    Ok(())
}

/// Plays a step every [`STEP`], on a fixed schedule so that slow steps do not slow the match down.
fn play_clock(shared: &Shared) {
    let mut next = Instant::now() + STEP;
    loop {
        let now = Instant::now();
        if next > now {
            std::thread::sleep(next - now);
        } else if now - next > STEP * 10 {
            // Far behind (the machine was suspended): carry on from now rather than rush.
            next = now;
        }
        next += STEP;
        let mut live = shared.lock();
        let before = live.version();
        live.tick();
        if live.version() != before {
            shared.changed.notify_all();
        }
    }
}

/// Answers one request (a failed answer only loses that request).
fn answer(mut request: tiny_http::Request, shared: &Shared) {
    let url = request.url().to_string();
    let (path, query) = url.split_once('?').unwrap_or((url.as_str(), ""));
    let json = "application/json";
    let method = request.method().clone();
    let (status, kind, body) = match (method, path) {
        (tiny_http::Method::Get, "/" | "/index.html") => (200, "text/html; charset=utf-8", PAGE.to_string()),
        (tiny_http::Method::Get, "/state") => {
            let after = query.split('&').find_map(|kv| kv.strip_prefix("after=")).and_then(|v| v.parse::<u64>().ok());
            (200, json, state_after(shared, after.unwrap_or(0)))
        }
        (tiny_http::Method::Post, "/input") => {
            let mut text = String::new();
            let read = request.as_reader().take(MAX_MESSAGE).read_to_string(&mut text);
            let message = read
                .map_err(|e| format!("cannot read the message: {e}"))
                .and_then(|_| serde_json::from_str::<InputMessage>(&text).map_err(|e| format!("bad message: {e}")));
            let applied = message.and_then(|m| {
                let mut live = shared.lock();
                let applied = live.input(&m);
                shared.changed.notify_all();
                applied
            });
            match applied {
                Ok(()) => (200, json, "{\"ok\":true}".to_string()),
                Err(e) => (400, json, serde_json::json!({ "error": e }).to_string()),
            }
        }
        _ => (404, "text/plain; charset=utf-8", format!("not found: {path}")),
    };
    let mut response = tiny_http::Response::from_string(body).with_status_code(status);
    for (name, value) in [("Content-Type", kind), ("Cache-Control", "no-store")] {
        if let Ok(header) = tiny_http::Header::from_bytes(name, value) {
            response = response.with_header(header);
        }
    }
    let _ = request.respond(response);
}

/// The state as JSON once its version is past `after` (or [`POLL_WAIT`] has gone by).
fn state_after(shared: &Shared, after: u64) -> String {
    let deadline = Instant::now() + POLL_WAIT;
    let mut live = shared.lock();
    while live.version() <= after {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() {
            break;
        }
        live = shared.changed.wait_timeout(live, left).unwrap_or_else(PoisonError::into_inner).0;
    }
    serde_json::to_string(&live.state()).unwrap_or_else(|e| serde_json::json!({ "error": e.to_string() }).to_string())
}
