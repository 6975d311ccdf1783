//! Relative placement (issue 18, item 1): the example drills start where they say, at every
//! reset, and the places compile to anchors the engine draws in dependency order.

use std::path::Path;

use touchline_dsl::{build_env, compile, compile_file};
use touchline_engine::scenario::{Anchor, Body, Spot};
use touchline_engine::{Action, Env, EnvConfig};

/// Metres between two points of one observation (GRF's observation units: 54.4 m along, 83.6 m across).
fn metres(a: [f32; 2], b: [f32; 2]) -> (f32, f32) {
    ((b[0] - a[0]) * 54.4, (b[1] - a[1]) * 83.6)
}

fn example(name: &str) -> Env {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios").join(name);
    let compiled = compile_file(&path).unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert!(compiled.warnings.items.is_empty(), "{}", compiled.warnings.render_plain());
    build_env(compiled.scenario, path.parent().unwrap(), EnvConfig::default(), 7).unwrap()
}

/// A player's observed position in his team's scenario units (players are placed at 55 m and
/// 84.96 m per unit).
fn scenario_units(p: [f32; 2]) -> [f32; 2] {
    [p[0] * 54.4 / 55.0, p[1] * 83.6 / 84.96]
}

/// Plays `episodes` episodes (a few idle steps each), calling `check` on the left team's view
/// of each reset.
fn each_reset(env: &mut Env, episodes: usize, mut check: impl FnMut(&touchline_engine::RawObservation)) {
    for episode in 0..episodes {
        if episode > 0 {
            env.reset().unwrap();
        }
        check(&env.observations()[0]);
        for _ in 0..3 {
            env.step(&[Action::Idle]).unwrap();
        }
    }
}

#[test]
fn the_winger_has_the_ball_at_his_feet_wherever_he_starts() {
    let mut env = example("winger_with_the_ball.tl");
    let mut spots = Vec::new();
    each_reset(&mut env, 200, |o| {
        let lm = o.left_team[1];
        let [x, y] = scenario_units(lm);
        assert!((0.2..=0.6).contains(&x) && (-0.38..=-0.2).contains(&y), "LM at {lm:?}");
        let (dx, dy) = metres(lm, [o.ball[0], o.ball[1]]);
        assert!((dx - 1.0).abs() < 0.02 && dy.abs() < 0.02, "the ball {dx} m, {dy} m from him");
        // The right team's LB, 6 m goal-side of him (the right team's view is turned: index 1).
        let lb = o.right_team[1];
        let (dx, dy) = metres(lm, lb);
        assert!((dx - 6.0).abs() < 0.02 && dy.abs() < 0.02, "the LB {dx} m, {dy} m from him");
        spots.push(lm);
    });
    spots.sort_by(|a, b| a[0].total_cmp(&b[0]));
    spots.dedup();
    assert!(spots.len() > 150, "drawn anew at every reset");
}

#[test]
fn the_defender_starts_five_metres_behind_the_attacker() {
    let mut env = example("defender_behind_attacker.tl");
    each_reset(&mut env, 200, |o| {
        let cf = o.left_team[1];
        let [x, y] = scenario_units(cf);
        assert!((0.05..=0.6).contains(&x) && (-0.3..=0.3).contains(&y), "CF at {cf:?}");
        let (dx, dy) = metres(cf, o.right_team[1]);
        assert!((dx + 5.0).abs() < 0.02 && dy.abs() < 0.02, "the CB {dx} m, {dy} m from him");
    });
}

#[test]
fn places_compile_to_anchors_in_the_named_players_frame() {
    let text = "scenario s {\n  extends academy\n  ball at left.CF + (2 m, -1 m)\n  team left {\n    GK at (-1, 0)\n    CF at (0.5, 0.1)\n  }\n  team right {\n    GK at (-1, 0)\n    CB at near(left.CF, 3 m)\n    CM at beside(right.CB, -4 m)\n    LB at left[1] - (0.1, 0)\n  }\n}\n";
    let s = compile(text, "s.tl").unwrap_or_else(|d| panic!("{}", d.render_plain())).scenario;
    let anchor = |spot: &Option<Spot>| match spot {
        Some(Spot::Relative(a)) => a.clone(),
        other => panic!("{other:?}"),
    };
    assert_eq!(anchor(&s.ball_random), Anchor { of: Body::Left(1), offset: [2.0, -1.0], radius: 0.0 });
    assert_eq!(anchor(&s.right_team[1].random), Anchor { of: Body::Left(1), offset: [0.0, 0.0], radius: 3.0 });
    assert_eq!(anchor(&s.right_team[2].random), Anchor { of: Body::Right(1), offset: [0.0, -4.0], radius: 0.0 });
    // Scenario units of the placed player: 0.1 × 55 m.
    let lb = anchor(&s.right_team[3].random);
    assert!((lb.offset[0] + 5.5).abs() < 1e-4 && lb.offset[1] == 0.0, "{lb:?}");
    // Nominal points: the ball 2 m along and 1 m across from the CF's (0.5, 0.1).
    let [bx, by] = s.ball_position;
    assert!((bx * 54.4 - (0.5 * 55.0 + 2.0)).abs() < 1e-3 && (by * 83.6 - (0.1 * 84.96 - 1.0)).abs() < 1e-3);
    // Through JSON and back to `.tl`, the same scenario.
    let json = serde_json::to_string(&s).unwrap();
    assert_eq!(touchline_dsl::load_json(&json, "s.json").unwrap(), s);
    let again = compile(&touchline_dsl::scenario_to_tl(&s), "again.tl").unwrap().scenario;
    assert_eq!(again.ball_random, s.ball_random);
    assert_eq!(again.right_team, s.right_team);
}

