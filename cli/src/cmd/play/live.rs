//! [`LiveMatch`]: the match a person plays, stepped by the clock and steered by the page.
//!
//! It owns the env, the person's [`HumanController`] and the episode's [`Recorder`]; the server
//! locks it to apply inputs and read the state, the clock thread to play a step. A version number
//! grows with every change, so that the page's long poll (`GET /state?after=V`) answers only
//! when there is something new.

use std::collections::VecDeque;
use std::io::Write;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use touchline_engine::{Env, Event, Side};
use touchline_render::replay::{Frame, Recorder};

use super::controller::{Button, HumanController};
use super::policy::PolicySocket;

/// How many recent events (passes, shots, goals, saves of the replay) the page lists.
const EVENTS_KEPT: usize = 8;

/// Where the match stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum Phase {
    /// Waiting for the first button: the person reads the key map before the kick-off.
    KickOff,
    Playing,
    Paused,
    /// The episode ended (or the engine stopped it); `restart` plays another.
    FullTime,
}

/// One message from the page: the buttons held now and those pressed since the last message
/// (buttons and the commands `pause`, `restart`, `builtin_ai`). See docs/play-protocol.md.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct InputMessage {
    /// Which person (controller index: left team first); 0 when left out.
    #[serde(default)]
    player: usize,
    #[serde(default)]
    held: Vec<String>,
    #[serde(default)]
    pressed: Vec<String>,
}

/// The state the page draws, after the latest step: positions in metres, engine frame.
#[derive(Debug, Serialize)]
pub(crate) struct LiveState<'a> {
    version: u64,
    scenario: &'a str,
    description: &'a str,
    phase: Phase,
    /// Side the person plays (`"left"` or `"right"`).
    side: &'static str,
    /// The person's player is handed to the built-in AI.
    builtin_ai: bool,
    episode: u64,
    step: u32,
    steps_left: u32,
    /// `[side (0 left, 1 right), shirt number, goalkeeper (0/1)]` per player.
    roster: &'a [[u8; 3]],
    ball: [f32; 3],
    players: Vec<[f32; 2]>,
    /// Roster index of the ball owner, -1 for none.
    owner: i32,
    /// Roster index of the person's player.
    controlled: Vec<u8>,
    score: [u16; 2],
    /// GRF's name of the game mode.
    mode: &'static str,
    /// The action the person's controller sent in the last step (GRF's name).
    last_action: &'static str,
    /// With `--opponent-port`: whether a policy is connected (the built-in AI plays its player
    /// until one is).
    policy_connected: Option<bool>,
    /// Every person at the match (one, or one per team): side, AI hand-over, last action, their
    /// team's passes and shots. The fields above are the first person's.
    controllers: Vec<ControllerState>,
    /// Passes and shots of the person's team this episode.
    passes: u32,
    shots: u32,
    events: &'a VecDeque<String>,
    /// The replay written when the last match ended, and an error if it could not be.
    saved: Option<String>,
    error: Option<&'a str>,
}

/// One person's part of the state.
#[derive(Debug, Serialize)]
pub(crate) struct ControllerState {
    side: &'static str,
    builtin_ai: bool,
    last_action: &'static str,
    /// Passes and shots of this person's team this episode.
    passes: u32,
    shots: u32,
}

/// The match being played; see the module documentation.
pub(crate) struct LiveMatch {
    env: Env,
    /// One per person, in the env's controller order (left team first).
    controllers: Vec<HumanController>,
    /// The env controller each person plays.
    people: Vec<usize>,
    /// The opponent played by a program over a socket, if any.
    policy: Option<PolicySocket>,
    recorder: Recorder,
    scripts: Vec<(String, String)>,
    record_dir: PathBuf,
    name: String,
    phase: Phase,
    version: u64,
    roster: Vec<[u8; 3]>,
    frame: Frame,
    last_actions: Vec<touchline_engine::Action>,
    events: VecDeque<String>,
    saved: Option<PathBuf>,
    error: Option<String>,
}

impl LiveMatch {
    /// A match of `env` (just reset), whose episodes are saved into `record_dir`; `policy` plays
    /// its env controller, people the others.
    pub(crate) fn new(
        env: Env,
        scripts: Vec<(String, String)>,
        record_dir: PathBuf,
        name: String,
        policy: Option<PolicySocket>,
    ) -> LiveMatch {
        let recorder = Recorder::start(&env).with_scripts(scripts.iter().cloned());
        let seats = env.num_controllers();
        let people: Vec<usize> = (0..seats).filter(|&i| policy.as_ref().is_none_or(|p| p.seat != i)).collect();
        let mut live = LiveMatch {
            env,
            controllers: vec![HumanController::default(); people.len()],
            people,
            policy,
            recorder,
            scripts,
            record_dir,
            name,
            phase: Phase::KickOff,
            version: 1,
            roster: Vec::new(),
            frame: Frame::default(),
            last_actions: vec![touchline_engine::Action::Idle; seats],
            events: VecDeque::new(),
            saved: None,
            error: None,
        };
        live.capture();
        if let Some(p) = &mut live.policy {
            p.observe(&live.env, false);
        }
        live
    }

