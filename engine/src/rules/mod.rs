//! The referee, one module per law: goals ([`goal`]), the ball leaving the field ([`judge`]) and
//! the restarts that follow ([`kickoff`], [`throw_in`], [`goal_kick`], [`corner_kick`]), offside
//! ([`offside`]), fouls and the advantage ([`fouls`]), cards and sending-offs ([`cards`]), free
//! kicks ([`free_kick`]) and penalty kicks ([`penalty_kick`]). Half-time is
//! [`crate::Match::start_second_half`].

pub mod cards;
pub mod corner_kick;
pub mod fouls;
pub mod free_kick;
pub mod goal;
pub mod goal_kick;
pub mod kickoff;
pub mod offside;
pub mod penalty_kick;
mod set_piece;
mod set_piece_places;
pub mod throw_in;

use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};

use crate::game::{GameMode, Match};
use crate::geometry::Side;
use crate::geometry::pitch::{GOAL_LINE_OUT_X, TOUCH_LINE_OUT_Y};

/// How play restarts: the set piece, the team taking it and where (m, global frame).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Restart {
    /// Kickoff, goal kick, corner kick, throw-in, free kick or penalty kick.
    pub mode: GameMode,
    /// The team that takes it.
    pub side: Side,
    /// Where the ball is placed (m).
    pub spot: Vec2,
}

/// Why play stopped.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum Stoppage {
    /// A goal (Law 10) for `scorer`.
    Goal {
        /// The team credited with the goal.
        scorer: Side,
    },
    /// The ball left the field (Law 9).
    Out {
        /// The restart awarded.
        restart: Restart,
    },
    /// An offside offence (Law 11).
    Offside {
        /// The free kick for the defenders.
        restart: Restart,
        /// The offender (side, index in team).
        offender: (Side, usize),
    },
    /// A foul whistled (Law 12), at once or after the advantage failed.
    Foul {
        /// The free kick or penalty kick for the fouled team.
        restart: Restart,
        /// The offender (side, index in team).
        offender: (Side, usize),
    },
}

/// Judges the ball's move from `before` to `after` (m) this tick: a goal, the ball wholly over a
/// line, or nothing. `last_touch` is the team that touched the ball last.
pub fn judge(before: Vec3, after: Vec3, last_touch: Option<Side>) -> Option<Stoppage> {
    if let Some(scorer) = goal::scored(before, after) {
        return Some(Stoppage::Goal { scorer });
    }
    if after.x.abs() > GOAL_LINE_OUT_X {
        // The side whose goal line the ball crossed defends it.
        let defending = if after.x > 0.0 { Side::Right } else { Side::Left };
        let restart = if last_touch == Some(defending) {
            corner_kick::restart(defending.opponent(), after)
        } else {
            goal_kick::restart(defending)
        };
        return Some(Stoppage::Out { restart });
    }
    if after.y.abs() > TOUCH_LINE_OUT_Y {
        let side = match last_touch {
            Some(s) => s.opponent(),
            // Nobody touched it (a scenario's opening roll): the team whose half it left from.
            None => {
                if after.x < 0.0 {
                    Side::Left
                } else {
                    Side::Right
                }
            }
        };
        return Some(Stoppage::Out { restart: throw_in::restart(side, after) });
    }
    None
}

/// Places players and ball for `restart` once the dead time is over.
pub(crate) fn set_up_restart(m: &mut Match, restart: Restart) {
    match restart.mode {
        GameMode::KickOff => kickoff::set_up(m, restart.side),
        GameMode::Penalty => penalty_kick::set_up(m, restart),
        _ => set_piece::set_up(m, restart),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn out(from: (f32, f32), to: (f32, f32), last: Option<Side>) -> Option<Stoppage> {
        judge(Vec3::new(from.0, from.1, 0.11), Vec3::new(to.0, to.1, 0.11), last)
    }

    #[test]
    fn the_right_restart_for_each_line() {
        let Some(Stoppage::Out { restart }) = out((10.0, 36.1), (10.0, 36.3), Some(Side::Left)) else { panic!() };
        assert_eq!((restart.mode, restart.side), (GameMode::ThrowIn, Side::Right));
        let Some(Stoppage::Out { restart }) = out((55.1, 10.0), (55.3, 10.0), Some(Side::Left)) else { panic!() };
        assert_eq!((restart.mode, restart.side), (GameMode::GoalKick, Side::Right));
        let Some(Stoppage::Out { restart }) = out((55.1, 10.0), (55.3, 10.0), Some(Side::Right)) else { panic!() };
        assert_eq!((restart.mode, restart.side), (GameMode::Corner, Side::Left));
        let Some(Stoppage::Out { restart }) = out((-55.1, -10.0), (-55.3, -10.0), Some(Side::Left)) else { panic!() };
        assert_eq!((restart.mode, restart.side), (GameMode::Corner, Side::Right));
        assert_eq!(restart.spot, Vec2::new(-55.0, -36.0));
        assert_eq!(out((0.0, 0.0), (1.0, 0.0), None), None);
    }

    #[test]
    fn a_ball_between_the_posts_is_a_goal() {
        assert_eq!(out((55.1, 1.0), (55.3, 1.0), Some(Side::Right)), Some(Stoppage::Goal { scorer: Side::Left }));
        assert_eq!(out((-55.1, 1.0), (-55.3, 1.0), Some(Side::Left)), Some(Stoppage::Goal { scorer: Side::Right }));
    }
}
