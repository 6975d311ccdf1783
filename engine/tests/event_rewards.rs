//! Event rewards (`RewardKind::Event`) on real play: GRF's checkpoint reward written as ten event
//! terms pays exactly what the built-in term pays, step for step, for left and right controllers;
//! the new events (possession won, pass intercepted, out of play) show up and fold into the
//! statistics; snapshots carry the event terms' progress.

mod common;

use touchline_engine::reward::{CHECKPOINT_COUNT, CHECKPOINT_REWARD, checkpoint_threshold};
use touchline_engine::scenario::{
    EventAtom, EventKind, EventReward, EventStep, EventTeam, Region, RewardKind, RewardTerm,
};
use touchline_engine::stats::Event;
use touchline_engine::{Action, Env, EnvConfig, Scenario, Side};

fn atom(event: EventKind, by_player: bool) -> EventAtom {
    EventAtom { event, team: EventTeam::Own, by_player }
}

/// Checkpoint `k` as an event term: the controlled player has the ball within the zone's
/// distance of the opponent goal centre, or the team scores; once, 0.1.
fn checkpoint_term(k: u8) -> RewardTerm {
    let zone = Region::Circle { x: 1.0, y: 0.0, r: checkpoint_threshold(k) };
    let step = EventStep::AnyOf(vec![atom(EventKind::HasBallIn(zone), true), atom(EventKind::GoalFor, false)]);
    RewardTerm {
        reward: RewardKind::Event(EventReward { sequence: vec![step], once: true }),
        weight: CHECKPOINT_REWARD,
    }
}

fn with_rewards(mut s: Scenario, rewards: Vec<RewardTerm>) -> Scenario {
    s.rewards = rewards;
    s
}

/// Plays `steps` steps of `name` twice with the same seeded random actions, once with the
/// built-in checkpoint term and once with the ten event terms, and compares every reward.
/// Returns how much checkpoint reward was paid (so a test can insist something happened).
fn compare(name: &str, config: EnvConfig, seed: u64, steps: usize) -> f32 {
    let base = common::scenario(name);
    let builtin = with_rewards(
        base.clone(),
        vec![
            RewardTerm::scoring(),
            RewardTerm {
                reward: RewardKind::Checkpoints { count: CHECKPOINT_COUNT, value: CHECKPOINT_REWARD },
                weight: 1.0,
            },
        ],
    );
    let events = with_rewards(
        base,
        std::iter::once(RewardTerm::scoring()).chain((0..CHECKPOINT_COUNT).map(checkpoint_term)).collect(),
    );
    let mut a = Env::with_config(builtin, config, seed).unwrap();
    let mut b = Env::with_config(events, config, seed).unwrap();
    let mut policy = common::RandomPolicy::new(seed);
    let mut actions = vec![Action::Idle; a.num_controllers()];
    let mut paid = 0.0;
    for step in 0..steps {
        for x in actions.iter_mut() {
            *x = policy.action(a.action_set());
        }
        let out_a = a.step(&actions).unwrap();
        let out_b = b.step(&actions).unwrap();
        assert_eq!(out_a, out_b, "{name} step {step}: the reward terms must not change play");
        assert_eq!(a.game().state_hash(), b.game().state_hash(), "{name} step {step}");
        for (i, (ra, rb)) in a.rewards().iter().zip(b.rewards()).enumerate() {
            assert!(
                (ra - rb).abs() <= 1e-6,
                "{name} seed {seed} step {step} controller {i}: built-in {ra}, events {rb}"
            );
        }
        let (ca, eb) = (a.info().checkpoint_reward, b.info().event_reward);
        assert!((ca - eb).abs() <= 1e-5, "{name} step {step}: checkpoint_reward {ca}, event_reward {eb}");
        assert_eq!(b.info().checkpoint_reward, 0.0);
        paid += ca;
        if out_a.terminated || out_a.truncated {
            a.reset().unwrap();
            b.reset().unwrap();
        }
    }
    paid
}

#[test]
fn checkpoints_as_event_terms_equal_the_builtin_term_in_academy() {
    let mut paid = 0.0;
    for (name, seed) in [
        ("academy_empty_goal_close", 1),
        ("academy_run_to_score_with_keeper", 2),
        ("academy_3_vs_1_with_keeper", 3),
        ("academy_counterattack_easy", 4),
        ("academy_run_to_score", 5),
    ] {
        paid += compare(name, EnvConfig::default(), seed, 1_500);
    }
    assert!(paid > 1.0, "random play collected {paid} of checkpoint reward: the test compared nothing");
}

#[test]
fn checkpoints_as_event_terms_equal_the_builtin_term_in_11_vs_11_on_both_sides() {
    // Two left controllers and one right controller: the right one sees its own frame and goals.
    let config = EnvConfig { left_agents: 2, right_agents: 1, ..EnvConfig::default() };
    let paid = compare("11_vs_11_easy_stochastic", config, 7, 3_000);
    assert!(paid > 0.0, "no checkpoint paid in 3000 steps");
}

