//! Starting from a restart (issue 18, item 2): the example drills written with `start with`
//! start in the restart's game mode with the law's positions, and play on as GRF's would.
//! Figures from GRF 2.10 (`tests/penalty` and academy_corner, run in GRF's own env) are quoted
//! where a test compares with them.

use std::path::Path;

use touchline_dsl::{build_env, compile, compile_file, scenario_to_tl};
use touchline_engine::scenario::{EndCondition, Facing, StartRestart};
use touchline_engine::{Action, Env, EnvConfig, GameMode, RawObservation, Side};

fn example(name: &str, seed: u64) -> Env {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios").join(name);
    let compiled = compile_file(&path).unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert!(compiled.warnings.items.is_empty(), "{}", compiled.warnings.render_plain());
    build_env(compiled.scenario, path.parent().unwrap(), EnvConfig::default(), seed).unwrap()
}

/// Steps `action` until the episode ends; the steps taken, whether it terminated, and the game
/// mode after each step.
fn play(env: &mut Env, action: Action) -> (u32, bool, Vec<GameMode>) {
    let mut modes = Vec::new();
    loop {
        let out = env.step(&[action]).unwrap();
        modes.push(env.observations()[0].game_mode);
        if out.terminated || out.truncated {
            return (modes.len() as u32, out.terminated, modes);
        }
    }
}

fn near(a: f32, b: f32, tolerance: f32) -> bool {
    (a - b).abs() <= tolerance
}

/// GRF's `tests/penalty` re-created with `start with penalty_kick for right`: the episode starts
/// in game mode 6 with the ball on the mark, and GRF's own test (`test_penalty`: the left agent
/// slides until done) finds everything where GRF's expects it, after GRF's 31 steps.
#[test]
fn grf_penalty_test_recreated() {
    let mut env = example("penalty_test.tl", 0);
    let o = &env.observations()[0];
    assert_eq!(o.game_mode, GameMode::Penalty);
    assert_eq!(o.game_mode as i32, 6, "GRF's raw game_mode for a penalty");
    assert!(near(o.ball[0], -0.809, 0.01) && o.ball[1].abs() < 0.01, "ball {:?}", o.ball);
    let (steps, terminated, modes) = play(&mut env, Action::Sliding);
    assert_eq!((steps, terminated), (31, false), "GRF truncates tests/penalty after 31 steps");
    // The lazy taker never takes it (GRF's test expects the ball still on the mark).
    assert!(modes.iter().all(|&m| m == GameMode::Penalty));
    let o = &env.observations()[0];
    assert!(near(o.ball[0], -0.809, 0.01) && o.ball[1].abs() < 0.01, "ball {:?}", o.ball);
    assert!(near(o.right_team[0][0], 1.0, 0.1), "right keeper {:?}", o.right_team[0]);
    assert!(near(o.right_team[1][0], -0.75, 0.1), "taker {:?}", o.right_team[1]);
    assert!(near(o.left_team[0][0], -0.95, 0.1), "left keeper {:?}", o.left_team[0]);
    assert!(near(o.left_team[1][0], -0.70, 0.1), "left RM {:?}", o.left_team[1]);
    // GRF puts keepers at ±0.991 at a set piece (0.98 of the half length); so does the law here.
    assert!(near(o.left_team[0][0], -0.991, 0.001) && near(o.right_team[0][0], 0.991, 0.001));
}

/// The penalty drill: the striker on the spot (half a metre behind the ball), the keeper on his
/// line, everyone else out of the area; the episode ends on the goal or the save, not after it.
#[test]
fn the_penalty_drill_starts_on_the_spot_and_ends_on_a_goal_a_save_or_a_miss() {
    let env = example("penalty_kick.tl", 0);
    let o = &env.observations()[0];
    assert_eq!(o.game_mode, GameMode::Penalty);
    assert!(near(o.ball[0], 44.0 / 54.4, 1e-4) && o.ball[1] == 0.0, "ball on the mark: {:?}", o.ball);
    assert!(near(o.left_team[1][0], 43.5 / 54.4, 1e-4), "taker {:?}", o.left_team[1]);
    // On the mark and not yet played, the ball is nobody's in the observation (GRF 2.10.2's
    // tests.penalty shows `ball_owned_team` −1 with the taker beside it).
    assert_eq!(o.ball_owned_team, -1);
    assert!(near(o.right_team[0][0], 0.98 * 55.0 / 54.4, 1e-4), "keeper on his line: {:?}", o.right_team[0]);
    assert_eq!(o.active, 1, "the agent drives the taker");

    // A goal or a save ends the drill within 40 steps; a miss (over or wide for a goal kick, or
    // off the woodwork back into play) runs on: a standing shot is not sure to be on target (GRF
    // 2.10's shot model). A shot with no direction goes at the middle of the goal, where the
    // keeper stands, and he gets a hand to more than half of them (11 goals in these 30 at
    // e9f2440), as GRF's keeper, who deflects what he cannot hold, does.
    let (mut goals, mut saves, mut misses) = (0, 0, 0);
    for seed in 0..30 {
        let mut env = example("penalty_kick.tl", seed);
        let (steps, terminated, _) = play(&mut env, Action::Shot);
        let game = env.game();
        if game.score() == [1, 0] {
            assert!(terminated && steps <= 40, "seed {seed}: a goal after {steps} steps");
            goals += 1;
        } else if terminated && steps <= 40 && game.last_touch() == Some((Side::Right, 0)) {
            saves += 1;
        } else {
            misses += 1;
        }
    }
    assert!(goals >= 6 && saves >= 6 && misses <= 8, "{goals} goals, {saves} saves, {misses} misses in 30 penalties");
}