    /// Grows with every change the page can see.
    pub(crate) fn version(&self) -> u64 {
        self.version
    }

    fn capture(&mut self) {
        self.frame.capture(&self.env);
        let game = self.env.game();
        self.roster = game
            .players()
            .iter()
            .map(|p| {
                [
                    p.side as u8,
                    u8::try_from(p.index + 1).unwrap_or(u8::MAX),
                    u8::from(p.role == touchline_engine::Role::GK),
                ]
            })
            .collect();
        self.version += 1;
    }

    /// Side of the person's player (a scenario may swap sides on odd episodes).
    fn side(&self) -> Side {
        self.env.controller_sides().nth(self.people[0]).unwrap_or(Side::Left)
    }

    /// Applies one message from the page; `Err` names what was not understood (nothing is applied).
    pub(crate) fn input(&mut self, message: &InputMessage) -> Result<(), String> {
        let buttons = |names: &[String], commands: bool| -> Result<Vec<Button>, String> {
            let mut out = Vec::new();
            for n in names {
                match Button::from_name(n) {
                    Some(b) => out.push(b),
                    None if commands && ["pause", "restart", "builtin_ai"].contains(&n.as_str()) => {}
                    None => {
                        let known: Vec<&str> = Button::ALL.iter().map(|b| b.name()).collect();
                        let extra = if commands { ", pause, restart, builtin_ai" } else { "" };
                        return Err(format!("unknown button `{n}` (known: {}{extra})", known.join(", ")));
                    }
                }
            }
            Ok(out)
        };
        let people = self.controllers.len();
        if message.player >= people {
            return Err(format!("no player {} in this match: it has {people} (0 to {})", message.player, people - 1));
        }
        let held = buttons(&message.held, false)?;
        let pressed = buttons(&message.pressed, true)?;
        let command = |c: &str| message.pressed.iter().any(|p| p == c);
        if command("restart") {
            self.restart();
        }
        if command("pause") {
            self.phase = match self.phase {
                Phase::Playing => Phase::Paused,
                Phase::Paused | Phase::KickOff => Phase::Playing,
                Phase::FullTime => Phase::FullTime,
            };
        }
        if command("builtin_ai") {
            self.controllers[message.player].toggle_builtin();
        }
        // Any button kicks off.
        if self.phase == Phase::KickOff && (!held.is_empty() || !pressed.is_empty()) {
            self.phase = Phase::Playing;
        }
        self.controllers[message.player].set_buttons(&held, &pressed);
        self.version += 1;
        Ok(())
    }

    /// The clock's call, ten times a second: plays one step while the match is on.
    pub(crate) fn tick(&mut self) {
        if self.phase != Phase::Playing {
            return;
        }
        let sides: Vec<Side> = self.env.controller_sides().collect();
        let mut people = self.controllers.iter_mut();
        let actions: Vec<_> = sides
            .iter()
            .enumerate()
            .map(|(seat, &side)| match &self.policy {
                Some(p) if p.seat == seat => p.action(),
                _ => people.next().map_or(touchline_engine::Action::Idle, |c| c.next_action(side == Side::Right)),
            })
            .collect();
        let outcome = match self.env.step(&actions) {
            Ok(outcome) => outcome,
            Err(e) => {
                // A scenario script can fail mid-match: the page shows why, the match stops.
                let message = e.to_string();
                let _ = writeln!(std::io::stderr(), "error: the match stopped: {message}");
                self.error = Some(message);
                self.phase = Phase::FullTime;
                self.version += 1;
                return;
            }
        };
        self.recorder.record(&self.env, &actions);
        self.last_actions.clone_from(&actions);
        self.note_events();
        self.capture();
        let done = outcome.terminated || outcome.truncated;
        if let Some(p) = &mut self.policy {
            p.observe(&self.env, done);
        }
        if done {
            self.phase = Phase::FullTime;
            self.save();
        }
    }

    fn note_events(&mut self) {
        let step = self.env.info().steps;
        let team = |side: Side| side.name();
        for event in self.env.game().events() {
            let line = match *event {
                Event::Goal { side, .. } => format!("step {step}: goal for {}", team(side)),
                Event::Shot { side, player, .. } => format!("step {step}: shot by {} #{}", team(side), player + 1),
                Event::Pass { side, player, .. } => format!("step {step}: pass by {} #{}", team(side), player + 1),
                _ => continue,
            };
            if self.events.len() == EVENTS_KEPT {
                self.events.pop_front();
            }
            self.events.push_back(line);
        }
    }

