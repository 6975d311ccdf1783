//! Putting the ball in motion: passes (ground, driven, lofted) and shots, with aim error that
//! grows as skill and difficulty fall. Also the auto-targeting of agents' passes: the best
//! team-mate in the movement direction (grf.md §5.4).

use glam::{Vec2, Vec3};

use super::input::{Kick, KickKind};
use crate::geometry::pitch::{BALL_RADIUS, GOAL_HALF_WIDTH, GRAVITY, HALF_LENGTH};
use crate::physics::{BALL_DRAG, Ball, ROLL_DECELERATION, ROLL_VISCOUS};
use crate::player::{Player, nearest_distance};
use crate::rng::MatchRng;

/// Speed (m/s) a ground pass should still have when it reaches the receiver.
const ARRIVAL_SPEED: f32 = 5.0;
/// Fastest ground pass (m/s).
const MAX_GROUND_PASS: f32 = 26.0;

/// Distance (m) a rolling ball covers while slowing from `v0` to `v1` under
/// a = -(c0 + c1·v): s = (v0 - v1)/c1 - c0/c1² · ln((c0 + c1·v0)/(c0 + c1·v1)).
fn rolling_distance(v0: f32, v1: f32) -> f32 {
    let (c0, c1) = (ROLL_DECELERATION, ROLL_VISCOUS);
    (v0 - v1) / c1 - c0 / (c1 * c1) * libm::logf((c0 + c1 * v0) / (c0 + c1 * v1))
}

