//! Law 12, fouls and the advantage, and Law 13, free kicks: a slide from behind through a
//! carrier outside the area is a foul and a caution at least; the fouled team does not keep the
//! ball, so the referee gives a direct free kick at the foul's spot, opponents 9.15 m away.

use touchline_engine::rules::Stoppage;
use touchline_engine::{Action, Env, GameMode, PlayerEntry, Role, Scenario, Side};

fn lazy(role: Role, x: f32, y: f32) -> PlayerEntry {
    PlayerEntry { lazy: true, ..PlayerEntry::new(role, x, y) }
}

#[test]
fn a_slide_from_behind_is_a_foul_with_a_card_and_a_free_kick() {
    // The right forward has the ball at x = -14.9 m running at the left goal; the left agent is
    // 1.75 m behind him.
    let scenario = Scenario {
        name: "foul".into(),
        game_duration: 100,
        deterministic: true,
        ball_position: [-0.27, 0.0],
        left_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::CM, -0.218, 0.0)],
        right_team: vec![lazy(Role::GK, -1.0, 0.0), lazy(Role::CF, 0.25, 0.0)],
        ..Scenario::default()
    };
    let mut env = Env::new(scenario, 0).unwrap();
    let mut slid = false;
    for _ in 0..100 {
        let action = if env.game().owner() == Some((Side::Right, 1)) && !slid {
            slid = true;
            Action::Sliding
        } else {
            Action::Idle
        };
        let out = env.step(&[action]).unwrap();
        if env.game().last_stoppage().is_some() || out.terminated || out.truncated {
            break;
        }
    }
    let game = env.game();
    let Some(Stoppage::Foul { restart, offender }) = game.last_stoppage() else {
        panic!("no foul: {:?}", game.last_stoppage());
    };
    assert_eq!(offender, (Side::Left, 1));
    assert_eq!((restart.mode, restart.side), (GameMode::FreeKick, Side::Right));
    assert!((restart.spot.x + 14.0).abs() < 2.5 && restart.spot.y.abs() < 2.0, "spot {}", restart.spot);
    assert_eq!(env.info().game_mode, GameMode::FreeKick);
    let left = game.stats().teams[0];
    assert_eq!(left.fouls, 1);
    assert!(left.yellow_cards + left.red_cards >= 1, "a reckless slide from behind is cautioned: {left:?}");
    let o = &env.observations()[0];
    assert!(o.left_team_yellow_card[1] || !o.left_team_active[1]);
    // The taker holds the ball at the spot; opponents keep their distance.
    assert_eq!(game.owner(), Some((Side::Right, 1)));
    let ball = game.ball().xy();
    for p in game.team(Side::Left).iter().filter(|p| p.active) {
        assert!(p.position.distance(ball) >= 9.0, "{p:?} too close to the free kick at {ball}");
    }
}
