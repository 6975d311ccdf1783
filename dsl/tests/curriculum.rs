//! `curriculum { … }`: lessons compiled to complete scenarios (param values, settings, another
//! scenario), criteria read, the compiled curriculum printed back and played in an env.

use touchline_dsl::{compile, load_json, scenario_to_tl};
use touchline_engine::scenario::Metric;
use touchline_engine::{Action, Env};

const GAP_DRILL: &str = "/// The defender's gap shrinks.
scenario gap_drill {
  extends academy
  param defender_gap = 20 m
  ball at (0.02, 0)
  team left {
    GK at (-1, 0)
    CB at (0, 0)
  }
  team right {
    GK at (-1, 0)
    CB at (-(0.1 + defender_gap), 0.05)
  }
  curriculum {
    lesson near {
      defender_gap = 30 m
      difficulty 0.1
    }
    lesson mid {
      defender_gap = 10 m
      advance when mean_score >= 0.5 over 50 episodes
    }
    lesson far extends academy_run_to_score_with_keeper
    advance when mean_reward >= 0.8 and success_rate >= 0.7 over 100 episodes min 20 episodes
  }
}
";

#[test]
fn lessons_compile_to_complete_scenarios() {
    let s = compile(GAP_DRILL, "gap_drill.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    let c = s.curriculum.as_ref().expect("a curriculum");
    let names: Vec<&str> = c.lessons.iter().map(|l| l.name.as_str()).collect();
    assert_eq!(names, ["near", "mid", "far"]);
    let x = |l: usize| c.lessons[l].scenario.right_team[1].x;
    assert!((s.right_team[1].x - -(0.1 + 20.0 / 55.0)).abs() < 1e-6, "the base reads the declared 20 m");
    assert!((x(0) - -(0.1 + 30.0 / 55.0)).abs() < 1e-6);
    assert!((x(1) - -(0.1 + 10.0 / 55.0)).abs() < 1e-6);
    assert_eq!(c.lessons[0].scenario.right_team_difficulty, 0.1);
    assert_eq!(c.lessons[1].scenario.right_team_difficulty, s.right_team_difficulty, "only `near` sets it");
    assert_eq!(c.lessons[2].scenario.right_team.len(), 6, "`far` plays academy_run_to_score_with_keeper");
    assert!(c.lessons.iter().all(|l| l.scenario.curriculum.is_none() && l.scenario.name == "gap_drill"));
    // `near` and `far` take the block's criterion, `mid` its own.
    let global = c.lessons[0].advance.as_ref().unwrap();
    assert_eq!((global.window, global.min_episodes, global.thresholds.len()), (100, 20, 2));
    assert_eq!(global.thresholds[0].metric, Metric::MeanReward);
    assert_eq!(c.lessons[2].advance, c.lessons[0].advance);
    let own = c.lessons[1].advance.as_ref().unwrap();
    assert_eq!((own.window, own.min_episodes, own.thresholds[0].metric), (50, 50, Metric::MeanScore));
}

#[test]
fn a_compiled_curriculum_survives_json_and_printing() {
    let s = compile(GAP_DRILL, "gap_drill.tl").unwrap().scenario;
    let json = serde_json::to_string_pretty(&s).unwrap();
    assert_eq!(load_json(&json, "gap_drill.json").unwrap(), s);
    let text = scenario_to_tl(&s);
    let back = compile(&text, "printed.tl").unwrap_or_else(|d| panic!("{text}\n{}", d.render_plain()));
    assert_eq!(back.scenario, s, "{text}");
}

#[test]
fn an_env_plays_the_lessons_in_order() {
    let text = "scenario quick {\n  extends academy_empty_goal_close\n  param start = 0.7\n  ball at (start + 0.02, 0)\n  \
                team left { GK at (-1, 0) CB at (start, 0) }\n  curriculum {\n    lesson close\n    \
                lesson farther { start = 0.3 }\n    advance when success_rate >= 0 over 2 episodes\n  }\n}\n";
    let s = compile(text, "quick.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    let mut env = Env::new(s, 0).unwrap();
    let mut seen = Vec::new();
    for _ in 0..5 {
        loop {
            let out = env.step(&[Action::Right]).unwrap();
            if out.terminated || out.truncated {
                break;
            }
        }
        seen.push(env.info().lesson);
        env.reset().unwrap();
    }
    assert_eq!(seen, [0, 0, 1, 1, 1]);
    assert_eq!(env.lesson(), Some((1, "farther")));
    assert_eq!(env.scenario().left_team[1].x, 0.3);
}
