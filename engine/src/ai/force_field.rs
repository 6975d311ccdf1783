//! GRF's force field, the sum behind its players' off-the-ball support runs and its carriers'
//! dribbling: spots that pull or push a player, whose weighted mean direction is where he goes.

use glam::Vec2;

use crate::player::SPRINT_SPEED;

/// A force field being summed at a point (GRF's force-field movement). Each spot pulls or pushes
/// along the unit vector to it, weighted by its power and, for a spot with a reach, by
/// (1 − d/reach)^exp; pulls from within the damping distance are damped by d/damping, so the
/// player does not overshoot what pulls him.
pub(crate) struct ForceField {
    at: Vec2,
    damping: f32,
    sum: Vec2,
    weight: f32,
}

impl ForceField {
    /// An empty field summed at `at` (m), pulls damped within `damping` m.
    pub(crate) fn new(at: Vec2, damping: f32) -> ForceField {
        ForceField { at, damping, sum: Vec2::ZERO, weight: 0.0 }
    }

    /// A pull towards `origin` of `power` whatever the distance.
    pub(crate) fn attract_constant(&mut self, origin: Vec2, power: f32) {
        let to = origin - self.at;
        self.pull(to, to.length(), power);
    }

    /// A pull towards `origin` within `reach` (m), fading linearly to nothing there.
    pub(crate) fn attract(&mut self, origin: Vec2, power: f32, reach: f32) {
        let to = origin - self.at;
        let d = to.length();
        if d < reach {
            self.pull(to, d, power * (1.0 - d / reach));
        }
    }

    /// A push away from `origin` within `reach` (m), `exp` 1, 0.7 or 0.5 (the square root, exact).
    pub(crate) fn repel(&mut self, origin: Vec2, power: f32, reach: f32, exp: f32) {
        let to = origin - self.at;
        let d = to.length();
        if d >= reach || d == 0.0 {
            return;
        }
        let near = 1.0 - d / reach;
        let near = if exp == 1.0 {
            near
        } else if exp == 0.5 {
            near.sqrt()
        } else {
            super::power::pow_unit(near, exp)
        };
        let force = power * near;
        self.sum -= to * (force / d);
        self.weight += force;
    }

    /// A pull along `to` (length `d`), damped within the damping distance.
    fn pull(&mut self, to: Vec2, d: f32, force: f32) {
        if force <= 0.0 || d == 0.0 {
            return;
        }
        let damp = if d < self.damping { d / self.damping } else { 1.0 };
        self.sum += to * (force * damp / d);
        self.weight += force;
    }

    /// The movement the field asks for (m/s): the weighted mean direction at a sprint's length,
    /// shorter as the spots pull different ways; zero with none.
    pub(crate) fn movement(&self) -> Vec2 {
        if self.weight == 0.0 { Vec2::ZERO } else { self.sum / self.weight * SPRINT_SPEED }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pull_and_an_equal_push_cancel() {
        let mut field = ForceField::new(Vec2::ZERO, 7.0);
        field.attract_constant(Vec2::new(20.0, 0.0), 1.0);
        field.repel(Vec2::new(-1.0, 0.0), 1.0, 1e9, 1.0);
        assert!(field.movement().x > 0.0);
        let mut field = ForceField::new(Vec2::ZERO, 7.0);
        field.attract_constant(Vec2::new(20.0, 0.0), 1.0);
        field.repel(Vec2::new(1.0, 0.0), 1.0, 1e9, 1.0);
        assert!(field.movement().length() < 1e-3, "{}", field.movement());
    }
}
