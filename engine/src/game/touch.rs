//! The kicking motion a pass is struck with, and what it allows: GRF's best possible touch.
//!
//! GRF 2.10.2 plays every pass as a kicking animation picked for how far the ball leaves from the
//! way the body faces, at the player's pace. Each animation carries a power factor `f` and a
//! touch difficulty `d` (the `touch_maxpowerfactor` and `touch_difficultyfactor` variables of its
//! pass animations, read off GRF's data files). The touch caps the ball's speed at
//! `base × (0.7·f + 0.3) + 0.5 × the ball's own speed` (base 30 m/s for a ground pass, 42 for a
//! high one); a quarter of the pace it lacks, at most 2.5 m/s, goes into lift; and the touch
//! rises by a further `d × (1 − 0.5 × passing) × 5 × U(0.2, 1)` m/s. So a pass played straight
//! on from a run leaves at up to 30 m/s, one turned right round from a stand at 17.4 m/s, and
//! one turned round at a sprint at 15.3 m/s and bobbling. Measured with a GRF build that logged
//! every pass touch (academy_run_to_score_with_keeper, random agent, 76 passes): every cap
//! logged is one of these animations' (docs/grf-compatibility.md#pitch-geometry).
//!
//! GRF picks one animation of a set; touchline interpolates between the set's turns, so a pass
//! gets smoothly harder as the turn grows. GRF's pull of a difficult touch towards the
//! animation's own direction is not modelled: the animation is turned to suit the pass, so it
//! moves the ball little.

use glam::{Vec2, Vec3};

use super::input::KickKind;
use crate::rng::MatchRng;

/// Top speed (m/s) of a ground pass's touch before the animation's power factor: GRF's
/// `maxPowerShortPass` (short and long passes alike).
const GROUND_BASE: f32 = 30.0;
/// The same for a high pass: GRF's `maxPowerHighPass`.
const HIGH_BASE: f32 = 42.0;
/// Most lift (m/s) a capped touch gets from the pace it lacks: GRF adds a quarter of the missing
/// pace, up to 10 m/s of it.
const MAX_MISSING_LIFT: f32 = 2.5;

/// GRF's standing pass animations (turn in degrees from the facing, power factor, difficulty):
/// `pass/idle/000`, `090` and `180`.
const STANDING: [(f32, f32, f32); 3] = [(22.5, 0.8, 0.0), (90.0, 0.7, 0.0), (180.0, 0.4, 0.4)];
/// GRF's pass animations on the move (walk and sprint: `000`, `045`, `090`, `135`), the turn
/// right round set by pace ([`turned_round`]).
const MOVING: [(f32, f32, f32); 4] = [(22.5, 1.0, 0.0), (45.0, 0.9, 0.0), (90.0, 0.7, 0.2), (135.0, 0.6, 0.4)];
/// GRF's turns right round: `pass/dribble/180_turn` up to its dribble-walk switch (4.2 m/s),
/// `pass/sprint/180` from its walk-sprint switch (6 m/s) on; between them a blend.
const DRIBBLE_TURN: (f32, f32) = (0.5, 0.6);
const SPRINT_TURN: (f32, f32) = (0.3, 0.7);
/// Below this pace (m/s) the standing animations play: GRF's idle-dribble switch.
const STANDING_PACE: f32 = 1.8;

/// The kicking animation of a pass: its power factor and touch difficulty, both in [0, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PassMotion {
    pub power: f32,
    pub difficulty: f32,
}

impl PassMotion {
    /// A throw-in: GRF's standing throws (`pass/idle/special/000_throw`, `045_throw` and their
    /// high-pass twins) have a power factor of 0.4 and no difficulty, whichever way they go.
    pub(crate) const THROW: PassMotion = PassMotion { power: 0.4, difficulty: 0.0 };

