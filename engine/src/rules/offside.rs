//! Law 11, offside.
//!
//! - **Law**: a player is in an offside position when he is in the opponents' half and nearer to
//!   their goal line than both the ball and the second-last opponent. It is an offence only if he
//!   then becomes involved in play; there is no offside from a throw-in, goal kick or corner kick.
//! - **When it triggers**: at every kick (pass or shot) the referee notes the kicker's team-mates
//!   in an offside position; if one of them is the next player to touch the ball, play stops.
//!   A touch by anyone else (an opponent, an onside team-mate) clears the note. Only when the
//!   scenario's `offsides` is true, and not when the defending team has one active player or none.
//! - **Restart**: an indirect free kick for the defenders where the offender touched the ball
//!   (see [`super::free_kick`]).
//! - **GRF behaviour**: the same: "at every ball touch the referee records attackers beyond the
//!   defending offside line (excluding the toucher); if one of them is the next player to touch the
//!   ball → free kick for the defenders at the offender's position" (docs/grf-compatibility.md#laws).
//! - **Differences**: positions are judged at the players' centres (GRF does the same); a save or
//!   a deflection by a defender clears the note (the Law keeps the offence alive after a
//!   deflection or save); every free kick may be scored directly.

use glam::Vec2;

use crate::game::Match;
use crate::geometry::Side;
use crate::player::Player;

/// The offside line (team frame of the attackers, m along their attack) for attackers facing
/// `defenders`, with the ball at `ball_x` (same frame): the second-last active defender, the ball
/// or the halfway line, whichever is furthest forward. `None` when the defenders have one active
/// player or none (no offside then, docs/grf-compatibility.md#laws).
pub fn line(defenders: &[Player], attack_sign: f32, ball_x: f32) -> Option<f32> {
    let (mut last, mut second) = (f32::NEG_INFINITY, f32::NEG_INFINITY);
    let mut active = 0;
    for d in defenders.iter().filter(|d| d.active) {
        active += 1;
        let x = d.position.x * attack_sign;
        if x > last {
            second = last;
            last = x;
        } else if x > second {
            second = x;
        }
    }
    (active > 1).then(|| second.max(ball_x).max(0.0))
}

/// Whether `p` (an attacker) stands beyond `line` (his team frame).
#[inline]
pub fn beyond(p: &Player, line: f32) -> bool {
    p.position.x * p.side.attack_sign() > line
}

/// Bit i set for player i of `side` who is in an offside position as `kicker` (global index)
/// plays the ball at `ball` (m).
pub(crate) fn positions(m: &Match, side: Side, kicker: usize, ball: Vec2) -> u16 {
    let sign = side.attack_sign();
    let Some(line) = line(m.team(side.opponent()), sign, ball.x * sign) else { return 0 };
    let mut mask = 0u16;
    for g in m.ranges[side.index()].clone() {
        let p = &m.players[g];
        if g != kicker && p.active && beyond(p, line) {
            mask |= 1 << p.index;
        }
    }
    mask
}

/// Whether the touch of the ball by `g` (global index) is an offside offence; clears the note
/// whenever anyone touches the ball.
pub(crate) fn judge_touch(m: &mut Match, g: usize) -> bool {
    let p = &m.players[g];
    let offence = m.offside_watch.side == Some(p.side) && m.offside_watch.mask & (1 << p.index) != 0;
    m.offside_watch = Watch::default();
    offence
}

/// The players noted in an offside position at the last kick.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub(crate) struct Watch {
    /// The kicking team.
    pub(crate) side: Option<Side>,
    /// Bit i: player i of that team was in an offside position.
    pub(crate) mask: u16,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::player::Role;

    fn at(side: Side, x: f32) -> Player {
        Player::new(side, 0, Role::CB, Vec2::new(x, 0.0), Vec2::ZERO)
    }

    #[test]
    fn the_line_is_the_second_last_defender_the_ball_or_halfway() {
        // Right team defends +x: keeper at 54, defender at 20.
        let defenders = [at(Side::Right, 54.0), at(Side::Right, 20.0), at(Side::Right, 10.0)];
        assert_eq!(line(&defenders, 1.0, 5.0), Some(20.0));
        assert_eq!(line(&defenders, 1.0, 30.0), Some(30.0));
        let deep = [at(Side::Right, 54.0), at(Side::Right, -20.0)];
        assert_eq!(line(&deep, 1.0, -30.0), Some(0.0), "never offside in one's own half");
        assert_eq!(line(&defenders[..1], 1.0, 0.0), None, "one defender: no offside");
        // Seen from the right team attacking -x.
        let left = [at(Side::Left, -54.0), at(Side::Left, -30.0)];
        assert_eq!(line(&left, -1.0, 0.0), Some(30.0));
    }
}
