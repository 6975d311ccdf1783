//! The ball: flight under gravity and quadratic air drag, bounces with restitution, rolling with
//! friction, and contacts with the goal frames and nets through [`PitchColliders`].

use glam::{Vec2, Vec3};

use super::colliders::{PitchColliders, Surface};
use crate::geometry::pitch::{BALL_RADIUS, GRAVITY, RIM_HALF_LENGTH, RIM_HALF_WIDTH};

/// Quadratic air drag coefficient k in a = -k·|v|·v (1/m), GRF's ball constant (GRF 2.10's
/// engine; a football of 0.43 kg, 0.038 m² and Cd ≈ 0.25 gives ½ρCdA/m ≈ 0.013).
pub const BALL_DRAG: f32 = 0.015;
/// Restitution of a bounce on grass (GRF 0.62, docs/grf-compatibility.md#pitch-geometry).
pub const BOUNCE_RESTITUTION: f32 = 0.62;
/// Constant part of the rolling deceleration (m/s²), GRF's ground friction (GRF 2.10's engine).
pub const ROLL_DECELERATION: f32 = 1.6;
/// Quadratic part of the grass friction (1/m), GRF's ground friction. A rolling ball also keeps
/// losing air drag ([`BALL_DRAG`]), as GRF's does (its drag acts on the ball whatever its height),
/// so on the grass a = -(1.6 + 0.055·v²): a ball rolled at 10 m/s stops after about 13.5 m, one
/// at 20 m/s after about 20 m. Measured in GRF 2.10.2 (academy_empty_goal, a pass back to the
/// keeper, ball traced every 0.1 s): rolling from 8.86 to 2.97 m/s took 9.5 m, this law's 9.48 m
/// (without the drag, 11.1 m).
pub const ROLL_QUADRATIC: f32 = 0.04;
/// Everything quadratic a rolling ball loses (1/m): air drag plus grass friction.
pub const ROLL_QUADRATIC_TOTAL: f32 = BALL_DRAG + ROLL_QUADRATIC;

/// The share of its speed across the grass a ball keeps when it lands at `impact` m/s (its
/// downward speed): GRF 2.10's bounce, whose impact friction clamp((impact - 0.5) / 12, 0, 1)
/// mixes half of itself (plus the grass's 0.01) of the ball's run into its spin, taken here as a
/// ball without spin. A ball dropping at 1 m/s keeps 0.97, at 3 m/s 0.885, at 6 m/s 0.76.
/// Measured in GRF 2.10.2 (academy_run_to_score_with_keeper, random agent, 145 bounces of loose
/// balls traced every 0.1 s): the ball keeps a median 0.63, 0.71 and 0.79 of its speed across
/// the 0.4 s round bounces at 5-7, 3.5-5 and 1.5-3.5 m/s down, air drag included.
#[inline]
pub fn bounce_keep(impact: f32) -> f32 {
    0.99 - 0.5 * ((impact - 0.5) / 12.0).clamp(0.0, 1.0)
}

/// The speed (m/s) a ball rolling at `speed` keeps after `dt` seconds on the grass: the air drag,
/// then the quadratic grass loss, then the constant one, in the order GRF's engine applies them.
#[inline]
pub fn rolled_speed(speed: f32, dt: f32) -> f32 {
    let s = speed - BALL_DRAG * speed * speed * dt;
    let s = s - ROLL_QUADRATIC * s * s * dt;
    (s - ROLL_DECELERATION * dt).max(0.0)
}
/// Below this vertical speed (m/s) a bouncing ball settles into rolling.
const SETTLE_SPEED: f32 = 0.8;

/// Ball state in the engine frame (m, m/s).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Ball {
    /// Centre position (m); z = [`BALL_RADIUS`] when resting on the grass.
    pub position: Vec3,
    /// Velocity (m/s).
    pub velocity: Vec3,
    /// Angular velocity (rad/s), from rolling and kicks; cosmetic (no Magnus force yet).
    pub spin: Vec3,
}

impl Ball {
    /// A ball at rest on the grass at `(x, y)` (m).
    pub fn at_rest(at: Vec2) -> Ball {
        Ball { position: at.extend(BALL_RADIUS), velocity: Vec3::ZERO, spin: Vec3::ZERO }
    }

    /// Whether the ball is on the grass (rolling or at rest).
    #[inline]
    pub fn on_ground(&self) -> bool {
        self.position.z <= BALL_RADIUS + 0.005 && self.velocity.z.abs() < SETTLE_SPEED
    }

    /// Position on the ground plane (m).
    #[inline]
    pub fn xy(&self) -> Vec2 {
        self.position.truncate()
    }

