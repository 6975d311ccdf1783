//! Replays: a whole 3000-step match round-trips through bytes and re-simulates bit for bit;
//! damaged files give clear errors, never a panic.

use touchline_engine::{Action, ActionSet, Env, EnvConfig, Scenario};
use touchline_render::Scene;
use touchline_render::replay::{Recorder, Replay, ReplayError, Start};

fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("stdlib scenario")).expect("valid JSON")
}

/// Plays a whole episode with actions from a fixed pseudo-random sequence mixing agent actions
/// and the built-in AI, recording it.
fn record_episode(env: &mut Env) -> Replay {
    let mut recorder = Recorder::start(env);
    let set = ActionSet::V2;
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut actions = vec![Action::Idle; env.num_controllers()];
    loop {
        for a in &mut actions {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            // Half the steps the built-in AI plays, so that the match moves and goals happen.
            let i = (state >> 33) as usize % 40;
            *a = if i >= 20 { Action::BuiltinAi } else { set.actions()[i] };
        }
        let out = env.step(&actions).expect("step");
        recorder.record(env, &actions);
        if out.terminated || out.truncated {
            return recorder.finish();
        }
    }
}

fn full_match() -> (Env, Replay) {
    let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(scenario("11_vs_11_easy_stochastic"), config, 7).expect("env");
    let replay = record_episode(&mut env);
    (env, replay)
}

#[test]
fn a_3000_step_match_round_trips_bit_identically() {
    let (env, replay) = full_match();
    assert_eq!(replay.steps(), 3001, "11_vs_11 plays game_duration + 1 steps");
    let bytes = replay.to_bytes();
    let back = Replay::from_bytes(&bytes).expect("reads back");
    assert_eq!(back, replay, "bytes round-trip");
    // Re-simulation checks every frame's exact state hash; the end state is the recorded env's.
    let mut visited = 0;
    let end = back.simulate(|_, k| visited = k).expect("reproduces");
    assert_eq!(visited, 3001);
    assert_eq!(end.game().state_hash(), env.game().state_hash());
    assert_eq!(end.info(), env.info());
    assert_eq!(end.observations(), env.observations());
    eprintln!("3001-step replay: {} bytes", bytes.len());
}

#[test]
fn later_episodes_and_mid_episode_starts_reproduce() {
    let mut env = Env::new(scenario("academy_3_vs_1_with_keeper"), 3).expect("env");
    record_episode(&mut env);
    env.reset().unwrap();
    let second = record_episode(&mut env);
    assert_eq!(second.start, Start::Reset { seed: 3, episode: 1 });
    second.simulate(|_, _| {}).expect("episode 1 reproduces");

    // Started mid-episode: the start state travels as a snapshot.
    env.reset().unwrap();
    for _ in 0..5 {
        env.step(&[Action::Right]).expect("step");
    }
    let tail = record_episode(&mut env);
    assert!(matches!(tail.start, Start::Snapshot(_)));
    assert_eq!(tail.first_step, 5);
    Replay::from_bytes(&tail.to_bytes()).expect("reads").simulate(|_, _| {}).expect("reproduces");
}

#[test]
fn stored_frames_draw_the_recorded_state() {
    let mut env = Env::new(scenario("academy_counterattack_easy"), 1).expect("env");
    let replay = record_episode(&mut env);
    let mut from_replay = Scene::default();
    replay.scene(replay.steps(), &mut from_replay);
    let live = Scene::of_env(&env);
    assert_eq!(from_replay.score, live.score);
    assert_eq!(from_replay.mode, live.mode);
    assert_eq!(from_replay.steps, live.steps);
    for (a, b) in from_replay.players.iter().zip(&live.players) {
        assert_eq!((a.side, a.number, a.controlled, a.has_ball), (b.side, b.number, b.controlled, b.has_ball));
        // Frames keep centimetres, rounded: half a centimetre off at most, plus f32's own
        // rounding of positions some 30 m from the centre (a few micrometres).
        let near = |x: f32, y: f32| (x - y).abs() <= 0.005 + 1e-4;
        assert!(
            near(a.position[0], b.position[0]) && near(a.position[1], b.position[1]),
            "{:?} vs {:?}",
            a.position,
            b.position
        );
    }
}

#[test]
fn a_changed_action_is_caught_as_divergence() {
    let mut env = Env::new(scenario("academy_run_to_score"), 0).expect("env");
    let mut replay = record_episode(&mut env);
    // From step 10 on, the agent runs towards his own goal instead.
    let k = 10;
    for a in &mut replay.actions[k..] {
        *a = Action::Left;
    }
    match replay.simulate(|_, _| {}) {
        Err(ReplayError::Diverged { frame, .. }) => assert!(frame > k, "diverges after the changed step, at {frame}"),
        other => panic!("expected divergence, got {other:?}"),
    }
}

