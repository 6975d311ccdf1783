//! Behaviours and conditions in the language: each form compiled to the engine's values, frames
//! and units, `end when`, `extends`, diagnostics, printing and formatting round trips, and
//! compiled scenarios played by the engine (the example scenarios among them).

use touchline_engine::GameMode;
use touchline_engine::scenario::{
    Behaviour, Comparison, Condition, EndCondition, Owner, PassKind, Region, Stage, Target,
};
use touchline_engine::{Env, EnvConfig, Scenario, Side};

use touchline_dsl::{Code, Diagnostics, compile, compile_file, format_source, scenario_to_tl};

const TEAMS: &str = "
  team left { GK at (-1, 0) CB at (-0.5, 0) CM at (0, 0.1) CF at (0.3, 0) }
  team right {
    GK at (-1, 0)
    CB at (-0.7, 0) does press
    CM at (0.2, 0.1) does dribble_to((0.7, 0.2)) then shoot
    LB at (-0.6, 0.3) does move_to((-0.5, 0)) until distance(ball, me) < 8 m then mark(left[2])
    RB at (-0.6, -0.3) does do follow(ball) until owner is right or steps >= 50 then builtin(0.9)
    CF at (0.1, 0) does script \"scripts/striker.rhai\"
    DM at (-0.3, 0) does pass_to(right.CB, long) then hold_position
    LM at (-0.2, 0.2) does idle
    RM at (-0.2, -0.2) does follow(left.CF) until done
    AM at (0, 0) does builtin
  }
";

/// Compiles `text`: the scenario and the diagnostics (warnings, or every error).
fn resolve(text: &str) -> (Option<Scenario>, Diagnostics) {
    match compile(text, "test.tl") {
        Ok(c) => (Some(c.scenario), c.warnings),
        Err(d) => (None, d),
    }
}

fn scenario(body: &str) -> Scenario {
    let text = format!("scenario s {{\n  extends academy\n{body}\n}}\n");
    let (s, diags) = resolve(&text);
    assert!(!diags.has_errors(), "{}", diags.render_plain());
    s.expect("compiles")
}

/// A named region as compiled (`end when ball in NAME` keeps it in `BallIn`).
fn region(name: &str) -> Region {
    let s = scenario(&format!("{TEAMS}  end when ball in {name}"));
    match s.end_when.as_slice() {
        [EndCondition::BallIn(r)] => r.clone(),
        other => panic!("{other:?}"),
    }
}

fn stages(s: &Scenario, side: Side, i: usize) -> &[Stage] {
    let team = if side == Side::Left { &s.left_team } else { &s.right_team };
    &team[i].behaviour
}

fn errors(body: &str) -> Vec<Code> {
    let text = format!("scenario s {{\n  extends academy\n{body}\n}}\n");
    let (_, diags) = resolve(&text);
    diags.items.iter().map(|d| d.code).collect()
}

fn stage(behaviour: Behaviour) -> Stage {
    Stage { behaviour, until: None }
}

#[test]
fn every_behaviour_compiles_to_its_engine_value() {
    let s = scenario(TEAMS);
    assert!(stages(&s, Side::Right, 0).is_empty(), "no behaviour: the built-in AI");
    assert_eq!(stages(&s, Side::Right, 1), [stage(Behaviour::Press)]);
    assert_eq!(stages(&s, Side::Right, 2), [stage(Behaviour::DribbleTo { point: [0.7, 0.2], shoot: true })]);
    assert_eq!(
        stages(&s, Side::Right, 3),
        [
            Stage {
                behaviour: Behaviour::MoveTo { point: [-0.5, 0.0] },
                until: Some(Condition::Distance { a: Target::Ball, b: Target::Me, op: Comparison::Lt, metres: 8.0 }),
            },
            stage(Behaviour::Mark(Target::Left(2))),
        ]
    );
    assert_eq!(
        stages(&s, Side::Right, 4),
        [
            Stage {
                behaviour: Behaviour::Follow(Target::Ball),
                until: Some(Condition::Any(vec![
                    Condition::Owner(Owner::Team(Side::Right)),
                    Condition::Steps { op: Comparison::Ge, steps: 50 },
                ])),
            },
            stage(Behaviour::Builtin { difficulty: Some(0.9) }),
        ]
    );
    assert_eq!(stages(&s, Side::Right, 5), [stage(Behaviour::Script { path: "scripts/striker.rhai".into() })]);
    assert_eq!(
        stages(&s, Side::Right, 6),
        [stage(Behaviour::PassTo { player: 1, kind: PassKind::Long }), stage(Behaviour::HoldPosition)]
    );
    assert_eq!(stages(&s, Side::Right, 7), [stage(Behaviour::Idle)]);
    assert_eq!(
        stages(&s, Side::Right, 8),
        [Stage { behaviour: Behaviour::Follow(Target::Left(3)), until: Some(Condition::Done) }]
    );
    assert_eq!(stages(&s, Side::Right, 9), [stage(Behaviour::Builtin { difficulty: None })]);
}

