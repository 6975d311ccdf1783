//! No heap allocation inside `Env::step` once the env is reset (issue 3): a counting global
//! allocator watches thousands of steps of a full match and of an Academy drill.

mod common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use touchline_engine::Action;

struct Counting;

// Per thread: the test harness's own threads allocate while the test runs.
thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    if COUNTING.with(Cell::get) {
        ALLOCATIONS.with(|a| a.set(a.get() + 1));
    }
}

// SAFETY: every call is forwarded unchanged to the system allocator; the wrapper only counts.
#[expect(unsafe_code, reason = "a global allocator must implement an unsafe trait")]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn step_does_not_allocate() {
    for (name, builtin) in
        [("11_vs_11_easy_stochastic", true), ("academy_empty_goal_close", false), ("academy_corner", false)]
    {
        let mut env = if builtin { common::builtin_env(name, 1) } else { common::env(name, 1) };
        let mut policy = common::RandomPolicy::new(3);
        let mut actions = [Action::Idle; 1];
        for _ in 0..3000 {
            actions[0] = if builtin { Action::BuiltinAi } else { policy.action(env.action_set()) };
            COUNTING.with(|c| c.set(true));
            let out = env.step(&actions).unwrap();
            COUNTING.with(|c| c.set(false));
            if out.terminated || out.truncated {
                env.reset().unwrap();
            }
        }
        assert_eq!(ALLOCATIONS.with(Cell::get), 0, "{name}: step allocated");
    }
}

/// A match where every outfield player has a behaviour (moving, dribbling, passing, pressing,
/// marking, holding), stages switched by conditions, and an `end when` condition.
fn behaviour_scenario() -> touchline_engine::Scenario {
    use touchline_engine::scenario::{Behaviour, Comparison, Condition, EndCondition, PassKind, Stage, Target};
    use touchline_engine::{PlayerEntry, Role, Scenario};
    let with = |role, x, y, stages: Vec<Stage>| PlayerEntry { behaviour: stages, ..PlayerEntry::new(role, x, y) };
    let stage = |behaviour| Stage { behaviour, until: None };
    let after = |behaviour, steps| Stage { behaviour, until: Some(Condition::Steps { op: Comparison::Ge, steps }) };
    Scenario {
        left_team: vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            with(
                Role::CF,
                0.0,
                0.0,
                vec![
                    after(Behaviour::DribbleTo { point: [0.4, 0.1], shoot: false }, 40),
                    stage(Behaviour::PassTo { player: 2, kind: PassKind::Short }),
                    stage(Behaviour::Follow(Target::Ball)),
                ],
            ),
            with(
                Role::LM,
                0.2,
                -0.3,
                vec![after(Behaviour::HoldPosition, 80), stage(Behaviour::MoveTo { point: [0.7, 0.0] })],
            ),
            with(Role::RM, 0.1, 0.3, vec![stage(Behaviour::DribbleTo { point: [0.8, 0.0], shoot: true })]),
        ],
        right_team: vec![
            PlayerEntry::new(Role::GK, -1.0, 0.0),
            with(Role::CM, -0.2, 0.0, vec![stage(Behaviour::Press)]),
            with(Role::CB, -0.5, 0.2, vec![stage(Behaviour::Mark(Target::Left(2)))]),
            with(Role::CB, -0.5, -0.2, vec![stage(Behaviour::Builtin { difficulty: Some(0.3) })]),
        ],
        ball_position: [0.01, 0.0],
        game_duration: 400,
        end_when: vec![EndCondition::When(Condition::Any(vec![
            Condition::Score { side: touchline_engine::Side::Left, op: Comparison::Ge, goals: 2 },
            Condition::Distance { a: Target::Ball, b: Target::Point([1.0, 0.0]), op: Comparison::Lt, metres: 1.0 },
        ]))],
        ..Scenario::default()
    }
}

#[test]
fn behaviours_do_not_allocate() {
    let config = touchline_engine::EnvConfig { left_agents: 0, ..touchline_engine::EnvConfig::default() };
    let mut env = touchline_engine::Env::with_config(behaviour_scenario(), config, 1).unwrap();
    for _ in 0..3000 {
        COUNTING.with(|c| c.set(true));
        let out = env.step(&[]).unwrap();
        COUNTING.with(|c| c.set(false));
        if out.terminated || out.truncated {
            env.reset().unwrap();
        }
    }
    assert_eq!(ALLOCATIONS.with(Cell::get), 0, "behaviours: step allocated");
}

#[test]
fn event_rewards_do_not_allocate() {
    use touchline_engine::scenario::{
        EventAtom, EventKind, EventReward, EventStep, EventTeam, Region, RewardKind, RewardTerm,
    };
    let atom = |event| EventAtom { event, team: EventTeam::Own, by_player: false };
    let term = |sequence, once| RewardTerm { reward: RewardKind::Event(EventReward { sequence, once }), weight: 0.1 };
    let zone = Region::Rect { x: [0.7, 1.0], y: [-0.24, 0.24] };
    let mut s = common::scenario("11_vs_11_easy_stochastic");
    s.rewards = vec![
        RewardTerm::scoring(),
        term(vec![EventStep::One(atom(EventKind::PassCompleted)), EventStep::One(atom(EventKind::Shot))], false),
        term(vec![EventStep::AnyOf(vec![atom(EventKind::HasBallIn(zone.clone())), atom(EventKind::GoalFor)])], true),
        term(vec![EventStep::AllOf(vec![atom(EventKind::PossessionWon), atom(EventKind::BallEnters(zone))])], false),
        term(vec![EventStep::One(EventAtom { team: EventTeam::Opponent, ..atom(EventKind::HasBall) })], false),
    ];
    let config = touchline_engine::EnvConfig {
        action_set: touchline_engine::ActionSet::V2,
        left_agents: 2,
        right_agents: 1,
        ..touchline_engine::EnvConfig::default()
    };
    let mut env = touchline_engine::Env::with_config(s, config, 1).unwrap();
    let mut paid = 0.0;
    for _ in 0..3000 {
        COUNTING.with(|c| c.set(true));
        let out = env.step(&[Action::BuiltinAi; 3]).unwrap();
        COUNTING.with(|c| c.set(false));
        paid += env.info().event_reward;
        if out.terminated || out.truncated {
            env.reset().unwrap();
        }
    }
    assert!(paid != 0.0, "no event reward paid: the test exercised nothing");
    assert_eq!(ALLOCATIONS.with(Cell::get), 0, "a step with event rewards allocated");
}

#[test]
fn step_does_not_allocate_in_a_curriculum() {
    // Lessons change every 2 episodes: recording results and the lesson's bookkeeping stay
    // allocation-free (the window is allocated when the env is built).
    let mut env = touchline_engine::Env::new(common::curriculum(2, 0.0), 1).unwrap();
    let mut policy = common::RandomPolicy::new(5);
    let mut actions = [Action::Idle; 1];
    for _ in 0..3000 {
        actions[0] = policy.action(env.action_set());
        COUNTING.with(|c| c.set(true));
        let out = env.step(&actions).unwrap();
        COUNTING.with(|c| c.set(false));
        if out.terminated || out.truncated {
            env.reset().unwrap();
        }
    }
    assert_eq!(env.lesson().map(|l| l.0), Some(2), "the env went through the lessons");
    assert_eq!(ALLOCATIONS.with(Cell::get), 0, "step allocated");
}