    /// Advances the ball `dt` seconds. Returns the surface it last touched, if any.
    pub fn integrate(&mut self, dt: f32, colliders: &PitchColliders) -> Option<Surface> {
        if self.on_ground() {
            self.position.z = BALL_RADIUS;
            self.velocity.z = 0.0;
            let v = self.velocity.truncate();
            let speed = v.length();
            let kept = rolled_speed(speed, dt);
            let v = if kept <= 0.0 { Vec2::ZERO } else { v * (kept / speed) };
            self.velocity = v.extend(0.0);
            // Rolling without slipping: ω = ẑ × v / r.
            self.spin = Vec3::new(-v.y, v.x, 0.0) / BALL_RADIUS;
        } else {
            let speed = self.velocity.length();
            self.velocity += (Vec3::new(0.0, 0.0, -GRAVITY) - BALL_DRAG * speed * self.velocity) * dt;
        }

        let mut touched = None;
        let mut remaining = dt;
        for _ in 0..3 {
            match colliders.sweep(self.position, self.velocity, remaining) {
                Some(hit) if self.velocity.dot(hit.normal) < 0.0 => {
                    self.position += self.velocity * hit.time + hit.normal * 1e-4;
                    self.respond(hit.normal, hit.surface);
                    remaining -= hit.time;
                    touched = Some(hit.surface);
                }
                _ => {
                    self.position += self.velocity * remaining;
                    remaining = 0.0;
                    break;
                }
            }
        }
        if remaining > 0.0 {
            self.position += self.velocity * remaining;
        }
        if self.position.z < BALL_RADIUS {
            self.position.z = BALL_RADIUS;
            self.velocity.z = self.velocity.z.max(0.0);
        }
        // Advertising boards: the ball never leaves the rim.
        if self.position.x.abs() > RIM_HALF_LENGTH || self.position.y.abs() > RIM_HALF_WIDTH {
            self.position.x = self.position.x.clamp(-RIM_HALF_LENGTH, RIM_HALF_LENGTH);
            self.position.y = self.position.y.clamp(-RIM_HALF_WIDTH, RIM_HALF_WIDTH);
            self.velocity = Vec3::ZERO;
        }
        touched
    }

    fn respond(&mut self, normal: Vec3, surface: Surface) {
        let vn = self.velocity.dot(normal);
        let (restitution, keep) = surface.response(-vn);
        let normal_part = normal * vn;
        let tangent = self.velocity - normal_part;
        self.velocity = tangent * keep - normal_part * restitution;
        if surface == Surface::Ground && self.velocity.z < SETTLE_SPEED {
            self.velocity.z = 0.0;
            self.position.z = BALL_RADIUS;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::TICK_SECONDS;

    fn run(ball: &mut Ball, ticks: usize, colliders: &PitchColliders) -> Vec<Surface> {
        (0..ticks).filter_map(|_| ball.integrate(TICK_SECONDS, colliders)).collect()
    }

    #[test]
    fn a_rolling_ball_slows_and_stops() {
        let c = PitchColliders::new();
        let mut b = Ball::at_rest(Vec2::ZERO);
        b.velocity = Vec3::new(10.0, 0.0, 0.0);
        run(&mut b, 1500, &c);
        assert_eq!(b.velocity, Vec3::ZERO);
        // GRF's drag and friction: ln(1 + 0.055·10²/1.6) / (2·0.055) ≈ 13.5 m.
        assert!((12.8..14.2).contains(&b.position.x), "rolled {}", b.position.x);
    }

    #[test]
    fn a_dropped_ball_bounces_lower_each_time_then_rolls() {
        let c = PitchColliders::new();
        let mut b = Ball::at_rest(Vec2::ZERO);
        b.position.z = 3.0;
        let mut peaks = Vec::new();
        let mut rising = false;
        let mut last_z = b.position.z;
        for _ in 0..600 {
            b.integrate(TICK_SECONDS, &c);
            if rising && b.position.z < last_z {
                peaks.push(last_z);
            }
            rising = b.position.z > last_z;
            last_z = b.position.z;
            assert!(b.position.z >= BALL_RADIUS - 1e-6);
        }
        assert!(peaks.len() >= 2, "peaks {peaks:?}");
        assert!(peaks.windows(2).all(|w| w[1] < w[0]));
        assert!(b.on_ground());
    }

    #[test]
    fn a_ball_landing_hard_loses_more_of_its_pace_across_the_grass() {
        // GRF 2.10's impact friction: 0.97 kept landing at 1 m/s down, 0.76 at 6 m/s.
        assert!((bounce_keep(1.0) - 0.969).abs() < 1e-3 && (bounce_keep(6.0) - 0.761).abs() < 1e-3);
        assert_eq!(bounce_keep(0.2), 0.99);
        assert_eq!(bounce_keep(30.0), 0.49);
        let c = PitchColliders::new();
        let across_after_landing = |drop: f32| {
            let mut b = Ball::at_rest(Vec2::ZERO);
            b.position.z = drop;
            b.velocity = Vec3::new(10.0, 0.0, 0.0);
            let before = loop {
                let v = b.velocity;
                if b.integrate(TICK_SECONDS, &c) == Some(Surface::Ground) {
                    break v.truncate().length();
                }
            };
            b.velocity.truncate().length() / before
        };
        let (soft, hard) = (across_after_landing(0.5), across_after_landing(2.5));
        assert!(hard < soft - 0.1 && soft > 0.88, "kept {soft} from 0.5 m, {hard} from 2.5 m");
    }
}
