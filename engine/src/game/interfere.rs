//! The standing tackle (GRF's interfere): when a challenger starts one, how fast he goes in while
//! he winds it up, how near the ball must be when its touch lands, and how long it goes on after
//! a touch that knocks the ball loose.
//!
//! GRF picks an interfere animation only if the animation's touch would meet the ball, with the
//! body carried by the animation's own movement (docs/grf-compatibility.md, "a defender against an
//! idle carrier"). So a challenger coming in fast starts his tackle before the ball is in reach
//! and slows on the way in: in GRF 2.10.2's academy_counterattack_hard the hunter sprinting at an
//! idle carrier slows from 7.4 to 3.8 m/s over the last 1.8 m and touches the ball with his body
//! 0.7 m from the carrier's. Started only once the ball was within reach, touchline's hunter ran
//! into the carrier at 7 m/s before his touch and stumbled.

use glam::Vec2;

use crate::physics::{MotionLimits, TICK_SECONDS};

/// Fastest (m/s) a player winding up a standing tackle moves: GRF's interfere animations carry
/// the body at 1.1-1.4 m/s from a stand and 2.0-3.7 m/s from a walk (5.8 m/s for the one long
/// reach from a sprint), whatever the player was asked to do.
pub(super) const PACE: f32 = 3.7;
/// The touch lands with the ball this near (m; GRF's animations reach about 1.3 m).
pub(super) const REACH: f32 = 1.3;
/// Ticks from the start to the touch, drawn uniformly (GRF: 150-250 ms).
pub(super) const WIND_UP_TICKS: (u16, u16) = (15, 25);
/// Ticks the tackle goes on after a touch that knocks the ball loose, drawn uniformly: GRF's
/// interfere animations last another 170-340 ms after their touch (traced in GRF 2.10.2,
/// docs/grf-compatibility.md, "a defender against an idle carrier"), and until they end the
/// tackler cannot play the ball he knocked. Free at once, touchline's tackler trapped his own
/// knock on the next tick, so every knock was a won ball.
pub(super) const FOLLOW_THROUGH_TICKS: (u16, u16) = (17, 34);

/// A duration in ticks drawn uniformly from `(shortest, longest)` with `unit` in [0, 1).
pub(super) fn draw_ticks((shortest, longest): (u16, u16), unit: f32) -> u16 {
    shortest + (unit * f32::from(longest - shortest + 1)) as u16
}

