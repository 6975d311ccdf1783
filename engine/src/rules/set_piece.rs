//! Shared set-up of a set piece (goal kick, corner kick, throw-in, free kick; penalty kicks have
//! their own in [`super::penalty_kick`]): ball on the spot, the taker at the ball holding it until he plays it, goalkeepers
//! back on their lines (docs/grf-compatibility.md#formations), at a goal kick everyone else at his place in GRF's
//! set-piece shape ([`super::set_piece_places`]; Law 16: the opponents outside the penalty area), at the others the
//! opponents at least 9.15 m away (Laws 13, 15, 17).

use glam::Vec2;

use super::{Restart, set_piece_places};
use crate::game::{GameMode, Match};
use crate::geometry::TeamFrame;
use crate::geometry::pitch::{BALL_RADIUS, CENTRE_CIRCLE_RADIUS, HALF_LENGTH, HALF_WIDTH};
use crate::physics::Ball;

/// Keepers go back to 0.98 of the half length at set pieces (docs/grf-compatibility.md#formations).
const KEEPER_LINE_X: f32 = 0.98 * HALF_LENGTH;

pub(crate) fn set_up(m: &mut Match, restart: Restart) {
    let side = restart.side;
    let range = m.ranges[side.index()].clone();
    let wants_keeper = restart.mode == GameMode::GoalKick;
    let taker = range
        .clone()
        .filter(|&g| m.players[g].active && m.players[g].is_keeper() == wants_keeper)
        .min_by(|&a, &b| {
            let da = m.players[a].position.distance_squared(restart.spot);
            let db = m.players[b].position.distance_squared(restart.spot);
            da.total_cmp(&db)
        })
        .or_else(|| range.clone().find(|&g| m.players[g].active))
        .unwrap_or(range.start);

    // The taker faces into the pitch from behind the ball.
    let inward = match restart.mode {
        GameMode::ThrowIn => Vec2::new(side.attack_sign() * 0.3, -restart.spot.y.signum()).normalize(),
        GameMode::Corner => (-restart.spot).normalize_or(Vec2::X),
        _ => Vec2::new(side.attack_sign(), 0.0),
    };
    for g in 0..m.players.len() {
        let p = &mut m.players[g];
        if !p.active {
            continue;
        }
        p.halt();
        if g == taker {
            p.position = restart.spot - inward * 0.5;
            p.facing = inward;
        } else if p.is_keeper() {
            p.position = Vec2::new(-p.side.attack_sign() * KEEPER_LINE_X, 0.0);
            p.facing = Vec2::new(p.side.attack_sign(), 0.0);
        } else if restart.mode == GameMode::GoalKick {
            // GRF's set-piece preparation: everyone to his formation place in his team's band.
            let frame = TeamFrame::of(p.side);
            p.position = frame.vec2(set_piece_places::goal_kick_place(p.home, p.side == side));
            p.facing = (restart.spot - p.position).normalize_or(Vec2::new(p.side.attack_sign(), 0.0));
        } else if p.side != side {
            let away = p.position - restart.spot;
            if away.length() < CENTRE_CIRCLE_RADIUS {
                let moved = restart.spot + away.normalize_or(inward) * CENTRE_CIRCLE_RADIUS;
                // Stay on the field: near a line the distance is kept along it instead.
                p.position =
                    Vec2::new(moved.x.clamp(-HALF_LENGTH, HALF_LENGTH), moved.y.clamp(-HALF_WIDTH, HALF_WIDTH));
            }
        }
    }
    hand_ball_to(m, taker, restart.spot, restart.mode);
}

/// The referee hands the ball, on the spot `spot` (m), to `taker` for the set piece `mode`: he
/// holds it at his feet until he plays it, and his team has it without having won it (no
/// possession change is counted). Shared with [`super::penalty_kick`].
pub(super) fn hand_ball_to(m: &mut Match, taker: usize, spot: Vec2, mode: GameMode) {
    m.ball = Ball::at_rest(spot);
    m.ball.position.z = BALL_RADIUS;
    m.owner = Some(taker);
    m.carry_distance = 0.5;
    m.last_touch = Some(taker);
    m.possessor = Some(taker);
    m.taker = Some(taker);
    m.mode = mode;
}
