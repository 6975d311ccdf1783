//! [`Recorder`]: builds a [`Replay`] while an env plays.

use touchline_engine::{Action, Env, Role};

use super::{Frame, Replay, RosterEntry, Start};

/// Records an episode step by step. Start it right after a reset (or anywhere: mid-episode, the
/// start state is saved as a snapshot), call [`Recorder::record`] after every step with the
/// actions that were passed to it, and [`Recorder::finish`] at the end.
///
/// Recording one step stores the actions and one [`Frame`] (about 100 bytes for 22 players before
/// compression): a small fraction of the step's own cost (see the `render` bench).
#[derive(Clone, Debug)]
pub struct Recorder {
    replay: Replay,
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
            },
        }
    }

    /// Records the step `env` just played with `actions` (the slice given to
    /// [`Env::step`], one per controller).
    pub fn record(&mut self, env: &Env, actions: &[Action]) {
        self.replay.actions.extend_from_slice(actions);
        let mut frame = Frame::default();
        frame.capture(env);
        self.replay.frames.push(frame);
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
