//! Moving the players four at a time: [`move_player`]'s kinematics in the lanes of SIMD vectors.
//!
//! A player's tick of movement is a short chain of square roots and divisions (the acceleration
//! limit, the turn, the renormalised facing), each waiting on the one before, and it runs for
//! every player every tick. Four players in the four lanes of a `Vec4` share one chain (measured:
//! a full match's step 2-4 % faster; the processor already overlapped much of the players' work).
//! Every lane computes exactly what [`move_player`] computes (glam's `Vec4` arithmetic, square
//! root and division are IEEE's, lane by lane, and each branch becomes a select of the value the
//! taken branch gives), so the players move the same bit for bit; the test below holds it to that.

use glam::{Vec2, Vec4};

use super::player_motion::{MotionLimits, TURN_COS, TURN_SIN, move_player};
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};
use crate::player::Player;

/// Players moved together.
const LANES: usize = 4;

/// What one player asks of his legs this tick: [`move_player`]'s arguments.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Stride {
    /// The velocity he asks for (m/s), after the match's caps.
    pub(crate) velocity: Vec2,
    /// Where he looks when he stands (any length).
    pub(crate) look: Vec2,
    /// His acceleration and deceleration (m/s²).
    pub(crate) limits: MotionLimits,
}

/// Players waiting to be moved, gathered four at a time. Push every player to move this tick,
/// then [`Strides::finish`]: a full group moves at once, and the few left at the end one by one.
pub(crate) struct Strides {
    who: [usize; LANES],
    /// The pushed players' state and strides, one lane each (see [`COLUMNS`]): written
    /// straight into the lanes as they are pushed (gathered as whole `Stride`s and transposed
    /// afterwards, every value was copied twice).
    columns: [[f32; LANES]; COLUMNS],
    len: usize,
    /// Length of the tick (s).
    dt: f32,
}

impl Strides {
    /// No one yet, for a tick of `dt` seconds.
    pub(crate) fn new(dt: f32) -> Strides {
        Strides { who: [0; LANES], columns: [[0.0; LANES]; COLUMNS], len: 0, dt }
    }

    /// Moves `players[g]` by `stride`, now or with the next three players pushed.
    pub(crate) fn push(&mut self, players: &mut [Player], g: usize, stride: Stride) {
        let p = &players[g];
        let row = [
            p.position.x,
            p.position.y,
            p.velocity.x,
            p.velocity.y,
            p.facing.x,
            p.facing.y,
            stride.velocity.x,
            stride.velocity.y,
            stride.look.x,
            stride.look.y,
            stride.limits.acceleration,
            stride.limits.deceleration,
        ];
        let k = self.len;
        for (column, value) in self.columns.iter_mut().zip(row) {
            column[k] = value;
        }
        self.who[k] = g;
        self.len += 1;
        if self.len == LANES {
            move_four(players, &self.who, &self.columns, self.dt);
            self.len = 0;
        }
    }

    /// Moves the players pushed since the last full group.
    pub(crate) fn finish(&mut self, players: &mut [Player]) {
        let c = &self.columns;
        for k in 0..self.len {
            let velocity = Vec2::new(c[6][k], c[7][k]);
            let look = Vec2::new(c[8][k], c[9][k]);
            let limits = MotionLimits { acceleration: c[10][k], deceleration: c[11][k] };
            move_player(&mut players[self.who[k]], velocity, look, limits, self.dt);
        }
        self.len = 0;
    }
}

/// Values per pushed player: his position, velocity and facing (x, y each), then his stride's
/// velocity, look, acceleration and deceleration.
const COLUMNS: usize = 12;