/// An idle taker: GRF's anti-stalling counter makes him play the ball after 20 steps of waiting
/// (GRF 2.10, tests/penalty with an idle right agent: the forced kick 28 steps after the award).
/// The forced button is short_pass, and a pass goes to a team-mate whatever the direction: here
/// the only one is our keeper, so the ball goes back upfield and nothing ends the drill. The
/// taker is not made to run meanwhile: a ball on the mark is nobody's in the observation, which
/// GRF's rule reads (docs/grf-compatibility.md#action-effects).
#[test]
fn an_idle_taker_is_made_to_play_the_ball() {
    let mut env = example("penalty_kick.tl", 0);
    let (steps, terminated, modes) = play(&mut env, Action::Idle);
    assert!(modes[..20].iter().all(|&m| m == GameMode::Penalty), "{modes:?}");
    let taken = modes.iter().position(|&m| m == GameMode::Normal).expect("the kick was never taken") + 1;
    assert!((21..=30).contains(&taken), "taken at step {taken}");
    assert!(!terminated && steps == 401, "{steps} steps, terminated {terminated}");
    assert_eq!(env.game().score(), [0, 0]);
    assert_eq!(env.observations()[0].sticky_actions, [0; 10], "no direction held");
    let ball = env.game().ball().position;
    assert!(ball.x < 44.0 - 20.0, "the pass went back towards our keeper: ball at {ball}");
}

/// academy_corner from a real corner kick: game mode 4 at the start (GRF's academy_corner starts
/// in open play with the ball at the flag), the taker at the flag, the defenders 9.15 m away, and
/// play going on from the kick.
#[test]
fn the_corner_drill_starts_with_a_corner_kick_and_plays_on() {
    let mut env = example("corner_kick.tl", 3);
    let o: RawObservation = env.observations()[0].clone();
    assert_eq!(o.game_mode as i32, 4, "GRF's raw game_mode for a corner");
    assert!(near(o.ball[0], 55.0 / 54.4, 1e-4) && near(o.ball[1], 36.0 / 83.6, 1e-4), "ball {:?}", o.ball);
    // Placed for the kick, the ball is nobody's in the observation until it is played (GRF's
    // owner is the last toucher; `Match::observed_owner`), though the taker has it at his feet.
    assert_eq!(o.ball_owned_team, -1);
    // The left back, GRF's corner taker at (1, 0.42), takes it.
    assert_eq!(env.game().owner(), Some((Side::Left, 1)));
    let spot = glam::Vec2::new(55.0, 36.0);
    for p in env.game().team(Side::Right).iter().filter(|p| !p.is_keeper()) {
        assert!(p.position.distance(spot) >= 9.15 - 1e-3, "{} {} at {}", p.role, p.index, p.position);
    }
    assert!(near(o.right_team[0][0], 0.991, 0.001), "keeper on his line");
    // A pass from the flag: open play, and the episode goes on (out of play ends it only when
    // the mode turns from normal to a set piece).
    let mut steps = 0;
    let mut normal_at = None;
    loop {
        steps += 1;
        let out = env.step(&[if steps < 3 { Action::ShortPass } else { Action::Idle }]).unwrap();
        let mode = env.observations()[0].game_mode;
        if mode == GameMode::Normal && normal_at.is_none() {
            normal_at = Some(steps);
        }
        if out.terminated || out.truncated {
            break;
        }
    }
    let taken = normal_at.expect("the corner was never taken");
    assert!(taken <= 10, "taken at step {taken}");
    assert!(steps > taken + 5, "the episode ended {} steps after the kick", steps - taken);
}

