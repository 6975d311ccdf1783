//! `param NAME = VALUE`, assignments and arithmetic: values, units, precedence and late binding
//! through `extends`.

use touchline_dsl::compile;
use touchline_engine::scenario::{Distribution, Region, Sample, Shared, Spot};

fn scenario(text: &str) -> touchline_engine::Scenario {
    compile(text, "params.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario
}

const METRES_PER_X: f32 = 55.0;

#[test]
fn params_and_arithmetic_give_positions_and_settings() {
    let s = scenario(
        "scenario s {\n  extends academy\n  param gap = 11 m\n  param theta = 0.3\n  param half = 100 steps\n  \
         difficulty theta * 2 - 0.1\n  game_duration half * 2 + 1\n  team left { GK at (-1, 0) CF at (0.5 + gap, -gap / 4) }\n  \
         team right { GK at (-1, 0) CB at (-(0.25 + 0.25), 1 + 2 * 3 - 7) }\n}\n",
    );
    assert!((s.right_team_difficulty - 0.5).abs() < 1e-6);
    assert_eq!(s.game_duration, 201);
    let cf = &s.left_team[1];
    assert!((cf.x - (0.5 + 11.0 / METRES_PER_X)).abs() < 1e-6, "{}", cf.x);
    assert!(cf.y < 0.0 && cf.y > -0.1, "{}", cf.y);
    let cb = &s.right_team[1];
    assert_eq!((cb.x, cb.y), (-0.5, 0.0), "`*` binds tighter than `+`, `-` is left-associative");
}

#[test]
fn a_param_can_be_a_point_a_distribution_or_a_region() {
    let s = scenario(
        "scenario s {\n  extends academy\n  param spot = (0.5, 0.1)\n  param spread = uniform(-0.1, 0.1)\n  param box = circle(0.6, 0, 0.05)\n  \
         ball at spot\n  team left { GK at (-1, 0) CF at (0.4, spread) }\n  team right { GK at (-1, 0) CB in box }\n}\n",
    );
    assert_eq!(s.ball_position, [0.5, 0.1]);
    assert!(matches!(
        s.left_team[1].random,
        Some(Spot::Point { y: Sample::Shared(Shared { of: Distribution::Uniform(a, b), .. }), .. }) if a == -0.1 && b == 0.1
    ));
    assert!(matches!(s.right_team[1].random, Some(Spot::In(Region::Circle { .. }))));
}

#[test]
fn params_bind_late_through_extends() {
    let text = "preset drill {\n  extends academy\n  param gap = 0.2\n  team left { GK at (-1, 0) CF at (gap, 0) }\n  \
                team right { GK at (-1, 0) }\n}\nscenario by_param {\n  extends drill\n  param gap = 0.3\n}\n";
    assert_eq!(scenario(text).left_team[1].x, 0.3);
    let assigned = text.replace("param gap = 0.3", "gap = 0.4");
    assert_eq!(scenario(&assigned).left_team[1].x, 0.4);
    let own = text.replace("param gap = 0.3", "");
    assert_eq!(scenario(&own).left_team[1].x, 0.2);
}

#[test]
fn units_must_agree_in_arithmetic() {
    let e = compile(
        "scenario s {\n  extends academy\n  game_duration 100 steps + 2 m\n  team left { GK at (-1, 0) }\n  team right { GK at (-1, 0) }\n}\n",
        "params.tl",
    )
    .unwrap_err();
    assert_eq!(e.errors().next().unwrap().code, touchline_dsl::Code::WrongUnit);
    assert!(e.render_plain().contains("cannot add a plain number and `m`"), "{}", e.render_plain());
    let e = compile(
        "scenario s {\n  extends academy\n  difficulty 1 / 0\n  team left { GK at (-1, 0) }\n  team right { GK at (-1, 0) }\n}\n",
        "params.tl",
    )
    .unwrap_err();
    assert!(e.render_plain().contains("division by zero"));
}

#[test]
fn a_key_written_with_equals_says_so() {
    let e = compile(
        "scenario s {\n  extends academy\n  game_duration = 200\n  team left { GK at (-1, 0) }\n  team right { GK at (-1, 0) }\n}\n",
        "params.tl",
    )
    .unwrap_err();
    let d = e.errors().next().unwrap();
    assert_eq!(d.code, touchline_dsl::Code::UnknownParam);
    assert!(d.help.as_deref().unwrap().contains("without `=`"));
}

#[test]
fn formatting_keeps_params_arithmetic_and_curricula() {
    let text = "scenario s {\n  extends academy\n  param gap=10 m\n  team left { GK at (-1, 0) CF at ((0.1+gap)*2, 0) }\n  \
                team right { GK at (-1, 0) }\n  curriculum { // the lessons\n lesson a { gap = 20 m difficulty 0.1 }\n  lesson b extends academy_empty_goal\n \
                advance when success_rate>=0.5 and mean_reward >= 0.1 over 10 episodes min 5 episodes }\n}\n";
    let once = touchline_dsl::format_source(text, "f.tl").unwrap();
    assert!(once.contains("  param gap = 10 m\n"), "{once}");
    assert!(once.contains("CF at ((0.1 + gap) * 2, 0)"), "{once}");
    assert!(
        once.contains(
            "  curriculum { // the lessons\n    lesson a {\n      gap = 20 m\n      difficulty 0.1\n    }\n    lesson b extends academy_empty_goal\n    \
             advance when success_rate >= 0.5 and mean_reward >= 0.1 over 10 episodes min 5 episodes\n  }\n"
        ),
        "{once}"
    );
    assert_eq!(touchline_dsl::format_source(&once, "f.tl").unwrap(), once);
    assert_eq!(compile(&once, "f.tl").unwrap().scenario, compile(text, "f.tl").unwrap().scenario);
}
