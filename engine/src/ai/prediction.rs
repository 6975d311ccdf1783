//! Where the ball is going and who gets there first.

use std::sync::{Mutex, PoisonError};

use glam::{Vec2, Vec3, Vec4};

use super::{Analysis, Difficulty, MatchView};
use crate::geometry::pitch::{BALL_RADIUS, GRAVITY};
use crate::geometry::{Side, TeamFrame};
use crate::physics::{BALL_DRAG, BOUNCE_RESTITUTION, Ball, bounce_keep, rolled_speed};

/// Number of predicted samples.
pub const SAMPLES: usize = 20;
/// Time between samples (s).
pub const SAMPLE_DT: f32 = 0.1;
/// How near (m) a runner must come to a predicted position of the ball to meet it there
/// ([`BallPath::intercept`]).
pub(crate) const INTERCEPT_REACH: f32 = 0.6;

/// The sample times (s): `SAMPLE_DT · (k + 1)` for sample k, as the samples are timed.
const TIMES: [f32; SAMPLES] = {
    let mut times = [0.0; SAMPLES];
    let mut k = 0;
    while k < SAMPLES {
        times[k] = SAMPLE_DT * (k + 1) as f32;
        k += 1;
    }
    times
};

/// Samples in a group of the path's lanes (a `Vec4`).
const LANE: usize = 4;
const GROUPS: usize = SAMPLES / LANE;
const _: () = assert!(SAMPLES.is_multiple_of(LANE));

/// The ball's predicted positions at 0.1 s, 0.2 s, … 2.0 s (m), from a simplified model (no goal
/// frames, no players).
#[derive(Clone, Copy, Debug)]
pub struct BallPath {
    /// Predicted positions.
    at: [Vec3; SAMPLES],
    /// The same positions' x, y and z apart, four samples to a `Vec4`: [`BallPath::intercept`],
    /// run for every player at every decision, tests four samples at once with SIMD.
    lanes: [[Vec4; GROUPS]; 3],
}

impl BallPath {
    /// The path through the predicted positions `at`.
    pub fn new(at: [Vec3; SAMPLES]) -> BallPath {
        let mut lanes = [[Vec4::ZERO; GROUPS]; 3];
        for (c, group) in at.chunks_exact(LANE).enumerate() {
            for (axis, lane) in lanes.iter_mut().enumerate() {
                lane[c] = Vec4::from_array([group[0][axis], group[1][axis], group[2][axis], group[3][axis]]);
            }
        }
        BallPath { at, lanes }
    }

    /// The predicted positions, 0.1 s apart from 0.1 s on (m).
    pub fn at(&self) -> &[Vec3; SAMPLES] {
        &self.at
    }

    /// Predicts the path of a free ball (an owned ball moves with its owner).
    pub fn predict(ball: &Ball) -> BallPath {
        let mut at = [Vec3::ZERO; SAMPLES];
        let (mut p, mut v) = (ball.position, ball.velocity);
        const SUB: usize = 2;
        let dt = SAMPLE_DT / SUB as f32;
        // Set once the ball has stopped on the grass: from then on every step leaves it where it
        // is (speed 0 keeps speed 0, the position gains +0), so the remaining samples are copies.
        let mut stopped = false;
        // Set once the ball rolls: it rolls on in a straight line until it stops, so from the
        // next sample only its speed is worked out, along that line (a square root and a
        // division per sub-step fewer: the prediction runs at every decision of both teams).
        let mut rolling = false;
        for k in 0..SAMPLES {
            if stopped {
                at[k] = p;
                continue;
            }
            if rolling {
                let h = v.truncate();
                let mut speed = h.length();
                let direction = h / speed;
                let mut xy = p.truncate();
                for sample in &mut at[k..] {
                    for _ in 0..SUB {
                        speed = rolled_speed(speed, dt);
                        xy += direction * (speed * dt);
                    }
                    *sample = xy.extend(BALL_RADIUS);
                }
                break;
            }
            for _ in 0..SUB {
                if p.z <= BALL_RADIUS + 0.01 && v.z.abs() < 0.8 {
                    let h = v.truncate();
                    let s = h.length();
                    let kept = rolled_speed(s, dt);
                    stopped |= kept <= 0.0;
                    let h = if kept <= 0.0 { Vec2::ZERO } else { h * (kept / s) };
                    v = h.extend(0.0);
                    p.z = BALL_RADIUS;
                    rolling = !stopped;
                } else {
                    let s = v.length();
                    v += (Vec3::new(0.0, 0.0, -GRAVITY) - BALL_DRAG * s * v) * dt;
                    rolling = false;
                }
                p += v * dt;
                if p.z < BALL_RADIUS {
                    p.z = BALL_RADIUS;
                    let keep = bounce_keep(-v.z);
                    v.x *= keep;
                    v.y *= keep;
                    v.z = if -v.z * BOUNCE_RESTITUTION < 0.8 { 0.0 } else { -v.z * BOUNCE_RESTITUTION };
                }
            }
            at[k] = p;
        }
        BallPath::new(at)
    }

