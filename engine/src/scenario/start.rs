//! How an episode begins beyond where everyone stands: from a restart as the laws set it up
//! (`.tl`: `start with penalty_kick for left`) and which way each player faces
//! (`.tl`: `CB at (…) facing ball`).

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::game::GameMode;
use crate::geometry::Side;
use crate::geometry::coords::ball_start_to_world;
use crate::rules::{self, Restart};

/// The restart every episode starts from: after the players are placed, the referee sets it up
/// exactly as he would during a match (the engine's own restart code: the taker at the ball,
/// keepers on their lines, opponents 9.15 m away, and for a penalty kick everyone else outside
/// the area and behind the ball), and the game mode is the restart's until the taker plays the
/// ball.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StartRestart {
    /// The restart, by GRF's game mode: `KickOff`, `GoalKick`, `FreeKick`, `Corner`, `ThrowIn` or
    /// `Penalty` (`Normal` is refused by [`super::Scenario::validate`]).
    pub mode: GameMode,
    /// The team that takes it.
    pub team: Side,
    /// Where, in the global frame, normalised units (the ball's frame), for the restarts that
    /// need it: a free kick is taken from this point (clamped into ±0.95 of the half length and
    /// width, as the engine clamps every free kick), a throw-in from the touchline nearest it at its
    /// x (clamped to ±54.4 m), a corner kick from the corner flag on its side of the pitch (the sign
    /// of y). Kickoffs, goal kicks and penalty kicks have fixed spots and leave it out.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at: Option<[f32; 2]>,
}

impl StartRestart {
    /// Whether this restart needs an `at` point.
    pub fn needs_point(mode: GameMode) -> bool {
        matches!(mode, GameMode::FreeKick | GameMode::Corner | GameMode::ThrowIn)
    }

    /// Checks what [`StartRestart::restart`] relies on.
    pub(crate) fn check(&self) -> Result<(), String> {
        let name = self.mode.name();
        if self.mode == GameMode::Normal {
            return Err("an episode cannot start with the restart `Normal`: it is open play".into());
        }
        match (Self::needs_point(self.mode), self.at) {
            (true, None) => Err(format!("a {name} start needs the point it is taken from (`at`)")),
            (false, Some(_)) => Err(format!("a {name} start has a fixed spot and takes no point (`at`)")),
            (true, Some([x, y])) if !super::on_pitch(x, y) => {
                Err(format!("the {name} point ({x}, {y}) is off the pitch"))
            }
            (true, Some([_, y])) if y == 0.0 && self.mode != GameMode::FreeKick => {
                Err(format!("a {name} point on the pitch's long axis (y = 0) names neither touchline"))
            }
            _ => Ok(()),
        }
    }

    /// The restart in the engine's terms: mode, taking team and the ball's spot (m, global
    /// frame), from the same functions the referee uses during a match.
    pub fn restart(&self) -> Restart {
        let at = self.at.map_or(Vec2::ZERO, |[x, y]| ball_start_to_world(x, y));
        match self.mode {
            GameMode::GoalKick => rules::goal_kick::restart(self.team),
            GameMode::FreeKick => rules::free_kick::restart(self.team, at),
            GameMode::Corner => rules::corner_kick::restart(self.team, Vec3::new(0.0, at.y, 0.0)),
            GameMode::ThrowIn => rules::throw_in::restart(self.team, at.extend(0.0)),
            GameMode::Penalty => rules::penalty_kick::restart(self.team),
            GameMode::KickOff | GameMode::Normal => {
                Restart { mode: GameMode::KickOff, side: self.team, spot: Vec2::ZERO }
            }
        }
    }
}

/// Which way a player faces at the start of an episode (before anyone moves). Without one he
/// faces the goal he attacks, as every player always has.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Facing {
    /// Towards where the ball starts.
    Ball,
    /// Towards the centre of the goal he attacks.
    Goal,
    /// Along `[dx, dy]` in his team's own frame (dx > 0: towards the goal he attacks), any
    /// non-zero length; normalised when applied.
    Direction([f32; 2]),
}

impl Facing {
    /// Checks that a direction is finite and not zero.
    pub(crate) fn check(&self) -> Result<(), String> {
        match *self {
            Facing::Direction([dx, dy]) if !(dx.is_finite() && dy.is_finite()) || (dx == 0.0 && dy == 0.0) => {
                Err(format!("facing direction ({dx}, {dy}) must be finite and not zero"))
            }
            _ => Ok(()),
        }
    }

    /// The unit vector (global frame) a player of `side` standing at `position` (m) faces, the
    /// ball starting at `ball` (m). A point on top of him keeps `fallback`.
    pub(crate) fn direction(&self, side: Side, position: Vec2, ball: Vec2, fallback: Vec2) -> Vec2 {
        let frame = crate::geometry::TeamFrame::of(side);
        let towards = match *self {
            Facing::Ball => ball - position,
            Facing::Goal => Vec2::new(side.attack_sign() * crate::geometry::pitch::HALF_LENGTH, 0.0) - position,
            Facing::Direction([dx, dy]) => frame.vec2(Vec2::new(dx, dy)),
        };
        towards.try_normalize().unwrap_or(fallback)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_restart_comes_from_the_referees_own_code() {
        let pen = StartRestart { mode: GameMode::Penalty, team: Side::Right, at: None };
        assert_eq!(pen.restart(), rules::penalty_kick::restart(Side::Right));
        let corner = StartRestart { mode: GameMode::Corner, team: Side::Left, at: Some([1.0, -0.42]) };
        assert_eq!(corner.restart().spot, Vec2::new(55.0, -36.0));
        let throw = StartRestart { mode: GameMode::ThrowIn, team: Side::Left, at: Some([0.5, 0.3]) };
        assert_eq!(throw.restart().spot, Vec2::new(0.5 * 54.4, 36.0));
        assert!(StartRestart { mode: GameMode::Normal, ..pen }.check().is_err());
        assert!(StartRestart { at: Some([0.5, 0.0]), ..throw }.check().is_err());
        assert!(StartRestart { at: None, ..corner }.check().is_err());
        assert!(StartRestart { at: Some([0.5, 0.1]), ..pen }.check().is_err());
    }

    #[test]
    fn facing_reads_the_players_own_frame() {
        let right = Facing::Direction([1.0, 0.0]).direction(Side::Right, Vec2::ZERO, Vec2::ZERO, Vec2::Y);
        assert_eq!(right, Vec2::new(-1.0, 0.0));
        let ball = Facing::Ball.direction(Side::Left, Vec2::ZERO, Vec2::new(0.0, 5.0), Vec2::X);
        assert_eq!(ball, Vec2::Y);
        assert_eq!(Facing::Ball.direction(Side::Left, Vec2::ONE, Vec2::ONE, Vec2::X), Vec2::X);
        assert!(Facing::Direction([0.0, 0.0]).check().is_err());
    }
}
