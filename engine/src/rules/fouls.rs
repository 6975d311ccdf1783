//! Law 12, fouls: standing and sliding tackles that hit the player instead of the ball, and the
//! advantage.
//!
//! - **Law**: a direct free kick is awarded when a player trips, charges or tackles an opponent
//!   carelessly, recklessly or with excessive force. The referee may let play go on when that
//!   benefits the fouled team (advantage), and penalises the original offence if the expected
//!   advantage does not follow. Reckless challenges are cautioned, those with excessive force
//!   sent off (see [`super::cards`]).
//! - **When it triggers**: *standing tackle*: an opponent within 0.9 m of the ball carrier wins the
//!   ball with a small chance each tick and trips him with a smaller one, which grows when the
//!   tackler comes from behind and falls with his tackling skill. *Sliding tackle*: the first
//!   contact of a slide with the carrier or his ball is judged by a severity from its timing (ball
//!   first or man first), whether it comes from behind, its speed, the tackler's skill and chance:
//!   above 1.0 a foul, above 1.4 a yellow card, above 2.0 a red card (GRF's thresholds,
//!   docs/grf-compatibility.md#laws).
//! - **Restart**: outside the offender's penalty area the foul waits for the advantage: if the
//!   fouled team still has the ball after 3 s play goes on; if the offenders win it first, or the
//!   fouled team has lost it when the 3 s are up, a direct free kick at the foul's spot (see
//!   [`super::free_kick`]). Inside it, a penalty kick at once (see [`super::penalty_kick`]).
//! - **GRF behaviour**: standing-tackle fouls with advantage (cancelled if the victim's team
//!   keeps possession more than 3 s); sliding severities with the thresholds above; fouls in the
//!   box give penalties (docs/grf-compatibility.md#laws).
//! - **Differences**: our severity formula is our own (GRF's mixes animation timing we do not
//!   have); no advantage inside the penalty area; a goal or the ball going out during the
//!   advantage ends it.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::{Stoppage, cards, free_kick, penalty_kick};
use crate::game::Match;
use crate::geometry::Side;
use crate::player::Player;
use crate::stats::Event;

/// Ticks the referee waits to see whether the advantage comes (3 s, docs/grf-compatibility.md#laws).
pub const ADVANTAGE_TICKS: u16 = 300;
/// Severity above which a challenge is a foul (docs/grf-compatibility.md#laws).
pub const FOUL_SEVERITY: f32 = 1.0;
/// Chance per tick that a standing challenge trips the carrier, for a tackler of no skill from
/// the front (less with skill, twice from behind).
const TRIP_CHANCE: f32 = 0.005;

/// A foul waiting for the advantage to show.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct PendingFoul {
    /// The offender (global index).
    pub(crate) offender: usize,
    /// The fouled team.
    pub(crate) victim: Side,
    /// Where it happened (m).
    pub(crate) spot: Vec2,
    /// Ticks since the foul.
    pub(crate) ticks: u16,
}

/// Whether `tackler` comes at `carrier` from behind (from the half-space behind his facing).
#[inline]
pub fn from_behind(tackler: &Player, carrier: &Player) -> bool {
    (carrier.position - tackler.position).dot(carrier.facing) > 0.25
}

/// Chance this tick that a standing challenge by `tackler` (tackling skill `skill` in [0, 1])
/// trips `carrier`. It grows with the carrier's pace, from none for a carrier standing still to
/// full at a sprint: in GRF 2.10 a trip comes from a collision, and a player's own speed is what
/// most unbalances him in one.
#[inline]
pub fn trip_chance(tackler: &Player, carrier: &Player, skill: f32) -> f32 {
    let pace = (carrier.velocity.length() / crate::player::SPRINT_SPEED).min(1.0);
    TRIP_CHANCE * pace * (1.2 - skill) * if from_behind(tackler, carrier) { 2.0 } else { 1.0 }
}

/// Severity of a trip from a standing challenge; `roll` uniform in [0, 1).
#[inline]
pub fn standing_severity(tackler: &Player, carrier: &Player, roll: f32) -> f32 {
    1.0 + 0.5 * roll * roll + if from_behind(tackler, carrier) { 0.3 } else { 0.0 }
}

