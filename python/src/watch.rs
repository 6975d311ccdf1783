//! Hot reload for Python (`watch=True`): one [`Watched`] scenario source shared by every env made
//! from one set of arguments (an `Env`, or all the matches of a `VectorEnv`).
//!
//! The watcher recompiles on its own thread; each env switches to the newest good version at its
//! next reset ([`Watched::env_playing`]). What the watcher reports (a failed compile, a version an
//! env refused) is queued here as rendered text, and the Python wrappers turn each message into
//! one `UserWarning` when they next reset or step: Python code is never run on the watcher's
//! thread.

use std::sync::{Arc, Mutex, PoisonError};

use pyo3::prelude::*;
use touchline_dsl::Watched;
use touchline_dsl::watch::{WatchError, WatchEvent};

use crate::errors::{ScenarioError, scenario_error, script_errors};

/// The most messages kept between two drains: a file saved broken in a tight loop by a tool
/// should not grow the queue without bound.
const MAX_QUEUED: usize = 64;

/// A watched scenario and the watcher's messages not yet shown.
#[derive(Debug)]
pub(crate) struct Watch {
    pub(crate) watched: Watched,
    messages: Arc<Mutex<Vec<String>>>,
}

impl Watch {
    /// Compiles `spec` (a `.tl` or `.json` path) and starts watching it and its scripts.
    ///
    /// # Errors
    /// `ScenarioError` for a first compile that fails (as without `watch`), for a stdlib name
    /// (there is no file to watch) and for a watcher that cannot start (`tl::S007`).
    pub(crate) fn start(py: Python<'_>, spec: &str) -> PyResult<Arc<Watch>> {
        if touchline_dsl::stdlib::tl_source(spec).is_some() {
            return Err(ScenarioError::new_err(format!(
                "watch=True needs a scenario file (`.tl` or `.json`) to watch; `{spec}` is a stdlib scenario"
            )));
        }
        let watched = Watched::new(spec, touchline_dsl::script::ScriptOptions::default()).map_err(|e| match e {
            WatchError::Load(e) => scenario_error(py, &e),
            WatchError::Scripts(e) => script_errors(py, &e),
            other => {
                let exc = ScenarioError::new_err(touchline_dsl::render_plain(&other));
                match exc.value(py).setattr("code", "tl::S007") {
                    Ok(()) => exc,
                    Err(e) => e,
                }
            }
        })?;
        let messages = Arc::new(Mutex::new(Vec::new()));
        let queue = Arc::clone(&messages);
        watched.on_event(move |event| {
            let text = match event {
                WatchEvent::Failed(error) => format!(
                    "touchline: the scenario changed but does not load; the env keeps the last good version\n{}",
                    touchline_dsl::render_plain(*error)
                ),
                WatchEvent::Refused(error) => {
                    format!(
                        "touchline: the env cannot play the changed scenario and keeps the last good version: {error}"
                    )
                }
                _ => return,
            };
            let mut queue = queue.lock().unwrap_or_else(PoisonError::into_inner);
            // Every env of a vector env refuses the same version: one message.
            if queue.len() < MAX_QUEUED && queue.last() != Some(&text) {
                queue.push(text);
            }
        });
        Ok(Arc::new(Watch { watched, messages }))
    }

    /// The messages since the last call, oldest first.
    pub(crate) fn take_messages(&self) -> Vec<String> {
        std::mem::take(&mut *self.messages.lock().unwrap_or_else(PoisonError::into_inner))
    }
}
