//! Curricula in the env: lessons advance at reset when the criterion holds over the window of
//! finished episodes, the progress is reported in `info` and kept by snapshots, and every lesson
//! must give the env the same controllers.

mod common;

use touchline_engine::scenario::Metric;
use touchline_engine::{Action, EngineError, Env, EnvConfig, Snapshot};

/// Plays one episode with `action` every step; returns whether the left team scored.
fn episode(env: &mut Env, action: Action) -> bool {
    loop {
        let out = env.step(&[action]).unwrap();
        if out.terminated || out.truncated {
            return env.info().score[0] > 0;
        }
    }
}

#[test]
fn lessons_advance_at_reset_when_the_window_meets_the_criterion() {
    // success_rate >= 0 holds for any full window: every 2 episodes the env moves on.
    let mut env = Env::new(common::curriculum(2, 0.0), 7).unwrap();
    assert_eq!(env.lesson(), Some((0, "close")));
    assert_eq!(env.scenario().name, "academy_empty_goal_close");
    assert_eq!(env.info().lesson, 0);
    let mut lessons = Vec::new();
    for _ in 0..7 {
        episode(&mut env, Action::Idle);
        let progress = env.curriculum_progress().unwrap();
        lessons.push((env.info().lesson, progress.episodes));
        env.reset().unwrap();
    }
    // The lesson changes at the reset after the 2nd episode of a lesson, and stays on the last.
    assert_eq!(lessons, [(0, 1), (0, 2), (1, 1), (1, 2), (2, 1), (2, 2), (2, 3)]);
    assert_eq!(env.lesson(), Some((2, "keeper")));
    assert_eq!(env.scenario().name, "academy_run_to_score_with_keeper");
    assert_eq!(env.info().lesson, 2);
}

#[test]
fn an_unmet_criterion_keeps_the_lesson_and_the_window_slides() {
    // Idling never scores: success rate 0 < 0.5, so the env stays on the first lesson.
    let mut env = Env::new(common::curriculum(3, 0.5), 1).unwrap();
    for _ in 0..5 {
        assert!(!episode(&mut env, Action::Idle));
        env.reset().unwrap();
    }
    assert_eq!(env.lesson(), Some((0, "close")));
    let p = env.curriculum_progress().unwrap();
    assert_eq!((p.lesson, p.lessons, p.episodes, p.window), (0, 3, 5, 3));
    assert_eq!(env.lesson_metric(Metric::SuccessRate), Some(0.0));
    assert_eq!(env.lesson_metric(Metric::MeanScore), Some(0.0));
    // Running right at the empty goal from close range scores.
    let mut scored = 0;
    for _ in 0..3 {
        scored += usize::from(episode(&mut env, Action::Right));
        env.reset().unwrap();
    }
    assert!(scored >= 2, "scored {scored} of 3");
    assert_eq!(env.lesson().unwrap().0, 1, "the window of the last 3 now has a success rate >= 0.5");
}

#[test]
fn a_reset_before_the_end_records_nothing() {
    let mut env = Env::new(common::curriculum(1, 0.0), 3).unwrap();
    env.step(&[Action::Idle]).unwrap();
    env.reset().unwrap();
    assert_eq!(env.curriculum_progress().unwrap().episodes, 0);
    assert_eq!(env.lesson().unwrap().0, 0);
}

#[test]
fn snapshots_keep_the_lesson_and_the_window() {
    let mut env = Env::new(common::curriculum(2, 0.0), 5).unwrap();
    for _ in 0..3 {
        episode(&mut env, Action::Idle);
        env.reset().unwrap();
    }
    assert_eq!(env.lesson().unwrap().0, 1);
    let saved = Snapshot::from_bytes(&env.snapshot().to_bytes()).unwrap();
    let before: Vec<_> = (0..5).map(|_| env.step(&[Action::Right]).unwrap()).collect();
    let obs = env.observations()[0].clone();
    // Move on to the last lesson, then come back.
    episode(&mut env, Action::Idle);
    env.reset().unwrap();
    episode(&mut env, Action::Idle);
    env.reset().unwrap();
    assert_eq!(env.lesson().unwrap().0, 2);
    env.restore(&saved).unwrap();
    assert_eq!(env.lesson(), Some((1, "far")));
    assert_eq!(env.scenario().name, "academy_empty_goal");
    let after: Vec<_> = (0..5).map(|_| env.step(&[Action::Right]).unwrap()).collect();
    assert_eq!(before, after);
    assert_eq!(env.observations()[0], obs);
    assert_eq!(env.curriculum_progress().unwrap().episodes, 1);
}

#[test]
fn the_same_seed_and_actions_give_the_same_lessons() {
    let run = || {
        let mut env = Env::new(common::curriculum(2, 0.5), 11).unwrap();
        let mut trace = Vec::new();
        for i in 0..8 {
            let action = if i % 3 == 0 { Action::Idle } else { Action::Right };
            let scored = episode(&mut env, action);
            trace.push((env.info().lesson, scored, env.info().steps));
            env.reset().unwrap();
        }
        trace
    };
    assert_eq!(run(), run());
}

#[test]
fn every_lesson_must_give_the_same_controllers() {
    let mut s = common::curriculum(2, 0.0);
    let lessons = &mut s.curriculum.as_mut().unwrap().lessons;
    lessons[1].scenario.control_all_players = true;
    let config = EnvConfig::default();
    let Err(EngineError::InvalidConfig { reason }) = Env::with_config(s, config, 0) else {
        panic!("a lesson with another number of controllers must be refused")
    };
    assert!(reason.contains("lesson `far`"), "{reason}");
    let three = EnvConfig { left_agents: 3, ..EnvConfig::default() };
    let Err(EngineError::InvalidConfig { reason }) = Env::with_config(common::curriculum(2, 0.0), three, 0) else {
        panic!("academy_empty_goal_close has two controllable left players")
    };
    assert!(reason.contains("lesson `close`"), "{reason}");
}

#[test]
fn a_curriculum_survives_json() {
    let s = common::curriculum(4, 0.25);
    let text = serde_json::to_string(&s).unwrap();
    let back: touchline_engine::Scenario = serde_json::from_str(&text).unwrap();
    assert_eq!(back, s);
    assert!(common::scenario("academy_empty_goal_close").curriculum.is_none());
    assert!(!serde_json::to_string(&common::scenario("academy_corner")).unwrap().contains("curriculum"));
}
