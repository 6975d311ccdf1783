//! Law 14, the penalty kick, modelled on GRF's `tests/penalty` (docs/grf-compatibility.md#scenario-players,
//! #grf-tests test_penalty): the left agent slides into a right forward who has the ball inside the left
//! penalty area; the referee gives a penalty kick: ball on the mark (x ≈ −0.809), keepers on their lines, the taker
//! at the ball and everyone else outside the area.

use touchline_engine::rules::Stoppage;
use touchline_engine::{Action, Env, GameMode, PlayerEntry, Role, Scenario, Side};

fn lazy(role: Role, x: f32, y: f32) -> PlayerEntry {
    PlayerEntry { lazy: true, ..PlayerEntry::new(role, x, y) }
}

#[test]
fn a_slide_in_the_area_gives_a_penalty_kick() {
    let scenario = Scenario {
        name: "penalty".into(),
        game_duration: 30,
        deterministic: true,
        ball_position: [-0.72, 0.0],
        left_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, -0.69, 0.0)],
        right_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::RM, 0.7, 0.0)],
        ..Scenario::default()
    };
    let mut env = Env::new(scenario, 0).unwrap();
    let mut modes = Vec::new();
    loop {
        let out = env.step(&[Action::Sliding]).unwrap();
        modes.push(env.info().game_mode);
        if out.terminated || out.truncated {
            break;
        }
    }
    let game = env.game();
    let Some(Stoppage::Foul { restart, offender }) = game.last_stoppage() else {
        panic!("no foul: {:?}", game.last_stoppage());
    };
    assert_eq!(offender, (Side::Left, 1));
    assert_eq!((restart.mode, restart.side), (GameMode::Penalty, Side::Right));
    assert!(modes.contains(&GameMode::Penalty));
    let stats = game.stats();
    assert_eq!((stats.teams[0].fouls, stats.teams[1].penalties), (1, 1));
    // GRF's expectations, in the left agent's observation.
    let o = &env.observations()[0];
    assert!((o.ball[0] + 0.809).abs() < 0.01 && o.ball[1].abs() < 0.01, "ball {:?}", o.ball);
    assert!((o.right_team[0][0] - 1.0).abs() < 0.1, "right keeper {:?}", o.right_team[0]);
    assert!((o.right_team[1][0] + 0.75).abs() < 0.1, "taker {:?}", o.right_team[1]);
    assert!((o.left_team[0][0] + 0.95).abs() < 0.1, "left keeper {:?}", o.left_team[0]);
    assert!((o.left_team[1][0] + 0.70).abs() < 0.1, "offender {:?}", o.left_team[1]);
}
