//! Static colliders (rapier3d) for the ground and both goals' posts, crossbars and nets, and the
//! swept ball query against them.

use glam::Vec3;
use rapier3d::geometry::{ColliderBuilder, ColliderHandle, ColliderSet};
use rapier3d::parry::math::Pose;
use rapier3d::parry::query::{ShapeCastOptions, cast_shapes};
use rapier3d::parry::shape::Ball as BallShape;

use crate::geometry::pitch::{BALL_RADIUS, GOAL_DEPTH, GOAL_HALF_WIDTH, GOAL_HEIGHT, HALF_LENGTH, POST_RADIUS};

/// What the ball hit: decides restitution and friction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// The grass.
    Ground,
    /// A goal post.
    Post,
    /// A crossbar.
    Crossbar,
    /// The net (back, sides, roof).
    Net,
}

impl Surface {
    /// (normal restitution, tangential velocity kept) on an impact at `impact` m/s into the
    /// surface.
    pub fn response(self, impact: f32) -> (f32, f32) {
        match self {
            // GRF's ball bounce factor 0.62 (docs/grf-compatibility.md#pitch-geometry); the pace
            // the grass takes grows with the impact (GRF's impact friction).
            Surface::Ground => (0.62, super::ball::bounce_keep(impact)),
            Surface::Post | Surface::Crossbar => (0.75, 0.95),
            // Nets absorb the ball so it drops and stays in the goal.
            Surface::Net => (0.08, 0.25),
        }
    }
}

/// A contact found by [`PitchColliders::sweep`].
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// Time until contact (s), within the swept interval.
    pub time: f32,
    /// Unit normal pointing from the collider towards the ball.
    pub normal: Vec3,
    /// Which collider.
    pub surface: Surface,
}

/// The fixed colliders of the pitch.
#[derive(Clone)]
pub struct PitchColliders {
    set: ColliderSet,
    ground: ColliderHandle,
    /// Per goal (left at -x, right at +x): the parts, what they are, and their bounding boxes
    /// grown by the ball's radius (min, max) for cheap culling before the exact cast.
    goals: [Vec<(ColliderHandle, Surface, Vec3, Vec3)>; 2],
    ball: BallShape,
}

impl std::fmt::Debug for PitchColliders {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PitchColliders").field("colliders", &self.set.len()).finish()
    }
}

impl Default for PitchColliders {
    fn default() -> Self {
        Self::new()
    }
}

impl PitchColliders {
    /// The colliders every match shares: they never change, so they are built once per process.
    pub fn shared() -> std::sync::Arc<PitchColliders> {
        static SHARED: std::sync::OnceLock<std::sync::Arc<PitchColliders>> = std::sync::OnceLock::new();
        SHARED.get_or_init(|| std::sync::Arc::new(PitchColliders::new())).clone()
    }
}

/// Half height of a post capsule's segment: the post reaches the crossbar's centre line.
const POST_TOP: f32 = GOAL_HEIGHT + POST_RADIUS;
/// Net panels' half thickness (m).
const NET_HALF_THICKNESS: f32 = 0.05;

impl PitchColliders {
    /// Builds the ground and both goals.
    pub fn new() -> PitchColliders {
        let mut set = ColliderSet::new();
        // Ground: a thick slab whose top face is z = 0.
        let ground = set.insert(ColliderBuilder::cuboid(80.0, 60.0, 1.0).translation(Vec3::new(0.0, 0.0, -1.0)));
        let mut parts_of: [Vec<(ColliderHandle, Surface)>; 2] = [Vec::new(), Vec::new()];
        for (i, sign) in [-1.0f32, 1.0].into_iter().enumerate() {
            let line_x = sign * HALF_LENGTH;
            let post_y = GOAL_HALF_WIDTH + POST_RADIUS;
            let parts = &mut parts_of[i];
            for y in [-post_y, post_y] {
                let h = set.insert(ColliderBuilder::capsule_z(POST_TOP / 2.0, POST_RADIUS).translation(Vec3::new(
                    line_x,
                    y,
                    POST_TOP / 2.0,
                )));
                parts.push((h, Surface::Post));
            }
            let bar = set
                .insert(ColliderBuilder::capsule_y(post_y, POST_RADIUS).translation(Vec3::new(line_x, 0.0, POST_TOP)));
            parts.push((bar, Surface::Crossbar));
            let mid_x = line_x + sign * GOAL_DEPTH / 2.0;
            let half_h = POST_TOP / 2.0;
            let back = set.insert(ColliderBuilder::cuboid(NET_HALF_THICKNESS, post_y, half_h).translation(Vec3::new(
                line_x + sign * (GOAL_DEPTH + NET_HALF_THICKNESS),
                0.0,
                half_h,
            )));
            parts.push((back, Surface::Net));
            for y in [-(post_y + NET_HALF_THICKNESS), post_y + NET_HALF_THICKNESS] {
                let side = set.insert(
                    ColliderBuilder::cuboid(GOAL_DEPTH / 2.0, NET_HALF_THICKNESS, half_h)
                        .translation(Vec3::new(mid_x, y, half_h)),
                );
                parts.push((side, Surface::Net));
            }
            let roof = set.insert(
                ColliderBuilder::cuboid(GOAL_DEPTH / 2.0, post_y, NET_HALF_THICKNESS).translation(Vec3::new(
                    mid_x,
                    0.0,
                    POST_TOP + NET_HALF_THICKNESS,
                )),
            );
            parts.push((roof, Surface::Net));
        }
        let grow = Vec3::splat(BALL_RADIUS + 0.01);
        let goals = parts_of.map(|parts| {
            parts
                .into_iter()
                .map(|(h, surface)| {
                    let aabb = set[h].compute_aabb();
                    (h, surface, aabb.mins - grow, aabb.maxs + grow)
                })
                .collect()
        });
        PitchColliders { set, ground, goals, ball: BallShape::new(BALL_RADIUS) }
    }

