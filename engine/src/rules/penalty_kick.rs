//! Law 14, the penalty kick.
//!
//! - **Law**: a penalty kick is awarded when a player commits a direct-free-kick offence inside
//!   his own penalty area. The ball is on the penalty mark, the defending keeper on his goal line,
//!   every other player outside the penalty area, behind the ball and at least 9.15 m from the
//!   mark.
//! - **When it triggers**: a foul (see [`super::fouls`]) whose spot lies in the offender's own
//!   penalty area (16.5 m deep, |y| < 20.15 − 0.06 m, docs/grf-compatibility.md#laws).
//! - **Restart**: ball on the mark, 11 m from the goal line (±44 m,
//!   docs/grf-compatibility.md#pitch-geometry); the fouled team's outfield player nearest the mark takes it;
//!   game mode 6 until he plays the ball.
//! - **GRF behaviour**: the same mark and mode (GRF's `tests/penalty` expects the ball at
//!   x ≈ −0.809); keepers back to their lines.
//! - **Differences**: the defending keeper stands 1.1 m in front of his line (where GRF puts keepers
//!   at every set piece); no penalty shoot-outs (GRF has none either).

use glam::Vec2;

use super::Restart;
use crate::game::{GameMode, Match};
use crate::geometry::pitch::{
    CENTRE_CIRCLE_RADIUS, HALF_LENGTH, LINE_HALF_WIDTH, PENALTY_AREA_DEPTH, PENALTY_AREA_HALF_WIDTH,
    PENALTY_MARK_DISTANCE,
};
use crate::geometry::{Side, TeamFrame};

/// Keepers' depth at set pieces (docs/grf-compatibility.md#formations).
const KEEPER_LINE_X: f32 = 0.98 * HALF_LENGTH;

/// Whether a foul at `at` (m) by a player of `offender` is inside his own penalty area.
pub fn in_own_area(offender: Side, at: Vec2) -> bool {
    let from_line = HALF_LENGTH + at.x * offender.attack_sign();
    (0.0..=PENALTY_AREA_DEPTH).contains(&from_line) && at.y.abs() < PENALTY_AREA_HALF_WIDTH - LINE_HALF_WIDTH
}

/// The penalty kick for `side` (attacking the goal at `side.attack_sign()` · 55 m).
pub fn restart(side: Side) -> Restart {
    let spot = Vec2::new(side.attack_sign() * (HALF_LENGTH - PENALTY_MARK_DISTANCE), 0.0);
    Restart { mode: GameMode::Penalty, side, spot }
}

/// Places everyone for `restart` (a penalty kick).
pub(crate) fn set_up(m: &mut Match, restart: Restart) {
    let side = restart.side;
    let frame = TeamFrame::of(side);
    let range = m.ranges[side.index()].clone();
    let taker = range
        .clone()
        .filter(|&g| m.players[g].active && !m.players[g].is_keeper())
        .min_by(|&a, &b| {
            let da = m.players[a].position.distance_squared(restart.spot);
            let db = m.players[b].position.distance_squared(restart.spot);
            da.total_cmp(&db)
        })
        .or_else(|| range.clone().find(|&g| m.players[g].active))
        .unwrap_or(range.start);
    let mark_t = frame.vec2(restart.spot).x;
    let area_edge_t = HALF_LENGTH - PENALTY_AREA_DEPTH - 0.5;
    for g in 0..m.players.len() {
        let p = &mut m.players[g];
        if !p.active {
            continue;
        }
        p.halt();
        if g == taker {
            p.position = restart.spot - frame.vec2(Vec2::X) * 0.5;
            p.facing = frame.vec2(Vec2::X);
        } else if p.is_keeper() {
            p.position = Vec2::new(-p.side.attack_sign() * KEEPER_LINE_X, 0.0);
            p.facing = Vec2::new(p.side.attack_sign(), 0.0);
        } else {
            // Outside the area, behind the ball and outside the penalty arc.
            let mut at = frame.vec2(p.position);
            at.x = at.x.min(area_edge_t);
            let dy = at.y.abs();
            if dy < CENTRE_CIRCLE_RADIUS {
                let arc = mark_t - (CENTRE_CIRCLE_RADIUS * CENTRE_CIRCLE_RADIUS - dy * dy).sqrt() - 0.3;
                at.x = at.x.min(arc);
            }
            p.position = frame.vec2(at);
        }
    }
    super::set_piece::hand_ball_to(m, taker, restart.spot, GameMode::Penalty);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_area_is_the_offenders_own() {
        assert!(in_own_area(Side::Left, Vec2::new(-45.0, 5.0)));
        assert!(!in_own_area(Side::Right, Vec2::new(-45.0, 5.0)));
        assert!(in_own_area(Side::Right, Vec2::new(40.0, -20.0)));
        assert!(!in_own_area(Side::Right, Vec2::new(38.0, 0.0)));
        assert_eq!(restart(Side::Right).spot, Vec2::new(-44.0, 0.0));
    }
}
