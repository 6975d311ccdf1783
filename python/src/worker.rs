//! A worker thread that owns a run of envs and steps them on request. Handing work to a sleeping
//! pool thread costs tens of microseconds, as much as stepping a dozen Academy envs, so the worker
//! spins for a short while after each step waiting for the next one, and only then parks.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use touchline_engine::EngineError;

use crate::core::{EnvCore, ObsOut};

/// How long an idle worker spins before parking.
const SPIN: Duration = Duration::from_micros(200);

/// What the worker owns, and the results of its last job. Outputs are laid out like the caller's
/// arrays (env-major), for a straight copy.
pub(crate) struct Slot {
    pub(crate) envs: Vec<EnvCore>,
    pub(crate) actions: Vec<u32>,
    pub(crate) rewards: Vec<f32>,
    pub(crate) terminated: Vec<bool>,
    pub(crate) truncated: Vec<bool>,
    pub(crate) obs_f32: Vec<f32>,
    pub(crate) obs_u8: Vec<u8>,
    pub(crate) finals_f32: Vec<f32>,
    pub(crate) finals_u8: Vec<u8>,
    pub(crate) error: Option<EngineError>,
}

struct Shared {
    slot: Mutex<Slot>,
    /// Jobs requested so far; the worker runs one per increment.
    requested: AtomicU64,
    /// Jobs finished so far.
    finished: AtomicU64,
    exit: AtomicBool,
}

/// A thread stepping its own envs.
pub(crate) struct Worker {
    shared: Arc<Shared>,
    handle: Option<JoinHandle<()>>,
}

impl Slot {
    pub(crate) fn new(envs: Vec<EnvCore>) -> Slot {
        let m: usize = envs.iter().map(|e| e.env.num_controllers()).sum();
        let obs: usize = envs.iter().map(|e| e.env.num_controllers() * e.observation_len()).sum();
        let uint8 = envs.first().is_some_and(|e| e.dtype() == "uint8");
        let (f, u) = if uint8 { (0, obs) } else { (obs, 0) };
        Slot {
            actions: vec![0; m],
            rewards: vec![0.0; m],
            terminated: vec![false; envs.len()],
            truncated: vec![false; envs.len()],
            obs_f32: vec![0.0; f],
            obs_u8: vec![0; u],
            finals_f32: vec![0.0; f],
            finals_u8: vec![0; u],
            error: None,
            envs,
        }
    }

    /// Steps every env: rewards, flags and observations into the slot; an env that ends writes
    /// its last observation into the finals, resets and writes its new first observation.
    pub(crate) fn step(&mut self) {
        self.error = None;
        let (mut a, mut o) = (0, 0);
        for (i, e) in self.envs.iter_mut().enumerate() {
            let m = e.env.num_controllers();
            let len = m * e.observation_len();
            let outcome = match e.step(&self.actions[a..a + m]) {
                Ok(outcome) => outcome,
                Err(err) => {
                    self.error = Some(err);
                    return;
                }
            };
            self.rewards[a..a + m].copy_from_slice(e.env.rewards());
            self.terminated[i] = outcome.terminated;
            self.truncated[i] = outcome.truncated;
            let done = outcome.terminated || outcome.truncated;
            if done {
                e.write_observations(out(&mut self.finals_f32, &mut self.finals_u8, o, len), false);
                e.reset(None);
            }
            e.write_observations(out(&mut self.obs_f32, &mut self.obs_u8, o, len), done);
            a += m;
            o += len;
        }
    }
}

/// The observation range `[at, at + len)` of whichever buffer is in use.
fn out<'a>(f: &'a mut [f32], u: &'a mut [u8], at: usize, len: usize) -> ObsOut<'a> {
    if f.is_empty() { ObsOut::U8(&mut u[at..at + len]) } else { ObsOut::F32(&mut f[at..at + len]) }
}

impl Worker {
    pub(crate) fn spawn(envs: Vec<EnvCore>) -> std::io::Result<Worker> {
        let shared = Arc::new(Shared {
            slot: Mutex::new(Slot::new(envs)),
            requested: AtomicU64::new(0),
            finished: AtomicU64::new(0),
            exit: AtomicBool::new(false),
        });
        let inner = Arc::clone(&shared);
        let handle = std::thread::Builder::new().name("touchline-vector".into()).spawn(move || run(&inner))?;
        Ok(Worker { shared, handle: Some(handle) })
    }

    /// The worker's envs and buffers, to fill actions before [`Worker::start`] or to read results
    /// after [`Worker::wait`].
    pub(crate) fn slot(&self) -> MutexGuard<'_, Slot> {
        self.shared.slot.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Asks for one step of every env.
    pub(crate) fn start(&self) {
        self.shared.requested.fetch_add(1, Ordering::Release);
        if let Some(h) = &self.handle {
            h.thread().unpark();
        }
    }

    /// Waits until the requested step is done.
    pub(crate) fn wait(&self) {
        let target = self.shared.requested.load(Ordering::Acquire);
        let mut spins = 0u32;
        while self.shared.finished.load(Ordering::Acquire) < target {
            spins += 1;
            if spins < 1 << 16 {
                std::hint::spin_loop();
            } else {
                std::thread::yield_now();
            }
        }
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.shared.exit.store(true, Ordering::Release);
        if let Some(h) = self.handle.take() {
            h.thread().unpark();
            let _ = h.join();
        }
    }
}

fn run(shared: &Shared) {
    let mut done = 0u64;
    loop {
        // Spin for a moment, then park until the next request or exit.
        let idle_since = Instant::now();
        while shared.requested.load(Ordering::Acquire) == done {
            if shared.exit.load(Ordering::Acquire) {
                return;
            }
            if idle_since.elapsed() < SPIN {
                std::hint::spin_loop();
            } else {
                std::thread::park_timeout(Duration::from_millis(50));
            }
        }
        let target = shared.requested.load(Ordering::Acquire);
        while done < target {
            let mut slot = shared.slot.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
            // A panic inside the engine must not kill the thread silently: report it as the
            // job's failure and stay alive.
            let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| slot.step()));
            if result.is_err() {
                slot.error = Some(EngineError::InvalidConfig { reason: "internal error in a vector worker".into() });
            }
            drop(slot);
            done += 1;
            shared.finished.store(done, Ordering::Release);
        }
    }
}
