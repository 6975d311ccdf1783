//! The goalkeeper: stands on the line between ball and goal centre, comes off his line as the
//! ball comes closer, moves across (and dives) to shots heading into goal, rushes out to loose balls
//! he reaches first, and distributes the ball once he holds it.

use glam::Vec2;

use super::{Analysis, Difficulty, MatchView, Plan};
use crate::game::{Kick, KickKind, KickTarget};
use crate::geometry::pitch::{GOAL_HALF_WIDTH, HALF_LENGTH, in_penalty_area};
use crate::player::nearest_distance;

/// Ticks a keeper holds the ball before distributing it.
const HOLD_TICKS: u64 = 60;

/// The plan for goalkeeper `g` (not holding the ball: see [`distribute`]).
pub fn plan(view: &MatchView, g: usize, analysis: &Analysis, _difficulty: &Difficulty) -> Plan {
    let me = &view.players[g];
    let frame = analysis.frame;
    let ball = view.ball.xy();
    let ball_t = frame.vec2(ball);
    let me_t = frame.vec2(me.position);
    let goal_t = Vec2::new(-HALF_LENGTH, 0.0);

    // A ball on its way into the goal: get across to where it crosses the line.
    if view.owner.is_none() {
        for (k, p) in analysis.path.at.iter().enumerate() {
            let p_t = frame.vec2(p.truncate());
            if p_t.x < -HALF_LENGTH + 1.0 {
                if p_t.y.abs() < GOAL_HALF_WIDTH + 1.0 && p.z < 3.0 {
                    let t = 0.1 * (k + 1) as f32;
                    let target_t = Vec2::new(-HALF_LENGTH + 0.8, p_t.y.clamp(-GOAL_HALF_WIDTH, GOAL_HALF_WIDTH));
                    let target = frame.vec2(target_t);
                    let lateral = (target_t - me_t).length();
                    // Too far to step across in time: dive.
                    let slide = lateral > 1.2 && t < 0.6;
                    return Plan { slide, ..Plan::go(target, me.max_speed, ball - me.position) };
                }
                break;
            }
        }
        // A loose ball in the area that he reaches before any opponent: come and claim it.
        if let Some((_, _, meet)) = analysis.chaser {
            let meet_t = frame.vec2(meet);
            let (t_keeper, at) = analysis.path.intercept(me.position, me.max_speed, 2.5);
            if in_penalty_area(meet_t.x, meet_t.y, -1.0) && t_keeper < analysis.opponent_time * 0.9 {
                return Plan::go(at, me.max_speed, ball - me.position);
            }
        }
    }

    // Positioning on the ball–goal line, further out as the ball comes nearer.
    let to_ball = ball_t - goal_t;
    let dist = to_ball.length();
    let depth = (1.0 + 0.08 * dist).clamp(1.0, 5.5).min(dist * 0.5);
    let target_t = goal_t + to_ball.normalize_or(Vec2::X) * depth;
    let target = frame.vec2(target_t);
    let speed = if target.distance(me.position) > 3.0 { me.max_speed } else { 4.0 };
    Plan::go(target, speed, ball - me.position)
}

/// The keeper holds the ball: wait a moment, then play it to the most open team-mate (short if
/// he is close and free, long otherwise).
pub fn distribute(view: &MatchView, g: usize, held_for: u64, analysis: &Analysis) -> Plan {
    let me = &view.players[g];
    let ball = view.ball.xy();
    if held_for < HOLD_TICKS {
        return Plan::go(me.position, 0.0, frame_forward(analysis));
    }
    let opponents = view.team(me.side.opponent());
    let mut best = None;
    let mut best_value = f32::NEG_INFINITY;
    for mate in view.team(me.side) {
        if !mate.active || mate.index == me.index {
            continue;
        }
        let free = nearest_distance(opponents, mate.position);
        let d = mate.position.distance(ball);
        let value = free.min(15.0) - 0.05 * d;
        if value > best_value {
            best_value = value;
            best = Some((mate.position, d));
        }
    }
    match best {
        Some((at, d)) => {
            let kind = if d < 30.0 { KickKind::ShortPass } else { KickKind::HighPass };
            Plan {
                kick: Some(Kick { kind, target: KickTarget::Point(at), height: 0.0, power: 0.5 }),
                ..Plan::go(me.position, 0.0, at - me.position)
            }
        }
        None => {
            let at = ball + frame_forward(analysis) * 40.0;
            Plan {
                kick: Some(Kick { kind: KickKind::HighPass, target: KickTarget::Point(at), height: 0.0, power: 0.5 }),
                ..Plan::go(me.position, 0.0, at - ball)
            }
        }
    }
}

fn frame_forward(analysis: &Analysis) -> Vec2 {
    analysis.frame.vec2(Vec2::X)
}