    /// Earliest time (s) and place a runner at `from` with top speed `speed` (m/s) can meet the
    /// ball below `max_height` (m); after the horizon, the last sample plus the run to it.
    ///
    /// The first sample k with `z <= max_height` and `|xy − from| − INTERCEPT_REACH <= speed · t_k`,
    /// tested four samples at a time: each lane computes what a scalar loop over the samples would
    /// (glam's `Vec4` arithmetic and square root are IEEE's, lane by lane), so the answer is the
    /// same bit for bit.
    pub fn intercept(&self, from: Vec2, speed: f32, max_height: f32) -> (f32, Vec2) {
        let reach = Vec4::splat(INTERCEPT_REACH);
        let (fx, fy) = (Vec4::splat(from.x), Vec4::splat(from.y));
        let (speed4, max_height) = (Vec4::splat(speed), Vec4::splat(max_height));
        let [xs, ys, zs] = &self.lanes;
        for c in 0..GROUPS {
            let (dx, dy) = (xs[c] - fx, ys[c] - fy);
            let distance = (dx * dx + dy * dy).sqrt();
            let t = Vec4::from_slice(&TIMES[c * LANE..]);
            let meets = zs[c].cmple(max_height) & (distance - reach).cmple(speed4 * t);
            let mask = meets.bitmask();
            if mask != 0 {
                let k = c * LANE + mask.trailing_zeros() as usize;
                return (TIMES[k], self.at[k].truncate());
            }
        }
        let last = self.at[SAMPLES - 1].truncate();
        (SAMPLE_DT * SAMPLES as f32 + last.distance(from) / speed, last)
    }
}

/// The last free-ball prediction and the ball state it was made from. In a tick, both teams'
/// analyses, the magnet and the controllers' time to the ball all ask for the path of the same
/// ball (only a kick moves it between them), and [`BallPath::predict`] is a function of the
/// ball's position and velocity alone, so they share one prediction and play is unchanged bit for
/// bit. The prediction was the largest single cost of an Academy drill's step.
///
/// Not part of a snapshot: a copy or a restored match starts empty and predicts again. Behind a
/// mutex (never contended: a match runs on one thread) so that a match stays `Sync`.
#[derive(Debug, Default)]
pub struct BallPathMemo(Mutex<Option<([u32; 6], BallPath)>>);

impl BallPathMemo {
    /// [`BallPath::predict`] for `ball`, made again only when its position or velocity changed
    /// (compared bit for bit).
    pub fn path(&self, ball: &Ball) -> BallPath {
        let (p, v) = (ball.position, ball.velocity);
        let key = [p.x, p.y, p.z, v.x, v.y, v.z].map(f32::to_bits);
        let mut memo = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        match &*memo {
            Some((k, path)) if *k == key => *path,
            _ => {
                let path = BallPath::predict(ball);
                *memo = Some((key, path));
                path
            }
        }
    }
}

impl Clone for BallPathMemo {
    fn clone(&self) -> Self {
        BallPathMemo::default()
    }
}