#[test]
fn behaviour_points_are_in_the_team_frame_with_player_metres() {
    // 11 m along x is 11 / 55 = 0.2 for a player (docs/grf-compatibility.md#scenario-semantics), whichever
    // side he plays on.
    let s = scenario(
        "  team left { GK at (-1, 0) CB at (-0.5, 0) does move_to((11 m, 0)) }
  team right { GK at (-1, 0) CB at (-0.5, 0) does move_to(11 m, -0.1) until me in circle(0, 0, 5.5 m) }",
    );
    assert_eq!(stages(&s, Side::Left, 1), [stage(Behaviour::MoveTo { point: [0.2, 0.0] })]);
    assert_eq!(
        stages(&s, Side::Right, 1),
        [Stage {
            behaviour: Behaviour::MoveTo { point: [0.2, -0.1] },
            until: Some(Condition::In { what: Target::Me, region: Region::Circle { x: 0.0, y: 0.0, r: 0.1 } }),
        }]
    );
}

#[test]
fn conditions_bind_or_then_and_then_not() {
    let s = scenario(&format!(
        "{TEAMS}  end when score or owner is nobody or game_mode is corner and not (score(left) >= 1 or left[1] in penalty_area)"
    ));
    assert!(s.end_episode_on_score);
    let corner_and = Condition::All(vec![
        Condition::Mode(GameMode::Corner),
        Condition::Not(Box::new(Condition::Any(vec![
            Condition::Score { side: Side::Left, op: Comparison::Ge, goals: 1 },
            Condition::In { what: Target::Left(1), region: region("penalty_area") },
        ]))),
    ]);
    assert_eq!(s.end_when, [EndCondition::When(Condition::Owner(Owner::Nobody)), EndCondition::When(corner_and)]);
}

#[test]
fn end_when_keeps_its_own_forms_and_reads_the_rest_globally() {
    let s = scenario(&format!(
        "{TEAMS}  end when out_of_play or steps >= 200 or ball in opponent_penalty_area or script \"end.rhai\" or steps > 10 or (steps >= 30) or distance(left.CF, (5.44 m, 0)) <= 2 m or owner is right.GK"
    ));
    assert!(s.end_episode_on_out_of_play && !s.end_episode_on_score);
    let area = region("opponent_penalty_area");
    assert_eq!(
        s.end_when,
        [
            EndCondition::Steps(200),
            EndCondition::BallIn(area),
            EndCondition::Script { path: "end.rhai".into() },
            EndCondition::When(Condition::Steps { op: Comparison::Gt, steps: 10 }),
            EndCondition::When(Condition::Steps { op: Comparison::Ge, steps: 30 }),
            // 5.44 m is 0.1 in the global (ball) frame: 54.4 m per unit.
            EndCondition::When(Condition::Distance {
                a: Target::Left(3),
                b: Target::Point([0.1, 0.0]),
                op: Comparison::Le,
                metres: 2.0,
            }),
            EndCondition::When(Condition::Owner(Owner::Player(Target::Right(0)))),
        ]
    );
}

#[test]
fn conditions_may_name_players_of_teams_given_later() {
    let s = scenario(
        "  end when distance(ball, right.GK) < 3 m
  team left { GK at (-1, 0) CF at (0.5, 0) does dribble_to((0.9, 0)) then shoot until owner is right.GK }
  team right { GK at (-1, 0) }",
    );
    assert_eq!(
        s.end_when,
        [EndCondition::When(Condition::Distance {
            a: Target::Ball,
            b: Target::Right(0),
            op: Comparison::Lt,
            metres: 3.0
        })]
    );
    assert_eq!(stages(&s, Side::Left, 1)[0].until, Some(Condition::Owner(Owner::Player(Target::Right(0)))));
}

#[test]
fn a_behaviour_statement_sets_a_player_of_the_parent() {
    let text = format!(
        "preset drill {{\n  extends academy\n{TEAMS}}}\nscenario s {{\n  extends drill\n  behaviour right.CB does mark(left.CF)\n  behaviour right[2] does idle\n}}\n"
    );
    let (s, diags) = resolve(&text);
    assert!(!diags.has_errors(), "{}", diags.render_plain());
    let s = s.expect("resolves");
    assert_eq!(stages(&s, Side::Right, 1), [stage(Behaviour::Mark(Target::Left(3)))]);
    assert_eq!(stages(&s, Side::Right, 2), [stage(Behaviour::Idle)]);
    // The others keep the parent's behaviours.
    assert_eq!(stages(&s, Side::Right, 7), [stage(Behaviour::Idle)]);
    assert_eq!(stages(&s, Side::Right, 4).len(), 2);
}

