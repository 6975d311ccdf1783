//! The Python exception tree and the mapping of Rust errors onto it. Nothing panics across the
//! boundary: [`guard`] turns a panic into a `RuntimeError`.

use std::panic::{AssertUnwindSafe, catch_unwind};

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use touchline_dsl::LoadError;
use touchline_engine::EngineError;

pyo3::create_exception!(
    _touchline,
    TouchlineError,
    pyo3::exceptions::PyException,
    "Base class of every error raised by touchline."
);
pyo3::create_exception!(
    _touchline,
    ScenarioError,
    TouchlineError,
    "A scenario could not be loaded; the message is the rendered diagnostic."
);

pyo3::create_exception!(
    _touchline,
    ReplayError,
    TouchlineError,
    "A replay file that cannot be read (damaged, another format version) or that does not re-simulate."
);

/// A scenario that failed to load: `ScenarioError` with the plain rendered diagnostic as its
/// message and the stable code (`tl::E001`, …) as its `code` attribute.
pub(crate) fn scenario_error(py: Python<'_>, err: &LoadError) -> PyErr {
    let message = touchline_dsl::render_plain(err);
    let exc = ScenarioError::new_err(message);
    let code = err.code_str().to_string();
    if let Err(e) = exc.value(py).setattr("code", code) {
        return e;
    }
    exc
}

/// Scripts of a scenario that failed to load: `ScenarioError` with the plain rendered diagnostics
/// and the first one's code (`tl::S001` …).
pub(crate) fn script_errors(py: Python<'_>, err: &touchline_dsl::script::ScriptErrors) -> PyErr {
    use miette::Diagnostic;
    let message = touchline_dsl::render_plain(err);
    let exc = ScenarioError::new_err(message);
    let code = err.errors.first().and_then(|e| e.code()).map(|c| c.to_string()).unwrap_or_default();
    if let Err(e) = exc.value(py).setattr("code", code) {
        return e;
    }
    exc
}

/// Engine errors: bad input is a `ValueError`, stepping a finished episode a `RuntimeError`, an
/// invalid scenario or a failing script a `ScenarioError` with its `code`, as a scenario that does
/// not load: the script's (`tl::S005` from a `reset` hook, …), or `tl::S000` for a scenario the
/// engine refuses.
pub(crate) fn engine_error(err: EngineError) -> PyErr {
    match err {
        EngineError::EpisodeOver => PyRuntimeError::new_err(err.to_string()),
        EngineError::Script { message, code } => with_code(message, code),
        EngineError::InvalidScenario { .. } => with_code(err.to_string(), "tl::S000".to_owned()),
        EngineError::InvalidSnapshot { .. } | EngineError::SnapshotScenario { .. } => {
            PyValueError::new_err(err.to_string())
        }
        _ => PyValueError::new_err(err.to_string()),
    }
}

/// `ScenarioError(message)` with its `code` attribute.
fn with_code(message: String, code: String) -> PyErr {
    Python::attach(|py| {
        let exc = ScenarioError::new_err(message);
        match exc.value(py).setattr("code", code) {
            Ok(()) => exc,
            Err(e) => e,
        }
    })
}

/// Runs `f`, turning a Rust panic into a Python `RuntimeError` instead of unwinding into Python.
pub(crate) fn guard<T>(f: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(result) => result,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(PyRuntimeError::new_err(format!("touchline internal error (please report): {what}")))
        }
    }
}
