//! `touchline._touchline`: the Python extension over the touchline engine (pyo3, abi3).
//!
//! The Python package `touchline` wraps these classes in Gymnasium, PettingZoo and GRF-compatible
//! APIs; `_touchline.pyi` documents them.

mod convert;
mod core;
mod env;
mod errors;
mod recording;
mod replay;
mod vector;
mod watch;
mod worker;

use pyo3::prelude::*;

/// Names of the stdlib scenarios, sorted.
#[pyfunction]
fn scenario_names() -> Vec<&'static str> {
    touchline_dsl::stdlib::names().to_vec()
}

/// The compiled JSON of a scenario (stdlib name, or the path of a `.tl` or compiled `.json` file).
#[pyfunction]
fn scenario_json(py: Python<'_>, scenario: &str) -> PyResult<String> {
    errors::guard(|| {
        let s = touchline_dsl::load(scenario).map_err(|e| errors::scenario_error(py, &e))?;
        serde_json::to_string_pretty(&s).map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))
    })
}

#[pymodule]
fn _touchline(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("TouchlineError", py.get_type::<errors::TouchlineError>())?;
    m.add("ScenarioError", py.get_type::<errors::ScenarioError>())?;
    m.add("ReplayError", py.get_type::<errors::ReplayError>())?;
    m.add_function(wrap_pyfunction!(scenario_names, m)?)?;
    m.add_function(wrap_pyfunction!(scenario_json, m)?)?;
    m.add_class::<env::PyEnv>()?;
    m.add_class::<vector::PyVectorEnv>()?;
    m.add_class::<replay::PyReplay>()?;
    Ok(())
}
