//! The only place a rhai [`Engine`] is built: every engine that runs a scenario script is sandboxed
//! the same way (limits, strict variables, no modules, no clock, no `sleep`, `print` captured).

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, OnceLock, PoisonError};
use std::time::{Duration, Instant};

use rhai::module_resolvers::DummyModuleResolver;
use rhai::packages::{
    ArithmeticPackage, BasicArrayPackage, BasicFnPackage, BasicIteratorPackage, BasicMapPackage, BasicMathPackage,
    BasicStringPackage, BitFieldPackage, LogicPackage, MoreStringPackage, Package,
};
use rhai::{Dynamic, Engine, EvalAltResult, Position, Shared};

use super::{api, cost};

/// Resource limits of one hook call. A built-in on a collection costs one operation per element
/// it goes through (`cost`), so the operation budget bounds the time of a hook whatever it calls:
/// the measured worst case is in grammar/scripts.md ("Sandbox").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// rhai operations per hook call, built-ins on collections counting their length (default
    /// 100,000).
    pub operations: u64,
    /// Nested function calls (default 32).
    pub call_depth: usize,
    /// Longest string, in bytes (default 4,096).
    pub string_size: usize,
    /// Most array elements in one value, nested arrays included (default 4,096).
    pub array_size: usize,
    /// Most object-map entries in one value (default 1,024).
    pub map_size: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits { operations: 100_000, call_depth: 32, string_size: 4_096, array_size: 4_096, map_size: 1_024 }
    }
}

/// A last guard in wall-clock time, for a built-in whose cost `cost` does not count: a hook call
/// that runs this long fails. The operation budget is what bounds hooks (deterministically, far
/// below this); the guard can only turn a runaway hook into an error, never change a normal one.
pub(crate) const TIME_GUARD: Duration = Duration::from_secs(1);

/// Operations charged when a built-in calls a closure (`map`, `filter`, `sort` with a comparer…):
/// such a call takes about as long as this many plain operations.
const CLOSURE_CALL_COST: u64 = 16;

/// How often (in operations) the time guard looks at the clock.
const TIME_GUARD_EVERY: u64 = 1_024;

/// The value `on_progress` stops a call with when the budget counting built-ins is spent.
pub(crate) const OUT_OF_OPERATIONS: &str = "operations";
/// The value `on_progress` stops a call with when the time guard fires.
pub(crate) const OUT_OF_TIME: &str = "time";

/// What one hook call has spent besides rhai's own operation count: the operations charged by
/// built-ins on collections, and when the call started (for the time guard). Reset by
/// [`Meter::start`] before each call.
#[derive(Debug, Default)]
pub(crate) struct Meter {
    charged: AtomicU64,
    /// Operations seen by `on_progress`. rhai's own count does not include the operations of a
    /// closure that a built-in calls (`a.map(|x| …)`: each call starts again from the count at
    /// the built-in), so the sandbox counts every operation itself.
    ticks: AtomicU64,
    /// rhai's count at the last operation: when it goes back, a built-in has called a closure.
    last: AtomicU64,
    started: Mutex<Option<Instant>>,
}

impl Meter {
    /// Starts a hook call: nothing charged, the time guard's clock at zero.
    pub(crate) fn start(&self) {
        self.charged.store(0, Ordering::Relaxed);
        self.ticks.store(0, Ordering::Relaxed);
        self.last.store(0, Ordering::Relaxed);
        *self.started.lock().unwrap_or_else(PoisonError::into_inner) = Some(Instant::now());
    }

    /// Operations charged by built-ins so far in this call.
    pub(crate) fn charged(&self) -> u64 {
        self.charged.load(Ordering::Relaxed)
    }

    /// Charges `units` operations; an error, before the built-in does its work, when that passes
    /// `limit`.
    pub(crate) fn charge(&self, units: u64, limit: u64) -> Result<(), Box<EvalAltResult>> {
        let total = self.charged.fetch_add(units, Ordering::Relaxed).saturating_add(units);
        if total > limit { Err(Box::new(EvalAltResult::ErrorTooManyOperations(Position::NONE))) } else { Ok(()) }
    }

