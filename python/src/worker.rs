//! A worker thread that owns a run of envs and steps them on request. Handing work to a sleeping
//! pool thread costs tens of microseconds, as much as stepping a dozen Academy envs, so the worker
//! waits a short while after each step for the next one, and only then parks. Both sides wait
//! politely: a short busy spin, then yielding or parking, so that on a machine whose other cores
//! are busy the thread that has work gets the core (a pure spin there made two threads several
//! times slower than one).

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use touchline_engine::EngineError;

use crate::core::{Autoreset, EnvCore, ObsOut};

/// How long an idle worker waits for the next step before parking; after [`BUSY_SPIN`] it yields
/// its core while it waits.
const SPIN: Duration = Duration::from_micros(200);
/// How long either side busy-spins before yielding (worker) or parking (caller).
const BUSY_SPIN: Duration = Duration::from_micros(20);

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
    /// The vector env's autoreset mode.
    pub(crate) mode: Autoreset,
}

struct Shared {
    slot: Mutex<Slot>,
    /// Jobs requested so far; the worker runs one per increment.
    requested: AtomicU64,
    /// Jobs claimed so far, by the worker or by a caller that found one not yet started.
    claimed: AtomicU64,
    /// Jobs finished so far.
    finished: AtomicU64,
    exit: AtomicBool,
    /// The caller parked in [`Worker::wait`], to wake when a job finishes.
    waiter: Mutex<Option<std::thread::Thread>>,
}

/// A thread stepping its own envs.
pub(crate) struct Worker {
    shared: Arc<Shared>,
    handle: Option<JoinHandle<()>>,
}

impl Slot {
    pub(crate) fn new(envs: Vec<EnvCore>, mode: Autoreset) -> Slot {
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
            mode,
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
            let finals = out(&mut self.finals_f32, &mut self.finals_u8, o, len);
            let obs = out(&mut self.obs_f32, &mut self.obs_u8, o, len);
            match e.vector_step(&self.actions[a..a + m], self.mode, &mut self.rewards[a..a + m], obs, Some(finals)) {
                Ok((terminated, truncated)) => {
                    self.terminated[i] = terminated;
                    self.truncated[i] = truncated;
                }
                Err(err) => {
                    self.error = Some(err);
                    return;
                }
            }
            a += m;
            o += len;
        }
    }
}

fn out<'a>(f: &'a mut [f32], u: &'a mut [u8], at: usize, len: usize) -> ObsOut<'a> {
    if f.is_empty() { ObsOut::U8(&mut u[at..at + len]) } else { ObsOut::F32(&mut f[at..at + len]) }
}

impl Worker {
    pub(crate) fn spawn(envs: Vec<EnvCore>, mode: Autoreset) -> std::io::Result<Worker> {
        let shared = Arc::new(Shared {
            slot: Mutex::new(Slot::new(envs, mode)),
            requested: AtomicU64::new(0),
            claimed: AtomicU64::new(0),
            finished: AtomicU64::new(0),
            exit: AtomicBool::new(false),
            waiter: Mutex::new(None),
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
        // A job the worker has not started yet (its core busy elsewhere) the caller runs itself:
        // with work stealing, threads never make a step slower than one thread would.
        if target > 0
            && self.shared.claimed.compare_exchange(target - 1, target, Ordering::AcqRel, Ordering::Acquire).is_ok()
        {
            run_job(&self.shared);
            self.shared.finished.store(target, Ordering::Release);
            return;
        }
        let finished = || self.shared.finished.load(Ordering::Acquire) >= target;
        let since = Instant::now();
        while !finished() {
            if since.elapsed() < BUSY_SPIN {
                std::hint::spin_loop();
                continue;
            }
            // Park until the worker wakes us; registered before the last check, so a job that
            // finishes in between still unparks (or the check sees it).
            *lock(&self.shared.waiter) = Some(std::thread::current());
            if finished() {
                break;
            }
            std::thread::park_timeout(Duration::from_millis(1));
        }
        lock(&self.shared.waiter).take();
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
            let idle = idle_since.elapsed();
            if idle < BUSY_SPIN {
                std::hint::spin_loop();
            } else if idle < SPIN {
                std::thread::yield_now();
            } else {
                std::thread::park_timeout(Duration::from_millis(50));
            }
        }
        let target = shared.requested.load(Ordering::Acquire);
        while done < target {
            let job = done + 1;
            // The caller may have taken the job already; then it also marks it finished.
            if shared.claimed.compare_exchange(done, job, Ordering::AcqRel, Ordering::Acquire).is_ok() {
                run_job(shared);
                shared.finished.store(job, Ordering::Release);
                if let Some(waiter) = lock(&shared.waiter).take() {
                    waiter.unpark();
                }
            }
            done = job;
        }
    }
}

/// Steps the slot's envs once. A panic inside the engine must not kill the thread silently or
/// reach Python: it is reported as the job's failure.
fn run_job(shared: &Shared) {
    let mut slot = lock(&shared.slot);
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| slot.step()));
    if result.is_err() {
        slot.error = Some(EngineError::InvalidConfig { reason: "internal error in a vector worker".into() });
    }
}

/// Locks `m`, through a poisoned lock too (a panic elsewhere leaves the data usable here).
fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}
