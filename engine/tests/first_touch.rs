//! GRF's on-the-ball AI decides before the touch: the first player to a loose ball, once he is
//! under a second from it, strikes the pass or shot he would choose with it at his feet as his
//! first touch, and never shows as its owner (GRF 2.10's ElizaController; measured in
//! academy_run_to_score, where GRF's chasing defenders play a stopped ball on at once).

use touchline_engine::{Match, PlayerEntry, Role, Scenario, Side};

fn keeper() -> PlayerEntry {
    PlayerEntry::new(Role::GK, -1.0, 0.0)
}

#[test]
fn a_forward_running_onto_a_loose_ball_at_the_penalty_spot_shoots_first_time() {
    // Our centre forward 16 m from goal, the ball at rest on the penalty spot, only the keepers
    // besides him: he runs in and shoots with his first touch.
    let s = Scenario {
        left_team: vec![keeper(), PlayerEntry::new(Role::CF, 0.7, 0.0)],
        right_team: vec![keeper()],
        game_duration: 400,
        ..Scenario::default()
    };
    s.validate().unwrap();
    let mut first_time = 0;
    for seed in 0..10 {
        let mut game = Match::new(&s, 0, seed);
        game.place_ball(glam::Vec3::new(44.0, 0.0, 0.11), glam::Vec3::ZERO, None);
        for tick in 0..300 {
            game.tick();
            if game.owner().is_some() {
                // He (or the keeper) took it: not a first-time shot.
                eprintln!("seed {seed}: owned by {:?} at tick {tick}", game.owner());
                break;
            }
            if game.ball().velocity.x > 15.0 {
                assert_eq!(game.last_touch(), Some((Side::Left, 1)), "seed {seed}: struck by our forward");
                first_time += 1;
                break;
            }
        }
    }
    assert!(first_time >= 8, "{first_time} of 10 shots struck first time");
}
