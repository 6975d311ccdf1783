//! [`Watched`]: a scenario source that recompiles itself when its files change, for hot reload.
//!
//! A background thread watches the folders of the scenario file and of every script it names
//! (folders, not files, so that an editor's save-by-rename, or a file deleted and re-created, is
//! still seen) and batches bursts of events (debounced, 100 ms). Only a change of **content**
//! recompiles: after each batch the watched files are hashed, and nothing happens unless a hash
//! differs from the last compile's (reading a file, the compile's own reads, `touch`, a save of
//! the same text: no reload). A good compile becomes the new *generation*; a failed one is
//! reported once (see [`Watched::on_event`]) and not again until the files change, and the last
//! good generation stays. Each compile runs on a thread of its own: one that does not finish in
//! [`COMPILE_TIMEOUT`] is reported and the watcher goes on. Envs built with [`Watched::env`] poll
//! at each reset and switch, between episodes and all at once, to the newest generation (scenario
//! and scripts together): a broken version never reaches a step.

use std::collections::BTreeSet;
use std::hash::{DefaultHasher, Hash, Hasher};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender, channel};
use std::sync::{Arc, Mutex, PoisonError, Weak};
use std::time::{Duration, Instant};

use miette::Diagnostic;
use notify_debouncer_full::notify::event::{AccessKind, AccessMode};
use notify_debouncer_full::notify::{EventKind, RecursiveMode};
use notify_debouncer_full::{DebounceEventResult, DebouncedEvent, new_debouncer};
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
    /// A compile did not finish in [`COMPILE_TIMEOUT`]; the watcher goes on, and a later change
    /// compiles again.
    #[error("`{path}` did not compile within {} s; the watcher goes on with the last good version", COMPILE_TIMEOUT.as_secs())]
    #[diagnostic(code(tl::S007), help("save the file again once it is fixed"))]
    Timeout {
        /// The scenario.
        path: String,
    },
}

/// How long one compile may take before the watcher reports it and goes on (it keeps waiting
/// for the compile's result, which applies if it is still the newest).
pub const COMPILE_TIMEOUT: Duration = Duration::from_secs(10);

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

/// Compiles `spec` on a thread of its own, sending the result with `attempt` on `tx`.
fn compile_in_background(spec: &str, options: ScriptOptions, attempt: u64, tx: &Sender<Message>) {
    let (owned, sender) = (spec.to_owned(), tx.clone());
    let spawned = std::thread::Builder::new().name("touchline-compile".into()).spawn(move || {
        let result = compile(&owned, options);
        let _ = sender.send(Message::Compiled { attempt, result: Box::new(result) });
    });
    if let Err(e) = spawned {
        let error = WatchError::Watcher { path: spec.to_owned(), message: format!("no thread to compile on: {e}") };
        let _ = tx.send(Message::Compiled { attempt, result: Box::new(Err(error)) });
    }
}

/// What the watcher thread hears: a batch of file events, or a compile's result.
enum Message {
    Files(DebounceEventResult),
    Compiled { attempt: u64, result: Box<Result<Build, WatchError>> },
}

/// Largest file hashed to tell whether it changed (a scenario or a script is far smaller).
const MAX_HASHED_BYTES: u64 = 64 * 1024 * 1024;

/// A hash of `file`'s content: `None` for a file that is missing, unreadable or not a regular file
/// (which is not opened: a FIFO would block the watcher).
fn content_hash(file: &Path) -> Option<u64> {
    if !std::fs::metadata(file).ok()?.is_file() {
        return None;
    }
    let mut bytes = Vec::new();
    std::fs::File::open(file).ok()?.take(MAX_HASHED_BYTES).read_to_end(&mut bytes).ok()?;
    let mut hasher = DefaultHasher::new();
    bytes.hash(&mut hasher);
    Some(hasher.finish())
}

/// The content hashes of `files`, in order.
fn content_hashes(files: &[PathBuf]) -> Vec<(PathBuf, Option<u64>)> {
    files.iter().map(|f| (f.clone(), content_hash(f))).collect()
}

/// Whether an event may mean new content: not a file being opened or read (the compile's own
/// reads, an editor or `cat` looking at it), but closing a file written counts.
fn may_change(event: &DebouncedEvent) -> bool {
    match event.kind {
        EventKind::Access(AccessKind::Close(AccessMode::Write)) => true,
        EventKind::Access(_) => false,
        _ => true,
    }
}