/// A param holding a distribution is drawn once per reset: its uses share the draw, in each one's
/// units (issue 18, item 1).
#[test]
fn a_distribution_param_is_drawn_once_per_reset() {
    let text = "scenario s {\n  extends academy\n  param height = uniform(-0.3, 0.3)\n  param dx = uniform(-5 m, 5 m)\n  ball at (dx, 0)\n  team left {\n    GK at (-1, 0)\n    CF at (0.5, height)\n    LM at (0.3, height)\n    RM at (dx, 0.2)\n  }\n  team right { GK at (-1, 0) }\n}\n";
    let compiled = compile(text, "s.tl").unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert!(compiled.warnings.items.is_empty(), "{}", compiled.warnings.render_plain());
    let s = compiled.scenario;
    let mut heights = Vec::new();
    for episode in 0..100 {
        let p = s.draw(1, episode);
        assert_eq!(p.left[1].y, p.left[2].y, "episode {episode}: both forwards share the draw");
        // The same metres for the ball (54.4 m a unit) and the RM (55 m a unit).
        assert!((p.ball[0] * 54.4 - p.left[3].x * 55.0).abs() < 1e-3, "episode {episode}");
        heights.push(p.left[1].y);
    }
    heights.sort_by(f32::total_cmp);
    heights.dedup();
    assert!(heights.len() > 90, "drawn anew at every reset: {heights:?}");
    // Written out twice, a distribution is drawn twice.
    let twice = text
        .replace("(0.5, height)", "(0.5, uniform(-0.3, 0.3))")
        .replace("(0.3, height)", "(0.3, uniform(-0.3, 0.3))");
    let s = compile(&twice, "s.tl").unwrap().scenario;
    assert!((0..20).any(|e| {
        let p = s.draw(1, e);
        p.left[1].y != p.left[2].y
    }));
    // Through JSON, the sharing stays.
    let json = serde_json::to_string(&compiled_again(text)).unwrap();
    assert!(json.contains("\"shared\""), "{json}");
}

fn compiled_again(text: &str) -> touchline_engine::Scenario {
    let s = compile(text, "s.tl").unwrap().scenario;
    touchline_dsl::load_json(&serde_json::to_string(&s).unwrap(), "s.json").unwrap()
}

/// `.tl` keeps a shared draw: the printed file declares a `param` for it and names it at each use
/// (a lesson that changes it assigns it), so compiling the text again gives the same scenario,
/// which draws the same places.
#[test]
fn a_shared_draw_survives_the_tl_round_trip() {
    let text = "scenario s {\n  extends academy\n  param height = uniform(-0.3, 0.3)\n  param dx = uniform(-5 m, 5 m)\n  ball at (dx, 0)\n  team left {\n    GK at (-1, 0)\n    CF at (0.5, height)\n    LM at (0.3, height)\n    RM at (dx, 0.2)\n  }\n  team right { GK at (-1, 0) }\n  curriculum {\n    lesson narrow { }\n    lesson wide { dx = normal(0 m, 4 m) }\n    advance when success_rate >= 0.8 over 20 episodes\n  }\n}\n";
    let s = compile(text, "s.tl").unwrap().scenario;
    let printed = touchline_dsl::scenario_to_tl(&s);
    let again = compile(&printed, "again.tl").unwrap_or_else(|d| panic!("{printed}\n{}", d.render_plain()));
    assert!(again.warnings.items.is_empty(), "{}", again.warnings.render_plain());
    let again = again.scenario;
    assert!(printed.contains("param draw2 = uniform(-5 m, 5 m)"), "{printed}");
    assert!(printed.contains("draw2 = normal(0 m, 4 m)"), "{printed}");
    // A key is a hash of the param's name, and the printed names are `draw1`, `draw2`, …: the
    // same scenario up to that renaming.
    assert_eq!(keys_by_first_use(&again), keys_by_first_use(&s), "{printed}");
    assert_eq!(touchline_dsl::scenario_to_tl(&again), printed, "printing is a fixed point");
    let lessons = |s: &touchline_engine::Scenario| {
        s.curriculum.as_ref().unwrap().lessons.iter().map(|l| l.scenario.clone()).collect::<Vec<_>>()
    };
    for (a, b) in std::iter::once((s.clone(), again.clone())).chain(lessons(&s).into_iter().zip(lessons(&again))) {
        for episode in 0..20 {
            let (p, q) = (a.draw(3, episode), b.draw(3, episode));
            let places = |p: &touchline_engine::scenario::Placement| {
                let xy: Vec<[f32; 2]> = p.left.iter().chain(&p.right).map(|e| [e.x, e.y]).collect();
                (p.ball, xy)
            };
            assert_eq!(places(&p), places(&q), "episode {episode}");
            assert_eq!(p.left[1].y, p.left[2].y, "one draw for both forwards");
        }
    }
}

