//! [`Watched`]: a scenario source that recompiles itself when its files change, for hot reload.
//!
//! A background thread watches the folders of the scenario file and of every script it names
//! (folders, not files, so that an editor's save-by-rename, or a file deleted and re-created, is
//! still seen), batches bursts of writes (debounced, 100 ms), and recompiles. A good compile
//! becomes the new *generation*; a failed one is reported (see [`Watched::on_event`]) and the last
//! good generation stays. Envs built with [`Watched::env`] poll at each reset and switch, between
//! episodes and all at once, to the newest generation (scenario and scripts together): a broken
//! version never reaches a step.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::sync::{Arc, Mutex, PoisonError, Weak};
use std::time::Duration;

use miette::Diagnostic;
use notify_debouncer_full::notify::RecursiveMode;
use notify_debouncer_full::{DebounceEventResult, new_debouncer};
use thiserror::Error;
use touchline_engine::{EngineError, Env, EnvConfig, HookOutcome, HookView, Hooks, Scenario};

use crate::script::{ScriptErrors, ScriptHooks, ScriptOptions, Scripts};
use crate::{LoadError, load, script_dir};

/// Why a (re)compile failed.
#[derive(Debug, Error, Diagnostic)]
#[non_exhaustive]
pub enum WatchError {
    /// The scenario does not load.
    #[error(transparent)]
    #[diagnostic(transparent)]
    Load(#[from] LoadError),
    /// Its scripts do not load.
    #[error(transparent)]
    #[diagnostic(transparent)]
    Scripts(#[from] ScriptErrors),
    /// The file watcher could not start.
    #[error("cannot watch `{path}`: {message}")]
    #[diagnostic(code(tl::S007))]
    Watcher {
        /// The folder.
        path: String,
        /// The watcher's error.
        message: String,
    },
}

/// One good compile: the scenario and its scripts.
#[derive(Clone, Debug)]
pub struct Build {
    /// The scenario.
    pub scenario: Scenario,
    /// Its compiled scripts.
    pub scripts: Scripts,
    /// The files it was read from (scenario and scripts), which are watched.
    pub files: Vec<PathBuf>,
}

/// What the watcher reports.
#[derive(Debug)]
#[non_exhaustive]
pub enum WatchEvent<'a> {
    /// Generation `generation` compiled; envs switch to it at their next reset.
    Reloaded {
        /// The new generation (1 is the first compile).
        generation: u64,
    },
    /// A change did not compile; envs keep the last good generation.
    Failed(&'a WatchError),
    /// An env refused a new generation (another number of agents); it keeps the previous one.
    Refused(&'a EngineError),
}

type Listener = Box<dyn Fn(&WatchEvent<'_>) + Send + Sync>;

struct Shared {
    spec: String,
    options: ScriptOptions,
    /// The newest good build and its generation.
    current: Mutex<(u64, Arc<Build>)>,
    generation: AtomicU64,
    listener: Mutex<Option<Listener>>,
}

impl Shared {
    fn tell(&self, event: &WatchEvent<'_>) {
        if let Some(listener) = self.listener.lock().unwrap_or_else(PoisonError::into_inner).as_ref() {
            listener(event);
        }
    }

    fn current(&self) -> (u64, Arc<Build>) {
        let current = self.current.lock().unwrap_or_else(PoisonError::into_inner);
        (current.0, Arc::clone(&current.1))
    }
}

/// A scenario source (a `.json` or `.tl` path, as given to [`load`]) that follows edits of its files.
pub struct Watched {
    shared: Arc<Shared>,
}

impl std::fmt::Debug for Watched {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Watched").field("spec", &self.shared.spec).field("generation", &self.generation()).finish()
    }
}

fn compile(spec: &str, options: ScriptOptions) -> Result<Build, WatchError> {
    let path = Path::new(spec);
    let (scenario, mut files) = if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("tl")) {
        // A `.tl` source lists the files it read: itself and its imports.
        let compiled = crate::compile_file(path).map_err(|d| LoadError::Compile(Box::new(d)))?;
        (compiled.scenario, compiled.files)
    } else {
        (load(spec)?, vec![PathBuf::from(spec)])
    };
    let scripts = Scripts::compile(&scenario, &script_dir(spec), options)?;
    files.extend(scripts.files().iter().cloned());
    Ok(Build { scenario, scripts, files })
}

/// The folders to watch for `files` (a file's parent; `.` for a bare name).
fn folders(files: &[PathBuf]) -> BTreeSet<PathBuf> {
    files
        .iter()
        .map(|f| match f.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        })
        .collect()
}

/// Whether `event_path` is one of `files` (compared by file name within the same folder, so that
/// relative and absolute spellings match).
fn concerns(files: &[PathBuf], event_path: &Path) -> bool {
    files.iter().any(|f| {
        f.file_name() == event_path.file_name()
            && match (std::fs::canonicalize(f.parent().unwrap_or(Path::new("."))), event_path.parent()) {
                (Ok(a), Some(b)) => std::fs::canonicalize(b).is_ok_and(|b| a == b),
                _ => true,
            }
    })
}

impl Watched {
    /// Compiles `spec` and starts watching its files.
    ///
    /// # Errors
    /// The first compile's diagnostics (nothing is watched then), or a watcher that cannot start.
    pub fn new(spec: &str, options: ScriptOptions) -> Result<Watched, WatchError> {
        let build = compile(spec, options)?;
        let watched_folders = folders(&build.files);
        let shared = Arc::new(Shared {
            spec: spec.to_owned(),
            options,
            current: Mutex::new((1, Arc::new(build))),
            generation: AtomicU64::new(1),
            listener: Mutex::new(None),
        });
        let (tx, rx) = channel();
        let mut debouncer = new_debouncer(Duration::from_millis(100), None, tx)
            .map_err(|e| WatchError::Watcher { path: spec.to_owned(), message: e.to_string() })?;
        for folder in &watched_folders {
            debouncer
                .watch(folder, RecursiveMode::NonRecursive)
                .map_err(|e| WatchError::Watcher { path: folder.display().to_string(), message: e.to_string() })?;
        }
        let weak = Arc::downgrade(&shared);
        std::thread::Builder::new()
            .name("touchline-watch".into())
            .spawn(move || watch_loop(&weak, &rx, debouncer, watched_folders))
            .map_err(|e| WatchError::Watcher { path: spec.to_owned(), message: e.to_string() })?;
        Ok(Watched { shared })
    }