impl Watched {
    /// Compiles `spec` and starts watching its files.
    ///
    /// # Errors
    /// The first compile's diagnostics (nothing is watched then), or a watcher that cannot start.
    /// The first compile, too, runs on a thread of its own: one that does not finish in
    /// [`COMPILE_TIMEOUT`] is [`WatchError::Timeout`].
    pub fn new(spec: &str, options: ScriptOptions) -> Result<Watched, WatchError> {
        let (tx, rx) = channel();
        compile_in_background(spec, options, 0, &tx);
        let build = match rx.recv_timeout(COMPILE_TIMEOUT) {
            Ok(Message::Compiled { result, .. }) => (*result)?,
            _ => return Err(WatchError::Timeout { path: spec.to_owned() }),
        };
        let seen = content_hashes(&build.files);
        let watched_folders = folders(&build.files);
        let shared = Arc::new(Shared {
            spec: spec.to_owned(),
            options,
            current: Mutex::new((1, Arc::new(build))),
            generation: AtomicU64::new(1),
            listener: Mutex::new(None),
        });
        let events = tx.clone();
        let mut debouncer = new_debouncer(Duration::from_millis(100), None, move |batch| {
            let _ = events.send(Message::Files(batch));
        })
        .map_err(|e| WatchError::Watcher { path: spec.to_owned(), message: e.to_string() })?;
        for folder in &watched_folders {
            debouncer
                .watch(folder, RecursiveMode::NonRecursive)
                .map_err(|e| WatchError::Watcher { path: folder.display().to_string(), message: e.to_string() })?;
        }
        let weak = Arc::downgrade(&shared);
        std::thread::Builder::new()
            .name("touchline-watch".into())
            .spawn(move || {
                let mut watcher =
                    Watcher { shared: weak, tx, debouncer, watching: watched_folders, seen, attempt: 0, pending: None };
                watcher.run(&rx);
            })
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
        self.env_playing(config, seed).map(|(env, _)| env)
    }

    /// As [`Watched::env`], with a handle telling which generation the env plays: the one it
    /// switched to at its last reset (not the newest compiled, which it takes at its next reset,
    /// and not one it refused).
    ///
    /// # Errors
    /// As [`Watched::env`].
    pub fn env_playing(&self, config: EnvConfig, seed: u64) -> Result<(Env, Playing), EngineError> {
        let (generation, build) = self.shared.current();
        let playing = Playing(Arc::new(AtomicU64::new(generation)));
        let hooks = WatchedHooks {
            shared: Arc::clone(&self.shared),
            generation,
            inner: build.scripts.hooks(),
            previous: None,
            playing: playing.clone(),
        };
        Ok((Env::with_hooks(build.scenario.clone(), config, seed, Box::new(hooks))?, playing))
    }
}

/// Which generation of a [`Watched`] scenario an env plays (see [`Watched::env_playing`]).
#[derive(Clone, Debug)]
pub struct Playing(Arc<AtomicU64>);

impl Playing {
    /// The generation (1 for the first compile).
    pub fn generation(&self) -> u64 {
        self.0.load(Ordering::Acquire)
    }
}

type Debouncer = notify_debouncer_full::Debouncer<
    notify_debouncer_full::notify::RecommendedWatcher,
    notify_debouncer_full::RecommendedCache,
>;

/// The watcher thread's state: recompiles when the content of the watched files changes, until the
/// [`Watched`] and every env built from it are gone.
struct Watcher {
    shared: Weak<Shared>,
    /// Where compile threads send their results.
    tx: Sender<Message>,
    debouncer: Debouncer,
    watching: BTreeSet<PathBuf>,
    /// Each watched file's content hash when it was last compiled (well or not).
    seen: Vec<(PathBuf, Option<u64>)>,
    /// The newest compile started; older results are dropped.
    attempt: u64,
    /// The newest compile while it runs: when it started, and whether its slowness was reported.
    pending: Option<(Instant, bool)>,
}

