//! Feeds arbitrary UTF-8 text to the compiled-scenario (JSON) loader: it must load or fail with a
//! diagnostic that renders, never panic; a scenario that loads is played 50 steps over a reset.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| touchline_fuzz::json(text));
