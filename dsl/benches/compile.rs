//! Speed of the scenario language (criterion). Issue 4 asks for all 35 stdlib scenarios compiled in
//! under 5 ms in total, and a reset of a randomised Academy scenario written in `.tl` in under 20 µs.
//!
//! Run: `cargo bench -p touchline-dsl --bench compile`

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use touchline_dsl::{compile, stdlib};
use touchline_engine::Env;

/// An Academy drill with a uniform and a normal spot, a region and a `require` between two of
/// them: every reset draws (and, when the constraint fails, redraws) the placement.
const RANDOMISED: &str = r#"
/// A striker and a marker placed anew at every reset.
scenario randomised_academy {
  extends academy
  ball at (uniform(0.55, 0.75), normal(0, 0.05))
  team left {
    GK at (-1, 0)
    CF at (uniform(0.5, 0.7), uniform(-0.15, 0.15))
    CM at (normal(0.35, 0.05), normal(0, 0.1))
  }
  team right {
    GK at (-1, 0)
    CB in rect((-0.8, -0.2), (-0.55, 0.2))
  }
  require distance(left.CF, right.CB) >= 4 m
  require distance(ball, left.CF) <= 12 m
}
"#;

fn compile_stdlib(c: &mut Criterion) {
    let sources: Vec<(String, &str)> = stdlib::names()
        .iter()
        .copied()
        .chain(stdlib::test_names())
        .map(|n| (format!("stdlib/{n}.tl"), stdlib::tl_source(n).expect("stdlib source")))
        .collect();
    assert_eq!(sources.len(), 35);
    c.bench_function("compile/all_35_stdlib_scenarios", |b| {
        b.iter(|| {
            for (origin, text) in &sources {
                black_box(compile(text, origin).expect("stdlib compiles"));
            }
        })
    });
    let corner = stdlib::tl_source("academy_corner").expect("academy_corner");
    c.bench_function("compile/academy_corner", |b| b.iter(|| black_box(compile(corner, "academy_corner.tl"))));
    c.bench_function("compile/randomised_academy_with_require", |b| {
        b.iter(|| black_box(compile(RANDOMISED, "randomised.tl")))
    });
    // Behaviours and conditions: the example scenarios that use them (examples/scenarios).
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios");
    let mut examples: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("examples/scenarios")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "tl"))
        .map(|p| (p.display().to_string(), std::fs::read_to_string(&p).expect("readable")))
        .collect();
    examples.sort();
    c.bench_function(&format!("compile/{}_behaviour_examples", examples.len()), |b| {
        b.iter(|| {
            for (origin, text) in &examples {
                black_box(compile(text, origin).expect("the examples compile"));
            }
        })
    });
}

fn reset(c: &mut Criterion) {
    let scenario = compile(RANDOMISED, "randomised.tl").expect("the bench scenario compiles").scenario;
    let mut env = Env::new(scenario, 0).expect("env");
    let mut seed = 0u64;
    c.bench_function("reset/randomised_academy/reset_with_seed", |b| {
        b.iter(|| {
            seed += 1;
            env.reset_with_seed(seed).unwrap();
            black_box(env.observations());
        })
    });
    c.bench_function("reset/randomised_academy/reset", |b| {
        b.iter(|| {
            env.reset().unwrap();
            black_box(env.observations());
        })
    });
    let fixed = compile(stdlib::tl_source("academy_3_vs_1_with_keeper").expect("source"), "a.tl").expect("compiles");
    let mut env = Env::new(fixed.scenario, 0).expect("env");
    c.bench_function("reset/academy_3_vs_1_with_keeper (not randomised)", |b| {
        b.iter(|| {
            env.reset().unwrap();
            black_box(env.observations());
        })
    });
}

criterion_group!(benches, compile_stdlib, reset);
criterion_main!(benches);
