//! Cost of event rewards per `Env::step` (criterion): the same scenario and actions with no event
//! term and with ten (GRF's checkpoint reward as ten `any of (has_ball in circle by player,
//! goal_for) once` terms), and with ten `each time` terms over the match event stream (passes,
//! shots, possession, a sequence and an `all of` group), which never finish and so are evaluated
//! at every step. Issue 9 asks for under 1 µs added per step.
//!
//! `pay/…` times the evaluator alone (`EventRewards::pay` for one controller, a step's usual
//! handful of events), without the noise of the step around it.
//!
//! Run: `cargo bench -p touchline-engine --bench event_rewards`

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use touchline_engine::reward::{
    CHECKPOINT_COUNT, CHECKPOINT_REWARD, EventProgress, EventRewards, Viewpoint, checkpoint_threshold,
};
use touchline_engine::scenario::{
    EventAtom, EventKind, EventReward, EventStep, EventTeam, Region, RewardKind, RewardTerm,
};
use touchline_engine::stats::Event;
use touchline_engine::{Action, ActionSet, Env, EnvConfig, RawObservation, Scenario, Side};

fn scenario(name: &str) -> Scenario {
    let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).expect("stdlib scenario")).expect("valid JSON")
}

fn atom(event: EventKind) -> EventAtom {
    EventAtom { event, team: EventTeam::Own, by_player: false }
}

fn term(sequence: Vec<EventStep>, once: bool, weight: f32) -> RewardTerm {
    RewardTerm { reward: RewardKind::Event(EventReward { sequence, once }), weight }
}

/// GRF's checkpoints as ten event terms.
fn checkpoints() -> Vec<RewardTerm> {
    (0..CHECKPOINT_COUNT)
        .map(|k| {
            let zone = Region::Circle { x: 1.0, y: 0.0, r: checkpoint_threshold(k) };
            let mut has = atom(EventKind::HasBallIn(zone));
            has.by_player = true;
            term(vec![EventStep::AnyOf(vec![has, atom(EventKind::GoalFor)])], true, CHECKPOINT_REWARD)
        })
        .collect()
}

/// Ten `each time` terms over the event stream and the state.
fn stream() -> Vec<RewardTerm> {
    let one = |k| vec![EventStep::One(atom(k))];
    let box_ = Region::Rect { x: [0.7, 1.0], y: [-0.24, 0.24] };
    vec![
        term(one(EventKind::PassCompleted), false, 0.05),
        term(one(EventKind::PassIntercepted), false, -0.1),
        term(one(EventKind::ShotOnTarget), false, 0.2),
        term(one(EventKind::PossessionLost), false, -0.1),
        term(one(EventKind::Foul), false, -0.3),
        term(one(EventKind::BallEnters(box_.clone())), false, 0.1),
        term(one(EventKind::HasBallIn(box_)), false, 0.001),
        term(vec![EventStep::One(atom(EventKind::PossessionWon)), EventStep::One(atom(EventKind::Shot))], false, 0.5),
        term(
            vec![EventStep::AllOf(vec![atom(EventKind::Pass), atom(EventKind::OutOfPlay), atom(EventKind::Card)])],
            false,
            0.1,
        ),
        term(
            vec![EventStep::AnyOf(vec![
                atom(EventKind::Offside),
                atom(EventKind::GoalAgainst),
                atom(EventKind::RedCard),
            ])],
            false,
            -1.0,
        ),
    ]
}

/// Steps `env` with seeded random actions (or the built-in AI), resetting at episode ends.
fn bench(c: &mut Criterion, group: &str, id: &str, mut env: Env, builtin: bool) {
    let mut g = c.benchmark_group(group);
    g.throughput(Throughput::Elements(1));
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let set = env.action_set();
    g.bench_function(id, |b| {
        b.iter(|| {
            let action = if builtin {
                Action::BuiltinAi
            } else {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                set.actions()[(state % set.len() as u64) as usize]
            };
            let out = env.step(&[action]).expect("step");
            if out.terminated || out.truncated {
                env.reset().unwrap();
            }
            black_box(env.rewards());
        })
    });
    g.finish();
}

fn event_rewards(c: &mut Criterion) {
    for (name, builtin) in [("academy_run_to_score_with_keeper", false), ("11_vs_11_easy_stochastic", true)] {
        let config = EnvConfig { action_set: ActionSet::V2, ..EnvConfig::default() };
        let base = scenario(name);
        let with = |terms: Vec<RewardTerm>| {
            let mut s = base.clone();
            s.rewards = std::iter::once(RewardTerm::scoring()).chain(terms).collect();
            Env::with_config(s, config, 0).expect("env")
        };
        bench(c, name, "no_event_terms", with(Vec::new()), builtin);
        bench(c, name, "10_checkpoint_terms", with(checkpoints()), builtin);
        bench(c, name, "10_stream_terms", with(stream()), builtin);
    }
}

/// The evaluator alone: ten terms for one controller over three events and the state checks.
fn pay(c: &mut Criterion) {
    let events = [
        Event::Pass { side: Side::Left, player: 4, to: Some(7) },
        Event::PassCompleted { side: Side::Left, player: 4 },
        Event::Shot { side: Side::Right, player: 9, on_target: false },
    ];
    let obs = RawObservation {
        ball: [0.6, 0.05, 0.11],
        ball_owned_team: 0,
        ball_owned_player: 4,
        active: 4,
        ..RawObservation::default()
    };
    let view = Viewpoint { side: Side::Left, player: 4, observation: &obs, previous_ball: [0.55, 0.05] };
    let mut g = c.benchmark_group("pay");
    g.throughput(Throughput::Elements(1));
    for (id, terms) in [("10_checkpoint_terms", checkpoints()), ("10_stream_terms", stream())] {
        let rewards = EventRewards::new(&Scenario { rewards: terms, ..Scenario::default() });
        let mut progress = vec![EventProgress::default(); rewards.len()];
        g.bench_function(id, |b| {
            b.iter(|| {
                // Checkpoint terms finish once paid: start each iteration afresh so that every
                // iteration evaluates all ten (the fill is part of the cost measured, a few ns).
                progress.fill(EventProgress::default());
                black_box(rewards.pay(&mut progress, black_box(&events), &view))
            })
        });
    }
    g.finish();
}

criterion_group!(benches, event_rewards, pay);
criterion_main!(benches);
