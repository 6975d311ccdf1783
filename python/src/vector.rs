//! `touchline._touchline.VectorEnv`: many matches stepped in Rust threads (rayon) with the GIL
//! released, writing straight into the caller's numpy arrays.

use numpy::{PyReadonlyArray2, PyReadwriteArray1, PyReadwriteArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use touchline_engine::StepInfo;

use crate::core::{Autoreset, EnvArgs, EnvCore, EnvOptions, ObsOut};
use crate::errors::{engine_error, guard};
use crate::worker::{Slot, Worker};
use touchline_engine::EngineError;

/// `num_envs` matches with the same arguments and seeds `seed + i` (see `_touchline.pyi`).
///
/// The envs are cut into one contiguous run per thread: the calling thread steps the first run
/// (with the GIL released) while each [`Worker`] owns and steps one of the others.
#[pyclass(module = "touchline._touchline", name = "VectorEnv")]
pub(crate) struct PyVectorEnv {
    envs: Vec<EnvCore>,
    workers: Vec<Worker>,
    actions: Vec<u32>,
    mode: Autoreset,
    /// With `watch=True`: the watched source all the matches follow.
    watch: Option<std::sync::Arc<crate::watch::Watch>>,
}

/// The observation array the caller passed: float32 or uint8, (num_envs, M, *shape).
fn obs_buffer<'a>(obs: &'a Bound<'_, PyAny>, dtype: &str, len: usize) -> PyResult<ObsArray<'a>> {
    let wrong =
        || PyValueError::new_err(format!("observations must be a C-contiguous {dtype} array with {len} elements"));
    let array = match dtype {
        "uint8" => ObsArray::U8(obs.extract::<numpy::PyReadwriteArrayDyn<'a, u8>>().map_err(|_| wrong())?),
        "float32" => ObsArray::F32(obs.extract::<numpy::PyReadwriteArrayDyn<'a, f32>>().map_err(|_| wrong())?),
        _ => {
            return Err(PyValueError::new_err(
                "the raw representation has no vector form; use an array representation",
            ));
        }
    };
    let n = match &array {
        ObsArray::U8(a) => a.len(),
        ObsArray::F32(a) => a.len(),
    };
    if n != len {
        return Err(wrong());
    }
    Ok(array)
}

enum ObsArray<'py> {
    F32(numpy::PyReadwriteArrayDyn<'py, f32>),
    U8(numpy::PyReadwriteArrayDyn<'py, u8>),
}

/// The observation array's memory, split per env by the caller.
enum Slice<'a> {
    F32(&'a mut [f32]),
    U8(&'a mut [u8]),
}

impl PyVectorEnv {
    fn per_env_obs(&self) -> usize {
        self.envs.first().map_or(0, |e| e.env.num_controllers() * e.observation_len())
    }

    fn dtype(&self) -> &'static str {
        self.envs.first().map_or("float32", EnvCore::dtype)
    }
}

fn slice<'a>(array: &'a mut ObsArray<'_>) -> PyResult<Slice<'a>> {
    let not_contiguous = || PyValueError::new_err("observations must be C-contiguous");
    Ok(match array {
        ObsArray::F32(a) => Slice::F32(a.as_slice_mut().map_err(|_| not_contiguous())?),
        ObsArray::U8(a) => Slice::U8(a.as_slice_mut().map_err(|_| not_contiguous())?),
    })
}

/// An element type of observation arrays.
trait ObsElem: Copy + Send + Sync {
    fn out(slice: &mut [Self]) -> ObsOut<'_>;
    /// The worker slot's buffer of this type: (observations, final observations).
    fn of(slot: &Slot) -> (&[Self], &[Self]);
}

impl ObsElem for f32 {
    fn out(slice: &mut [f32]) -> ObsOut<'_> {
        ObsOut::F32(slice)
    }
    fn of(slot: &Slot) -> (&[f32], &[f32]) {
        (&slot.obs_f32, &slot.finals_f32)
    }
}

impl ObsElem for u8 {
    fn out(slice: &mut [u8]) -> ObsOut<'_> {
        ObsOut::U8(slice)
    }
    fn of(slot: &Slot) -> (&[u8], &[u8]) {
        (&slot.obs_u8, &slot.finals_u8)
    }
}

/// Columns of a vector env's info row: score left, score right, steps left, game mode, score
/// reward, checkpoint reward, event reward, script reward, script errors, steps, episode index,
/// lesson, scenario version (the order `touchline/vector.py` reads them in).
const INFO_COLUMNS: usize = 13;

/// Writes `info` and the scenario version as one row of [`INFO_COLUMNS`].
fn info_row(info: &StepInfo, version: u64, row: &mut [f64]) {
    let values = [
        f64::from(info.score[0]),
        f64::from(info.score[1]),
        f64::from(info.steps_left),
        f64::from(info.game_mode as u8),
        f64::from(info.score_reward),
        f64::from(info.checkpoint_reward),
        f64::from(info.event_reward),
        f64::from(info.script_reward),
        f64::from(info.script_errors),
        f64::from(info.steps),
        info.episode as f64,
        info.lesson as f64,
        version as f64,
    ];
    row.copy_from_slice(&values);
}

/// One vector step's flat outputs (the caller's arrays).
struct Outputs<'a, T> {
    rewards: &'a mut [f32],
    terminated: &'a mut [bool],
    truncated: &'a mut [bool],
    obs: &'a mut [T],
    finals: Option<&'a mut [T]>,
}

impl<T: ObsElem> Outputs<'_, T> {
    /// Steps the calling thread's envs (the first ones) straight into the outputs.
    fn step_own(
        &mut self,
        envs: &mut [EnvCore],
        actions: &[u32],
        mode: Autoreset,
        m: usize,
        per_env: usize,
    ) -> Result<(), EngineError> {
        for (i, e) in envs.iter_mut().enumerate() {
            let obs = T::out(&mut self.obs[i * per_env..(i + 1) * per_env]);
            let finals = self.finals.as_deref_mut().map(|f| T::out(&mut f[i * per_env..(i + 1) * per_env]));
            let (terminated, truncated) =
                e.vector_step(&actions[i * m..(i + 1) * m], mode, &mut self.rewards[i * m..(i + 1) * m], obs, finals)?;
            self.terminated[i] = terminated;
            self.truncated[i] = truncated;
        }
        Ok(())
    }

    /// Copies a worker's results for envs `first..first + slot.envs.len()` into the outputs.
    fn copy_from(&mut self, slot: &Slot, first: usize, m: usize, per_env: usize) {
        let n = slot.envs.len();
        let (obs, finals) = T::of(slot);
        self.rewards[first * m..(first + n) * m].copy_from_slice(&slot.rewards);
        self.terminated[first..first + n].copy_from_slice(&slot.terminated);
        self.truncated[first..first + n].copy_from_slice(&slot.truncated);
        self.obs[first * per_env..(first + n) * per_env].copy_from_slice(obs);
        if let Some(f) = self.finals.as_deref_mut() {
            for i in 0..n {
                if slot.mode == Autoreset::SameStep && (slot.terminated[i] || slot.truncated[i]) {
                    let range = (first + i) * per_env..(first + i + 1) * per_env;
                    f[range].copy_from_slice(&finals[i * per_env..(i + 1) * per_env]);
                }
            }
        }
    }
}

