//! Golden equality: every stdlib `.tl` source (GRF's 19 scenarios and its 16 `tests/` scenarios)
//! compiles to exactly the compiled JSON checked in beside it, which holds GRF's tables
//! (docs/grf-compatibility.md#scenario-settings, #scenario-players).

use touchline_engine::Scenario;

fn golden(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn all_35_stdlib_sources_compile_to_their_golden_json() {
    let names: Vec<&str> =
        touchline_dsl::stdlib::names().iter().copied().chain(touchline_dsl::stdlib::test_names()).collect();
    assert_eq!(names.len(), 35);
    for name in names {
        let source = touchline_dsl::stdlib::tl_source(name).unwrap_or_else(|| panic!("{name} has no .tl"));
        let compiled = touchline_dsl::compile(source, &format!("stdlib/{name}.tl"))
            .unwrap_or_else(|d| panic!("{name}:\n{}", d.render_plain()));
        assert!(compiled.warnings.items.is_empty(), "{name}: {}", compiled.warnings.render_plain());
        assert_eq!(compiled.scenario, golden(name), "{name}");
    }
}

#[test]
fn printing_a_compiled_scenario_gives_source_that_compiles_back() {
    for name in touchline_dsl::stdlib::names().iter().copied().chain(touchline_dsl::stdlib::test_names()) {
        let scenario = touchline_dsl::load(name).unwrap();
        let text = touchline_dsl::scenario_to_tl(&scenario);
        let back = touchline_dsl::compile(&text, "printed.tl")
            .unwrap_or_else(|d| panic!("{name}:\n{text}\n{}", d.render_plain()));
        assert_eq!(back.scenario, scenario, "{name}");
    }
}
