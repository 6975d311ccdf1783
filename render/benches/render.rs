//! Speed of rendering and of replay recording (criterion). Issue 8 asks for a 96 × 72 frame in
//! under 50 µs, a 1280 × 720 frame in under 5 ms, and replay recording adding under 10 % to a step.
//!
//! Run: `cargo bench -p touchline-render --bench render`

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};
use touchline_render::replay::Recorder;
use touchline_render::{PIXELS_HEIGHT, PIXELS_WIDTH, PixelsEncoder, PixelsKind, RenderOptions, Renderer, Scene};

fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("stdlib scenario")).expect("valid JSON")
}

/// An 11-v-11 env some way into a match (players spread over the pitch).
fn match_env() -> Env {
    let v2 = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario("11_vs_11_easy_stochastic"), v2, 0).expect("env");
    for _ in 0..300 {
        env.step(&[Action::BuiltinAi]).expect("step");
    }
    env
}

fn frames(c: &mut Criterion) {
    let env = match_env();
    let scene = Scene::of_env(&env);
    let mut group = c.benchmark_group("render");
    let mut pixels = PixelsEncoder::new(PIXELS_WIDTH, PIXELS_HEIGHT, PixelsKind::Rgb).expect("encoder");
    let mut out = vec![0u8; pixels.len()];
    group.bench_function("pixels_96x72_from_env", |b| {
        b.iter(|| {
            pixels.encode(&env, 0, &mut out);
            black_box(&out);
        })
    });
    let mut gray = PixelsEncoder::new(PIXELS_WIDTH, PIXELS_HEIGHT, PixelsKind::Gray).expect("encoder");
    let mut out = vec![0u8; gray.len()];
    group.bench_function("pixels_gray_96x72_from_env", |b| {
        b.iter(|| {
            gray.encode(&env, 0, &mut out);
            black_box(&out);
        })
    });
    let mut hd = Renderer::new(1280, 720, RenderOptions::default()).expect("renderer");
    group
        .bench_function("frame_1280x720_with_scoreboard", |b| b.iter(|| black_box(hd.render(black_box(&scene)).len())));
    let mut rgb = vec![0u8; 1280 * 720 * 3];
    group.bench_function("frame_1280x720_rgb_out", |b| {
        b.iter(|| {
            hd.render(&scene);
            hd.write_rgb(&mut rgb);
            black_box(&rgb);
        })
    });
    group.finish();
}

fn recording(c: &mut Criterion) {
    let mut group = c.benchmark_group("replay");
    let mut env = match_env();
    group.bench_function("step_11v11_builtin", |b| {
        b.iter(|| {
            let out = env.step(&[Action::BuiltinAi]).expect("step");
            if out.terminated || out.truncated {
                env.reset().unwrap();
            }
        })
    });
    // Recording every step, and writing the replay's bytes at the end of each episode.
    let mut env = match_env();
    let mut recorder = Recorder::start(&env);
    group.bench_function("step_11v11_builtin_recorded", |b| {
        b.iter(|| {
            let actions = [Action::BuiltinAi];
            let out = env.step(&actions).expect("step");
            recorder.record(&env, &actions);
            if out.terminated || out.truncated {
                env.reset().unwrap();
                let done = std::mem::replace(&mut recorder, Recorder::start(&env));
                black_box(done.finish().to_bytes().len());
            }
        })
    });
    // The two parts of the recording cost: storing one step, and writing a whole match.
    let env = match_env();
    let mut recorder = Recorder::start(&env);
    group.bench_function("record_one_step_11v11", |b| {
        b.iter(|| {
            if recorder.steps() > 10_000 {
                recorder = Recorder::start(&env);
            }
            recorder.record(&env, &[Action::BuiltinAi]);
        })
    });
    let mut env = match_env();
    env.reset().unwrap();
    let mut recorder = Recorder::start(&env);
    loop {
        let out = env.step(&[Action::BuiltinAi]).expect("step");
        recorder.record(&env, &[Action::BuiltinAi]);
        if out.terminated || out.truncated {
            break;
        }
    }
    let replay = recorder.finish();
    group.sample_size(10);
    group.bench_function("to_bytes_3001_step_match", |b| b.iter(|| black_box(replay.to_bytes().len())));
    group.finish();
}

criterion_group!(benches, frames, recording);
criterion_main!(benches);