/// Severity of a slide by `tackler` meeting `carrier` whose ball is at `ball` (m): low when he
/// reaches the ball before the man from the front, high when he goes through the man from behind
/// at speed. `skill` is his tackling skill in [0, 1], `roll` uniform in [0, 1).
pub fn sliding_severity(tackler: &Player, carrier: &Player, ball: Vec2, skill: f32, roll: f32) -> f32 {
    let to_ball = tackler.position.distance(ball);
    let to_man = tackler.position.distance(carrier.position);
    let ball_first = to_ball + 0.2 < to_man;
    let mut severity = if ball_first { 0.35 } else { 0.95 };
    if from_behind(tackler, carrier) {
        severity += 0.55;
    }
    severity += 0.06 * tackler.velocity.length() - 0.45 * skill + 0.9 * roll * roll;
    severity
}

/// `offender` (global index) fouled the carrier `victim` with `severity` (≥ [`FOUL_SEVERITY`]):
/// records the foul and any card, then either stops play (a penalty kick) or starts waiting for
/// the advantage.
pub(crate) fn commit(m: &mut Match, offender: usize, victim: usize, severity: f32) -> Option<Stoppage> {
    let spot = m.players[victim].position;
    let side = m.players[offender].side;
    let victim_side = side.opponent();
    let penalty = penalty_kick::in_own_area(side, spot);
    m.record(Event::Foul { side, player: m.players[offender].index, penalty });
    cards::judge(m, offender, severity);
    if penalty {
        m.pending_foul = None;
        return Some(Stoppage::Foul {
            restart: penalty_kick::restart(victim_side),
            offender: (side, m.players[offender].index),
        });
    }
    m.pending_foul = Some(PendingFoul { offender, victim: victim_side, spot, ticks: 0 });
    None
}

/// The advantage, once per tick in play: whistles the pending foul when the offenders have won
/// the ball, or when the time is up and the fouled team no longer has it; lets play go on when
/// the fouled team kept it.
pub(crate) fn advantage(m: &mut Match) -> Option<Stoppage> {
    let mut foul = m.pending_foul?;
    foul.ticks += 1;
    let holder = m.owner.or(m.last_touch).map(|g| m.players[g].side);
    let offenders_have_it = m.owner.is_some_and(|g| m.players[g].side != foul.victim);
    if offenders_have_it || (foul.ticks >= ADVANTAGE_TICKS && holder != Some(foul.victim)) {
        m.pending_foul = None;
        let o = &m.players[foul.offender];
        return Some(Stoppage::Foul {
            restart: free_kick::restart(foul.victim, foul.spot),
            offender: (o.side, o.index),
        });
    }
    if foul.ticks >= ADVANTAGE_TICKS {
        m.pending_foul = None;
        m.record(Event::Advantage { side: foul.victim });
        return None;
    }
    m.pending_foul = Some(foul);
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::player::Role;

    fn player(side: Side, x: f32, facing: f32) -> Player {
        let mut p = Player::new(side, 1, Role::CM, Vec2::new(x, 0.0), Vec2::ZERO);
        p.facing = Vec2::new(facing, 0.0);
        p
    }

    #[test]
    fn from_behind_and_man_first_are_worse() {
        // Carrier at 0 facing +x with the ball at 0.5.
        let carrier = player(Side::Left, 0.0, 1.0);
        let mut behind = player(Side::Right, -1.0, 1.0);
        behind.velocity = Vec2::new(7.0, 0.0);
        let mut front = player(Side::Right, 1.4, -1.0);
        front.velocity = Vec2::new(-7.0, 0.0);
        assert!(from_behind(&behind, &carrier) && !from_behind(&front, &carrier));
        let ball = Vec2::new(0.5, 0.0);
        let clean = sliding_severity(&front, &carrier, ball, 0.8, 0.0);
        let reckless = sliding_severity(&behind, &carrier, ball, 0.3, 0.9);
        assert!(clean < FOUL_SEVERITY, "{clean}");
        assert!(reckless > 1.4, "{reckless}");
        // A carrier standing still is not tripped; one on the move is, worse from behind.
        assert_eq!(trip_chance(&behind, &carrier, 0.5), 0.0);
        let mut running = carrier.clone();
        running.velocity = Vec2::new(5.0, 0.0);
        assert!(trip_chance(&behind, &running, 0.5) > trip_chance(&front, &running, 0.5));
        assert!(trip_chance(&front, &running, 0.5) > 0.0);
        assert!(standing_severity(&front, &carrier, 0.0) >= FOUL_SEVERITY);
    }
}