#[test]
fn extends_replaces_a_team_with_its_behaviours() {
    let text = format!(
        "preset drill {{\n  extends academy\n{TEAMS}}}\nscenario s {{\n  extends drill\n  team right {{ GK at (-1, 0) CB at (-0.5, 0) }}\n}}\n"
    );
    let (s, diags) = resolve(&text);
    assert!(!diags.has_errors(), "{}", diags.render_plain());
    let s = s.expect("resolves");
    assert!(s.right_team.iter().all(|p| p.behaviour.is_empty()));
    assert_eq!(stages(&s, Side::Right, 1).len(), 0);
}

#[test]
fn wrong_behaviours_and_conditions_are_reported() {
    let team = |line: &str| {
        format!("  team left {{ GK at (-1, 0) CB at (-0.5, 0) }}\n  team right {{ GK at (-1, 0) CB at (0, 0) {line} }}")
    };
    let cases: [(&str, Code); 16] = [
        ("does pres", Code::UnknownBehaviour),
        ("does (0.5, 0)", Code::UnknownBehaviour),
        ("does move_to(left[1])", Code::BehaviourArguments),
        ("does move_to((0.5, 0), (0.1, 0))", Code::BehaviourArguments),
        ("does mark(ball)", Code::BehaviourArguments),
        ("does mark(right.GK)", Code::BehaviourArguments),
        ("does pass_to(right.GK, lob)", Code::BehaviourArguments),
        ("does press(1)", Code::BehaviourArguments),
        ("does pass_to(left.GK)", Code::PassTarget),
        ("does pass_to(right[1])", Code::PassTarget),
        ("does press until game_mode is corner_kick", Code::UnknownGameMode),
        ("does press until speed(ball) > 3", Code::UnknownMeasure),
        ("does builtin(1.5)", Code::OutOfRange),
        ("does move_to((3, 0))", Code::OutOfRange),
        ("does move_to((0.5, 0)) then shoot", Code::MisplacedShoot),
        ("does press until score", Code::EndOnlyCondition),
    ];
    for (line, code) in cases {
        assert_eq!(errors(&team(line)), [code], "{line}");
    }
    let end = |cond: &str| format!("{}\n  end when {cond}", team(""));
    assert_eq!(errors(&end("distance(ball, me) < 3 m")), [Code::BehaviourOnly]);
    assert_eq!(errors(&end("steps > 3 and done")), [Code::BehaviourOnly]);
    assert_eq!(errors(&end("not out_of_play")), [Code::EndOnlyCondition]);
    assert_eq!(errors(&end("right[5] in box")), [Code::UnknownPlayer, Code::UnknownRegion]);
    assert_eq!(errors(&end("owner is right.CM")), [Code::UnknownPlayer]);
    assert_eq!(errors(&end("distance(ball, left[0]) < 3")), [Code::WrongUnit]);
}

#[test]
fn a_stage_after_one_that_never_ends_is_unreachable() {
    let team = |line: &str| {
        format!("  team left {{ GK at (-1, 0) CF at (0.5, 0) }}\n  team right {{ GK at (-1, 0) CB at (0, 0) {line} }}")
    };
    assert_eq!(errors(&team("does press then idle")), [Code::UnreachableStage]);
    assert_eq!(errors(&team("does follow(ball) until done then idle then press")), [Code::UnreachableStage]);
    assert!(errors(&team("does press until steps >= 10 then idle")).is_empty());
    assert!(errors(&team("does move_to((0.5, 0)) then idle")).is_empty());
    assert!(errors(&team("does dribble_to((0.5, 0)) then shoot then idle")).is_empty());
}

#[test]
fn printing_and_compiling_again_gives_the_same_scenario() {
    let s = scenario(&format!(
        "{TEAMS}  end when score or distance(left.CF, (0.1, 0)) <= 2 m or (steps >= 30) or (ball in goal_area) or (owner is left or game_mode is throw_in) and not (steps < 5 and score(right) != 0)"
    ));
    let text = scenario_to_tl(&s);
    let (again, diags) = resolve(&text);
    assert!(!diags.has_errors(), "{text}\n{}", diags.render_plain());
    assert_eq!(again.expect("resolves"), s, "{text}");
}

