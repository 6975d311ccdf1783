//! `touchline._touchline.Replay`: a `.tlreplay` file read by the Rust reader, for checking and
//! analysing recorded episodes from Python.

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use touchline_dsl::script::{ScriptOptions, Scripts};
use touchline_render::replay::{Replay, ReplayError as RustReplayError, state_hash};
use touchline_render::video::{Video, VideoOptions};

use crate::errors::{ReplayError, guard};

/// One replay file, read and checked (header, checksum, consistency) but not yet re-simulated.
#[pyclass(module = "touchline._touchline", name = "Replay", frozen)]
pub(crate) struct PyReplay {
    replay: Replay,
    path: String,
}

fn replay_error(path: &str, e: &RustReplayError) -> PyErr {
    let mut message = format!("cannot use the replay {path}: {e}");
    let mut source = std::error::Error::source(e);
    while let Some(s) = source {
        message.push_str(&format!(": {s}"));
        source = s.source();
    }
    ReplayError::new_err(message)
}

#[pymethods]
impl PyReplay {
    /// Reads `path`.
    #[new]
    fn new(py: Python<'_>, path: std::path::PathBuf) -> PyResult<PyReplay> {
        guard(|| {
            let shown = path.display().to_string();
            let bytes = std::fs::read(&path)
                .map_err(|e| pyo3::exceptions::PyOSError::new_err(format!("cannot read the replay {shown}: {e}")))?;
            let replay = py.detach(|| Replay::from_bytes(&bytes)).map_err(|e| replay_error(&shown, &e))?;
            Ok(PyReplay { replay, path: shown })
        })
    }

    /// The scenario's name.
    #[getter]
    fn scenario_name(&self) -> String {
        self.replay.scenario.name.clone()
    }

    /// Steps recorded.
    #[getter]
    fn steps(&self) -> usize {
        self.replay.steps()
    }

    /// Actions per step (controlled players).
    #[getter]
    fn controllers(&self) -> usize {
        self.replay.controllers
    }

    /// Steps the episode had played before the recording started.
    #[getter]
    fn first_step(&self) -> u32 {
        self.replay.first_step
    }

    /// Paths (as the scenario names them) of the scripts the replay carries.
    #[getter]
    fn script_paths(&self) -> Vec<String> {
        self.replay.scripts.iter().map(|s| s.path.clone()).collect()
    }

    /// The state hash stored with each frame (`steps + 1` of them; frame 0 is the start).
    #[getter]
    fn frame_hashes(&self) -> Vec<u32> {
        self.replay.frames.iter().map(|f| f.hash).collect()
    }

    /// Score `[left, right]` of each frame.
    #[getter]
    fn scores(&self) -> Vec<[u16; 2]> {
        self.replay.frames.iter().map(|f| f.score).collect()
    }

    /// GRF names of each step's actions, one list of `controllers` names per step.
    #[getter]
    fn actions(&self) -> Vec<Vec<&'static str>> {
        (0..self.replay.steps()).map(|k| self.replay.step_actions(k).iter().map(|a| a.name()).collect()).collect()
    }

    /// The recorder's per-step values, in the order they were first given: name -> float32
    /// array of shape (steps,), NaN where none was given.
    #[getter]
    fn values<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for v in &self.replay.values {
            d.set_item(&v.name, PyArray1::from_slice(py, &v.values))?;
        }
        Ok(d)
    }

    /// Re-simulates the episode in a fresh env (scripts compiled from the text the replay
    /// carries) and returns the state hash of every frame; raises `touchline.ReplayError` at the
    /// first frame that differs from the stored one.
    fn simulate(&self, py: Python<'_>) -> PyResult<Vec<u32>> {
        guard(|| {
            let sources = self.replay.scripts.iter().map(|s| (s.path.as_str(), s.text.as_str()));
            let scripts = Scripts::from_sources(&self.replay.scenario, sources, ScriptOptions::default())
                .map_err(|e| crate::errors::script_errors(py, &e))?;
            let mut hashes = Vec::with_capacity(self.replay.frames.len());
            py.detach(|| {
                self.replay.simulate_with(scripts.engine_hooks(), |env, _| hashes.push(state_hash(env.game())))
            })
            .map_err(|e| replay_error(&self.path, &e))?;
            Ok(hashes)
        })
    }

    /// Draws the replay into `path`: `NAME.gif`, `NAME.mp4` (needs `ffmpeg` on the PATH) or a
    /// folder of PNG frames, `width` × `height` pixels, every `every`th step, `fps` frames per
    /// second (10 is real time). Returns the number of frames written.
    #[pyo3(signature = (path, *, width = 640, height = 360, every = 1, fps = 10))]
    fn write_video(
        &self,
        py: Python<'_>,
        path: std::path::PathBuf,
        width: u32,
        height: u32,
        every: u32,
        fps: u32,
    ) -> PyResult<usize> {
        guard(|| {
            if !(16..=8192).contains(&width)
                || !(16..=8192).contains(&height)
                || every == 0
                || !(1..=100).contains(&fps)
            {
                return Err(pyo3::exceptions::PyValueError::new_err(format!(
                    "width and height must be 16 to 8192 pixels, every 1 or more, fps 1 to 100; \
                     got {width} x {height}, every {every}, fps {fps}"
                )));
            }
            let options = VideoOptions { width, height, every, fps };
            py.detach(|| Video::write(&self.replay, &path, options))
                .map_err(|e| pyo3::exceptions::PyOSError::new_err(e.to_string()))
        })
    }

    fn __repr__(&self) -> String {
        format!("Replay({:?}, scenario={:?}, steps={})", self.path, self.replay.scenario.name, self.replay.steps())
    }
}
