//! The only converter between engine metres and GRF's normalised coordinates, and between the
//! global frame and a team's own frame (docs/grf-compatibility.md#scenario-semantics, #coordinates).

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

/// Metres per normalised x unit in observations (GRF: world x / 54.4).
pub const OBS_X_SCALE: f32 = 54.4;
/// Metres per normalised y unit in observations (GRF: world y / 83.6; anisotropic on purpose).
pub const OBS_Y_SCALE: f32 = 83.6;
/// Metres per normalised x unit when a scenario places a player (GRF places at 55·x).
pub const FORMATION_X_SCALE: f32 = 55.0;
/// Metres per normalised y unit when a scenario places a player (GRF: 2.36 · 36 · y = 84.96·y).
pub const FORMATION_Y_SCALE: f32 = 2.36 * 36.0;

/// Where the pitch's lines lie in a scenario's normalised units, `[x, y]`: the goal lines at
/// |x| = 1, the touchlines at |y| = 0.42 (GRF's scenario frame: the pitch's 68 m are 0.84 units).
pub const SCENARIO_LINES: [f32; 2] = [1.0, 0.42];
/// The rim in the same units, `[x, y]`: the farthest a scenario may place a player or the ball,
/// or a behaviour's point may lie, |x| ≤ 1.1 and |y| ≤ 0.48 (GRF's simulated area reaches 60 m
/// along and 40 m across from the centre spot).
pub const SCENARIO_RIM: [f32; 2] = [1.1, 0.48];

/// A side of the match. Left = team 0 (defends x = -1), right = team 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Side {
    /// Team 0, defending the goal at x = -55 m.
    Left = 0,
    /// Team 1, defending the goal at x = +55 m.
    Right = 1,
}

impl Side {
    /// Both sides, left first.
    pub const BOTH: [Side; 2] = [Side::Left, Side::Right];

    /// Index 0 or 1.
    #[inline]
    pub fn index(self) -> usize {
        self as usize
    }

    /// The other side.
    #[inline]
    pub fn opponent(self) -> Side {
        match self {
            Side::Left => Side::Right,
            Side::Right => Side::Left,
        }
    }

    /// +1 for the left team (attacks +x), -1 for the right team.
    #[inline]
    pub fn attack_sign(self) -> f32 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }

    /// `"left"` or `"right"`.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }

    /// Side from index 0 / 1.
    #[inline]
    pub fn from_index(i: usize) -> Side {
        if i == 0 { Side::Left } else { Side::Right }
    }
}

/// A team's own frame: the global frame rotated 180° for the right team, so that every team
/// attacks towards +x. Converting twice is the identity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TeamFrame {
    sign: f32,
}

impl TeamFrame {
    /// The frame of `side`.
    #[inline]
    pub fn of(side: Side) -> TeamFrame {
        TeamFrame { sign: side.attack_sign() }
    }

    /// Global → team frame (and back: the map is its own inverse).
    #[inline]
    pub fn vec2(self, v: Vec2) -> Vec2 {
        v * self.sign
    }

    /// Same as [`TeamFrame::vec2`] for a 3D vector; z is unchanged.
    #[inline]
    pub fn vec3(self, v: Vec3) -> Vec3 {
        Vec3::new(v.x * self.sign, v.y * self.sign, v.z)
    }
}

/// A player's starting position in metres (global frame) from a scenario entry given in its
/// team's own frame (GRF: 55·x, 84.96·y, mirrored for the right team).
#[inline]
pub fn formation_to_world(side: Side, x: f32, y: f32) -> Vec2 {
    TeamFrame::of(side).vec2(Vec2::new(x * FORMATION_X_SCALE, y * FORMATION_Y_SCALE))
}

/// The ball's starting position in metres from normalised global coordinates (54.4·x, 83.6·y).
#[inline]
pub fn ball_start_to_world(x: f32, y: f32) -> Vec2 {
    Vec2::new(x * OBS_X_SCALE, y * OBS_Y_SCALE)
}

/// A point (m) in observation units; z stays in metres (as GRF).
#[inline]
pub fn world_to_obs(p: Vec2) -> [f32; 2] {
    [p.x / OBS_X_SCALE, p.y / OBS_Y_SCALE]
}

/// A normalised observation point back to metres.
#[inline]
pub fn obs_to_world(x: f32, y: f32) -> Vec2 {
    Vec2::new(x * OBS_X_SCALE, y * OBS_Y_SCALE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reset_positions_match_grf_observations() {
        // docs/grf-compatibility.md#scenario-players: academy_corner left LB (1, 0.42) is observed at (1.0110, 0.4268).
        let p = world_to_obs(formation_to_world(Side::Left, 1.0, 0.42));
        assert!((p[0] - 1.0110).abs() < 1e-4 && (p[1] - 0.4268).abs() < 1e-4);
        // Right CB at (-0.75, 0.1) in its own frame is observed at (0.7583, -0.1016).
        let p = world_to_obs(formation_to_world(Side::Right, -0.75, 0.1));
        assert!((p[0] - 0.7583).abs() < 1e-4 && (p[1] + 0.1016).abs() < 1e-4);
        // The ball is observed exactly where the scenario puts it.
        let b = world_to_obs(ball_start_to_world(0.77, -0.28));
        assert!((b[0] - 0.77).abs() < 1e-6 && (b[1] + 0.28).abs() < 1e-6);
    }

    #[test]
    fn team_frame_is_an_involution() {
        let f = TeamFrame::of(Side::Right);
        let v = Vec2::new(3.0, -7.5);
        assert_eq!(f.vec2(f.vec2(v)), v);
        assert_eq!(TeamFrame::of(Side::Left).vec2(v), v);
    }
}