#[test]
fn formatting_keeps_behaviours_conditions_and_comments() {
    let messy = "scenario s {\n  team right {\n    GK at (-1, 0)\n    // presses first\n    CB at (0, 0) does do press until (steps>=10 or owner is   left)and not done then  dribble_to( (0.5,0) )then shoot // then shoots\n  }\n  behaviour   right.GK does idle\n  end when score or(distance(ball,left[0])<5 m)\n}\n";
    let once = format_source(messy, "m.tl").expect("formats");
    assert!(
        once.contains("    // presses first\n    CB at (0, 0) does press until (steps >= 10 or owner is left) and not done then dribble_to((0.5, 0)) then shoot // then shoots\n"),
        "{once}"
    );
    assert!(once.contains("  behaviour right.GK does idle\n"), "{once}");
    assert!(once.contains("  end when score or (distance(ball, left[0]) < 5 m)\n"), "{once}");
    assert_eq!(format_source(&once, "m.tl").expect("formats"), once);
}

/// An env of `s` with no agents: every player is played by his behaviour or the built-in AI.
fn env(s: Scenario, seed: u64) -> Env {
    Env::with_config(s, EnvConfig { left_agents: 0, ..EnvConfig::default() }, seed).expect("the engine plays it")
}

#[test]
fn a_right_players_behaviour_point_is_in_his_teams_frame() {
    // `move_to((11 m, 0))` in the right team's frame is 11 m into the left half, globally.
    let s = scenario(
        "  team left { GK at (-1, 0) lazy CB at (-0.6, 0.3) lazy }
  team right { GK at (-1, 0) lazy CB at (-0.3, 0.1) does move_to((11 m, 0)) }",
    );
    let mut env = env(s, 0);
    for _ in 0..80 {
        env.step(&[]).expect("steps");
    }
    let p = env.game().team(Side::Right)[1].position;
    assert!((p.x - -11.0).abs() < 1.0 && p.y.abs() < 1.0, "the right CB stands at ({}, {}) m", p.x, p.y);
}

#[test]
fn an_end_when_condition_of_the_language_ends_the_episode() {
    // The striker runs into the opponents' box; the episode ends when he is in it (global frame).
    let s = scenario(
        "  ball at (0, 0.3)
  team left { GK at (-1, 0) lazy CF at (0.3, 0) does move_to((0.9, 0)) }
  team right { GK at (-1, 0) lazy }
  end when left.CF in opponent_penalty_area and steps > 3",
    );
    let mut env = env(s, 0);
    let mut ended = None;
    for step in 1..=200 {
        if env.step(&[]).expect("steps").terminated {
            ended = Some(step);
            break;
        }
    }
    let step = ended.expect("the episode ends");
    let x = env.game().team(Side::Left)[1].position.x;
    // The box starts 16.5 m from the goal line (52.5 m from the centre,
    // docs/grf-compatibility.md#scenario-semantics scaling aside).
    assert!(x > 30.0, "ended at step {step} with the striker at x = {x} m");
    assert!(step > 3);
}

#[test]
fn every_example_scenario_compiles_without_warnings_and_plays() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios");
    let mut count = 0;
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("examples/scenarios exists")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "tl"))
        .collect();
    paths.sort();
    for path in paths {
        let text = std::fs::read_to_string(&path).expect("readable");
        assert!(text.starts_with("///"), "{}: starts with a doc line", path.display());
        assert_eq!(format_source(&text, "example.tl").expect("formats"), text, "{}: formatted", path.display());
        let compiled = compile_file(&path).unwrap_or_else(|d| panic!("{}:\n{}", path.display(), d.render_plain()));
        assert!(compiled.warnings.items.is_empty(), "{}:\n{}", path.display(), compiled.warnings.render_plain());
        let s = compiled.scenario;
        let behaving: Vec<(Side, usize)> = [(Side::Left, &s.left_team), (Side::Right, &s.right_team)]
            .into_iter()
            .flat_map(|(side, team)| {
                team.iter().enumerate().filter(|(_, p)| !p.behaviour.is_empty()).map(move |(i, _)| (side, i))
            })
            .collect();
        if behaving.is_empty() {
            // An example of another feature (event rewards, …): tests/examples.rs plays it.
            continue;
        }
        let mut env = env(s.clone(), 0);
        let start: Vec<_> = behaving.iter().map(|&(side, i)| env.game().team(side)[i].position).collect();
        let mut moved = false;
        for _ in 0..=s.game_duration {
            let outcome = env.step(&[]).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            moved |= behaving
                .iter()
                .zip(&start)
                .any(|(&(side, i), p0)| env.game().team(side)[i].position.distance(*p0) > 2.0);
            if outcome.terminated || outcome.truncated {
                break;
            }
        }
        assert!(moved, "{}: a player with a behaviour moves", path.display());
        count += 1;
    }
    assert!(count >= 4, "{count} example scenarios");
}
