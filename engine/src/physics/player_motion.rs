//! Player kinematics: bounded acceleration and turning towards the desired velocity, and
//! position-based separation of bodies that overlap.

use glam::Vec2;

use crate::game::PlayerInput;
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH, RIM_HALF_LENGTH, RIM_HALF_WIDTH};
use crate::player::Player;

/// Radius of a player's body for collisions (m).
pub(crate) const BODY_RADIUS: f32 = 0.35;

/// A player's movement limits, from his attributes and team difficulty.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MotionLimits {
    /// Acceleration towards a faster desired velocity (m/s²).
    pub(crate) acceleration: f32,
    /// Deceleration (m/s²).
    pub(crate) deceleration: f32,
}

impl Default for MotionLimits {
    fn default() -> Self {
        MotionLimits { acceleration: 7.0, deceleration: 12.0 }
    }
}

// Facing turns at most 0.12 rad per tick (12 rad/s); cos and sin precomputed so that no
// transcendental function runs per tick.
const TURN_COS: f32 = 0.992_808_6;
const TURN_SIN: f32 = 0.119_712_2;

/// Moves `player` one tick of `dt` seconds following `input`.
pub(crate) fn move_player(player: &mut Player, input: &PlayerInput, limits: MotionLimits, dt: f32) {
    let mut desired = input.velocity;
    // Inputs that push a player further outside the pitch are dropped (grf.md §5.4).
    if player.position.x.abs() > HALF_LENGTH + 2.0 && desired.x * player.position.x > 0.0 {
        desired.x = 0.0;
    }
    if player.position.y.abs() > HALF_WIDTH + 2.0 && desired.y * player.position.y > 0.0 {
        desired.y = 0.0;
    }
    let dv = desired - player.velocity;
    let speeding_up = desired.length_squared() > player.velocity.length_squared();
    let rate = if speeding_up { limits.acceleration } else { limits.deceleration };
    let max_dv = rate * dt;
    let len2 = dv.length_squared();
    player.velocity += if len2 > max_dv * max_dv { dv * (max_dv / len2.sqrt()) } else { dv };
    player.position += player.velocity * dt;

    let look = if desired.length_squared() > 0.25 { desired } else { input.look };
    turn_towards(&mut player.facing, look);
}

/// Keeps a player inside the pitch's rim (the advertising boards), stopping him against it.
pub(crate) fn keep_inside_rim(player: &mut Player) {
    let p = &mut player.position;
    if p.x.abs() > RIM_HALF_LENGTH {
        p.x = p.x.clamp(-RIM_HALF_LENGTH, RIM_HALF_LENGTH);
        player.velocity.x = 0.0;
    }
    if p.y.abs() > RIM_HALF_WIDTH {
        p.y = p.y.clamp(-RIM_HALF_WIDTH, RIM_HALF_WIDTH);
        player.velocity.y = 0.0;
    }
}

/// Turns the unit vector `facing` towards `target` by at most one tick's turn.
fn turn_towards(facing: &mut Vec2, target: Vec2) {
    let len2 = target.length_squared();
    if len2 < 1e-6 {
        return;
    }
    let t = target / len2.sqrt();
    let cos = facing.dot(t);
    if cos >= TURN_COS {
        *facing = t;
        return;
    }
    let cross = facing.perp_dot(t);
    let s = if cross >= 0.0 { TURN_SIN } else { -TURN_SIN };
    let f = *facing;
    *facing = Vec2::new(f.x * TURN_COS - f.y * s, f.x * s + f.y * TURN_COS).normalize_or(t);
}

/// Pushes apart every pair of overlapping player bodies (equal shares) and removes the
/// approaching part of their relative velocity; then keeps everyone inside the rim.
pub(crate) fn separate_players(players: &mut [Player]) {
    const MIN_DIST: f32 = 2.0 * BODY_RADIUS;
    let n = players.len();
    for i in 0..n {
        if !players[i].active {
            continue;
        }
        for j in (i + 1)..n {
            if !players[j].active {
                continue;
            }
            let d = players[j].position - players[i].position;
            let d2 = d.length_squared();
            if d2 >= MIN_DIST * MIN_DIST {
                continue;
            }
            let dist = d2.sqrt();
            let normal = if dist > 1e-5 { d / dist } else { Vec2::new(1.0, 0.0) };
            let push = normal * ((MIN_DIST - dist) * 0.5);
            players[i].position -= push;
            players[j].position += push;
            let closing = (players[j].velocity - players[i].velocity).dot(normal);
            if closing < 0.0 {
                let impulse = normal * (closing * 0.5);
                players[i].velocity += impulse;
                players[j].velocity -= impulse;
            }
        }
    }
    for p in players.iter_mut() {
        keep_inside_rim(p);
    }
}
