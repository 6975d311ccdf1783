//! Off-the-ball behaviours: `idle`, `hold_position`, `follow`, `move_to` and `mark`. Each turns
//! one player's situation into this tick's [`PlayerInput`] (velocities in m/s, global frame).

use glam::Vec2;

use crate::game::PlayerInput;
use crate::geometry::pitch::HALF_LENGTH;
use crate::player::{Player, WALK_SPEED};

/// Within this distance (m) of its point a `move_to` has arrived.
pub(crate) const ARRIVED: f32 = 0.5;
/// How far off the ball or a followed player a follower stays (m): close, but off the ball
/// (a still ball is within reach at 1.15 m), so that `follow(ball)` shadows the ball without
/// playing it.
pub(crate) const FOLLOW_GAP: f32 = 1.5;
/// How far goal-side of his man a marker stands (m): close enough to challenge.
pub(crate) const MARK_GAP: f32 = 1.5;
/// Gain of the pull towards a moving spot (1/s), as the AI's arrival slow-down.
const PULL: f32 = 2.5;
/// A `hold_position` player pushed further off his place than this (m) sprints back.
const SPRINT_BACK: f32 = 5.0;

/// Stand still, facing the ball at `ball` (m).
#[inline]
pub(crate) fn idle(p: &Player, ball: Vec2) -> PlayerInput {
    PlayerInput { look: ball - p.position, ..PlayerInput::default() }
}

/// Run to `target` (m) at up to `speed` (m/s), slowing down within the last metres to stop on it
/// (as the built-in AI's plans do), looking at `look` when standing.
#[inline]
pub(crate) fn arrive(p: &Player, target: Vec2, speed: f32, look: Vec2) -> PlayerInput {
    let to = target - p.position;
    let dist = to.length();
    let speed = speed.min(dist * PULL);
    let velocity = if dist > 0.15 { to * (speed / dist) } else { Vec2::ZERO };
    PlayerInput { velocity, look, ..PlayerInput::default() }
}

/// Keep pace with a spot moving at `spot_velocity`: its velocity plus a pull towards it, at most
/// `speed` (m/s).
#[inline]
pub(crate) fn pursue(p: &Player, spot: Vec2, spot_velocity: Vec2, speed: f32, look: Vec2) -> PlayerInput {
    let to = spot - p.position;
    if to.length_squared() < 0.15 * 0.15 && spot_velocity.length_squared() < 0.01 {
        return PlayerInput { look, ..PlayerInput::default() };
    }
    let mut velocity = spot_velocity + to * PULL;
    let s2 = velocity.length_squared();
    if s2 > speed * speed {
        velocity *= speed / s2.sqrt();
    }
    PlayerInput { velocity, look, ..PlayerInput::default() }
}

/// `hold_position`: back to `anchor` (m) when pushed off it, facing the ball.
#[inline]
pub(crate) fn hold(p: &Player, anchor: Vec2, ball: Vec2) -> PlayerInput {
    let speed = if p.position.distance(anchor) > SPRINT_BACK { p.max_speed } else { WALK_SPEED };
    arrive(p, anchor, speed, ball - p.position)
}

/// `follow`: stay [`FOLLOW_GAP`] off a target at `at` moving at `velocity` (m, m/s).
#[inline]
pub(crate) fn follow(p: &Player, at: Vec2, velocity: Vec2, ball: Vec2) -> PlayerInput {
    let away = (p.position - at).normalize_or_zero();
    pursue(p, at + away * FOLLOW_GAP, velocity, p.max_speed, ball - p.position)
}

/// `mark`: stand [`MARK_GAP`] goal-side of `man` (between him and the marker's own goal),
/// moving with him.
#[inline]
pub(crate) fn mark(p: &Player, man: &Player, ball: Vec2) -> PlayerInput {
    let own_goal = Vec2::new(-p.side.attack_sign() * HALF_LENGTH, 0.0);
    let spot = man.position + (own_goal - man.position).normalize_or_zero() * MARK_GAP;
    pursue(p, spot, man.velocity, p.max_speed, ball - p.position)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;

    fn player(side: Side, x: f32, y: f32) -> Player {
        Player::new(side, 1, Role::CB, Vec2::new(x, y), Vec2::ZERO)
    }

    #[test]
    fn arrive_slows_down_and_stops_on_the_spot() {
        let p = player(Side::Left, 0.0, 0.0);
        let far = arrive(&p, Vec2::new(20.0, 0.0), 8.0, Vec2::X);
        assert_eq!(far.velocity, Vec2::new(8.0, 0.0));
        let near = arrive(&p, Vec2::new(1.0, 0.0), 8.0, Vec2::X);
        assert!((near.velocity.x - 2.5).abs() < 1e-6);
        assert_eq!(arrive(&p, Vec2::new(0.1, 0.0), 8.0, Vec2::X).velocity, Vec2::ZERO);
    }

    #[test]
    fn a_marker_goes_goal_side() {
        // Left marker: his goal is at x = -55; the man at (10, 0) is marked from (8.5, 0).
        let p = player(Side::Left, 0.0, 0.0);
        let man = player(Side::Right, 10.0, 0.0);
        let v = mark(&p, &man, Vec2::ZERO).velocity;
        assert!(v.x > 0.0 && v.y.abs() < 1e-6);
        let on_spot = player(Side::Left, 10.0 - MARK_GAP, 0.0);
        assert_eq!(mark(&on_spot, &man, Vec2::ZERO).velocity, Vec2::ZERO);
        // A right-team marker stands on the +x side of his man.
        let r = player(Side::Right, 11.0, 0.0);
        assert!(mark(&r, &man, Vec2::ZERO).velocity.x > 0.0);
    }
}
