//! Where the ball is going and who gets there first.

use glam::{Vec2, Vec3};

use super::{Analysis, Difficulty, MatchView};
use crate::geometry::pitch::{BALL_RADIUS, GRAVITY};
use crate::geometry::{Side, TeamFrame};
use crate::physics::{BALL_DRAG, BOUNCE_RESTITUTION, Ball, rolled_speed};

/// Number of predicted samples.
pub const SAMPLES: usize = 20;
/// Time between samples (s).
pub const SAMPLE_DT: f32 = 0.1;

/// The ball's predicted positions at 0.1 s, 0.2 s, … 2.0 s (m), from a simplified model (no goal
/// frames, no players).
#[derive(Clone, Copy, Debug)]
pub struct BallPath {
    /// Predicted positions.
    pub at: [Vec3; SAMPLES],
}

impl BallPath {
    /// Predicts the path of a free ball (an owned ball moves with its owner).
    pub fn predict(ball: &Ball) -> BallPath {
        let mut at = [Vec3::ZERO; SAMPLES];
        let (mut p, mut v) = (ball.position, ball.velocity);
        const SUB: usize = 2;
        let dt = SAMPLE_DT / SUB as f32;
        for slot in &mut at {
            for _ in 0..SUB {
                if p.z <= BALL_RADIUS + 0.01 && v.z.abs() < 0.8 {
                    let h = v.truncate();
                    let s = h.length();
                    let kept = rolled_speed(s, dt);
                    let h = if kept <= 0.0 { Vec2::ZERO } else { h * (kept / s) };
                    v = h.extend(0.0);
                    p.z = BALL_RADIUS;
                } else {
                    let s = v.length();
                    v += (Vec3::new(0.0, 0.0, -GRAVITY) - BALL_DRAG * s * v) * dt;
                }
                p += v * dt;
                if p.z < BALL_RADIUS {
                    p.z = BALL_RADIUS;
                    v.z = if -v.z * BOUNCE_RESTITUTION < 0.8 { 0.0 } else { -v.z * BOUNCE_RESTITUTION };
                }
            }
            *slot = p;
        }
        BallPath { at }
    }

    /// Earliest time (s) and place a runner at `from` with top speed `speed` (m/s) can meet the
    /// ball below `max_height` (m); after the horizon, the last sample plus the run to it.
    pub fn intercept(&self, from: Vec2, speed: f32, max_height: f32) -> (f32, Vec2) {
        let reach = 0.6;
        for (k, p) in self.at.iter().enumerate() {
            let t = SAMPLE_DT * (k + 1) as f32;
            if p.z <= max_height && (p.truncate().distance(from) - reach) <= speed * t {
                return (t, p.truncate());
            }
        }
        let last = self.at[SAMPLES - 1].truncate();
        (SAMPLE_DT * SAMPLES as f32 + last.distance(from) / speed, last)
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
            BallPath { at }
        }
        None => BallPath::predict(view.ball),
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
    Analysis { frame: TeamFrame::of(side), path, chaser: best, second: second.map(|s| s.0), opponent_time }
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
}
