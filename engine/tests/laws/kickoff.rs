//! Law 8: after a goal, the conceding team kicks off from the centre spot with everyone in his own
//! half; the kickoff formation goes to the conceding team.

use glam::{Vec2, Vec3};
use touchline_engine::{Action, GameMode, Side};

use super::common;

#[test]
fn the_conceding_team_kicks_off() {
    for (scorer, x) in [(Side::Left, 50.0f32), (Side::Right, -50.0)] {
        let mut env = touchline_engine::Env::new(common::scenario("11_vs_11_stochastic"), 3).unwrap();
        // Clear the keepers out of the way and roll the ball into the goal.
        for side in Side::BOTH {
            env.game_mut().place_player(side, 0, Vec2::new(0.0, side.attack_sign() * 30.0));
        }
        env.game_mut().place_ball(Vec3::new(x, 0.0, 0.11), Vec3::new(x.signum() * 20.0, 0.0, 0.0), Some((scorer, 5)));
        for _ in 0..10 {
            env.step(&[Action::Idle]).unwrap();
            if env.info().score != [0, 0] {
                break;
            }
        }
        let mut expected = [0, 0];
        expected[scorer.index()] = 1;
        assert_eq!(env.info().score, expected);
        assert_eq!(env.info().game_mode, GameMode::Normal, "the kickoff counts as taken at once");
        let game = env.game();
        assert!(game.ball().xy().length() < 1.0, "ball at {}", game.ball().xy());
        let nearest = game.players().iter().min_by(|a, b| a.position.length().total_cmp(&b.position.length())).unwrap();
        assert_eq!(nearest.side, scorer.opponent(), "the conceding team stands at the ball");
        for p in game.players() {
            assert!(p.position.x * p.side.attack_sign() <= 1.0, "{p:?} is in the opponents' half");
        }
    }
}