    /// Calls `listener` (on the watcher's thread) for every reload, failed compile and refusal.
    pub fn on_event(&self, listener: impl Fn(&WatchEvent<'_>) + Send + Sync + 'static) {
        *self.shared.listener.lock().unwrap_or_else(PoisonError::into_inner) = Some(Box::new(listener));
    }

    /// The newest good generation (1 for the first compile).
    pub fn generation(&self) -> u64 {
        self.shared.generation.load(Ordering::Acquire)
    }

    /// The newest good build.
    pub fn current(&self) -> Arc<Build> {
        self.shared.current().1
    }

    /// An env on the newest build that switches to newer ones at each reset (a changed scenario is
    /// refused, and reported, when it gives another number of agents).
    ///
    /// # Errors
    /// As [`Env::with_hooks`].
    pub fn env(&self, config: EnvConfig, seed: u64) -> Result<Env, EngineError> {
        let (generation, build) = self.shared.current();
        let hooks =
            WatchedHooks { shared: Arc::clone(&self.shared), generation, inner: build.scripts.hooks(), previous: None };
        Env::with_hooks(build.scenario.clone(), config, seed, Box::new(hooks))
    }
}

/// The watcher thread: recompiles after each batch of changes to the watched files, until the
/// [`Watched`] and every env built from it are gone.
fn watch_loop(
    shared: &Weak<Shared>,
    rx: &Receiver<DebounceEventResult>,
    mut debouncer: notify_debouncer_full::Debouncer<
        notify_debouncer_full::notify::RecommendedWatcher,
        notify_debouncer_full::RecommendedCache,
    >,
    mut watching: BTreeSet<PathBuf>,
) {
    loop {
        let events = match rx.recv_timeout(Duration::from_millis(200)) {
            Ok(Ok(events)) => events,
            Ok(Err(_)) => Vec::new(),
            Err(RecvTimeoutError::Timeout) => {
                if shared.strong_count() == 0 {
                    return;
                }
                continue;
            }
            Err(RecvTimeoutError::Disconnected) => return,
        };
        let Some(shared) = shared.upgrade() else { return };
        let files = shared.current().1.files.clone();
        if !events.iter().any(|e| e.paths.iter().any(|p| concerns(&files, p))) {
            continue;
        }
        match compile(&shared.spec, shared.options) {
            Ok(build) => {
                let wanted = folders(&build.files);
                for folder in wanted.difference(&watching) {
                    // A folder that cannot be watched is reported by the next failed compile.
                    let _ = debouncer.watch(folder, RecursiveMode::NonRecursive);
                }
                watching.extend(wanted);
                let generation = {
                    let mut current = shared.current.lock().unwrap_or_else(PoisonError::into_inner);
                    *current = (current.0 + 1, Arc::new(build));
                    current.0
                };
                shared.generation.store(generation, Ordering::Release);
                shared.tell(&WatchEvent::Reloaded { generation });
            }
            Err(error) => shared.tell(&WatchEvent::Failed(&error)),
        }
    }
}

/// The hooks of an env built by [`Watched::env`]: the current build's scripts, swapped at reset.
struct WatchedHooks {
    shared: Arc<Shared>,
    generation: u64,
    inner: ScriptHooks,
    /// The hooks before the last swap, kept until the env accepts the new scenario.
    previous: Option<ScriptHooks>,
}

impl std::fmt::Debug for WatchedHooks {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("WatchedHooks").field("generation", &self.generation).field("inner", &self.inner).finish()
    }
}

impl Hooks for WatchedHooks {
    fn reset(&mut self, view: &HookView<'_>) -> Result<(), EngineError> {
        self.previous = None;
        self.inner.reset(view)
    }