    /// The motion for a pass of `kind` leaving `turn` rad (0 to π, either side) from the way the
    /// body faced when the pass was asked for, the player then moving at `pace` m/s.
    pub(crate) fn new(kind: KickKind, turn: f32, pace: f32) -> PassMotion {
        let degrees = turn.abs().to_degrees().min(180.0);
        if kind == KickKind::HighPass {
            // GRF's high-pass animations carry no factors (1.0, no difficulty) save the turn
            // right round, `highpass/walk/180_turn`, which leaves 169° off at 0.7; none has one
            // further round than 90° before it.
            let t = ((degrees - 90.0) / (169.0 - 90.0)).clamp(0.0, 1.0);
            return PassMotion { power: 1.0 - 0.3 * t, difficulty: 0.0 };
        }
        let (power, difficulty) = if pace < STANDING_PACE {
            interpolate(&STANDING, degrees, None)
        } else {
            interpolate(&MOVING, degrees, Some(turned_round(pace)))
        };
        PassMotion { power, difficulty }
    }

    /// The fastest (m/s) a pass of `kind` leaves the foot, the ball already moving at
    /// `ball_speed` m/s.
    pub(crate) fn cap(&self, kind: KickKind, ball_speed: f32) -> f32 {
        let base = if kind == KickKind::HighPass { HIGH_BASE } else { GROUND_BASE };
        base * (0.7 * self.power + 0.3) + 0.5 * ball_speed
    }

    /// `wanted`, the velocity (m/s) a pass of `kind` asks for, as the touch plays it: capped
    /// at [`PassMotion::cap`] with a quarter of the lacking pace (at most [`MAX_MISSING_LIFT`])
    /// put into lift, then lifted by the motion's difficulty (less for a better passer,
    /// `passing` in [0, 1]) times 5 × U(0.2, 1) m/s; its mean, 3 m/s a unit, in a
    /// deterministic match.
    pub(crate) fn touch(
        &self,
        kind: KickKind,
        wanted: Vec3,
        ball_speed: f32,
        passing: f32,
        rng: &mut MatchRng,
    ) -> Vec3 {
        let cap = self.cap(kind, ball_speed);
        let pace = wanted.length();
        let mut v = wanted;
        if pace > cap {
            v = wanted * (cap / pace);
            v.z += (0.25 * (pace - cap)).min(MAX_MISSING_LIFT);
        }
        let difficulty = self.difficulty * (1.0 - 0.5 * passing.clamp(0.0, 1.0));
        if difficulty > 0.0 {
            let draw = if rng.noisy() { 0.2 + 0.8 * rng.unit() } else { 0.6 };
            v.z += difficulty * 5.0 * draw;
        }
        v
    }
}

/// The angle (rad, 0 to π) between the way the body faced, `body` (unit), and the pass, `dir`.
pub(crate) fn turn(body: Vec2, dir: Vec2) -> f32 {
    super::kick::signed_angle(body, dir).abs()
}

/// The turn right round at `pace` m/s: (power, difficulty).
fn turned_round(pace: f32) -> (f32, f32) {
    let t = ((pace - 4.2) / (6.0 - 4.2)).clamp(0.0, 1.0);
    (DRIBBLE_TURN.0 + (SPRINT_TURN.0 - DRIBBLE_TURN.0) * t, DRIBBLE_TURN.1 + (SPRINT_TURN.1 - DRIBBLE_TURN.1) * t)
}