    /// Writes the finished episode's replay (errors are shown on the page, not fatal: the person
    /// may want to play on).
    fn save(&mut self) {
        let replay = std::mem::replace(
            &mut self.recorder,
            Recorder::start(&self.env).with_scripts(self.scripts.iter().cloned()),
        )
        .finish();
        let path = free_name(&self.record_dir, &self.name, self.env.seed(), self.env.info().episode);
        let written = std::fs::create_dir_all(&self.record_dir).and_then(|()| replay.save(&path));
        match written {
            Ok(()) => {
                // Not `println!`: with stdout closed (a page opened by a script that stopped
                // reading) it would panic the clock thread and stop the match.
                let _ = writeln!(std::io::stdout(), "recorded {}", path.display());
                self.saved = Some(path);
            }
            Err(e) => {
                let message = format!("cannot write the replay {}: {e}", path.display());
                let _ = writeln!(std::io::stderr(), "error: {message}");
                self.error = Some(message);
            }
        }
    }

    /// Starts the next episode (an unfinished one is not saved).
    pub(crate) fn restart(&mut self) {
        if let Err(e) = self.env.reset() {
            self.error = Some(e.to_string());
            self.phase = Phase::FullTime;
            self.version += 1;
            return;
        }
        self.recorder = Recorder::start(&self.env).with_scripts(self.scripts.iter().cloned());
        self.controllers.iter_mut().for_each(HumanController::new_episode);
        if let Some(p) = &mut self.policy {
            p.observe(&self.env, false);
        }
        self.events.clear();
        self.error = None;
        self.phase = Phase::Playing;
        self.capture();
    }

    /// What the page shows.
    pub(crate) fn state(&self) -> LiveState<'_> {
        let m = |cm: i16| f32::from(cm) / 100.0;
        let f = &self.frame;
        let info = self.env.info();
        let side = self.side();
        let stats = &self.env.game().stats().teams[side as usize];
        LiveState {
            version: self.version,
            scenario: &self.name,
            description: &self.env.scenario().description,
            phase: self.phase,
            side: side.name(),
            builtin_ai: self.controllers.first().is_some_and(HumanController::builtin),
            episode: info.episode,
            step: info.steps,
            steps_left: info.steps_left,
            roster: &self.roster,
            ball: [m(f.ball[0]), m(f.ball[1]), m(f.ball[2])],
            players: f.players.iter().map(|p| [m(p[0]), m(p[1])]).collect(),
            owner: f.owner.map_or(-1, i32::from),
            controlled: f.controlled.clone(),
            score: f.score,
            mode: info.game_mode.name(),
            last_action: self.last_actions[self.people[0]].name(),
            policy_connected: self.policy.as_ref().map(PolicySocket::connected),
            controllers: self
                .people
                .iter()
                .zip(&self.controllers)
                .map(|(&seat, c)| {
                    let side = self.env.controller_sides().nth(seat).unwrap_or(Side::Left);
                    let a = self.last_actions[seat];
                    let team = &self.env.game().stats().teams[side as usize];
                    ControllerState {
                        side: side.name(),
                        builtin_ai: c.builtin(),
                        last_action: a.name(),
                        passes: team.passes,
                        shots: team.shots,
                    }
                })
                .collect(),
            passes: stats.passes,
            shots: stats.shots,
            events: &self.events,
            saved: self.saved.as_ref().map(|p| p.display().to_string()),
            error: self.error.as_deref(),
        }
    }
}

/// `DIR/play_<scenario>_seed<S>_ep<E>.tlreplay`, with `_2`, `_3`, … added when that file exists
/// (a second session with the same seed keeps the first one's matches).
fn free_name(dir: &Path, scenario: &str, seed: u64, episode: u64) -> PathBuf {
    let stem = format!("play_{scenario}_seed{seed}_ep{episode}");
    let mut path = dir.join(format!("{stem}.tlreplay"));
    let mut k = 2;
    while path.exists() {
        path = dir.join(format!("{stem}_{k}.tlreplay"));
        k += 1;
    }
    path
}

#[cfg(test)]
mod tests {
    use touchline_engine::{EnvConfig, Scenario};

    use super::*;

    fn live(name: &str, dir: &Path) -> LiveMatch {
        live_with(name, dir, 1, 0)
    }

