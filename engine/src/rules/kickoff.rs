//! Law 8, the start and restart of play: the kickoff.
//!
//! - **Law**: a kickoff starts each half and restarts play after a goal; the team that conceded
//!   kicks off. Every player is in his own half; opponents of the kicking team stay outside the
//!   centre circle until the ball is in play.
//! - **When it triggers**: after a goal's dead time (the initial kickoff is the scenario's start).
//! - **Restart**: every player back to his formation place (clamped into his own half), the ball
//!   on the centre spot. If the conceding team is not the one with a player nearest the ball and
//!   both teams have as many players, the two teams exchange formations, so the kickoff formation
//!   goes to the conceding team (docs/grf-compatibility.md#scenario-semantics). Play is on at once: the
//!   kickoff counts as taken on the first tick, so game mode 1 is not seen by agents
//!   (docs/grf-compatibility.md#game-modes).
//! - **GRF behaviour**: as above.
//! - **Differences**: opponents of the kicking team are moved out of the centre circle (Law 8);
//!   GRF leaves the receiving formation's forward 2.75 m from the ball.

use glam::Vec2;

use super::Restart;
use crate::game::{GameMode, Match};
use crate::geometry::coords::formation_to_world;
use crate::geometry::pitch::CENTRE_CIRCLE_RADIUS;
use crate::geometry::{Side, TeamFrame};

/// The kickoff after `scorer` scored: the other team kicks off from the centre spot.
pub fn after_goal(scorer: Side) -> Restart {
    Restart { mode: GameMode::KickOff, side: scorer.opponent(), spot: Vec2::ZERO }
}

/// Closest distance (m) of a formation's players to the centre spot.
fn nearest_to_centre(m: &Match, side: Side) -> f32 {
    m.formations[side.index()]
        .iter()
        .map(|&[x, y]| formation_to_world(side, x, y).length())
        .fold(f32::INFINITY, f32::min)
}

/// Places both teams for a kickoff by `kicking`.
pub(crate) fn set_up(m: &mut Match, kicking: Side) {
    let other = kicking.opponent();
    let equal = m.formations[0].len() == m.formations[1].len();
    if equal && nearest_to_centre(m, other) < nearest_to_centre(m, kicking) {
        // Exchange places (not roles or flags): slot i of each team takes the other's place i.
        let (left, right) = m.formations.split_at_mut(1);
        for (a, b) in left[0].iter_mut().zip(right[0].iter_mut()) {
            std::mem::swap(a, b);
        }
    }
    for g in 0..m.players.len() {
        if !m.players[g].active {
            // Sent off: stays off the field.
            continue;
        }
        let side = m.players[g].side;
        let [ex, ey] = m.formations[side.index()][m.players[g].index];
        let mut at = formation_to_world(side, ex.min(0.0), ey);
        if side == other && at.length() < CENTRE_CIRCLE_RADIUS {
            at = at.normalize_or(Vec2::new(-side.attack_sign(), 0.0)) * CENTRE_CIRCLE_RADIUS;
            if at.x * side.attack_sign() > 0.0 {
                at.x = 0.0;
                at.y = CENTRE_CIRCLE_RADIUS.copysign(ey);
            }
        }
        let p = &mut m.players[g];
        p.halt();
        p.position = at;
        p.home = TeamFrame::of(side).vec2(formation_to_world(side, ex, ey));
        p.facing = Vec2::new(side.attack_sign(), 0.0);
    }
    for side in Side::BOTH {
        let range = m.ranges[side.index()].clone();
        crate::ai::team_shape::assign_formation(&mut m.players[range], TeamFrame::of(side));
    }
    m.ball = crate::physics::Ball::at_rest(Vec2::ZERO);
    m.owner = None;
    // Nobody has the ball at a kickoff: the first trap wins no possession.
    m.possessor = None;
    m.taker = None;
    m.mode = GameMode::Normal;
}
