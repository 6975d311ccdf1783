//! `touchline._touchline.VectorEnv`: many matches stepped in Rust threads (rayon) with the GIL
//! released, writing straight into the caller's numpy arrays.

use numpy::{PyReadonlyArray2, PyReadwriteArray1, PyReadwriteArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use rayon::prelude::*;

use crate::core::{EnvArgs, EnvCore, ObsOut};
use crate::errors::{engine_error, guard};

/// `num_envs` matches with the same arguments and seeds `seed + i` (see `_touchline.pyi`).
#[pyclass(module = "touchline._touchline", name = "VectorEnv")]
pub(crate) struct PyVectorEnv {
    envs: Vec<EnvCore>,
    pool: rayon::ThreadPool,
    actions: Vec<u32>,
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
}

impl ObsElem for f32 {
    fn out(slice: &mut [f32]) -> ObsOut<'_> {
        ObsOut::F32(slice)
    }
}

impl ObsElem for u8 {
    fn out(slice: &mut [u8]) -> ObsOut<'_> {
        ObsOut::U8(slice)
    }
}

/// One vector step's inputs and flat outputs.
struct Batch<'a> {
    actions: &'a [u32],
    rewards: &'a mut [f32],
    terminated: &'a mut [bool],
    truncated: &'a mut [bool],
    controllers: usize,
    per_env: usize,
}

impl Batch<'_> {
    /// Steps every env; an env that ends writes its last observation into `finals` (if given),
    /// resets, and writes its new first observation into `obs`. With one thread the work stays
    /// on the calling thread; otherwise each thread takes one contiguous run of envs.
    fn run<T: ObsElem>(
        self,
        envs: &mut [EnvCore],
        pool: &rayon::ThreadPool,
        obs: &mut [T],
        finals: Option<&mut [T]>,
    ) -> Result<(), touchline_engine::EngineError> {
        let (m, per_env) = (self.controllers, self.per_env);
        let one = |e: &mut EnvCore,
                   a: &[u32],
                   r: &mut [f32],
                   term: &mut bool,
                   trunc: &mut bool,
                   o: &mut [T],
                   f: Option<&mut [T]>|
         -> Result<(), touchline_engine::EngineError> {
            let outcome = e.step(a)?;
            r.copy_from_slice(e.env.rewards());
            *term = outcome.terminated;
            *trunc = outcome.truncated;
            let done = outcome.terminated || outcome.truncated;
            if done {
                if let Some(f) = f {
                    e.write_observations(T::out(f), false);
                }
                e.reset(None);
            }
            e.write_observations(T::out(o), done);
            Ok(())
        };
        let threads = pool.current_num_threads();
        let n = envs.len();
        let mut finals = finals;
        if threads <= 1 || n == 1 {
            let mut final_chunks = finals.as_deref_mut().map(|f| f.chunks_mut(per_env));
            for (i, e) in envs.iter_mut().enumerate() {
                let f = final_chunks.as_mut().and_then(Iterator::next);
                one(
                    e,
                    &self.actions[i * m..(i + 1) * m],
                    &mut self.rewards[i * m..(i + 1) * m],
                    &mut self.terminated[i],
                    &mut self.truncated[i],
                    &mut obs[i * per_env..(i + 1) * per_env],
                    f,
                )?;
            }
            return Ok(());
        }
        let run = n.div_ceil(threads);
        pool.install(|| {
            let work = envs
                .par_iter_mut()
                .zip(self.actions.par_chunks(m))
                .zip(self.rewards.par_chunks_mut(m))
                .zip(self.terminated.par_iter_mut().zip(self.truncated.par_iter_mut()))
                .zip(obs.par_chunks_mut(per_env))
                .with_min_len(run);
            match finals {
                Some(f) => work
                    .zip(f.par_chunks_mut(per_env))
                    .try_for_each(|(((((e, a), r), (t, u)), o), f)| one(e, a, r, t, u, o, Some(f))),
                None => work.try_for_each(|((((e, a), r), (t, u)), o)| one(e, a, r, t, u, o, None)),
            }
        })
    }
}

