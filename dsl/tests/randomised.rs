//! Randomised scenarios: compiled once, they draw new placements at every reset from the
//! episode's seed, identical for the same seed, and always meet their `require` constraints.

use touchline_engine::{Env, Scenario};

const DRILL: &str = r#"
/// The attacker starts anywhere in a box, the defender in the penalty area, the ball from a list.
scenario random_drill {
  extends academy_3_vs_1_with_keeper
  ball at choice[(0.6, 0), (0.6, 0.1), (0.65, -0.1)]
  team left {
    GK at (-1, 0)
    CM at (uniform(0.5, 0.7), normal(0, 0.1))
    CM in circle(0.7, 0.2, 3 m)
    CM at (0.7, -0.2)
  }
  team right {
    GK at (-1, 0)
    CB in penalty_area
  }
  require distance(left[1], right[1]) >= 8 m
  require distance(left[1], ball) <= 12 m
}
"#;

fn drill() -> Scenario {
    touchline_dsl::compile(DRILL, "random_drill.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario
}

/// Player positions of the first observation, left then right.
fn starts(env: &Env) -> Vec<[f32; 2]> {
    let obs = &env.observations()[0];
    obs.left_team.iter().chain(&obs.right_team).copied().collect()
}

#[test]
fn resets_draw_new_placements_and_seeds_repeat_them() {
    let scenario = drill();
    assert!(scenario.is_randomised());
    let mut a = Env::new(scenario.clone(), 3).unwrap();
    let mut b = Env::new(scenario, 3).unwrap();
    let mut seen = Vec::new();
    for _ in 0..20 {
        assert_eq!(starts(&a), starts(&b), "same seed, same placements");
        assert_eq!(a.observations()[0].ball, b.observations()[0].ball);
        seen.push(starts(&a));
        for env in [&mut a, &mut b] {
            env.step(&[touchline_engine::Action::Idle]).unwrap();
            env.reset().unwrap();
        }
    }
    let distinct: std::collections::HashSet<String> = seen.iter().map(|s| format!("{s:?}")).collect();
    assert_eq!(distinct.len(), 20, "every reset draws anew");
    a.reset_with_seed(4).unwrap();
    b.reset_with_seed(3).unwrap();
    assert_ne!(starts(&a), starts(&b), "another seed, other placements");
}

#[test]
fn require_and_supports_hold_in_10000_draws() {
    let s = drill();
    let world = |x: f32, y: f32, right: bool| {
        let sign = if right { -1.0 } else { 1.0 };
        glam::Vec2::new(sign * 55.0 * x, sign * 84.96 * y)
    };
    let balls = [[0.6, 0.0], [0.6, 0.1], [0.65, -0.1]];
    for episode in 0..10_000 {
        let p = s.draw(17, episode);
        assert!(p.satisfied, "episode {episode}");
        let attacker = world(p.left[1].x, p.left[1].y, false);
        let defender = world(p.right[1].x, p.right[1].y, true);
        let ball = glam::Vec2::new(54.4 * p.ball[0], 83.6 * p.ball[1]);
        assert!(attacker.distance(defender) >= 8.0, "episode {episode}");
        assert!(attacker.distance(ball) <= 12.0, "episode {episode}");
        assert!((0.5..=0.7).contains(&p.left[1].x) && p.left[1].y.abs() <= 0.42);
        assert!((p.left[2].x - 0.7).hypot(p.left[2].y - 0.2) <= 3.0 / 55.0 + 1e-6);
        assert!((0.7..=1.0).contains(&p.right[1].x.abs()) || p.right[1].x <= -0.7, "penalty area: {:?}", p.right[1]);
        assert!(balls.contains(&p.ball), "{:?}", p.ball);
    }
}

#[test]
fn the_compiled_json_keeps_the_distributions() {
    let s = drill();
    let json = serde_json::to_string(&s).unwrap();
    for key in ["\"uniform\"", "\"normal\"", "\"circle\"", "\"one_of\"", "\"min_distance\""] {
        assert!(json.contains(key), "{key} in {json}");
    }
    let back = touchline_dsl::load_json(&json, "drill.json").unwrap();
    assert_eq!(back, s);
    assert_eq!(back.draw(5, 9), s.draw(5, 9));
}

#[test]
fn every_grf_scenario_config_key_is_accepted() {
    let text = "scenario keys {\n  game_duration 10\n  deterministic true\n  game_engine_random_seed 7\n  offsides false\n  end_episode_on_score true\n  end_episode_on_out_of_play true\n  end_episode_on_possession_change true\n  left_team_difficulty 0.5\n  right_team_difficulty 0.25\n  second_half 5\n  control_all_players true\n  real_time false\n  reverse_team_processing false\n  ball at (0.1, 0.2)\n  team left { GK at (-1, 0) }\n  team right { GK at (-1, 0) }\n}\n";
    let c = touchline_dsl::compile(text, "keys.tl").unwrap_or_else(|d| panic!("{}", d.render_plain()));
    let s = &c.scenario;
    assert_eq!((s.game_duration, s.game_engine_random_seed, s.second_half), (10, 7, 5));
    assert!(s.deterministic && !s.offsides && s.control_all_players);
    assert!(s.end_episode_on_score && s.end_episode_on_out_of_play && s.end_episode_on_possession_change);
    assert_eq!((s.left_team_difficulty, s.right_team_difficulty, s.ball_position), (0.5, 0.25, [0.1, 0.2]));
    let codes: Vec<&str> = c.warnings.items.iter().map(|d| d.code.as_str()).collect();
    assert_eq!(codes, ["tl::W103", "tl::W103"], "real_time and reverse_team_processing change nothing");
    let printed = touchline_dsl::scenario_to_tl(s);
    assert_eq!(touchline_dsl::compile(&printed, "p.tl").unwrap().scenario, *s);
}

#[test]
fn difficulty_and_right_team_difficulty_are_one_key() {
    let text = "scenario s {\n  extends academy_empty_goal\n  difficulty 0.2\n  right_team_difficulty 0.3\n}\n";
    let err = touchline_dsl::compile(text, "s.tl").unwrap_err();
    let codes: Vec<&str> = err.items.iter().map(|d| d.code.as_str()).collect();
    assert_eq!(codes, ["tl::E110"]);
}
