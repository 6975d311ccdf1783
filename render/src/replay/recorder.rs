//! [`Recorder`]: builds a [`Replay`] while an env plays.

use touchline_engine::{Action, Env, Role};

use super::{Frame, Replay, RosterEntry, ScriptSource, Start, StepValues};

/// Records an episode step by step. Start it right after a reset (or anywhere: mid-episode, the
/// start state is saved as a snapshot), call [`Recorder::record`] after every step with the
/// actions that were passed to it, and [`Recorder::finish`] at the end. A scripted scenario's
/// recorder needs the scripts' text ([`Recorder::with_scripts`]) for the replay to re-simulate;
/// [`Recorder::value`] attaches named numbers to a step.
///
/// Recording one step stores the actions and one [`Frame`] (about 100 bytes for 22 players before
/// compression): a small fraction of the step's own cost (see the `render` bench).
#[derive(Clone, Debug)]
pub struct Recorder {
    replay: Replay,
    /// Values given for the step about to be recorded.
    pending: Vec<(String, f32)>,
}

impl Recorder {
    /// Starts recording `env` from its current state.
    pub fn start(env: &Env) -> Recorder {
        let info = env.info();
        let start = if info.steps == 0 {
            Start::Reset { seed: env.seed(), episode: info.episode }
        } else {
            Start::Snapshot(env.snapshot().to_bytes())
        };
        let roster = env
            .game()
            .players()
            .iter()
            .map(|p| RosterEntry {
                side: p.side,
                number: u8::try_from(p.index + 1).unwrap_or(u8::MAX),
                goalkeeper: p.role == Role::GK,
            })
            .collect();
        let mut first = Frame::default();
        first.capture(env);
        let steps_hint = (env.scenario().game_duration as usize + 1).min(10_000);
        let mut frames = Vec::with_capacity(steps_hint + 1);
        frames.push(first);
        Recorder {
            replay: Replay {
                scenario: env.scenario().clone(),
                config: *env.config(),
                start,
                first_step: info.steps,
                roster,
                actions: Vec::with_capacity(steps_hint * env.num_controllers()),
                controllers: env.num_controllers(),
                frames,
                scripts: Vec::new(),
                values: Vec::new(),
            },
            pending: Vec::new(),
        }
    }

    /// Stores the text of the scenario's scripts (path as the scenario names it, rhai source).
    #[must_use]
    pub fn with_scripts(mut self, scripts: impl IntoIterator<Item = (String, String)>) -> Recorder {
        self.replay.scripts = scripts.into_iter().map(|(path, text)| ScriptSource { path, text }).collect();
        self
    }

    /// Attaches `value` under `name` to the next step recorded (the step about to be played, e.g.
    /// the value estimate of the observation the policy acted on). A name given again before that
    /// step replaces the value. Steps without a value under a name hold NaN.
    pub fn value(&mut self, name: &str, value: f32) {
        match self.pending.iter_mut().find(|(n, _)| n == name) {
            Some(slot) => slot.1 = value,
            None => self.pending.push((name.to_owned(), value)),
        }
    }

    /// Records the step `env` just played with `actions` (the slice given to
    /// [`Env::step`], one per controller).
    pub fn record(&mut self, env: &Env, actions: &[Action]) {
        self.replay.actions.extend_from_slice(actions);
        let mut frame = Frame::default();
        frame.capture(env);
        self.replay.frames.push(frame);
        let steps = self.replay.steps();
        for (name, value) in self.pending.drain(..) {
            if !self.replay.values.iter().any(|v| v.name == name) {
                self.replay.values.push(StepValues { name: name.clone(), values: vec![f32::NAN; steps - 1] });
            }
            if let Some(series) = self.replay.values.iter_mut().find(|v| v.name == name) {
                series.values.push(value);
            }
        }
        for series in &mut self.replay.values {
            series.values.resize(steps, f32::NAN);
        }
    }

    /// Steps recorded so far.
    pub fn steps(&self) -> usize {
        self.replay.steps()
    }

    /// The replay so far (for instance to cut a clip round a goal before the episode ends).
    pub fn replay(&self) -> &Replay {
        &self.replay
    }

    /// The finished replay.
    pub fn finish(self) -> Replay {
        self.replay
    }
}
