//! [`build_env`]: a ready [`Env`] from a loaded scenario, with its scripts attached.

use std::path::{Path, PathBuf};

use miette::Diagnostic;
use thiserror::Error;
use touchline_engine::{EngineError, Env, EnvConfig, Scenario};

use crate::script::{ScriptErrors, ScriptOptions, Scripts};

/// Why [`build_env`] failed.
#[derive(Debug, Error, Diagnostic)]
#[non_exhaustive]
pub enum BuildError {
    /// The scenario's scripts do not load (`tl::S001` … `tl::S004`).
    #[error(transparent)]
    #[diagnostic(transparent)]
    Scripts(#[from] ScriptErrors),
    /// The engine refused the scenario or configuration, or a script failed at the first reset.
    #[error(transparent)]
    #[diagnostic(code(tl::S000))]
    Engine(#[from] EngineError),
}

/// The folder the scripts of the scenario `spec` (as given to [`crate::load`]) are relative to:
/// the scenario file's folder; the current folder for a stdlib name.
pub fn script_dir(spec: &str) -> PathBuf {
    if crate::stdlib::tl_source(spec).is_some() {
        return PathBuf::from(".");
    }
    match Path::new(spec).parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Builds the env of `scenario` with `config`, reset with `seed`: its scripts (reward terms and
/// end conditions; paths relative to `dir`, see [`script_dir`]) compiled and attached as hooks
/// with the default [`ScriptOptions`]. A scenario without scripts gets a plain env.
///
/// # Errors
/// [`BuildError::Scripts`] for scripts that do not load; [`BuildError::Engine`] for a scenario or
/// configuration the engine refuses.
pub fn build_env(scenario: Scenario, dir: &Path, config: EnvConfig, seed: u64) -> Result<Env, BuildError> {
    build_env_with(scenario, dir, config, seed, ScriptOptions::default())
}

/// As [`build_env`] with script `options` (limits, error policy).
///
/// # Errors
/// As [`build_env`].
pub fn build_env_with(
    scenario: Scenario,
    dir: &Path,
    config: EnvConfig,
    seed: u64,
    options: ScriptOptions,
) -> Result<Env, BuildError> {
    let scripts = Scripts::compile(&scenario, dir, options)?;
    Ok(attach(&scripts, scenario, config, seed)?)
}

/// Builds an env of `scenario` with already compiled `scripts` (e.g. one compile shared by the
/// envs of a vector env).
///
/// # Errors
/// As [`touchline_engine::Env::with_config`], and a script failing at the first reset.
pub fn attach(scripts: &Scripts, scenario: Scenario, config: EnvConfig, seed: u64) -> Result<Env, EngineError> {
    if scripts.is_empty() {
        Env::with_config(scenario, config, seed)
    } else {
        Env::with_hooks(scenario, config, seed, Box::new(scripts.hooks()))
    }
}
