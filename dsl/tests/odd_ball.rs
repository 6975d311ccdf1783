//! `on odd episodes ball at PLACE` with a random or relative place (issue 18): in odd episodes
//! the ball is drawn from it, placed from the bodies as they were drawn in that episode; even
//! episodes keep the `ball` statement's place; `.tl` printing writes it back.

use std::path::Path;

use touchline_dsl::{build_env, compile, scenario_to_tl};
use touchline_engine::scenario::{Anchor, Body, Spot};
use touchline_engine::{Action, EnvConfig, Scenario};

/// Metres per scenario unit: players (team frame), the ball (global frame).
const PLAYER: [f32; 2] = [55.0, 84.96];
const BALL: [f32; 2] = [54.4, 83.6];

fn compiled(text: &str) -> Scenario {
    let c = compile(text, "odd.tl").unwrap_or_else(|d| panic!("{}", d.render_plain()));
    assert!(c.warnings.items.is_empty(), "{}", c.warnings.render_plain());
    c.scenario
}

/// A drill whose CF is drawn at random, with the ball's place in odd episodes given by `odd`.
fn drill(odd: &str, swap: bool) -> String {
    let swap = if swap { "  on odd episodes swap teams\n" } else { "" };
    format!(
        "scenario odd {{\n  extends academy\n  ball at (0.1, 0.05)\n  on odd episodes ball {odd}\n{swap}  team left {{\n    GK at (-1, 0)\n    CF at (uniform(0.2, 0.6), uniform(-0.3, 0.3))\n  }}\n  team right {{\n    GK at (-1, 0)\n    CB at (-0.5, 0.1)\n  }}\n}}\n"
    )
}

/// Where the written-left list's CF and the ball stand in metres (world frame) in a placement of
/// episode `episode` (with the swap, that list plays on the right in odd episodes).
fn cf_and_ball(s: &Scenario, episode: u64) -> ([f32; 2], [f32; 2]) {
    let p = s.draw(3, episode);
    let swapped = s.swap_teams_on_odd_episodes && episode % 2 == 1;
    let (cf, sign) = if swapped { (&p.right[1], -1.0) } else { (&p.left[1], 1.0) };
    ([sign * cf.x * PLAYER[0], sign * cf.y * PLAYER[1]], [p.ball[0] * BALL[0], p.ball[1] * BALL[1]])
}

#[test]
fn odd_episodes_put_the_ball_a_metre_ahead_of_the_drawn_cf() {
    for swap in [false, true] {
        let s = compiled(&drill("at left.CF + (1 m, 0)", swap));
        assert_eq!(
            s.odd_episode_ball_random,
            Some(Spot::Relative(Anchor { of: Body::Left(1), offset: [1.0, 0.0], radius: 0.0 }))
        );
        // Its nominal point: a metre ahead of the CF's nominal (0.4, 0).
        let [x, y] = s.odd_episode_ball_position.expect("a nominal odd-episode ball");
        assert!((x * BALL[0] - (0.4 * PLAYER[0] + 1.0)).abs() < 1e-3 && y.abs() < 1e-6, "({x}, {y})");
        let mut odd_balls = Vec::new();
        for episode in 0..20 {
            let (cf, ball) = cf_and_ball(&s, episode);
            if episode % 2 == 0 {
                assert_eq!(s.draw(3, episode).ball, [0.1, 0.05], "episode {episode}: the even ball is fixed");
                continue;
            }
            // Ahead of him: towards the goal he attacks (+x on the left, -x on the right).
            let ahead = if swap { -1.0 } else { 1.0 };
            let (dx, dy) = (ball[0] - cf[0], ball[1] - cf[1]);
            assert!((dx - ahead).abs() < 1e-3 && dy.abs() < 1e-3, "swap {swap}, episode {episode}: {dx} m, {dy} m");
            odd_balls.push(ball[0]);
        }
        odd_balls.dedup();
        assert_eq!(odd_balls.len(), 10, "the CF, and so the ball, is drawn anew in each odd episode");
    }
}