#[test]
fn damaged_files_give_clear_errors() {
    let mut env = Env::new(scenario("academy_empty_goal_close"), 0).expect("env");
    let bytes = record_episode(&mut env).to_bytes();
    let err = |b: &[u8]| Replay::from_bytes(b).expect_err("damaged").to_string();

    assert!(err(b"").contains("not a touchline replay"));
    assert!(err(b"PK\x03\x04 a zip file").contains("not a touchline replay"));
    assert!(err(&bytes[..12]).contains("truncated"));
    // Every truncation is an error, never a panic.
    for len in 0..bytes.len() {
        assert!(Replay::from_bytes(&bytes[..len]).is_err(), "truncated to {len}");
    }
    assert!(err(&bytes[..bytes.len() - 1]).contains("truncated"));
    // Every single-byte corruption is an error.
    for i in 0..bytes.len() {
        let mut b = bytes.clone();
        b[i] ^= 0x20;
        assert!(Replay::from_bytes(&b).is_err(), "byte {i} flipped");
    }
    let mut b = bytes.clone();
    let last = b.len() - 1;
    b[last] ^= 1;
    assert!(err(&b).contains("corrupted"));
    let mut b = bytes.clone();
    b[8] = 99;
    assert!(err(&b).contains("format version 99"));
    let mut b = bytes.clone();
    b.push(0);
    assert!(err(&b).contains("after the payload"));
}

#[test]
fn decodable_but_inconsistent_replays_are_refused() {
    let mut env = Env::new(scenario("academy_empty_goal_close"), 0).expect("env");
    let replay = record_episode(&mut env);
    let mut r = replay.clone();
    r.actions.pop();
    assert!(matches!(Replay::from_bytes(&r.to_bytes()), Err(ReplayError::Inconsistent { .. })));
    let mut r = replay.clone();
    r.frames[1].players.pop();
    assert!(matches!(Replay::from_bytes(&r.to_bytes()), Err(ReplayError::Inconsistent { .. })));
    let mut r = replay;
    r.frames[0].controlled[0] = 200;
    assert!(matches!(Replay::from_bytes(&r.to_bytes()), Err(ReplayError::Inconsistent { .. })));
}

#[test]
fn clips_round_goals_reproduce_on_their_own() {
    let (_, replay) = full_match();
    // The clip round the first goal (or round the middle, should this match have none).
    let goals = replay.goal_frames();
    for &g in &goals {
        assert_ne!(replay.frames[g].score, replay.frames[g - 1].score);
    }
    let g = goals.first().copied().unwrap_or(1500);
    let clip = replay.clip(g.saturating_sub(100), (g + 1).min(replay.steps())).expect("clip");
    assert_eq!(clip.frames[..], replay.frames[g.saturating_sub(100)..=(g + 1).min(replay.steps())]);
    Replay::from_bytes(&clip.to_bytes()).expect("reads").simulate(|_, _| {}).expect("the clip reproduces");
    assert!(replay.clip(5, 4).is_err());
    assert!(replay.clip(0, replay.steps() + 1).is_err());
}

#[test]
fn step_values_and_script_texts_round_trip_and_clip() {
    let mut env = Env::new(scenario("academy_empty_goal_close"), 3).expect("env");
    let mut recorder = Recorder::start(&env).with_scripts([("a.rhai".to_owned(), "fn reward(s) { 0.0 }".to_owned())]);
    let mut k = 0;
    loop {
        // A value on every step, a second one only on odd steps (NaN elsewhere), from step 1.
        recorder.value("value", k as f32 * 0.5);
        if k % 2 == 1 {
            recorder.value("p_shot", 0.25);
        }
        let out = env.step(&[Action::Right]).expect("step");
        recorder.record(&env, &[Action::Right]);
        k += 1;
        if out.terminated || out.truncated || k == 30 {
            break;
        }
    }
    let replay = recorder.finish();
    let back = Replay::from_bytes(&replay.to_bytes()).expect("reads");
    assert_eq!(back.scripts, replay.scripts);
    assert_eq!(back.scripts[0].path, "a.rhai");
    let value = &back.values.iter().find(|v| v.name == "value").expect("value series").values;
    assert_eq!(value.len(), back.steps());
    assert!(value.iter().enumerate().all(|(i, &v)| v == i as f32 * 0.5));
    let p = &back.values.iter().find(|v| v.name == "p_shot").expect("p_shot series").values;
    assert!(p[0].is_nan() && p[1] == 0.25 && p[2].is_nan());
    let clip = back.clip(4, 10).expect("clip");
    assert_eq!(clip.values[0].values, value[4..10]);

    // Saved whole through a temporary file, and read back the same.
    let dir = std::env::temp_dir().join(format!("touchline-render-save-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("ep.tlreplay");
    back.save(&path).expect("save");
    assert_eq!(std::fs::read(&path).expect("read"), back.to_bytes());
    assert_eq!(std::fs::read_dir(&dir).expect("list").count(), 1, "no temporary file is left behind");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn values_of_the_wrong_length_are_refused() {
    let mut env = Env::new(scenario("academy_empty_goal_close"), 0).expect("env");
    let mut r = record_episode(&mut env);
    r.values.push(touchline_render::replay::StepValues { name: "v".into(), values: vec![0.0; r.steps() + 1] });
    assert!(matches!(Replay::from_bytes(&r.to_bytes()), Err(ReplayError::Inconsistent { .. })));
}