/// Initial speed of a ground pass that arrives `distance` m away at [`ARRIVAL_SPEED`].
pub(crate) fn ground_pass_speed(distance: f32) -> f32 {
    let (mut lo, mut hi) = (ARRIVAL_SPEED, MAX_GROUND_PASS);
    if rolling_distance(hi, ARRIVAL_SPEED) < distance {
        return hi;
    }
    for _ in 0..24 {
        let mid = 0.5 * (lo + hi);
        if rolling_distance(mid, ARRIVAL_SPEED) < distance {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}

/// Launch speed for a lofted ball at elevation (cos, sin) whose first bounce is `carry` m away,
/// with a margin for air drag.
fn lofted_speed(carry: f32, cos: f32, sin: f32) -> f32 {
    let vacuum = (GRAVITY * carry / (2.0 * sin * cos)).sqrt();
    vacuum * (1.0 + BALL_DRAG * 0.9 * vacuum * sin)
}

/// Rotates `v` by a small angle `a` (rad) using the small-angle form (|a| < 0.2 here).
#[inline]
fn rotate_small(v: Vec2, a: f32) -> Vec2 {
    let (s, c) = (a, 1.0 - 0.5 * a * a);
    Vec2::new(v.x * c - v.y * s, v.x * s + v.y * c)
}

/// Sets the ball's velocity for `kick` taken by `kicker`. `accuracy` in [0, 1] scales aim error
/// (1 = the best player at difficulty 1). `target` is the resolved aim point (m).
pub(crate) fn launch(ball: &mut Ball, kicker: &Player, kick: &Kick, target: Vec2, accuracy: f32, rng: &mut MatchRng) {
    let from = ball.xy();
    let to = target - from;
    let distance = to.length().max(0.5);
    let dir = if to.length_squared() > 1e-6 { to / distance } else { kicker.facing };
    // Aim error (rad): small for the best, growing faster as skill falls.
    let error = 0.015 + 0.04 * (1.0 - accuracy) + 0.06 * (1.0 - accuracy) * (1.0 - accuracy);
    let dir = rotate_small(dir, rng.noise(error * 1.7).clamp(-0.19, 0.19));
    let velocity = match kick.kind {
        KickKind::ShortPass => {
            let speed = ground_pass_speed(distance)
                * (1.0 + 0.1 * kick.power)
                * (1.0 + rng.noise(0.05 * (1.0 - accuracy) + 0.01));
            (dir * speed.min(MAX_GROUND_PASS)).extend(0.0)
        }
        KickKind::LongPass => {
            // Driven pass: 14° elevation, first bounce at about 70 % of the way.
            let (c, s) = (0.970_295_7, 0.241_921_9);
            let speed = lofted_speed(distance * 0.7, c, s).min(30.0);
            Vec3::new(dir.x * c * speed, dir.y * c * speed, s * speed)
        }
        KickKind::HighPass => {
            // Lofted pass: 30° elevation, lands just short of the receiver.
            let (c, s) = (0.866_025_4, 0.5);
            let speed = lofted_speed(distance * 0.88, c, s).min(30.0);
            Vec3::new(dir.x * c * speed, dir.y * c * speed, s * speed)
        }
        KickKind::Shot => {
            let speed = (22.0 + 10.0 * kick.power) * (0.85 + 0.15 * accuracy);
            // Average horizontal speed over the flight, slowed by drag.
            let mean = speed * (1.0 - (BALL_DRAG * 0.5 * distance).min(0.5));
            let t = distance / mean;
            let vz = ((kick.height - BALL_RADIUS) / t + 0.5 * GRAVITY * t).clamp(0.0, 12.0);
            let horizontal = (speed * speed - vz * vz).max(25.0).sqrt();
            (dir * horizontal).extend(vz)
        }
    };
    ball.velocity = velocity;
    ball.position.z = ball.position.z.max(BALL_RADIUS);
    ball.spin = Vec3::ZERO;
}

/// The shot's aim point: the goal line of the team `attack_sign` attacks, towards the corner
/// farther from the keeper.
pub(crate) fn shot_target(attack_sign: f32, keeper_y: Option<f32>, shooter_y: f32) -> Vec2 {
    let inside = GOAL_HALF_WIDTH - 0.9;
    let y = match keeper_y {
        Some(k) if k > 0.3 => -inside,
        Some(k) if k < -0.3 => inside,
        // Keeper central: the far post from the shooter.
        _ => {
            if shooter_y >= 0.0 {
                -inside
            } else {
                inside
            }
        }
    };
    Vec2::new(attack_sign * HALF_LENGTH, y)
}

/// Preferred pass length (m) per kind, for choosing a receiver.
fn preferred_distance(kind: KickKind) -> (f32, f32) {
    match kind {
        KickKind::ShortPass => (4.0, 22.0),
        KickKind::LongPass => (15.0, 45.0),
        KickKind::HighPass => (18.0, 60.0),
        KickKind::Shot => (0.0, 0.0),
    }
}

/// The best team-mate to receive a pass of `kind` played in `direction` (unit, global frame) by
/// `kicker`, and the point to aim at (leading a moving receiver). Without team-mates the ball is
/// played into space along `direction`.
pub(crate) fn auto_target(
    kind: KickKind,
    kicker: &Player,
    mates: &[Player],
    opponents: &[Player],
    direction: Vec2,
) -> Vec2 {
    let (short, long) = preferred_distance(kind);
    let mut best = None;
    let mut best_score = f32::NEG_INFINITY;
    for mate in mates {
        if !mate.active || mate.index == kicker.index {
            continue;
        }
        let to = mate.position - kicker.position;
        let d = to.length();
        if d < 1.0 {
            continue;
        }
        let cos = to.dot(direction) / d;
        if cos < 0.2 {
            continue;
        }
        let length_penalty = if d < short {
            (short - d) / short
        } else if d > long {
            (d - long) / long
        } else {
            0.0
        };
        let marked = nearest_distance(opponents, mate.position);
        let score = 2.0 * cos - length_penalty + 0.05 * marked.min(8.0);
        if score > best_score {
            best_score = score;
            best = Some((mate, d));
        }
    }
    match best {
        Some((mate, d)) => {
            let lead = match kind {
                KickKind::ShortPass => d / 15.0,
                KickKind::LongPass => d / 14.0 + 0.6,
                KickKind::HighPass => d / 16.0,
                KickKind::Shot => 0.0,
            };
            mate.position + mate.velocity * lead
        }
        None => {
            let d = match kind {
                KickKind::ShortPass => 15.0,
                KickKind::LongPass => 30.0,
                _ => 35.0,
            };
            kicker.position + direction * d
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ground_pass_speed_reaches_the_distance() {
        for d in [5.0f32, 10.0, 20.0, 30.0] {
            let v = ground_pass_speed(d);
            let s = rolling_distance(v, ARRIVAL_SPEED);
            assert!((s - d).abs() < 0.05, "{d}: {s}");
        }
    }

    #[test]
    fn shots_aim_away_from_the_keeper() {
        assert!(shot_target(1.0, Some(1.0), 0.0).y < 0.0);
        assert!(shot_target(1.0, Some(-1.0), 0.0).y > 0.0);
        assert_eq!(shot_target(-1.0, None, 5.0).x, -HALF_LENGTH);
    }
}