#[pymethods]
impl PyVectorEnv {
    #[new]
    #[pyo3(signature = (scenario, num_envs, *, num_threads = 0, representation = "simple115v2", left_agents = 1, right_agents = 0, rewards = "scoring", action_set = "default", seed = 0, stacked = false, channel_dimensions = (96, 72)))]
    #[expect(clippy::too_many_arguments, reason = "Python keyword arguments")]
    fn new(
        py: Python<'_>,
        scenario: &str,
        num_envs: usize,
        num_threads: usize,
        representation: &str,
        left_agents: usize,
        right_agents: usize,
        rewards: &str,
        action_set: &str,
        seed: u64,
        stacked: bool,
        channel_dimensions: (usize, usize),
    ) -> PyResult<PyVectorEnv> {
        guard(|| {
            if num_envs == 0 {
                return Err(PyValueError::new_err("num_envs must be at least 1"));
            }
            let args = EnvArgs::parse(
                py,
                scenario,
                representation,
                left_agents,
                right_agents,
                rewards,
                action_set,
                stacked,
                channel_dimensions,
            )?;
            if args.representation == crate::core::Representation::Raw {
                return Err(PyValueError::new_err(
                    "the raw representation has no vector form; use an array representation",
                ));
            }
            let envs = (0..num_envs)
                .map(|i| EnvCore::new(&args, seed.wrapping_add(i as u64)))
                .collect::<Result<Vec<_>, _>>()
                .map_err(engine_error)?;
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(num_threads)
                .build()
                .map_err(|e| PyValueError::new_err(format!("cannot start {num_threads} threads: {e}")))?;
            Ok(PyVectorEnv { envs, pool, actions: Vec::new() })
        })
    }

    #[getter]
    fn num_envs(&self) -> usize {
        self.envs.len()
    }

    #[getter]
    fn num_controllers(&self) -> usize {
        self.envs[0].env.num_controllers()
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

    #[pyo3(signature = (observations, seed = None))]
    fn reset(&mut self, py: Python<'_>, observations: &Bound<'_, PyAny>, seed: Option<u64>) -> PyResult<()> {
        guard(|| {
            let per_env = self.per_env_obs();
            let mut array = obs_buffer(observations, self.dtype(), per_env * self.envs.len())?;
            let out = slice(&mut array)?;
            let envs = &mut self.envs;
            let pool = &self.pool;
            let per_env = per_env.max(1);
            py.detach(|| {
                pool.install(|| match out {
                    Slice::F32(s) => {
                        envs.par_iter_mut().zip(s.par_chunks_mut(per_env)).enumerate().for_each(|(i, (e, o))| {
                            e.reset(seed.map(|s| s.wrapping_add(i as u64)));
                            e.write_observations(ObsOut::F32(o), true);
                        })
                    }
                    Slice::U8(s) => {
                        envs.par_iter_mut().zip(s.par_chunks_mut(per_env)).enumerate().for_each(|(i, (e, o))| {
                            e.reset(seed.map(|s| s.wrapping_add(i as u64)));
                            e.write_observations(ObsOut::U8(o), true);
                        })
                    }
                })
            });
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
            let n = self.envs.len();
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
                        return Err(PyValueError::new_err(format!("action {a} is outside the action set (0..{limit})")));
                    }
                }
            }
            let per_env = self.per_env_obs();
            let mut array = obs_buffer(observations, self.dtype(), per_env * n)?;
            let mut finals = final_observations.map(|f| obs_buffer(f, self.dtype(), per_env * n)).transpose()?;
            let out = slice(&mut array)?;
            let final_out = finals.as_mut().map(slice).transpose()?;
            let batch = Batch {
                actions: &self.actions,
                rewards: rewards.as_slice_mut().map_err(|_| contiguous())?,
                terminated: terminated.as_slice_mut().map_err(|_| contiguous())?,
                truncated: truncated.as_slice_mut().map_err(|_| contiguous())?,
                controllers: m,
                per_env: per_env.max(1),
            };
            let (envs, pool) = (&mut self.envs, &self.pool);
            let result = py.detach(|| match (out, final_out) {
                (Slice::F32(o), Some(Slice::F32(f))) => batch.run(envs, pool, o, Some(f)),
                (Slice::F32(o), _) => batch.run(envs, pool, o, None),
                (Slice::U8(o), Some(Slice::U8(f))) => batch.run(envs, pool, o, Some(f)),
                (Slice::U8(o), _) => batch.run(envs, pool, o, None),
            });
            result.map_err(engine_error)
        })
    }
}