impl PyVectorEnv {
    /// Steps every env: workers start, the calling thread steps its own run, then the workers'
    /// results are copied in.
    fn step_all<T: ObsElem>(&mut self, mut out: Outputs<'_, T>, m: usize, per_env: usize) -> Result<(), EngineError> {
        let own = self.envs.len();
        let mut first = own;
        for w in &self.workers {
            let mut slot = w.slot();
            let k = slot.envs.len();
            slot.actions.copy_from_slice(&self.actions[first * m..(first + k) * m]);
            drop(slot);
            w.start();
            first += k;
        }
        let result = out.step_own(&mut self.envs, &self.actions[..own * m], self.mode, m, per_env);
        let mut first = own;
        let mut failure = result.err();
        for w in &self.workers {
            w.wait();
            let mut slot = w.slot();
            if let Some(e) = slot.error.take() {
                failure.get_or_insert(e);
            }
            out.copy_from(&slot, first, m, per_env);
            first += slot.envs.len();
        }
        failure.map_or(Ok(()), Err)
    }
}

#[pymethods]
impl PyVectorEnv {
    #[new]
    #[pyo3(signature = (scenario, num_envs, options, *, num_threads = 0, seed = 0, autoreset_mode = "SameStep"))]
    fn new(
        py: Python<'_>,
        scenario: &str,
        num_envs: usize,
        options: &Bound<'_, PyAny>,
        num_threads: usize,
        seed: u64,
        autoreset_mode: &str,
    ) -> PyResult<PyVectorEnv> {
        guard(|| {
            let mode = Autoreset::parse(autoreset_mode)?;
            if num_envs == 0 {
                return Err(PyValueError::new_err("num_envs must be at least 1"));
            }
            let args = EnvArgs::parse(py, scenario, &EnvOptions::read(options)?)?;
            if args.representation == crate::core::Representation::Raw {
                return Err(PyValueError::new_err(
                    "the raw representation has no vector form; use an array representation",
                ));
            }
            let mut envs = (0..num_envs)
                .map(|i| EnvCore::new(&args, seed.wrapping_add(i as u64)))
                .collect::<Result<Vec<_>, _>>()
                .map_err(engine_error)?;
            let threads = if num_threads == 0 {
                std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
            } else {
                num_threads
            };
            // One contiguous run per thread, at most one thread per env; the calling thread keeps
            // the first run.
            let threads = threads.clamp(1, num_envs.max(1));
            let run = num_envs.div_ceil(threads);
            let mut rest = envs.split_off(run.min(num_envs));
            let mut workers = Vec::new();
            while !rest.is_empty() {
                let tail = rest.split_off(run.min(rest.len()));
                let worker = Worker::spawn(rest, mode)
                    .map_err(|e| PyValueError::new_err(format!("cannot start {threads} threads: {e}")))?;
                workers.push(worker);
                rest = tail;
            }
            Ok(PyVectorEnv { envs, workers, actions: Vec::new(), mode, watch: args.watch })
        })
    }

