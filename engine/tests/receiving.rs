//! A player going for a ball that comes at him runs at the pace that gets him to where he meets it
//! as the ball gets there (GRF's to-ball run: the time he needs over the time the ball takes, times
//! his top speed), so he controls it rather than sprinting into it and knocking it away.

use glam::Vec3;
use touchline_engine::{Match, PlayerEntry, Role, Scenario, Side};

fn keeper() -> PlayerEntry {
    PlayerEntry::new(Role::GK, -1.0, 0.0)
}

#[test]
fn a_ball_rolling_at_a_player_is_met_without_a_sprint_and_controlled() {
    // Our centre back about 27 m from our goal; a ball rolling at him at 12 m/s from 20 m up the
    // pitch, nobody else near (only the keepers).
    let s = Scenario {
        left_team: vec![keeper(), PlayerEntry::new(Role::CB, -0.5, 0.0)],
        right_team: vec![keeper()],
        game_duration: 400,
        ..Scenario::default()
    };
    s.validate().unwrap();
    for seed in 0..5 {
        let mut game = Match::new(&s, 0, seed);
        let cb = game.team(Side::Left)[1].position;
        game.place_ball(Vec3::new(cb.x + 20.0, cb.y, 0.11), Vec3::new(-12.0, 0.0, 0.0), None);
        let mut fastest: f32 = 0.0;
        let mut met = None;
        for tick in 0..200 {
            game.tick();
            let p = &game.team(Side::Left)[1];
            fastest = fastest.max(p.velocity.length());
            if game.owner().is_some() {
                met = Some((tick, game.owner(), p.velocity.length()));
                break;
            }
            // Until he has it, the ball keeps coming straight at him: nothing knocked it away.
            assert!(game.ball().velocity.x < 0.0 && game.ball().velocity.y.abs() < 0.5, "seed {seed} tick {tick}");
        }
        let (tick, owner, pace) = met.unwrap_or_else(|| panic!("seed {seed}: nobody took the ball"));
        assert_eq!(owner, Some((Side::Left, 1)), "seed {seed}");
        assert!(tick < 180, "seed {seed}: took it at tick {tick}");
        assert!(pace < 5.0 && fastest < 7.0, "seed {seed}: met it at {pace} m/s, ran at up to {fastest} m/s");
    }
}