/// The scenario as JSON with every shared key replaced by its rank of first appearance.
fn keys_by_first_use(s: &touchline_engine::Scenario) -> serde_json::Value {
    fn walk(v: &mut serde_json::Value, seen: &mut Vec<u64>) {
        match v {
            serde_json::Value::Object(map) => {
                if let Some(key) = map.get_mut("shared") {
                    let k = key.as_u64().unwrap();
                    let rank = seen.iter().position(|s| *s == k).unwrap_or_else(|| {
                        seen.push(k);
                        seen.len() - 1
                    });
                    *key = serde_json::Value::from(rank);
                }
                map.values_mut().for_each(|v| walk(v, seen));
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(|v| walk(v, seen)),
            _ => {}
        }
    }
    let mut v = serde_json::to_value(s).unwrap();
    walk(&mut v, &mut Vec::new());
    v
}

/// A child's `team` that puts another role (or no one) at an index the parent's places or
/// `require`s name is `tl::E155` on the child's `team` statement; keeping the role at its index,
/// or writing the place again, is fine (issue 18).
#[test]
fn a_child_team_that_moves_an_anchored_player_is_e155() {
    let parent = "preset drill {\n  extends academy\n  ball at left.CF + (1 m, 0)\n  on odd episodes ball at near(left.LM, 2 m)\n  team left {\n    GK at (-1, 0)\n    CF at (uniform(0.3, 0.6), 0)\n    LM at (0.3, -0.3)\n  }\n  team right {\n    GK at (-1, 0)\n    CB at behind(left.CF, 3 m)\n  }\n  require distance(left.LM, right.GK) >= 10 m\n}\n";
    let codes = |child: &str| -> Vec<(String, String)> {
        let text = format!("{parent}scenario child {{\n  extends drill\n{child}}}\n");
        match compile(&text, "child.tl") {
            Ok(_) => Vec::new(),
            Err(d) => d
                .items
                .iter()
                .map(|d| (d.code.as_str().to_owned(), text[d.span().start..d.span().end].to_owned()))
                .collect(),
        }
    };
    let e155 = |n| vec![("tl::E155".to_owned(), "team left".to_owned()); n];
    // The CF (ball, CB) and the LM (odd ball, require) swap places: reported once per player.
    assert_eq!(codes("  team left { GK at (-1, 0) LM at (0.3, -0.3) CF at (0.5, 0) }\n"), e155(2));
    // The LM is gone: the odd ball and the require name no one.
    assert_eq!(codes("  team left { GK at (-1, 0) CF at (0.5, 0) }\n"), e155(1));
    // Same roles at the same indices, other places: fine.
    assert_eq!(codes("  team left { GK at (-1, 0) CF at (0.5, 0.1) LM at (0.2, -0.2) RM at (0.2, 0.2) }\n"), vec![]);
    // Everything that names the moved players written again: fine.
    let again = "  ball at left.CF + (1 m, 0)\n  on odd episodes ball at near(left.LM, 2 m)\n  team right {\n    GK at (-1, 0)\n    CB at behind(left.CF, 3 m)\n  }\n  require distance(left.LM, right.GK) >= 10 m\n";
    assert_eq!(codes(&format!("  team left {{ GK at (-1, 0) LM at (0.3, -0.3) CF at (0.5, 0) }}\n{again}")), vec![]);
    // A new right team: the right GK keeps index 0, so the require still names him.
    assert_eq!(codes("  team right { GK at (-1, 0) CM at (0.2, 0) }\n"), vec![]);
    assert_eq!(
        codes("  team right { CM at (0.2, 0) GK at (-1, 0) }\n"),
        vec![("tl::E155".to_owned(), "team right".to_owned())]
    );
}