/// Every restart compiles to its engine form, and back to the same `.tl`.
#[test]
fn each_restart_compiles_and_prints_back() {
    let cases = [
        ("kickoff for right", GameMode::KickOff, Side::Right, None),
        ("goal_kick for left", GameMode::GoalKick, Side::Left, None),
        ("free_kick for left at (0.6, -10 m)", GameMode::FreeKick, Side::Left, Some([0.6, -10.0 / 83.6])),
        ("corner_kick for right at top", GameMode::Corner, Side::Right, Some([-1.0, -0.42])),
        ("throw_in for right at (-0.3, 0.4)", GameMode::ThrowIn, Side::Right, Some([-0.3, 0.4])),
        ("penalty_kick for left", GameMode::Penalty, Side::Left, None),
    ];
    for (text, mode, team, at) in cases {
        let source = format!(
            "scenario s {{\n  extends academy\n  start with {text}\n  end when save or keeper_holds_ball or restart_taken\n  \
             team left {{ GK at (-1, 0) CF at (0.5, 0) facing ball CM at (0.2, 0.1) facing (0, -1) }}\n  \
             team right {{ GK at (-1, 0) facing goal }}\n}}\n"
        );
        let compiled = compile(&source, "s.tl").unwrap_or_else(|d| panic!("{text}:\n{}", d.render_plain()));
        assert!(compiled.warnings.items.is_empty(), "{text}: {}", compiled.warnings.render_plain());
        let s = compiled.scenario;
        let start = s.start_with.unwrap();
        assert_eq!((start.mode, start.team), (mode, team), "{text}");
        match (start.at, at) {
            (Some(a), Some(b)) => assert!(near(a[0], b[0], 1e-6) && near(a[1], b[1], 1e-6), "{text}: {a:?}"),
            (a, b) => assert_eq!(a, b, "{text}"),
        }
        assert_eq!(s.end_when, [EndCondition::Save, EndCondition::KeeperHoldsBall, EndCondition::RestartTaken]);
        assert_eq!(s.left_team[1].facing, Some(Facing::Ball));
        assert_eq!(s.left_team[2].facing, Some(Facing::Direction([0.0, -1.0])));
        assert_eq!(s.right_team[0].facing, Some(Facing::Goal));
        // The ball's start is the restart's spot.
        let spot = StartRestart { mode, team, at: start.at }.restart().spot;
        assert!(near(s.ball_position[0] * 54.4, spot.x, 1e-3) && near(s.ball_position[1] * 83.6, spot.y, 1e-3));
        let again = compile(&scenario_to_tl(&s), "again.tl").unwrap_or_else(|d| panic!("{}", d.render_plain()));
        assert_eq!(again.scenario, s, "{text}: printed as\n{}", scenario_to_tl(&s));
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(serde_json::from_str::<touchline_engine::Scenario>(&json).unwrap(), s);
        Env::new(s, 0).unwrap();
    }
}

/// A child of a drill that starts with a restart keeps it.
#[test]
fn a_child_keeps_its_parents_start() {
    let source = "preset corner {\n  extends academy\n  start with corner_kick for left at bottom\n}\n\
                  scenario drill {\n  extends corner\n  team left { GK at (-1, 0) CF at (0.9, 0.3) }\n  team right { GK at (-1, 0) }\n}\n";
    let s = compile(source, "drill.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    assert_eq!(s.start_with.map(|w| w.mode), Some(GameMode::Corner));
    let env = Env::new(s, 0).unwrap();
    assert_eq!(env.game().mode(), GameMode::Corner);
    assert_eq!(env.game().owner(), Some((Side::Left, 1)));
}

/// `facing` reads a direction through a param, as every other value does.
#[test]
fn facing_takes_a_param() {
    let source = "scenario s {\n  extends academy\n  param look = (0, 1)\n  team left { GK at (-1, 0) CF at (0.5, 0) facing look }\n  team right { GK at (-1, 0) }\n}\n";
    let s = compile(source, "s.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    assert_eq!(s.left_team[1].facing, Some(Facing::Direction([0.0, 1.0])));
    let env = Env::new(s, 0).unwrap();
    assert_eq!(env.game().team(Side::Left)[1].facing, glam::Vec2::Y);
}

/// A save is also an event `reward on` can pay: the shooter's side is paid `opponent_save`, the
/// keeper's side `save` (here the penalty drill, the left agent shooting).
#[test]
fn a_save_is_an_event_rewards_can_pay() {
    let source = "scenario s {\n  extends academy\n  start with penalty_kick for left\n  team left { GK at (-1, 0) CF at (0.75, 0) }\n  team right { GK at (-1, 0) }\n  end when score or save\n  reward scoring\n  reward on opponent_save -1\n  reward on save 5\n}\n";
    let s = compile(source, "s.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    let again = compile(&scenario_to_tl(&s), "again.tl").unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert_eq!(again.scenario, s);
    let mut saves = 0;
    for seed in 0..30 {
        let mut env = Env::new(s.clone(), seed).unwrap();
        let mut total = 0.0;
        loop {
            let out = env.step(&[Action::Shot]).unwrap();
            total += env.rewards()[0];
            if out.terminated || out.truncated {
                break;
            }
        }
        let expected = if env.game().score()[0] == 1 { 1.0 } else { -1.0 };
        saves += usize::from(expected < 0.0);
        assert_eq!(total, expected, "seed {seed}");
    }
    assert!(saves > 0, "no penalty was saved in 30");
}
