//! `touchline._touchline.Env`: one match for Python.

use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBytes, PyDict, PyList, PyTuple};
use touchline_engine::{Side, StepInfo};
use touchline_render::{RenderOptions, Renderer, Scene};

use crate::convert::{dict_with_keys, raw_to_dict};
use crate::core::{EnvArgs, EnvCore, EnvOptions, ObsOut};
use crate::errors::{engine_error, guard};
use crate::recording::Recording;

/// What `Env.step` returns: (observation, rewards, terminated, truncated, info).
type StepResult<'py> = (Bound<'py, PyAny>, Bound<'py, PyArray1<f32>>, bool, bool, Bound<'py, PyDict>);

/// One match: the Rust `Env` plus an observation encoder (see `_touchline.pyi`).
#[pyclass(module = "touchline._touchline", name = "Env")]
pub(crate) struct PyEnv {
    core: EnvCore,
    /// The constructor's arguments, to rebuild the env when it is unpickled.
    init: InitArgs,
    actions: Vec<u32>,
    /// The renderer of `render()`, made at the first call (and again for another size).
    renderer: Option<Renderer>,
    /// With `watch=True`: the watched source (its messages for `watch_messages`).
    watch: Option<std::sync::Arc<crate::watch::Watch>>,
    /// The scenario's compiled scripts (their text goes into replays).
    scripts: touchline_dsl::script::Scripts,
    /// While recording is on (`start_recording`): the episode's replay so far.
    recording: Option<Recording>,
}

/// What an `Env` was made with (see [`PyEnv::__getnewargs_ex__`]).
struct InitArgs {
    scenario: String,
    /// The `touchline.EnvOptions` object itself, pickled with the env.
    options: Py<PyAny>,
    seed: u64,
}

/// Reads one action index per controller from an int, a sequence or a numpy array.
pub(crate) fn read_actions(actions: &Bound<'_, PyAny>, expected: usize, out: &mut Vec<u32>) -> PyResult<()> {
    out.clear();
    let action =
        |a: i64| u32::try_from(a).map_err(|_| PyValueError::new_err(format!("action {a} is negative or too large")));
    // The common case, a contiguous int64 array (the compat layer's and most trainers'), is read in
    // place: extracted as a sequence it made a numpy scalar per element, a microsecond a step.
    let array = actions.cast::<PyArray1<i64>>().ok().and_then(|a| a.try_readonly().ok());
    if let Some(values) = array.as_ref().and_then(|a| a.as_slice().ok()) {
        for &a in values {
            out.push(action(a)?);
        }
    } else if let Ok(a) = actions.extract::<i64>() {
        out.push(action(a)?);
    } else {
        let values: Vec<i64> = actions.extract().map_err(|_| {
            PyValueError::new_err("actions must be an int or a sequence / 1-D array of ints, one per controlled player")
        })?;
        for a in values {
            out.push(action(a)?);
        }
    }
    if out.len() != expected {
        return Err(PyValueError::new_err(format!(
            "expected {expected} actions (one per controlled player), got {}",
            out.len()
        )));
    }
    Ok(())
}

/// The keys `info_dict` sets, in its order.
const INFO_KEYS: [&str; 11] = [
    "score",
    "steps_left",
    "game_mode",
    "score_reward",
    "checkpoint_reward",
    "event_reward",
    "script_reward",
    "script_errors",
    "steps",
    "episode_index",
    "lesson",
];
static INFO_TEMPLATE: PyOnceLock<Py<PyDict>> = PyOnceLock::new();