    /// The earliest contact of a ball of radius [`BALL_RADIUS`] moving from `from` with velocity
    /// `velocity` during `dt` seconds, or `None`. Cheap bounding checks run first, so a ball far
    /// from both goals and above the grass costs a few comparisons.
    pub fn sweep(&self, from: Vec3, velocity: Vec3, dt: f32) -> Option<Hit> {
        let to = from + velocity * dt;
        let mut best: Option<Hit> = None;
        if to.z - BALL_RADIUS <= 0.0 && velocity.z < 0.0 {
            best = self.cast(self.ground, Surface::Ground, from, velocity, dt);
        }
        let (lo_x, hi_x) = (from.x.min(to.x) - BALL_RADIUS, from.x.max(to.x) + BALL_RADIUS);
        let (lo_y, hi_y) = (from.y.min(to.y) - BALL_RADIUS, from.y.max(to.y) + BALL_RADIUS);
        let lo_z = from.z.min(to.z) - BALL_RADIUS;
        let reach_y = GOAL_HALF_WIDTH + 2.0 * POST_RADIUS + 2.0 * NET_HALF_THICKNESS;
        if hi_y < -reach_y || lo_y > reach_y || lo_z > POST_TOP + 2.0 * NET_HALF_THICKNESS + POST_RADIUS {
            return best;
        }
        for (i, sign) in [-1.0f32, 1.0].into_iter().enumerate() {
            let near = HALF_LENGTH - POST_RADIUS;
            let far = HALF_LENGTH + GOAL_DEPTH + 2.0 * NET_HALF_THICKNESS;
            let (gx0, gx1) = if sign > 0.0 { (near, far) } else { (-far, -near) };
            if hi_x < gx0 || lo_x > gx1 {
                continue;
            }
            let (lo, hi) = (from.min(to), from.max(to));
            for &(handle, surface, min, max) in &self.goals[i] {
                if hi.cmplt(min).any() || lo.cmpgt(max).any() {
                    continue;
                }
                if let Some(hit) = self.cast(handle, surface, from, velocity, dt)
                    && best.is_none_or(|b| hit.time < b.time)
                {
                    best = Some(hit);
                }
            }
        }
        best
    }

    fn cast(&self, handle: ColliderHandle, surface: Surface, from: Vec3, velocity: Vec3, dt: f32) -> Option<Hit> {
        let collider = self.set.get(handle)?;
        // Already touching (resting against the net, pressed to a post): answer from the closest
        // point, in closed form. parry's cast would fall back to EPA here, which allocates.
        let projection = collider.shape().project_point(collider.position(), from, false);
        let away = from - projection.point;
        if projection.is_inside || away.length_squared() <= (BALL_RADIUS + 1e-4) * (BALL_RADIUS + 1e-4) {
            let normal = if projection.is_inside { -away } else { away }.normalize_or_zero();
            return (normal != Vec3::ZERO).then_some(Hit { time: 0.0, normal, surface });
        }
        let options = ShapeCastOptions {
            max_time_of_impact: dt,
            target_distance: 0.0,
            stop_at_penetration: true,
            compute_impact_geometry_on_penetration: false,
        };
        let hit = cast_shapes(
            &Pose::from_translation(from),
            velocity,
            &self.ball,
            collider.position(),
            Vec3::ZERO,
            collider.shape(),
            options,
        )
        .ok()??;
        // normal1 is the ball's outward normal at the contact; the push-out normal is its opposite.
        let normal = -hit.normal1;
        if !normal.is_finite() || normal.length_squared() < 0.5 {
            return None;
        }
        Some(Hit { time: hit.time_of_impact, normal, surface })
    }
}