/// Shared analysis for `side`'s decision.
pub fn analyse(view: &MatchView, side: Side, _difficulty: &Difficulty) -> Analysis {
    let path = match view.owner {
        // An owned ball is wherever its owner runs.
        Some(g) => {
            let owner = &view.players[g];
            let mut at = [Vec3::ZERO; SAMPLES];
            for (k, slot) in at.iter_mut().enumerate() {
                let t = SAMPLE_DT * (k + 1) as f32;
                *slot = (view.ball.xy() + owner.velocity * t.min(0.8)).extend(BALL_RADIUS);
            }
            BallPath::new(at)
        }
        None => view.paths.path(view.ball),
    };
    let mut best: Option<(usize, f32, Vec2)> = None;
    let mut second: Option<(usize, f32)> = None;
    for g in view.ranges[side.index()].clone() {
        let p = &view.players[g];
        if !p.active || p.lazy || p.is_keeper() || view.owner == Some(g) {
            continue;
        }
        let (t, at) = path.intercept(p.position, p.max_speed * 0.9, 1.0);
        match best {
            Some((_, bt, _)) if t >= bt => {
                if second.is_none_or(|(_, st)| t < st) {
                    second = Some((g, t));
                }
            }
            _ => {
                if let Some((bg, bt, _)) = best {
                    second = Some((bg, bt));
                }
                best = Some((g, t, at));
            }
        }
    }
    let mut opponent_time = f32::INFINITY;
    for g in view.ranges[side.opponent().index()].clone() {
        let p = &view.players[g];
        if p.active && view.owner != Some(g) {
            opponent_time = opponent_time.min(path.intercept(p.position, p.max_speed * 0.9, 1.0).0);
        }
    }
    Analysis {
        frame: TeamFrame::of(side),
        path,
        chaser: best,
        second: second.map(|s| s.0),
        opponent_time,
        defensive_line: view.defensive_line(side),
        micro_focus_strength: super::team_shape::micro_focus_strength(
            TeamFrame::of(side).vec2(view.ball.xy()).x,
            super::team_shape::possession_bias(view, side),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rolling_ball_is_predicted_ahead_and_slowing() {
        let mut b = Ball::at_rest(Vec2::ZERO);
        b.velocity = Vec3::new(10.0, 0.0, 0.0);
        let path = BallPath::predict(&b);
        assert!(path.at[0].x > 0.8 && path.at[0].x < 1.0);
        let steps: Vec<f32> = path.at.windows(2).map(|w| w[1].x - w[0].x).collect();
        assert!(steps.windows(2).all(|s| s[1] <= s[0]));
        let (t, at) = path.intercept(Vec2::new(10.0, 0.0), 8.0, 1.0);
        assert!(t < 1.0 && at.x > 0.0);
    }

    /// The scalar intercept the SIMD one must equal.
    fn intercept_sample_by_sample(path: &BallPath, from: Vec2, speed: f32, max_height: f32) -> (f32, Vec2) {
        for (k, p) in path.at.iter().enumerate() {
            let t = SAMPLE_DT * (k + 1) as f32;
            if p.z <= max_height && (p.truncate().distance(from) - INTERCEPT_REACH) <= speed * t {
                return (t, p.truncate());
            }
        }
        let last = path.at[SAMPLES - 1].truncate();
        (SAMPLE_DT * SAMPLES as f32 + last.distance(from) / speed, last)
    }

    #[test]
    fn intercepts_are_those_of_a_sample_by_sample_search() {
        let mut state: u32 = 0x9e37_79b9;
        let mut next = move |scale: f32| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            ((state % 20_001) as f32 / 10_000.0 - 1.0) * scale
        };
        for _ in 0..2_000 {
            let mut b = Ball::at_rest(Vec2::new(next(50.0), next(30.0)));
            b.position.z = 0.11 + next(3.0).abs();
            b.velocity = Vec3::new(next(25.0), next(25.0), next(10.0));
            let path = BallPath::predict(&b);
            let from = Vec2::new(next(50.0), next(30.0));
            let height = [1.0, 2.5][usize::from(next(1.0) > 0.0)];
            // A random top speed, and those on the edge of meeting one sample or missing it.
            let k = (next(1.0).abs() * (SAMPLES - 1) as f32) as usize;
            let edge = (path.at[k].truncate().distance(from) - INTERCEPT_REACH) / TIMES[k];
            for speed in [next(9.0).abs(), edge, edge.next_up(), edge.next_down()] {
                let (t, at) = path.intercept(from, speed, height);
                let (t0, at0) = intercept_sample_by_sample(&path, from, speed, height);
                let bits = |t: f32, at: Vec2| (t.to_bits(), at.to_array().map(f32::to_bits));
                assert_eq!(bits(t, at), bits(t0, at0), "speed {speed}");
            }
        }
    }
}