/// Whether a challenger at `at` (m) running at `velocity` (m/s) starts a standing tackle on a
/// ball at `ball` moving at `ball_velocity`: whether, by the earliest touch, his run slowed to
/// [`PACE`] at his deceleration and the ball's run bring the ball within [`REACH`]. A standing
/// challenger starts as the ball comes within reach; one sprinting at 7 m/s about 2.2 m out.
pub(super) fn starts(at: Vec2, velocity: Vec2, ball: Vec2, ball_velocity: Vec2) -> bool {
    let t = f32::from(WIND_UP_TICKS.0) * TICK_SECONDS;
    let speed = velocity.length();
    let run = if speed <= PACE {
        speed * t
    } else {
        let deceleration = MotionLimits::default().deceleration;
        // Braking to the tackle's pace, then at it.
        let braking = ((speed - PACE) / deceleration).min(t);
        let slowed = speed - deceleration * braking;
        0.5 * (speed + slowed) * braking + PACE * (t - braking)
    };
    let mine = at + velocity.normalize_or_zero() * run;
    mine.distance_squared(ball + ball_velocity * t) < REACH * REACH
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;
    use crate::game::Match;
    use crate::player::Role;
    use crate::scenario::{PlayerEntry, Scenario};

    /// Our centre midfielder standing at the centre spot with the ball 0.4 m ahead of him; theirs
    /// at `at` running at `velocity`, facing him across the ball.
    fn challenge(at: Vec2, velocity: Vec2) -> Match {
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::CM, -0.5, 0.0)],
            right_team: vec![PlayerEntry::new(Role::CM, -0.5, 0.0)],
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 0);
        m.players[0].position = Vec2::ZERO;
        m.players[0].velocity = Vec2::ZERO;
        m.players[0].facing = Vec2::X;
        m.players[1].position = at;
        m.players[1].velocity = velocity;
        m.players[1].facing = Vec2::NEG_X;
        m.ball.position = Vec3::new(0.4, 0.0, 0.11);
        m.ball.velocity = Vec3::ZERO;
        m.owner = Some(0);
        m
    }

    #[test]
    fn in_play_the_sprinter_goes_in_from_where_the_walker_does_not() {
        // 2.1 m from the ball: at 7 m/s his touch would meet it, at 1 m/s it would not.
        let mut sprinting = challenge(Vec2::new(2.5, 0.0), Vec2::new(-7.0, 0.0));
        sprinting.settle_possession();
        assert!(sprinting.players[1].interfere_ticks > 0, "the sprinter starts his tackle");
        let mut walking = challenge(Vec2::new(2.5, 0.0), Vec2::new(-1.0, 0.0));
        walking.settle_possession();
        assert_eq!(walking.players[1].interfere_ticks, 0, "the walker does not yet");
        assert_eq!(walking.owner, Some(0));
    }

    #[test]
    fn a_knocked_ball_is_not_the_tacklers_until_his_tackle_has_run_its_course() {
        // Walking in from 1.2 m, his touch lands with the ball nearer the carrier than him: a knock.
        let mut m = challenge(Vec2::new(1.2, 0.0), Vec2::new(-1.0, 0.0));
        m.players[1].interfere_ticks = 1;
        m.settle_possession();
        assert_eq!(m.owner, None, "the ball is knocked loose");
        assert_eq!(m.last_touch, Some(1));
        let (shortest, longest) = FOLLOW_THROUGH_TICKS;
        let left = m.players[1].touch_cooldown;
        assert!((shortest..=longest).contains(&left), "{left} ticks");
        // Even lying still at his feet, with the carrier out of it, the ball stays loose.
        m.players[0].touch_cooldown = 100;
        m.ball.position = (m.players[1].possession_point()).extend(0.11);
        m.ball.velocity = Vec3::ZERO;
        m.settle_possession();
        assert_eq!(m.owner, None);
        m.players[1].touch_cooldown = 0;
        m.settle_possession();
        assert_eq!(m.owner, Some(1), "his tackle over, he takes it");
    }

    #[test]
    fn follow_through_and_wind_up_draws_cover_their_whole_range() {
        assert_eq!(draw_ticks(FOLLOW_THROUGH_TICKS, 0.0), FOLLOW_THROUGH_TICKS.0);
        assert_eq!(draw_ticks(FOLLOW_THROUGH_TICKS, 0.999_999), FOLLOW_THROUGH_TICKS.1);
        assert_eq!(draw_ticks(WIND_UP_TICKS, 0.5), 20);
    }

    #[test]
    fn a_sprinter_starts_his_tackle_before_the_ball_is_in_reach_and_a_standing_man_as_it_comes() {
        let ball = Vec2::new(2.1, 0.0);
        let sprint = Vec2::new(7.0, 0.0);
        assert!(starts(Vec2::ZERO, sprint, ball, Vec2::ZERO), "2.1 m out at 7 m/s");
        assert!(!starts(Vec2::ZERO, sprint, Vec2::new(2.5, 0.0), Vec2::ZERO), "2.5 m out at 7 m/s");
        assert!(!starts(Vec2::ZERO, Vec2::ZERO, ball, Vec2::ZERO), "2.1 m out, standing");
        assert!(starts(Vec2::ZERO, Vec2::ZERO, Vec2::new(1.2, 0.0), Vec2::ZERO), "1.2 m out, standing");
        // Running away from the ball, or past it, he does not go in.
        assert!(!starts(Vec2::ZERO, -sprint, Vec2::new(1.2, 0.0), Vec2::ZERO));
        // A ball run towards him comes into reach sooner.
        assert!(starts(Vec2::ZERO, Vec2::ZERO, ball, Vec2::new(-6.0, 0.0)));
    }
}