    fn step(&mut self, view: &HookView<'_>, rewards: &mut [f32]) -> Result<HookOutcome, EngineError> {
        self.inner.step(view, rewards)
    }

    fn behaviour_action(
        &mut self,
        view: &HookView<'_>,
        side: touchline_engine::Side,
        player: usize,
        path: &str,
    ) -> Result<touchline_engine::Action, EngineError> {
        self.inner.behaviour_action(view, side, player, path)
    }

    fn log(&self) -> &[String] {
        self.inner.log()
    }

    fn save(&self) -> Vec<u8> {
        self.inner.save()
    }

    fn load(&mut self, bytes: &[u8]) -> Result<(), EngineError> {
        self.inner.load(bytes)
    }

    fn poll_scenario(&mut self) -> Option<Scenario> {
        if self.shared.generation.load(Ordering::Acquire) == self.generation {
            return None;
        }
        let (generation, build) = self.shared.current();
        self.generation = generation;
        self.previous = Some(std::mem::replace(&mut self.inner, build.scripts.hooks()));
        Some(build.scenario.clone())
    }

    fn scenario_refused(&mut self, error: &EngineError) {
        if let Some(previous) = self.previous.take() {
            self.inner = previous;
        }
        self.shared.tell(&WatchEvent::Refused(error));
    }

    fn clone_box(&self) -> Box<dyn Hooks> {
        Box::new(WatchedHooks {
            shared: Arc::clone(&self.shared),
            generation: self.generation,
            inner: self.inner.clone_of(),
            previous: None,
        })
    }
}
