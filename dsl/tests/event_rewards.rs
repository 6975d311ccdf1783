//! `reward on …` through the language: statements compile to the engine's event terms, print back
//! (`scenario_to_tl`) and format to text that compiles to the same value, and the ten-term
//! checkpoint example pays what `reward checkpoint` pays on the same play.

use touchline_dsl::{compile, compile_file, format_source, scenario_to_tl};
use touchline_engine::scenario::{EventKind, EventStep, EventTeam, RewardKind};
use touchline_engine::{Action, Env, EnvConfig, Scenario};

const DRILL: &str = r#"
/// Event rewards of every shape.
scenario drill {
  extends academy_counterattack_easy
  reward scoring
  reward on goal_for 1
  reward on pass_completed by player each time 0.05
  reward on shot_on_target once 0.2
  reward on ball enters opponent_penalty_area once 0.5
  reward on possession_won then shot once 1
  reward on any of (foul, card) each time -0.5
  reward on all of (opponent_has_ball, has_ball in circle(0, 0, 10 m) for team) -0.01
  reward on ball in rect((0.5, -0.2), (1, 0.2)) 0.001
  reward on goal_against -1
  reward on possession_lost by player then opponent_shot_on_target -0.3
}
"#;

fn compiled(text: &str) -> Scenario {
    compile(text, "drill.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario
}

#[test]
fn reward_on_compiles_to_event_terms() {
    let s = compiled(DRILL);
    assert_eq!(s.rewards.len(), 11);
    let RewardKind::Event(e) = &s.rewards[5].reward else { panic!("{:?}", s.rewards[5]) };
    assert_eq!(e.sequence.len(), 2);
    assert!(e.once);
    assert_eq!(s.rewards[5].weight, 1.0);
    let RewardKind::Event(e) = &s.rewards[7].reward else { panic!() };
    let EventStep::AllOf(atoms) = &e.sequence[0] else { panic!("{e:?}") };
    assert_eq!((atoms[0].team, &atoms[0].event), (EventTeam::Opponent, &EventKind::HasBall));
    // 10 m along x in ball units (54.4 m a unit).
    let EventKind::HasBallIn(touchline_engine::scenario::Region::Circle { r, .. }) = &atoms[1].event else { panic!() };
    assert!((r - 10.0 / 54.4).abs() < 1e-6);
    assert!(!e.once);
    let RewardKind::Event(e) = &s.rewards[2].reward else { panic!() };
    assert!(e.sequence[0].atoms()[0].by_player);
    assert_eq!(s.rewards[6].weight, -0.5);
    // The compiled form reads back.
    let json = serde_json::to_string(&s).unwrap();
    let back: Scenario = serde_json::from_str(&json).unwrap();
    assert_eq!(back.rewards, s.rewards);
    back.validate().unwrap();
}

#[test]
fn printing_and_formatting_round_trip() {
    let s = compiled(DRILL);
    let printed = scenario_to_tl(&s);
    assert!(printed.contains("reward on possession_won then shot once 1"), "{printed}");
    assert_eq!(compiled(&printed).rewards, s.rewards, "{printed}");
    let formatted = format_source(DRILL, "drill.tl").unwrap();
    assert!(formatted.contains("  reward on any of (foul, card) each time -0.5\n"), "{formatted}");
    assert_eq!(format_source(&formatted, "drill.tl").unwrap(), formatted);
    assert_eq!(compiled(&formatted).rewards, s.rewards);
}

#[test]
fn the_checkpoint_example_pays_what_the_builtin_checkpoint_pays() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios/checkpoints_by_events.tl");
    let events = compile_file(&path).unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    let mut builtin = events.clone();
    builtin.rewards = compiled(
        "/// x\nscenario s { extends academy_run_to_score_with_keeper reward scoring + checkpoint(count: 10, value: 0.1) }",
    )
    .rewards;
    let mut a = Env::new(builtin, 9).unwrap();
    let mut b = Env::new(events, 9).unwrap();
    let set = a.action_set();
    let mut state = 0x2545_F491_4F6C_DD1Du64;
    let (mut paid, mut goals) = (0.0, 0);
    for step in 0..40_000 {
        if step >= 8_000 && goals > 0 {
            break;
        }
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        // Mostly run right with the ball and shoot once near the goal, so that checkpoints and
        // goals happen (a shot from far out does not reach the goal, as in GRF). The chasing
        // defenders play a loose ball first time (GRF's on-the-ball AI), so goals are rare: the
        // loop runs at least 8,000 steps and on until a goal has been paid (up to 40,000).
        let near_goal = a.observations()[0].ball[0] > 0.75;
        let action = if state.is_multiple_of(8) {
            set.actions()[(state >> 8) as usize % set.len()]
        } else if near_goal && step % 2 == 0 {
            // One step of the button, released at the next: the shot goes at once.
            Action::Shot
        } else {
            Action::Right
        };
        let out = a.step(&[action]).unwrap();
        b.step(&[action]).unwrap();
        let (ra, rb) = (a.rewards()[0], b.rewards()[0]);
        assert!((ra - rb).abs() <= 1e-6, "step {step}: checkpoint {ra}, events {rb}");
        paid += a.info().checkpoint_reward;
        goals += u32::from(a.info().score_reward == 1.0);
        if out.terminated || out.truncated {
            a.reset().unwrap();
            b.reset().unwrap();
        }
    }
    assert!(paid > 5.0 && goals > 0, "checkpoint reward {paid}, goals {goals}: too little happened to compare");
}

#[test]
fn event_rewards_cost_no_step_of_play() {
    // The same scenario with and without event terms: identical match states (events are
    // observations) and identical scoring.
    let with = compiled(DRILL);
    let mut without = with.clone();
    without.rewards.truncate(1);
    let config = EnvConfig { left_agents: 1, right_agents: 1, ..EnvConfig::default() };
    let mut a = Env::with_config(with, config, 4).unwrap();
    let mut b = Env::with_config(without, config, 4).unwrap();
    let set = a.action_set();
    for k in 0..1_000usize {
        let actions = [set.actions()[k * 7 % set.len()], set.actions()[k * 11 % set.len()]];
        let out = a.step(&actions).unwrap();
        b.step(&actions).unwrap();
        assert_eq!(a.game().state_hash(), b.game().state_hash());
        assert_eq!(a.info().score_reward, b.info().score_reward);
        if out.terminated || out.truncated {
            a.reset().unwrap();
            b.reset().unwrap();
        }
    }
}
