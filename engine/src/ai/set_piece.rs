//! Set pieces: the taker waits a moment and then plays the ball (short throw-ins, crosses into the
//! box from corners, goal kicks like a keeper's distribution, shots from penalty kicks and from
//! free kicks within range, passes from other free kicks); the others take up their places.

use glam::Vec2;

use super::{Analysis, Difficulty, MatchView, Plan, goalkeeper, team_shape};
use crate::game::{GameMode, Kick, KickKind, KickTarget};
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};
use crate::player::{WALK_SPEED, nearest_distance};
use crate::rng::MatchRng;

/// Plan for player `g` while a set piece is pending.
pub(crate) fn plan(
    view: &MatchView,
    g: usize,
    analysis: &Analysis,
    difficulty: &Difficulty,
    rng: &mut MatchRng,
) -> Plan {
    let me = &view.players[g];
    let ball = view.ball.xy();
    if view.taker == Some(g) {
        let wait = 50 + (30.0 * (1.0 - difficulty.theta)) as u32;
        if view.set_piece_ticks < wait {
            return Plan::go(me.position, 0.0, analysis.frame.vec2(Vec2::X));
        }
        return take(view, g, analysis, rng);
    }
    if me.is_keeper() {
        return goalkeeper::plan(view, g, analysis, difficulty);
    }
    let mut target = team_shape::position(view, g, analysis, difficulty, false);
    let ours = view.taker.is_some_and(|t| view.players[t].side == me.side);
    if ours && view.mode == GameMode::Corner && (me.role.is_attacker() || me.role == crate::player::Role::CB) {
        // Attack the cross: spread across the six-yard box and the penalty spot.
        let y = (me.index as f32 * 2.3) % 12.0 - 6.0;
        target = analysis.frame.vec2(Vec2::new(HALF_LENGTH - 9.0, y));
    }
    let d = target.distance(me.position);
    Plan::go(target, if d > 8.0 { me.max_speed * 0.9 } else { WALK_SPEED }, ball - me.position)
}

fn take(view: &MatchView, g: usize, analysis: &Analysis, rng: &mut MatchRng) -> Plan {
    let me = &view.players[g];
    let frame = analysis.frame;
    let me_t = frame.vec2(me.position);
    let shooting_range = me_t.distance(Vec2::new(HALF_LENGTH, 0.0)) < 27.0 && me_t.y.abs() < 16.0;
    match view.mode {
        GameMode::GoalKick => goalkeeper::distribute(view, g, u64::MAX, analysis),
        GameMode::Penalty => {
            // Side netting, left or right at random, a little height.
            let y = if rng.unit() < 0.5 { -2.6 } else { 2.6 };
            let aim = frame.vec2(Vec2::new(HALF_LENGTH, y + rng.noise(0.6)));
            shot(me.position, aim, 0.8)
        }
        GameMode::FreeKick if shooting_range => {
            let y = if me_t.y > 0.0 { -2.4 } else { 2.4 };
            let aim = frame.vec2(Vec2::new(HALF_LENGTH, y + rng.noise(1.0)));
            shot(me.position, aim, 1.6)
        }
        GameMode::Corner => {
            let aim = frame.vec2(Vec2::new(HALF_LENGTH - 8.0 + rng.noise(2.0), rng.noise(5.0)));
            let receiver = view
                .team(me.side)
                .iter()
                .filter(|m| m.active && m.index != me.index && !m.is_keeper())
                .min_by(|a, b| a.position.distance_squared(aim).total_cmp(&b.position.distance_squared(aim)))
                .map_or(aim, |m| m.position);
            kick(me.position, KickKind::HighPass, receiver)
        }
        _ => {
            let opponents = view.team(me.side.opponent());
            let best = view
                .team(me.side)
                .iter()
                .filter(|m| m.active && m.index != me.index && !m.is_keeper())
                .map(|m| {
                    let free = nearest_distance(opponents, m.position);
                    let d = m.position.distance(me.position);
                    (m.position, free.min(10.0) - 0.15 * d)
                })
                .max_by(|a, b| a.1.total_cmp(&b.1));
            let mut target = best.map_or(me.position + frame.vec2(Vec2::new(15.0, 0.0)), |b| b.0);
            if view.mode == GameMode::ThrowIn {
                // Well into the field: a throw along the line goes straight out again.
                target.y = target.y.clamp(-HALF_WIDTH + 6.0, HALF_WIDTH - 6.0);
            }
            kick(me.position, KickKind::ShortPass, target)
        }
    }
}

fn shot(from: Vec2, aim: Vec2, height: f32) -> Plan {
    Plan {
        kick: Some(Kick { kind: KickKind::Shot, target: KickTarget::Point(aim), height, power: 0.7 }),
        ..Plan::go(from, 0.0, aim - from)
    }
}

fn kick(from: Vec2, kind: KickKind, target: Vec2) -> Plan {
    Plan {
        kick: Some(Kick { kind, target: KickTarget::Point(target), height: 0.0, power: 0.5 }),
        ..Plan::go(from, 0.0, target - from)
    }
}