    /// One operation (rhai's count `ops`): the operations counted so far, and with the charges.
    fn tick(&self, ops: u64) -> (u64, u64) {
        let ticks = self.ticks.fetch_add(1, Ordering::Relaxed) + 1;
        if ops <= self.last.swap(ops, Ordering::Relaxed) {
            // A built-in called a closure (or a closure returned): such a call costs far more
            // than an operation.
            self.charged.fetch_add(CLOSURE_CALL_COST, Ordering::Relaxed);
        }
        (ticks, ticks.saturating_add(self.charged()))
    }

    fn overran(&self) -> bool {
        self.started.lock().unwrap_or_else(PoisonError::into_inner).is_some_and(|t| t.elapsed() > TIME_GUARD)
    }
}

/// Where `print` and `debug` lines go: the hooks move them into the env's log after each call.
pub(crate) type PrintSink = Arc<Mutex<Vec<String>>>;

/// rhai's standard library less its core package, whose `sleep` blocks the thread (and whose
/// `exit`, `parse_json` and reflection scripts do not need), less blobs, and with no clock
/// (`no_time`). Built once: packages are immutable and shared.
fn packages() -> &'static [Shared<rhai::Module>] {
    static PACKAGES: OnceLock<Vec<Shared<rhai::Module>>> = OnceLock::new();
    PACKAGES.get_or_init(|| {
        vec![
            ArithmeticPackage::new().as_shared_module(),
            BasicStringPackage::new().as_shared_module(),
            BasicIteratorPackage::new().as_shared_module(),
            BasicFnPackage::new().as_shared_module(),
            BitFieldPackage::new().as_shared_module(),
            LogicPackage::new().as_shared_module(),
            BasicMathPackage::new().as_shared_module(),
            BasicArrayPackage::new().as_shared_module(),
            BasicMapPackage::new().as_shared_module(),
            MoreStringPackage::new().as_shared_module(),
        ]
    })
}

/// Builds a sandboxed engine: `limits` per call, built-ins on collections charged to `meter`;
/// strict variables when `strict` (the hooks' engine; the first pass that reads a script's
/// constants is not strict); no module resolver, `eval` disabled, no clock and no `sleep`, no
/// file or network functions (rhai has none built in); `print`/`debug` lines pushed to `sink`;
/// the read-only state API registered.
pub(crate) fn sandboxed(limits: &Limits, strict: bool, sink: &PrintSink, meter: &Arc<Meter>) -> Engine {
    let mut engine = Engine::new_raw();
    for package in packages() {
        engine.register_global_module(Shared::clone(package));
    }
    engine.set_max_operations(limits.operations);
    engine.set_max_call_levels(limits.call_depth);
    engine.set_max_expr_depths(64, 32);
    engine.set_max_string_size(limits.string_size);
    engine.set_max_array_size(limits.array_size);
    engine.set_max_map_size(limits.map_size);
    engine.set_max_variables(1_000);
    engine.set_max_functions(1_000);
    engine.set_strict_variables(strict);
    engine.set_module_resolver(DummyModuleResolver::new());
    engine.disable_symbol("eval");
    let max = limits.operations;
    let watched = Arc::clone(meter);
    engine.on_progress(move |ops| {
        let (ticks, spent) = watched.tick(ops);
        if spent > max {
            return Some(Dynamic::from(OUT_OF_OPERATIONS));
        }
        // On the count of operations alone: charges jump, and would skip multiples.
        (ticks.is_multiple_of(TIME_GUARD_EVERY) && watched.overran()).then(|| Dynamic::from(OUT_OF_TIME))
    });
    let out = Arc::clone(sink);
    engine.on_print(move |line| push(&out, line));
    let out = Arc::clone(sink);
    engine.on_debug(move |line, _, pos| push(&out, &format!("debug (line {}): {line}", pos.line().unwrap_or(0))));
    api::register(&mut engine);
    cost::register(&mut engine, limits, meter);
    engine
}

/// Longest line kept from `print`/`debug`, in bytes.
const MAX_LINE: usize = 1_000;

fn push(sink: &PrintSink, line: &str) {
    // A poisoned lock only means another thread panicked while printing: keep the lines anyway.
    let mut lines = sink.lock().unwrap_or_else(PoisonError::into_inner);
    // Bounded, so that a script printing every step cannot grow memory without end.
    if lines.len() < 1_000 {
        let mut end = line.len().min(MAX_LINE);
        while !line.is_char_boundary(end) {
            end -= 1;
        }
        let clipped = if end < line.len() { format!("{}…", &line[..end]) } else { line.to_owned() };
        lines.push(clipped);
    }
}