    /// A match with `left_agents` and `right_agents` people on each side.
    fn live_with(name: &str, dir: &Path, left_agents: usize, right_agents: usize) -> LiveMatch {
        let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let scenario: Scenario = serde_json::from_str(&std::fs::read_to_string(path).expect("read")).expect("json");
        let config =
            EnvConfig { left_agents, right_agents, action_set: touchline_engine::ActionSet::V2, checkpoints: false };
        let env = Env::with_config(scenario, config, 0).expect("env");
        LiveMatch::new(env, Vec::new(), dir.to_path_buf(), name.to_string(), None)
    }

    fn send(live: &mut LiveMatch, held: &[&str], pressed: &[&str]) {
        let message = InputMessage {
            player: 0,
            held: held.iter().map(|s| s.to_string()).collect(),
            pressed: pressed.iter().map(|s| s.to_string()).collect(),
        };
        live.input(&message).expect("input");
    }

    /// The Chromium test's key sequence (run right, then a shot held for a few steps) scores in
    /// academy_empty_goal_close for any timing the browser may give it, and the match is saved.
    #[test]
    fn running_right_and_shooting_scores_in_the_empty_goal_drill_and_is_recorded() {
        for run_steps in 3..12 {
            for shot_steps in 1..5 {
                let dir = tempfile::tempdir().expect("tempdir");
                let mut live = live("academy_empty_goal_close", dir.path());
                assert_eq!(live.state().phase, Phase::KickOff);
                send(&mut live, &["right"], &[]);
                (0..run_steps).for_each(|_| live.tick());
                send(&mut live, &["right", "shot"], &[]);
                (0..shot_steps).for_each(|_| live.tick());
                send(&mut live, &[], &[]);
                (0..40).for_each(|_| live.tick());
                let state = live.state();
                assert_eq!(state.score, [1, 0], "run {run_steps}, shot {shot_steps}");
                assert_eq!(state.phase, Phase::FullTime);
                let saved = state.saved.expect("saved");
                let replay = crate::cmd::replay::load(Path::new(&saved)).expect("load");
                crate::cmd::replay::verify(Path::new(&saved), &replay).expect("re-simulates");
            }
        }
    }

    /// On the right team the arrows still mean the screen's directions.
    #[test]
    fn the_right_team_runs_where_the_arrow_points_on_screen() {
        let dir = tempfile::tempdir().expect("tempdir");
        let mut live = live_with("academy_3_vs_1_with_keeper", dir.path(), 0, 1);
        let player = usize::from(live.state().controlled[0]);
        let before = live.state().players[player];
        send(&mut live, &["up"], &[]);
        (0..8).for_each(|_| live.tick());
        let after = live.state().players[player];
        assert_eq!(live.state().side, "right");
        assert!(before[1] - after[1] > 1.0 && (after[0] - before[0]).abs() < 1.0, "{before:?} -> {after:?}");
    }

    /// Two people, one per team: each message moves its sender's player only.
    #[test]
    fn two_people_each_move_their_own_player() {
        let dir = tempfile::tempdir().expect("tempdir");
        let mut live = live_with("academy_3_vs_1_with_keeper", dir.path(), 1, 1);
        let state = live.state();
        let (left, right) = (usize::from(state.controlled[0]), usize::from(state.controlled[1]));
        let before = (state.players[left], state.players[right]);
        let message = InputMessage { player: 1, held: vec!["down".into()], pressed: Vec::new() };
        live.input(&message).expect("input");
        (0..8).for_each(|_| live.tick());
        let state = live.state();
        assert_eq!(state.controllers.len(), 2);
        assert_eq!((state.controllers[0].side, state.controllers[1].side), ("left", "right"));
        assert!(state.players[right][1] - before.1[1] > 1.0, "the right player ran down the screen");
        assert!((state.players[left][1] - before.0[1]).abs() < 0.5, "the left player stood");
        let message = InputMessage { player: 2, held: Vec::new(), pressed: Vec::new() };
        assert!(live.input(&message).unwrap_err().contains("no player 2"));
    }

    #[test]
    fn pause_stops_the_clock_and_restart_plays_a_new_episode() {
        let dir = tempfile::tempdir().expect("tempdir");
        let mut live = live("academy_empty_goal_close", dir.path());
        live.tick();
        assert_eq!(live.state().step, 0, "no kick-off before a button");
        send(&mut live, &["right"], &[]);
        live.tick();
        send(&mut live, &["right"], &["pause"]);
        live.tick();
        assert_eq!((live.state().step, live.state().phase), (1, Phase::Paused));
        send(&mut live, &[], &["restart"]);
        assert_eq!((live.state().step, live.state().episode, live.state().phase), (0, 1, Phase::Playing));
        let bad = InputMessage { player: 0, held: vec!["jump".into()], pressed: Vec::new() };
        assert!(live.input(&bad).unwrap_err().contains("unknown button `jump`"));
    }
}
