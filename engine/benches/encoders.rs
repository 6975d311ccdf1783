//! Speed of the observation encoders (criterion) on an 11 v 11 observation: simple115v2 and the
//! 96 × 72 Super Mini Map, per controller.
//!
//! Run: `cargo bench -p touchline-engine --bench encoders`

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use touchline_engine::obs::{
    FrameStack, SMM_CHANNELS, SMM_HEIGHT, SMM_WIDTH, encode_simple115, encode_simple115v2, encode_smm,
};
use touchline_engine::{Action, Env, RawObservation, Scenario};

/// The first controller's observation a few steps into `11_vs_11_stochastic`.
fn observation() -> RawObservation {
    let path = format!("{}/../stdlib-scenarios/11_vs_11_stochastic.json", env!("CARGO_MANIFEST_DIR"));
    let scenario: Scenario =
        serde_json::from_str(&std::fs::read_to_string(path).expect("stdlib scenario")).expect("valid JSON");
    let mut env = Env::new(scenario, 0).expect("env");
    for _ in 0..20 {
        env.step(&[Action::Right]).expect("step");
    }
    env.observations()[0].clone()
}

fn encoders(c: &mut Criterion) {
    let obs = observation();
    let mut group = c.benchmark_group("encode");
    group.throughput(Throughput::Elements(1));

    let mut v = [0.0f32; 115];
    group.bench_function("simple115v2/11_vs_11", |b| {
        b.iter(|| {
            encode_simple115v2(black_box(&obs), &mut v);
            black_box(&v);
        })
    });
    group.bench_function("simple115/11_vs_11", |b| {
        b.iter(|| {
            encode_simple115(black_box(&obs), &mut v);
            black_box(&v);
        })
    });

    let len = SMM_WIDTH * SMM_HEIGHT * SMM_CHANNELS;
    let mut smm = vec![0u8; len];
    group.bench_function("smm_96x72/11_vs_11", |b| {
        b.iter(|| {
            encode_smm(black_box(&obs), SMM_WIDTH, SMM_HEIGHT, &mut smm);
            black_box(&smm);
        })
    });

    let mut stack = FrameStack::<u8>::new(len, SMM_CHANNELS, 4);
    stack.reset(&smm);
    let mut stacked = vec![0u8; stack.stacked_len()];
    group.bench_function("smm_96x72_push_and_stack4", |b| {
        b.iter(|| {
            stack.push(black_box(&smm));
            stack.write_stacked(&mut stacked);
            black_box(&stacked);
        })
    });
    group.finish();
}

criterion_group!(benches, encoders);
criterion_main!(benches);