pub(crate) fn info_dict<'py>(py: Python<'py>, info: &StepInfo) -> PyResult<Bound<'py, PyDict>> {
    let d = dict_with_keys(py, &INFO_TEMPLATE, &INFO_KEYS)?;
    d.set_item(intern!(py, "score"), vec![info.score[0], info.score[1]])?;
    d.set_item(intern!(py, "steps_left"), info.steps_left)?;
    d.set_item(intern!(py, "game_mode"), info.game_mode as u8)?;
    d.set_item(intern!(py, "score_reward"), info.score_reward)?;
    d.set_item(intern!(py, "checkpoint_reward"), info.checkpoint_reward)?;
    d.set_item(intern!(py, "event_reward"), info.event_reward)?;
    d.set_item(intern!(py, "script_reward"), info.script_reward)?;
    d.set_item(intern!(py, "script_errors"), info.script_errors)?;
    d.set_item(intern!(py, "steps"), info.steps)?;
    // Not "episode": Gymnasium's RecordEpisodeStatistics and Stable-Baselines3 reserve that key for
    // episode statistics (a dict with "r", "l", "t") and fail on any other value.
    d.set_item(intern!(py, "episode_index"), info.episode)?;
    d.set_item(intern!(py, "lesson"), info.lesson)?;
    Ok(d)
}

impl PyEnv {
    fn observation<'py>(&mut self, py: Python<'py>, fresh: bool) -> PyResult<Bound<'py, PyAny>> {
        let m = self.core.env.num_controllers();
        let mut shape = vec![m];
        shape.extend(self.core.observation_shape());
        let len = m * self.core.observation_len();
        match self.core.dtype() {
            "raw" => self.raw_observations(py).map(Bound::into_any),
            "uint8" => {
                let mut buf = vec![0u8; len];
                self.core.write_observations(ObsOut::U8(&mut buf), fresh);
                Ok(PyArray1::from_vec(py, buf).reshape(shape)?.into_any())
            }
            _ => {
                let mut buf = vec![0.0f32; len];
                self.core.write_observations(ObsOut::F32(&mut buf), fresh);
                Ok(PyArray1::from_vec(py, buf).reshape(shape)?.into_any())
            }
        }
    }
}

#[pymethods]
impl PyEnv {
    #[new]
    #[pyo3(signature = (scenario, options, *, seed = 0))]
    fn new(py: Python<'_>, scenario: &str, options: &Bound<'_, PyAny>, seed: u64) -> PyResult<PyEnv> {
        guard(|| {
            let args = EnvArgs::parse(py, scenario, &EnvOptions::read(options)?)?;
            let core = EnvCore::new(&args, seed).map_err(engine_error)?;
            let scripts = args.scripts.clone();
            let watch = args.watch;
            let init = InitArgs { scenario: scenario.to_owned(), options: options.clone().unbind(), seed };
            Ok(PyEnv { core, init, watch, actions: Vec::new(), renderer: None, scripts, recording: None })
        })
    }

    #[getter]
    fn num_controllers(&self) -> usize {
        self.core.env.num_controllers()
    }

    #[getter]
    fn action_count(&self) -> usize {
        self.core.env.action_set().len()
    }

