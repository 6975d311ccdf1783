//! `Env`'s replay recording: what `start_recording`, `record_values` and `save_replay` keep.
//!
//! Nothing here runs while recording is off: `Env.step` checks one `Option` and goes on.

use std::path::Path;

use touchline_dsl::script::Scripts;
use touchline_engine::{Action, EngineError, Env};
use touchline_render::replay::{Recorder, ReplayError};

/// The recording of the episode being played, restarted at every reset while it is on.
pub(crate) struct Recording {
    recorder: Recorder,
    /// The scenario's scripts: their text goes into every replay, their hooks re-simulate clips.
    scripts: Scripts,
    /// The last step's actions, decoded from indices (reused).
    actions: Vec<Action>,
}

impl Recording {
    /// Starts recording `env` from its current state (a reset, or mid-episode from a snapshot).
    pub(crate) fn start(env: &Env, scripts: Scripts) -> Recording {
        Recording { recorder: recorder(env, &scripts), scripts, actions: Vec::with_capacity(env.num_controllers()) }
    }

    /// Starts again from `env`'s current state (after a reset or a restored state), with the same
    /// scripts.
    pub(crate) fn restart(&mut self, env: &Env) {
        self.recorder = recorder(env, &self.scripts);
    }

    /// Records the step `env` just played with the action indices `actions`.
    ///
    /// # Errors
    /// An index outside the action set (the env accepted it, so this does not happen).
    pub(crate) fn record(&mut self, env: &Env, actions: &[u32]) -> Result<(), EngineError> {
        self.actions.clear();
        for &a in actions {
            self.actions.push(env.action_set().decode(a)?);
        }
        self.recorder.record(env, &self.actions);
        Ok(())
    }

    /// Attaches `value` under `name` to the next step recorded.
    pub(crate) fn value(&mut self, name: &str, value: f32) {
        self.recorder.value(name, value);
    }

    /// Steps recorded in this episode so far.
    pub(crate) fn steps(&self) -> usize {
        self.recorder.steps()
    }

    /// Writes the episode recorded so far to `path` (whole or not at all).
    pub(crate) fn save(&self, path: &Path) -> std::io::Result<()> {
        self.recorder.replay().save(path)
    }

    /// Writes frames `first..=last` of the episode recorded so far to `path`, as a replay that
    /// starts from a snapshot at `first` (GRF's goal dumps).
    pub(crate) fn save_clip(&self, path: &Path, first: usize, last: usize) -> Result<(), ClipError> {
        let clip = self.recorder.replay().clip_with(self.scripts.engine_hooks(), first, last)?;
        clip.save(path).map_err(ClipError::Write)
    }
}

/// Why a clip could not be saved.
pub(crate) enum ClipError {
    /// The span is out of range or the episode does not re-simulate to its start.
    Replay(ReplayError),
    /// The file cannot be written.
    Write(std::io::Error),
}

impl From<ReplayError> for ClipError {
    fn from(e: ReplayError) -> ClipError {
        ClipError::Replay(e)
    }
}

/// A recorder started at `env`'s state, holding the scripts' text.
fn recorder(env: &Env, scripts: &Scripts) -> Recorder {
    Recorder::start(env).with_scripts(scripts.sources().map(|(p, t)| (p.to_owned(), t.to_owned())))
}
