//! The fuzz targets, shared by the cargo-fuzz binaries (`fuzz_targets/`) and the stable mutation
//! driver (`src/bin/mutate.rs`). Each takes one input and panics on a bug: a panic of touchline
//! itself, or a diagnostic whose spans are not in its source.

use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

use touchline_dsl::Diagnostics;
use touchline_engine::EnvConfig;

/// Steps the `play` target takes.
pub const PLAY_STEPS: usize = 50;

/// Inputs that got as far as a built env and were played (the driver reports the share).
pub static PLAYED: AtomicU64 = AtomicU64::new(0);

/// The `compile` target: compiles `text` as a `.tl` source; every diagnostic must point inside its
/// source, on `char` boundaries, and render.
pub fn compile(text: &str) {
    let diags = match touchline_dsl::compile(text, "fuzz.tl") {
        Ok(compiled) => compiled.warnings,
        Err(diags) => diags,
    };
    check_diagnostics(&diags);
}

/// The `json` target: loads `text` as a compiled scenario; an error must render, and a scenario
/// that loads is played as in [`play`] (a compiled scenario is what Python loads without the
/// compiler).
pub fn json(text: &str) {
    match touchline_dsl::load_json(text, "fuzz.json") {
        Ok(scenario) => play_scenario(scenario, text),
        Err(e) => assert!(!touchline_dsl::render_plain(&e).is_empty(), "{}: renders empty", e.code_str()),
    }
}

/// The `play` target: compiles `text` (scripts and imports are looked up next to the example
/// scenarios) and, when it compiles, builds the env and plays [`PLAY_STEPS`] steps with actions
/// drawn from the text, resetting halfway and at each episode's end, so that the odd-episode swap
/// is played too.
pub fn play(text: &str) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios");
    let origin = dir.join("fuzz.tl");
    let compiled = match touchline_dsl::compile(text, &origin.to_string_lossy()) {
        Ok(c) => c,
        Err(diags) => {
            check_diagnostics(&diags);
            return;
        }
    };
    play_scenario(compiled.scenario, text);
}

/// Builds `scenario`'s env and plays [`PLAY_STEPS`] steps with actions drawn from `text`.
fn play_scenario(scenario: touchline_engine::Scenario, text: &str) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios");
    // A bad configuration for this scenario is an error, which is fine; a panic is not.
    let Ok(mut env) = touchline_dsl::build_env(scenario, &dir, EnvConfig::default(), text.len() as u64) else {
        return;
    };
    PLAYED.fetch_add(1, Ordering::Relaxed);
    let seed = text.bytes().fold(0u32, |h, b| h.wrapping_mul(31).wrapping_add(u32::from(b)));
    let actions = env.action_set().len() as u32;
    for step in 0..PLAY_STEPS {
        let n = env.num_controllers();
        let picks: Vec<u32> = (0..n as u32).map(|i| seed.wrapping_add(step as u32 * 7 + i) % actions.max(1)).collect();
        let ended = match env.step_indices(&picks) {
            Ok(out) => out.terminated || out.truncated,
            // A script error ends the episode as an error; the env must still reset.
            Err(_) => true,
        };
        assert!(env.rewards().iter().all(|r| r.is_finite()) || ended, "a reward is not finite");
        if ended || step == PLAY_STEPS / 2 {
            let _ = env.reset();
        }
    }
}

/// Checks that every diagnostic's spans lie in its source on `char` boundaries and that it renders.
fn check_diagnostics(diags: &Diagnostics) {
    for d in &diags.items {
        let source = d.source.inner();
        for (span, _) in &d.labels {
            assert!(span.start <= span.end && span.end <= source.len(), "{}: {span:?}", d.code);
            assert!(source.is_char_boundary(span.start) && source.is_char_boundary(span.end), "{}: {span:?}", d.code);
        }
    }
    let _ = diags.render_plain();
}
