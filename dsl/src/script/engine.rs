//! The only place a rhai [`Engine`] is built: every engine that runs a scenario script is sandboxed
//! the same way (limits, strict variables, no modules, no clock, `print` captured).

use std::sync::{Arc, Mutex};

use rhai::Engine;
use rhai::module_resolvers::DummyModuleResolver;

use super::api;

/// Resource limits of one hook call. The defaults let a reward script loop over all 22 players
/// many times while stopping a runaway loop within about a millisecond.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// rhai operations per hook call (default 100,000).
    pub operations: u64,
    /// Nested function calls (default 32).
    pub call_depth: usize,
    /// Longest string, in bytes (default 10,000).
    pub string_size: usize,
    /// Longest array (default 10,000 elements).
    pub array_size: usize,
    /// Largest object map (default 10,000 entries).
    pub map_size: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits { operations: 100_000, call_depth: 32, string_size: 10_000, array_size: 10_000, map_size: 10_000 }
    }
}

/// Where `print` and `debug` lines go: the hooks move them into the env's log after each call.
pub(crate) type PrintSink = Arc<Mutex<Vec<String>>>;

/// Builds a sandboxed engine: `limits` per call; strict variables when `strict` (the hooks' engine;
/// the first pass that reads a script's constants is not strict); no module resolver, `eval`
/// disabled, no clock (rhai's `no_time`), no file or network functions (rhai has none built in);
/// `print`/`debug` lines pushed to `sink`; the read-only state API registered.
pub(crate) fn sandboxed(limits: &Limits, strict: bool, sink: &PrintSink) -> Engine {
    let mut engine = Engine::new();
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
    let out = Arc::clone(sink);
    engine.on_print(move |line| push(&out, line.to_owned()));
    let out = Arc::clone(sink);
    engine.on_debug(move |line, _, pos| push(&out, format!("debug (line {}): {line}", pos.line().unwrap_or(0))));
    api::register(&mut engine);
    engine
}

fn push(sink: &PrintSink, line: String) {
    // A poisoned lock only means another thread panicked while printing: keep the lines anyway.
    let mut lines = sink.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    // Bounded, so that a script printing every step cannot grow memory without end.
    if lines.len() < 1_000 {
        lines.push(line);
    }
}
