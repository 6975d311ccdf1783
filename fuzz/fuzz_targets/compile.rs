//! Feeds arbitrary UTF-8 text to the scenario compiler: it must return (a scenario or
//! diagnostics), never panic, and every diagnostic's spans must lie inside its source on `char`
//! boundaries and render.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| touchline_fuzz::compile(text));