    /// What the watcher reported since the last call, as rendered text; empty without `watch=True`.
    fn watch_messages(&self) -> Vec<String> {
        self.watch.as_ref().map(|w| w.take_messages()).unwrap_or_default()
    }

    #[getter]
    fn num_envs(&self) -> usize {
        self.envs.len() + self.workers.iter().map(|w| w.slot().envs.len()).sum::<usize>()
    }

    #[getter]
    fn num_controllers(&self) -> usize {
        self.envs[0].env.num_controllers()
    }

    #[getter]
    fn controller_sides(&self) -> Vec<&'static str> {
        self.envs[0].env.controller_sides().map(touchline_engine::Side::name).collect()
    }

    #[getter]
    fn action_count(&self) -> usize {
        self.envs[0].env.action_set().len()
    }

    #[getter]
    fn observation_shape<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyTuple>> {
        pyo3::types::PyTuple::new(py, self.envs[0].observation_shape())
    }

    #[getter]
    fn observation_dtype(&self) -> &'static str {
        self.dtype()
    }

    /// Resets every match, or with `mask` only those where it is true; match `i` is reseeded with
    /// `seed + i` when a seed is given. Writes the reset matches' first observations.
    #[pyo3(signature = (observations, seed = None, mask = None))]
    fn reset(
        &mut self,
        py: Python<'_>,
        observations: &Bound<'_, PyAny>,
        seed: Option<u64>,
        mask: Option<Vec<bool>>,
    ) -> PyResult<()> {
        guard(|| {
            let per_env = self.per_env_obs().max(1);
            let n = self.num_envs();
            if mask.as_ref().is_some_and(|m| m.len() != n) {
                return Err(PyValueError::new_err(format!("the reset mask must have {n} entries, one per match")));
            }
            let mut array = obs_buffer(observations, self.dtype(), per_env * n)?;
            let out = slice(&mut array)?;
            // A reset happens once per run (episodes reset inside `step`): it runs serially.
            let (own, workers) = (&mut self.envs, &self.workers);
            // Every chosen match is reset even when one fails (a script's `reset` hook); the
            // first failure is raised, and the failed match stays ended (see `ended`).
            let failed = py.detach(|| {
                let mut guards: Vec<_> = workers.iter().map(Worker::slot).collect();
                let envs = own.iter_mut().chain(guards.iter_mut().flat_map(|g| g.envs.iter_mut()));
                let chosen = |i: usize| mask.as_ref().is_none_or(|m| m[i]);
                let mut failed = None;
                match out {
                    Slice::F32(s) => {
                        for (i, (e, o)) in envs.zip(s.chunks_mut(per_env)).enumerate().filter(|(i, _)| chosen(*i)) {
                            if let Err(err) = e.reset(seed.map(|s| s.wrapping_add(i as u64))) {
                                failed.get_or_insert(err);
                            }
                            e.write_observations(ObsOut::F32(o), true);
                        }
                    }
                    Slice::U8(s) => {
                        for (i, (e, o)) in envs.zip(s.chunks_mut(per_env)).enumerate().filter(|(i, _)| chosen(*i)) {
                            if let Err(err) = e.reset(seed.map(|s| s.wrapping_add(i as u64))) {
                                failed.get_or_insert(err);
                            }
                            e.write_observations(ObsOut::U8(o), true);
                        }
                    }
                }
                failed
            });
            failed.map_or(Ok(()), |e| Err(engine_error(e)))
        })
    }

    /// Which matches ended on their last step and have not been reset since (always none in
    /// the SameStep mode), env order.
    fn ended(&self) -> Vec<bool> {
        let guards: Vec<_> = self.workers.iter().map(Worker::slot).collect();
        self.envs.iter().chain(guards.iter().flat_map(|g| g.envs.iter())).map(|e| e.ended).collect()
    }

    /// Every env's whole state (engine snapshot plus stacked frames), env order.
    fn get_states<'py>(&self, py: Python<'py>) -> Vec<Bound<'py, pyo3::types::PyBytes>> {
        let guards: Vec<_> = self.workers.iter().map(Worker::slot).collect();
        let envs = self.envs.iter().chain(guards.iter().flat_map(|g| g.envs.iter()));
        envs.map(|e| pyo3::types::PyBytes::new(py, &e.state_bytes())).collect()
    }

    /// Restores `get_states` of a vector env built with the same arguments, and with `ended`
    /// (from [`PyVectorEnv::ended`]) which matches wait for their reset.
    #[pyo3(signature = (states, ended = None))]
    fn set_states(&mut self, states: Vec<Vec<u8>>, ended: Option<Vec<bool>>) -> PyResult<()> {
        guard(|| {
            let n = self.num_envs();
            if states.len() != n || ended.as_ref().is_some_and(|e| e.len() != n) {
                return Err(PyValueError::new_err(format!("expected {n} states and ended flags")));
            }
            let mut guards: Vec<_> = self.workers.iter().map(Worker::slot).collect();
            let envs = self.envs.iter_mut().chain(guards.iter_mut().flat_map(|g| g.envs.iter_mut()));
            for (i, (e, state)) in envs.zip(&states).enumerate() {
                e.restore_bytes(state).map_err(engine_error)?;
                e.ended = ended.as_ref().is_some_and(|flags| flags[i]);
            }
            Ok(())
        })
    }

    /// Writes each env's step info, one row per env of [`INFO_COLUMNS`] float64 columns: the
    /// current one into `current` (for an env that just ended, its next episode's) and that of the
    /// step that ended its last episode into `finals`.
    fn infos(&self, mut current: PyReadwriteArray2<'_, f64>, mut finals: PyReadwriteArray2<'_, f64>) -> PyResult<()> {
        guard(|| {
            let n = self.num_envs();
            if current.shape() != [n, INFO_COLUMNS] || finals.shape() != [n, INFO_COLUMNS] {
                return Err(PyValueError::new_err(format!("info arrays must be float64 ({n}, {INFO_COLUMNS})")));
            }
            let contiguous = || PyValueError::new_err("arrays must be C-contiguous");
            let current = current.as_slice_mut().map_err(|_| contiguous())?;
            let finals = finals.as_slice_mut().map_err(|_| contiguous())?;
            let guards: Vec<_> = self.workers.iter().map(Worker::slot).collect();
            let envs = self.envs.iter().chain(guards.iter().flat_map(|g| g.envs.iter()));
            for ((e, row), final_row) in envs.zip(current.chunks_mut(INFO_COLUMNS)).zip(finals.chunks_mut(INFO_COLUMNS))
            {
                info_row(e.env.info(), e.scenario_version(), row);
                info_row(&e.final_info, e.final_version, final_row);
            }
            Ok(())
        })
    }

    #[pyo3(signature = (actions, observations, rewards, terminated, truncated, final_observations = None))]
    #[expect(clippy::too_many_arguments, reason = "every output array is the caller's")]
    fn step(
        &mut self,
        py: Python<'_>,
        actions: PyReadonlyArray2<'_, i64>,
        observations: &Bound<'_, PyAny>,
        mut rewards: PyReadwriteArray2<'_, f32>,
        mut terminated: PyReadwriteArray1<'_, bool>,
        mut truncated: PyReadwriteArray1<'_, bool>,
        final_observations: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<()> {
        guard(|| {
            let n = self.num_envs();
            let m = self.envs[0].env.num_controllers();
            let limit = self.envs[0].env.action_set().len();
            if actions.shape() != [n, m] {
                return Err(PyValueError::new_err(format!(
                    "actions must have shape ({n}, {m}), got {:?}",
                    actions.shape()
                )));
            }
            if rewards.shape() != [n, m] || terminated.len() != n || truncated.len() != n {
                return Err(PyValueError::new_err(format!(
                    "rewards must be float32 ({n}, {m}); terminated and truncated bool ({n},)"
                )));
            }
            let contiguous = || PyValueError::new_err("arrays must be C-contiguous");
            self.actions.clear();
            for &a in actions.as_slice().map_err(|_| contiguous())? {
                match u32::try_from(a) {
                    Ok(v) if (v as usize) < limit => self.actions.push(v),
                    _ => {
                        return Err(PyValueError::new_err(format!(
                            "action {a} is outside the action set (0..{limit})"
                        )));
                    }
                }
            }
            if self.mode == Autoreset::Disabled
                && let Some(i) = self.ended().iter().position(|&e| e)
            {
                return Err(PyValueError::new_err(format!(
                    "match {i} ended on the last step and autoreset is disabled; reset it first with \
                     reset(options={{\"reset_mask\": mask}})"
                )));
            }
            let per_env = self.per_env_obs().max(1);
            let mut array = obs_buffer(observations, self.dtype(), per_env * n)?;
            let mut finals = final_observations.map(|f| obs_buffer(f, self.dtype(), per_env * n)).transpose()?;
            let out = slice(&mut array)?;
            let final_out = finals.as_mut().map(slice).transpose()?;
            let rewards = rewards.as_slice_mut().map_err(|_| contiguous())?;
            let terminated = terminated.as_slice_mut().map_err(|_| contiguous())?;
            let truncated = truncated.as_slice_mut().map_err(|_| contiguous())?;
            let result = py.detach(|| match (out, final_out) {
                (Slice::F32(obs), finals) => {
                    let finals = match finals {
                        Some(Slice::F32(f)) => Some(f),
                        _ => None,
                    };
                    self.step_all(Outputs { rewards, terminated, truncated, obs, finals }, m, per_env)
                }
                (Slice::U8(obs), finals) => {
                    let finals = match finals {
                        Some(Slice::U8(f)) => Some(f),
                        _ => None,
                    };
                    self.step_all(Outputs { rewards, terminated, truncated, obs, finals }, m, per_env)
                }
            });
            result.map_err(engine_error)
        })
    }
}