/// Piecewise-linear in the turn through `points` (and `last` at 180°), flat before the first.
fn interpolate(points: &[(f32, f32, f32)], degrees: f32, last: Option<(f32, f32)>) -> (f32, f32) {
    let mut prev = points[0];
    if degrees <= prev.0 {
        return (prev.1, prev.2);
    }
    let tail = last.map(|(p, d)| (180.0, p, d));
    for next in points[1..].iter().copied().chain(tail) {
        if degrees <= next.0 {
            let t = (degrees - prev.0) / (next.0 - prev.0);
            return (prev.1 + (next.1 - prev.1) * t, prev.2 + (next.2 - prev.2) * t);
        }
        prev = next;
    }
    (prev.1, prev.2)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cap(kind: KickKind, degrees: f32, pace: f32) -> f32 {
        PassMotion::new(kind, degrees.to_radians(), pace).cap(kind, 0.0)
    }

    #[test]
    fn the_caps_are_those_grfs_touch_log_showed() {
        // GRF 2.10.2's logged caps, less half the ball's speed: a forward pass on the run 30.0,
        // 45° off 27.9, square 23.7, right round from a stand 17.4 and at a sprint 15.3.
        let close = |a: f32, b: f32| (a - b).abs() < 0.05;
        assert!(close(cap(KickKind::ShortPass, 0.0, 5.0), 30.0));
        assert!(close(cap(KickKind::LongPass, 45.0, 5.0), 27.9));
        assert!(close(cap(KickKind::ShortPass, 90.0, 3.6), 23.7));
        assert!(close(cap(KickKind::ShortPass, 180.0, 0.0), 17.4));
        assert!(close(cap(KickKind::ShortPass, 180.0, 7.0), 15.3));
        // The high pass back to a keeper: GRF's 33 m/s.
        assert!(close(cap(KickKind::HighPass, 180.0, 0.0), 33.18));
        assert!(close(cap(KickKind::HighPass, 30.0, 6.0), 42.0));
        // Half the ball's own pace on top.
        let motion = PassMotion::new(KickKind::ShortPass, 0.0, 5.0);
        assert!((motion.cap(KickKind::ShortPass, 4.0) - 32.0).abs() < 1e-4);
    }

    #[test]
    fn the_further_round_the_weaker_and_the_harder() {
        for pace in [0.0, 3.0, 5.0, 8.0] {
            let mut last = PassMotion::new(KickKind::ShortPass, 0.0, pace);
            for degrees in (0..=180).step_by(5) {
                let m = PassMotion::new(KickKind::ShortPass, (degrees as f32).to_radians(), pace);
                assert!(m.power <= last.power + 1e-6 && m.difficulty >= last.difficulty - 1e-6, "{pace} {degrees}");
                assert!((0.0..=1.0).contains(&m.power) && (0.0..=1.0).contains(&m.difficulty));
                last = m;
            }
        }
    }

    #[test]
    fn a_capped_touch_keeps_its_line_and_lifts_a_quarter_of_what_it_lacks() {
        let mut rng = MatchRng::new(1, 0, false);
        let easy = PassMotion::new(KickKind::ShortPass, 0.0, 5.0);
        let wanted = Vec3::new(-40.0, 0.0, 4.4);
        let v = easy.touch(KickKind::ShortPass, wanted, 0.0, 0.8, &mut rng);
        let scale = 30.0 / wanted.length();
        assert!((v.x - wanted.x * scale).abs() < 1e-3 && v.y == 0.0, "{v}");
        assert!((v.z - (wanted.z * scale + 2.5)).abs() < 1e-3, "{v}");
        // Within the cap the touch is as asked, for an easy motion.
        let soft = Vec3::new(12.0, 0.0, 1.3);
        assert_eq!(easy.touch(KickKind::ShortPass, soft, 0.0, 0.8, &mut rng), soft);
        // A hard one rises: on average difficulty × (1 − passing / 2) × 3 m/s.
        let hard = PassMotion::new(KickKind::ShortPass, std::f32::consts::PI, 0.0);
        let lifted = hard.touch(KickKind::ShortPass, soft, 0.0, 0.8, &mut rng);
        assert!((lifted.z - (1.3 + 0.4 * 0.6 * 3.0)).abs() < 1e-4, "{lifted}");
        let mut noisy = MatchRng::new(1, 0, true);
        let draws: Vec<f32> = (0..50).map(|_| hard.touch(KickKind::ShortPass, soft, 0.0, 0.8, &mut noisy).z).collect();
        assert!(draws.iter().all(|z| (1.3 + 0.24..=1.3 + 1.2 + 1e-4).contains(z)));
        assert!(draws.windows(2).any(|w| w[0] != w[1]));
    }
}