/// The four players `who` (distinct), each by his stride, their lanes in `columns` (as
/// [`Strides::push`] writes them): [`move_player`] in four lanes.
fn move_four(players: &mut [Player], who: &[usize; LANES], columns: &[[f32; LANES]; COLUMNS], dt: f32) {
    let [px, py, vx, vy, fx, fy, mut dx, mut dy, lx, ly, acceleration, deceleration] = columns.map(Vec4::from_array);
    let zero = Vec4::ZERO;

    // Inputs that push a player further outside the pitch are dropped.
    let out_x = px.abs().cmpgt(Vec4::splat(HALF_LENGTH + 2.0)) & (dx * px).cmpgt(zero);
    dx = Vec4::select(out_x, zero, dx);
    let out_y = py.abs().cmpgt(Vec4::splat(HALF_WIDTH + 2.0)) & (dy * py).cmpgt(zero);
    dy = Vec4::select(out_y, zero, dy);

    // Towards the desired velocity at the acceleration (or deceleration) limit.
    let (dvx, dvy) = (dx - vx, dy - vy);
    let wanted2 = dx * dx + dy * dy;
    let speeding_up = wanted2.cmpgt(vx * vx + vy * vy);
    let max_dv = Vec4::select(speeding_up, acceleration, deceleration) * dt;
    let len2 = dvx * dvx + dvy * dvy;
    let limited = len2.cmpgt(max_dv * max_dv);
    let scale = max_dv / len2.sqrt();
    let vx = Vec4::select(limited, vx + dvx * scale, vx + dvx);
    let vy = Vec4::select(limited, vy + dvy * scale, vy + dvy);
    let (px, py) = (px + vx * dt, py + vy * dt);

    // The turn towards where he runs, or where he looks when he stands.
    let running = wanted2.cmpgt(Vec4::splat(0.25));
    let (tx, ty) = (Vec4::select(running, dx, lx), Vec4::select(running, dy, ly));
    let target2 = tx * tx + ty * ty;
    let still = target2.cmplt(Vec4::splat(1e-6));
    let length = target2.sqrt();
    let (ux, uy) = (tx / length, ty / length);
    let within_turn = (fx * tx + fy * ty).cmpge(Vec4::splat(TURN_COS) * length);
    let cross = fx * ty - fy * tx;
    let s = Vec4::select(cross.cmpge(zero), Vec4::splat(TURN_SIN), Vec4::splat(-TURN_SIN));
    let nx = fx * TURN_COS - fy * s;
    let ny = fx * s + fy * TURN_COS;
    let rcp = 1.0 / (nx * nx + ny * ny).sqrt();
    let normal = rcp.is_finite_mask() & rcp.cmpgt(zero);
    let (rx, ry) = (Vec4::select(normal, nx * rcp, ux), Vec4::select(normal, ny * rcp, uy));
    let fx = Vec4::select(still, fx, Vec4::select(within_turn, ux, rx));
    let fy = Vec4::select(still, fy, Vec4::select(within_turn, uy, ry));

    let [px, py, vx, vy, fx, fy] = [px, py, vx, vy, fx, fy].map(|v| v.to_array());
    for (k, &g) in who.iter().enumerate() {
        let p = &mut players[g];
        p.position = Vec2::new(px[k], py[k]);
        p.velocity = Vec2::new(vx[k], vy[k]);
        p.facing = Vec2::new(fx[k], fy[k]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;

    /// A player somewhere on (or just off) the pitch, running and asking for a run, from `next`
    /// (uniform in [0, 1)); now and then a case at an edge of the kinematics.
    fn case(next: &mut impl FnMut() -> f32, k: usize) -> (Player, Stride) {
        let mut p = Player::new(Side::Left, 0, Role::CM, Vec2::ZERO, Vec2::ZERO);
        let mut v = |scale: f32| Vec2::new(scale * (2.0 * next() - 1.0), scale * (2.0 * next() - 1.0));
        p.position = v(HALF_LENGTH + 6.0);
        p.velocity = v(9.0);
        p.facing = v(1.0).normalize_or(Vec2::X);
        let mut stride = Stride {
            velocity: v(9.0),
            look: v(3.0),
            limits: MotionLimits { acceleration: 6.0 + 2.0 * next(), ..MotionLimits::default() },
        };
        match k % 7 {
            0 => stride.velocity = Vec2::ZERO,
            1 => stride.velocity = p.velocity,
            2 => (stride.velocity, stride.look) = (Vec2::ZERO, Vec2::ZERO),
            3 => stride.velocity = p.facing * 0.4,
            4 => stride.look = -p.facing,
            _ => {}
        }
        (p, stride)
    }

    #[test]
    fn four_at_a_time_move_exactly_as_one_at_a_time() {
        let mut state = 0x9E37_79B9u32;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state % 100_000) as f32 / 100_000.0
        };
        for round in 0..2_000 {
            let n = 1 + round % 11;
            let cases: Vec<(Player, Stride)> = (0..n).map(|k| case(&mut next, round + k)).collect();
            let mut one_by_one: Vec<Player> = cases.iter().map(|c| c.0.clone()).collect();
            for (p, (_, s)) in one_by_one.iter_mut().zip(&cases) {
                move_player(p, s.velocity, s.look, s.limits, 0.01);
            }
            let mut batched: Vec<Player> = cases.iter().map(|c| c.0.clone()).collect();
            let mut strides = Strides::new(0.01);
            // Pushed in reverse, so the lanes do not follow the players' order.
            for g in (0..n).rev() {
                strides.push(&mut batched, g, cases[g].1);
            }
            strides.finish(&mut batched);
            for (a, b) in batched.iter().zip(&one_by_one) {
                for (x, y) in [(a.position, b.position), (a.velocity, b.velocity), (a.facing, b.facing)] {
                    assert_eq!(x.to_array().map(f32::to_bits), y.to_array().map(f32::to_bits), "round {round}");
                }
            }
        }
    }
}
