//! Compiles arbitrary text and plays what compiles for 50 steps over a reset: a scenario the
//! compiler accepts must build an env (or refuse its configuration with an error) and play.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| touchline_fuzz::play(text));
