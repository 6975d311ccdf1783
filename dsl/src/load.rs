//! [`load`]: a stdlib name or a file path to a checked [`Scenario`].

use std::path::Path;

use touchline_engine::Scenario;

use crate::load_error::LoadError;
use crate::{stdlib, suggest};

/// Loads the scenario `spec` names and checks it with [`Scenario::validate`].
///
/// `spec` is tried in this order:
/// 1. a stdlib scenario name ([`stdlib::names`]), e.g. `"academy_empty_goal_close"`;
/// 2. a path ending in `.json`: a compiled scenario, read and parsed as in [`load_file`];
/// 3. a path ending in `.tl`: a scenario-language source, compiled by [`crate::compile_file`].
///
/// Stdlib names include GRF's test scenarios (`tests/corner_test`, …).
///
/// # Errors
/// - `tl::E001` [`LoadError::UnknownScenario`]: anything else, with the closest stdlib name(s);
/// - `tl::E002` [`LoadError::Unreadable`]: the `.json` file cannot be read;
/// - `tl::E003` [`LoadError::Json`]: the file is not a compiled scenario (syntax or shape);
/// - `tl::E004` [`LoadError::Invalid`]: the scenario fails [`Scenario::validate`];
/// - [`LoadError::Compile`]: a `.tl` file (or a stdlib source) that does not compile, with every
///   diagnostic.
pub fn load(spec: &str) -> Result<Scenario, LoadError> {
    if let Some(text) = stdlib::tl_source(spec) {
        return crate::compile(text, &format!("stdlib/{spec}.tl"))
            .map(|c| c.scenario)
            .map_err(|d| LoadError::Compile(Box::new(d)));
    }
    let path = Path::new(spec);
    match path.extension().and_then(|e| e.to_str()) {
        Some(ext) if ext.eq_ignore_ascii_case("json") => load_file(path),
        Some(ext) if ext.eq_ignore_ascii_case("tl") => {
            crate::compile_file(path).map(|c| c.scenario).map_err(|d| LoadError::Compile(Box::new(d)))
        }
        _ => Err(unknown(spec)),
    }
}

/// Reads the compiled scenario (JSON) at `path`, parses and validates it as in [`load_json`],
/// with the path as the origin shown in diagnostics.
///
/// # Errors
/// `tl::E002` if the file cannot be read (or is not UTF-8); otherwise as [`load_json`].
pub fn load_file(path: &Path) -> Result<Scenario, LoadError> {
    let origin = path.display().to_string();
    let text =
        crate::source_file::read_text(path).map_err(|source| LoadError::Unreadable { path: origin.clone(), source })?;
    load_json(&text, &origin)
}

/// Parses `text`, a compiled scenario (a [`Scenario`] serialised as JSON; missing fields take GRF's
/// defaults), and validates it. `origin` names the text in diagnostics (a path or a stdlib name).
///
/// # Errors
/// - `tl::E003` [`LoadError::Json`]: bad JSON or the wrong shape, pointing at the line and column;
/// - `tl::E004` [`LoadError::Invalid`]: the scenario fails [`Scenario::validate`].
pub fn load_json(text: &str, origin: &str) -> Result<Scenario, LoadError> {
    // The version first: a newer file may hold fields this version does not know, and "unknown
    // field" would hide the real reason.
    #[derive(serde::Deserialize)]
    struct Version {
        #[serde(default)]
        format_version: u32,
    }
    if let Ok(Version { format_version }) = serde_json::from_str::<Version>(text)
        && format_version > touchline_engine::SCENARIO_FORMAT_VERSION
    {
        let reason = format!(
            "it was compiled by a newer touchline (format_version {format_version}); this one reads version {}",
            touchline_engine::SCENARIO_FORMAT_VERSION
        );
        return Err(LoadError::Invalid {
            origin: origin.to_owned(),
            source: touchline_engine::EngineError::InvalidScenario { reason },
        });
    }
    let scenario: Scenario = serde_json::from_str(text).map_err(|e| LoadError::from_json(&e, text, origin))?;
    scenario.validate().map_err(|source| LoadError::Invalid { origin: origin.to_owned(), source })?;
    Ok(scenario)
}

/// `tl::E001` for `spec`, suggesting the closest stdlib names.
fn unknown(spec: &str) -> LoadError {
    let close = suggest::closest(spec, stdlib::names());
    let quoted: Vec<String> = close.iter().map(|n| format!("`{n}`")).collect();
    let help = match quoted.as_slice() {
        [] => format!(
            "the stdlib scenarios are: {}; a file path must end in `.json` or `.tl`",
            stdlib::names().join(", ")
        ),
        [one] => format!("did you mean {one}?"),
        many => format!("did you mean one of {}?", many.join(", ")),
    };
    LoadError::UnknownScenario { name: spec.to_owned(), help }
}