#[test]
fn event_rewards_leave_the_trajectory_alone() {
    // The same scenario with and without event terms: identical match states at every step.
    let base = common::scenario("11_vs_11_easy_stochastic");
    let shot = EventReward { sequence: vec![EventStep::One(atom(EventKind::Shot, false))], once: false };
    let rewarded = with_rewards(
        base.clone(),
        vec![RewardTerm::scoring(), RewardTerm { reward: RewardKind::Event(shot), weight: 0.5 }],
    );
    let config = EnvConfig { action_set: touchline_engine::ActionSet::V2, ..EnvConfig::default() };
    let mut a = Env::with_config(base, config, 3).unwrap();
    let mut b = Env::with_config(rewarded, config, 3).unwrap();
    let (mut shots, mut paid) = (0, 0.0);
    for _ in 0..3_000 {
        a.step(&[Action::BuiltinAi]).unwrap();
        b.step(&[Action::BuiltinAi]).unwrap();
        assert_eq!(a.game().state_hash(), b.game().state_hash());
        shots += b.game().events().iter().filter(|e| matches!(e, Event::Shot { side: Side::Left, .. })).count();
        paid += b.info().event_reward;
    }
    assert!(shots > 0, "the left team never shot");
    assert!((paid - 0.5 * shots as f32).abs() < 1e-3, "paid {paid} for {shots} shots");
}

#[test]
fn new_events_happen_in_a_match_and_fold_into_the_statistics() {
    let config = EnvConfig { action_set: touchline_engine::ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(common::scenario("11_vs_11_easy_stochastic"), config, 11).unwrap();
    let mut seen = [0u32; 3];
    for _ in 0..3_000 {
        env.step(&[Action::BuiltinAi]).unwrap();
        // The restart after a ball out of play goes to the other team.
        for pair in env.game().events().windows(2) {
            if let [Event::OutOfPlay { side, .. }, next] = pair {
                assert!(matches!(next, Event::Restart { side: s, .. } if *s == side.opponent()), "{pair:?}");
            }
        }
        for e in env.game().events() {
            match e {
                Event::PossessionWon { side, from, .. } => {
                    assert!(*from < env.game().team(side.opponent()).len());
                    seen[0] += 1;
                }
                Event::PassIntercepted { side, by, .. } => {
                    assert!(*by < env.game().team(side.opponent()).len());
                    seen[1] += 1;
                }
                Event::OutOfPlay { .. } => seen[2] += 1,
                _ => {}
            }
        }
    }
    let stats = env.game().stats();
    let folded = [
        stats.teams.iter().map(|t| t.possessions_won).sum::<u32>(),
        stats.teams.iter().map(|t| t.passes_intercepted).sum::<u32>(),
        stats.teams.iter().map(|t| t.out_of_play).sum::<u32>(),
    ];
    assert!(seen.iter().all(|&n| n > 0), "possessions won, interceptions, outs: {seen:?}");
    // At most 32 events a step are listed: in this match none overflowed, so the counts agree.
    assert_eq!(seen, folded);
}

#[test]
fn snapshots_carry_event_progress() {
    // `shot then shot`, each time: after an odd number of shots the term waits for the next one.
    // A snapshot taken there and restored into an env that was reset (progress cleared) must
    // pay the next shot as the original does.
    let twice = EventReward {
        sequence: vec![EventStep::One(atom(EventKind::Shot, false)), EventStep::One(atom(EventKind::Shot, false))],
        once: false,
    };
    let s = with_rewards(
        common::scenario("11_vs_11_easy_stochastic"),
        vec![RewardTerm { reward: RewardKind::Event(twice), weight: 1.0 }],
    );
    let config = EnvConfig { action_set: touchline_engine::ActionSet::V2, ..EnvConfig::default() };
    let mut env = Env::with_config(s, config, 5).unwrap();
    let left_shots =
        |env: &Env| env.game().events().iter().filter(|e| matches!(e, Event::Shot { side: Side::Left, .. })).count();
    let mut shots = 0;
    while shots % 2 == 0 {
        env.step(&[Action::BuiltinAi]).unwrap();
        shots += left_shots(&env);
        assert!(env.info().steps < 3_000, "no left shot");
    }
    let bytes = env.snapshot().to_bytes();
    let mut other = env.clone();
    other.reset().unwrap();
    other.restore(&touchline_engine::Snapshot::from_bytes(&bytes).unwrap()).unwrap();
    let (mut paid, mut later) = (0.0, 0);
    while !env.is_done() {
        env.step(&[Action::BuiltinAi]).unwrap();
        other.step(&[Action::BuiltinAi]).unwrap();
        assert_eq!(env.rewards(), other.rewards());
        paid += env.rewards()[0];
        later += left_shots(&env);
        if later > 0 {
            break;
        }
    }
    assert!(later > 0 && paid == 1.0, "the next shot ({later}) completes the pair: paid {paid}");
}