    /// GRF names of the action set's actions, in index order.
    #[getter]
    fn action_names(&self) -> Vec<&'static str> {
        self.core.env.action_set().actions().iter().map(|a| a.name()).collect()
    }

    #[getter]
    fn observation_shape<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.core.observation_shape())
    }

    #[getter]
    fn observation_dtype(&self) -> &'static str {
        self.core.dtype()
    }

    #[getter]
    fn controller_sides(&self) -> Vec<&'static str> {
        self.core.env.controller_sides().map(Side::name).collect()
    }

    #[getter]
    fn scenario_name(&self) -> String {
        self.core.env.scenario().name.clone()
    }

    /// The curriculum lesson played, `(index, name)`; `None` without a curriculum.
    #[getter]
    fn lesson(&self) -> Option<(usize, String)> {
        self.core.env.lesson().map(|(i, name)| (i, name.to_owned()))
    }

    /// The version of the scenario the env plays: 0 without `watch=True`; with it, 1 for the file
    /// as first loaded and the watcher's count of good compiles since, taken up at a reset.
    #[getter]
    fn scenario_version(&self) -> u64 {
        self.core.scenario_version()
    }

    /// What the watcher reported since the last call (failed compiles, refused versions), as
    /// rendered text, oldest first; always empty without `watch=True`.
    fn watch_messages(&self) -> Vec<String> {
        self.watch.as_ref().map(|w| w.take_messages()).unwrap_or_default()
    }

    #[getter]
    fn game_duration(&self) -> u32 {
        self.core.env.scenario().game_duration
    }

    #[pyo3(signature = (seed = None))]
    fn reset<'py>(&mut self, py: Python<'py>, seed: Option<u64>) -> PyResult<Bound<'py, PyAny>> {
        guard(|| {
            self.core.reset(seed).map_err(engine_error)?;
            if let Some(r) = &mut self.recording {
                r.restart(&self.core.env);
            }
            self.observation(py, true)
        })
    }

    fn step<'py>(&mut self, py: Python<'py>, actions: &Bound<'py, PyAny>) -> PyResult<StepResult<'py>> {
        guard(|| {
            let mut buf = std::mem::take(&mut self.actions);
            let read = read_actions(actions, self.core.env.num_controllers(), &mut buf);
            let outcome = read.and_then(|()| self.core.step(&buf).map_err(engine_error));
            if let (Ok(_), Some(r)) = (&outcome, &mut self.recording) {
                r.record(&self.core.env, &buf).map_err(engine_error)?;
            }
            self.actions = buf;
            let outcome = outcome?;
            let obs = self.observation(py, false)?;
            let rewards = PyArray1::from_slice(py, self.core.env.rewards());
            let info = info_dict(py, self.core.env.info())?;
            info.set_item(intern!(py, "scenario_version"), self.core.scenario_version())?;
            if let Some((_, name)) = self.core.env.lesson() {
                info.set_item("lesson_name", name)?;
            }
            let log = self.core.env.hook_log();
            if !log.is_empty() {
                info.set_item("script_log", log.to_vec())?;
            }
            Ok((obs, rewards, outcome.terminated, outcome.truncated, info))
        })
    }

    /// The whole state of the episode as bytes (engine snapshot plus stacked frames).
    fn get_state<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        guard(|| Ok(PyBytes::new(py, &self.core.state_bytes())))
    }

    /// Restores a state from `get_state` of an env built with the same arguments.
    fn set_state(&mut self, state: &[u8]) -> PyResult<()> {
        guard(|| {
            self.core.restore_bytes(state).map_err(engine_error)?;
            if let Some(r) = &mut self.recording {
                r.restart(&self.core.env);
            }
            Ok(())
        })
    }

    /// Starts recording the episode from the current state (from its start right after a reset;
    /// mid-episode from a snapshot of the state). Recording goes on, restarting at every reset,
    /// until `stop_recording`.
    fn start_recording(&mut self) -> PyResult<()> {
        guard(|| {
            // With watch=True, the scripts of the newest good build (the ones the next reset
            // takes up).
            let scripts = match &self.watch {
                Some(w) => w.watched.current().scripts.clone(),
                None => self.scripts.clone(),
            };
            self.recording = Some(Recording::start(&self.core.env, scripts));
            Ok(())
        })
    }

    /// Stops recording and drops what was recorded.
    fn stop_recording(&mut self) {
        self.recording = None;
    }

    /// Whether recording is on.
    #[getter]
    fn recording(&self) -> bool {
        self.recording.is_some()
    }

    /// Steps recorded in the current episode (0 when recording is off).
    #[getter]
    fn recorded_steps(&self) -> usize {
        self.recording.as_ref().map_or(0, Recording::steps)
    }

    /// Attaches named numbers to the next step (the one the next `step` call plays), in order.
    fn record_values(&mut self, values: Vec<(String, f64)>) -> PyResult<()> {
        guard(|| {
            let Some(r) = &mut self.recording else {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "recording is off: call start_recording() first (or wrap the env in touchline.RecordReplay)",
                ));
            };
            if let Some((name, _)) = values.iter().find(|(name, _)| name.is_empty() || name.len() > 64) {
                return Err(PyValueError::new_err(format!(
                    "value names must be 1 to 64 characters long, got {name:?}"
                )));
            }
            for (name, value) in &values {
                r.value(name, *value as f32);
            }
            Ok(())
        })
    }

    /// Writes the episode recorded so far to `path` as a `.tlreplay` file (whole or not at all).
    fn save_replay(&self, path: std::path::PathBuf) -> PyResult<()> {
        guard(|| {
            let Some(r) = &self.recording else {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "recording is off: call start_recording() before playing the episode \
                     (or wrap the env in touchline.RecordReplay)",
                ));
            };
            r.save(&path).map_err(|e| {
                pyo3::exceptions::PyOSError::new_err(format!("cannot write the replay {}: {e}", path.display()))
            })
        })
    }

    /// Writes frames `first..=last` of the episode recorded so far (frame 0 is the recording's
    /// start, frame k the state after its k-th step) as a replay starting at `first`.
    fn save_replay_clip(&self, path: std::path::PathBuf, first: usize, last: usize) -> PyResult<()> {
        guard(|| {
            let Some(r) = &self.recording else {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "recording is off: call start_recording() before playing the episode",
                ));
            };
            r.save_clip(&path, first, last).map_err(|e| match e {
                crate::recording::ClipError::Replay(e) => {
                    PyValueError::new_err(format!("cannot cut frames {first}..={last}: {e}"))
                }
                crate::recording::ClipError::Write(e) => {
                    pyo3::exceptions::PyOSError::new_err(format!("cannot write the replay {}: {e}", path.display()))
                }
            })
        })
    }

    /// A 32-bit hash of the exact match state (the one replays store after every step).
    fn state_hash(&self) -> u32 {
        touchline_render::replay::state_hash(self.core.env.game())
    }

    /// Pickling (protocol 2 and up): the constructor's arguments ...
    fn __getnewargs_ex__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyTuple>, Bound<'py, PyDict>)> {
        let i = &self.init;
        let kwargs = PyDict::new(py);
        kwargs.set_item("seed", i.seed)?;
        let args = PyTuple::new(py, [i.scenario.clone().into_pyobject(py)?.into_any(), i.options.bind(py).clone()])?;
        Ok((args, kwargs))
    }

    /// ... and the episode's state, so an unpickled env goes on where this one is (in another
    /// process too: SuperSuit's and RLlib's workers).
    fn __getstate__<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        PyBytes::new(py, &self.core.state_bytes())
    }

    fn __setstate__(&mut self, state: &[u8]) -> PyResult<()> {
        self.set_state(state)
    }

    /// The match drawn from above: a `(height, width, 3)` uint8 RGB image with the scoreboard,
    /// every agent-driven player ringed in yellow.
    #[pyo3(signature = (width = 1280, height = 720))]
    fn render<'py>(&mut self, py: Python<'py>, width: usize, height: usize) -> PyResult<Bound<'py, PyAny>> {
        guard(|| {
            let mut renderer = match self.renderer.take() {
                Some(r) if r.width() == width && r.height() == height => r,
                _ => Renderer::new(width, height, RenderOptions::default())
                    .map_err(|e| PyValueError::new_err(e.to_string()))?,
            };
            renderer.render(&Scene::of_env(&self.core.env));
            let mut rgb = vec![0u8; width * height * 3];
            renderer.write_rgb(&mut rgb);
            self.renderer = Some(renderer);
            Ok(PyArray1::from_vec(py, rgb).reshape([height, width, 3])?.into_any())
        })
    }

    fn raw_observations<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        guard(|| {
            let dicts =
                self.core.env.observations().iter().map(|o| raw_to_dict(py, o)).collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, dicts)
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "Env(scenario={:?}, representation={:?}, controllers={})",
            self.core.env.scenario().name,
            self.core.representation,
            self.core.env.num_controllers()
        )
    }
}