#[test]
fn near_draws_the_odd_ball_within_the_radius() {
    let s = compiled(&drill("at near(left.CF, 3 m)", false));
    let mut gaps = Vec::new();
    for episode in (1..40).step_by(2) {
        let (cf, ball) = cf_and_ball(&s, episode);
        let gap = (ball[0] - cf[0]).hypot(ball[1] - cf[1]);
        assert!(gap <= 3.0 + 1e-3, "episode {episode}: {gap} m");
        gaps.push(gap);
    }
    assert!(gaps.iter().any(|g| *g > 0.5), "drawn in the disc, not at its centre: {gaps:?}");
}

#[test]
fn a_random_odd_ball_is_drawn_in_its_region() {
    let s = compiled(&drill("in rect((0.6, -0.2), (0.8, 0.2))", false));
    for episode in 0..20 {
        let [x, y] = s.draw(5, episode).ball;
        if episode % 2 == 1 {
            assert!((0.6..=0.8).contains(&x) && (-0.2..=0.2).contains(&y), "episode {episode}: ({x}, {y})");
        } else {
            assert_eq!([x, y], [0.1, 0.05]);
        }
    }
}

/// The env starts odd episodes where the placement says: the observed ball a metre ahead of the
/// observed CF.
#[test]
fn the_env_starts_odd_episodes_at_the_cf() {
    let s = compiled(&drill("at left.CF + (1 m, 0)", false));
    let mut env = build_env(s, Path::new("."), EnvConfig::default(), 11).unwrap();
    for episode in 0..20 {
        if episode > 0 {
            env.reset().unwrap();
        }
        let o = &env.observations()[0];
        let (cf, ball) = (o.left_team[1], o.ball);
        let (dx, dy) = ((ball[0] - cf[0]) * BALL[0], (ball[1] - cf[1]) * BALL[1]);
        if episode % 2 == 1 {
            assert!((dx - 1.0).abs() < 0.02 && dy.abs() < 0.02, "episode {episode}: {dx} m, {dy} m");
        } else {
            assert!((ball[0] - 0.1).abs() < 1e-4 && (ball[1] - 0.05).abs() < 1e-4, "episode {episode}: {ball:?}");
        }
        env.step(&[Action::Idle]).unwrap();
    }
}

/// `.tl` printing (`touchline compile --tl`) writes the place back, and it compiles to the same
/// scenario; a lesson that changes it prints its own.
#[test]
fn the_odd_ball_survives_the_tl_round_trip() {
    for odd in ["at left.CF + (1 m, 0)", "at near(left.CF + (2 m, -1 m), 3 m)", "in circle(0.7, 0, 0.1)"] {
        let s = compiled(&drill(odd, true));
        let text = scenario_to_tl(&s);
        assert!(text.contains("on odd episodes ball "), "{text}");
        let again = compiled(&text);
        assert_eq!(again, s, "{text}");
        assert_eq!(scenario_to_tl(&again), text, "printing is a fixed point");
    }
    let lessons = drill("at left.CF + (1 m, 0)", false).replace(
        "\n}\n",
        "\n  curriculum {\n    lesson near { on odd episodes ball at behind(left.CF, 2 m) }\n    lesson plain { }\n    advance when success_rate >= 0.8 over 20 episodes\n  }\n}\n",
    );
    let s = compiled(&lessons);
    let text = scenario_to_tl(&s);
    assert!(text.contains("on odd episodes ball at left[1] + (-2 m, 0 m)"), "{text}");
    assert_eq!(compiled(&text), s, "{text}");
}

/// A ball placed from a player who is placed from the ball is a circle in odd episodes too.
#[test]
fn an_odd_ball_in_a_circle_is_e151() {
    let text = drill("at left.CF", false).replace("CF at (uniform(0.2, 0.6), uniform(-0.3, 0.3))", "CF at ball");
    let Err(diags) = compile(&text, "odd.tl") else { panic!("a circle compiled") };
    let d = diags.items.first().expect("one diagnostic");
    assert_eq!(d.code.as_str(), "tl::E151", "{}", diags.render_plain());
    assert!(d.message.contains("in odd episodes"), "{}", d.message);
}