impl Watcher {
    fn run(&mut self, rx: &Receiver<Message>) {
        loop {
            let message = match rx.recv_timeout(Duration::from_millis(200)) {
                Ok(message) => message,
                Err(RecvTimeoutError::Timeout) => {
                    let Some(shared) = self.shared.upgrade() else { return };
                    self.report_slow_compile(&shared);
                    continue;
                }
                Err(RecvTimeoutError::Disconnected) => return,
            };
            let Some(shared) = self.shared.upgrade() else { return };
            match message {
                Message::Files(Ok(events)) => self.on_files(&shared, &events),
                Message::Files(Err(_)) => {}
                Message::Compiled { attempt, result } if attempt == self.attempt => {
                    self.pending = None;
                    self.on_compiled(&shared, *result);
                }
                // Superseded by a newer edit.
                Message::Compiled { .. } => {}
            }
        }
    }

    /// A batch of events: compiles again when a watched file's content differs from its last
    /// compile's, and only then (so one edit is one compile, and a failure is reported once).
    fn on_files(&mut self, shared: &Shared, events: &[DebouncedEvent]) {
        let files = shared.current().1.files.clone();
        if !events.iter().any(|e| may_change(e) && e.paths.iter().any(|p| concerns(&files, p))) {
            return;
        }
        let now = content_hashes(&files);
        let changed = now.iter().any(|(f, hash)| self.seen.iter().find(|(g, _)| g == f).is_none_or(|(_, h)| h != hash));
        if !changed {
            return;
        }
        for (file, hash) in now {
            match self.seen.iter_mut().find(|(g, _)| *g == file) {
                Some(entry) => entry.1 = hash,
                None => self.seen.push((file, hash)),
            }
        }
        self.attempt += 1;
        self.pending = Some((Instant::now(), false));
        compile_in_background(&shared.spec, shared.options, self.attempt, &self.tx);
    }

    fn on_compiled(&mut self, shared: &Shared, result: Result<Build, WatchError>) {
        match result {
            Ok(build) => {
                let wanted = folders(&build.files);
                for folder in wanted.difference(&self.watching) {
                    // A folder that cannot be watched is reported by the next failed compile.
                    let _ = self.debouncer.watch(folder, RecursiveMode::NonRecursive);
                }
                self.watching.extend(wanted);
                // Files the new version reads for the first time (a new import or script).
                for file in &build.files {
                    if !self.seen.iter().any(|(g, _)| g == file) {
                        self.seen.push((file.clone(), content_hash(file)));
                    }
                }
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

    /// Reports, once, a compile running longer than [`COMPILE_TIMEOUT`]; the watcher goes on
    /// (its result still applies if no newer edit came).
    fn report_slow_compile(&mut self, shared: &Shared) {
        if let Some((started, reported)) = &mut self.pending
            && !*reported
            && started.elapsed() > COMPILE_TIMEOUT
        {
            *reported = true;
            shared.tell(&WatchEvent::Failed(&WatchError::Timeout { path: shared.spec.clone() }));
        }
    }
}

/// The hooks of an env built by [`Watched::env`]: the current build's scripts, swapped at reset.
struct WatchedHooks {
    shared: Arc<Shared>,
    generation: u64,
    inner: ScriptHooks,
    /// The hooks before the last swap, kept until the env accepts the new scenario.
    previous: Option<(ScriptHooks, u64)>,
    /// The generation the env plays, for its owner.
    playing: Playing,
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
        let before = self.playing.generation();
        self.generation = generation;
        self.playing.0.store(generation, Ordering::Release);
        self.previous = Some((std::mem::replace(&mut self.inner, build.scripts.hooks()), before));
        Some(build.scenario.clone())
    }

    fn scenario_refused(&mut self, error: &EngineError) {
        if let Some((previous, generation)) = self.previous.take() {
            self.inner = previous;
            self.playing.0.store(generation, Ordering::Release);
        }
        self.shared.tell(&WatchEvent::Refused(error));
    }

    fn clone_box(&self) -> Box<dyn Hooks> {
        Box::new(WatchedHooks {
            shared: Arc::clone(&self.shared),
            generation: self.generation,
            inner: self.inner.clone_of(),
            previous: None,
            // A copy plays on its own: its version is its own from here.
            playing: Playing(Arc::new(AtomicU64::new(self.playing.generation()))),
        })
    }
}
