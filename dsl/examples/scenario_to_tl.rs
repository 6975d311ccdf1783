//! Prints any scenario (a stdlib name, a compiled `.json`, a `.tl`) as `.tl` source.
//!
//! `cargo run -p touchline-dsl --example scenario_to_tl -- academy_corner`

fn main() {
    for spec in std::env::args().skip(1) {
        match touchline_dsl::load(&spec) {
            Ok(scenario) => print!("{}", touchline_dsl::scenario_to_tl(&scenario)),
            Err(e) => {
                eprintln!("{}", touchline_dsl::render_plain(&e));
                std::process::exit(2);
            }
        }
    }
}
