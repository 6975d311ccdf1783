//! The goalkeeper (GRF 2.10's keeper, docs/grf-compatibility.md#team-ai): with the ball in his
//! half he stands on the line between ball and goal centre and comes off it as the ball comes
//! closer; with the ball in the other half he waits 10 m out. He moves across (and dives) to
//! shots heading into goal, rushes out at a carrier nobody covers, goes for loose balls he
//! reaches clearly first, and distributes the ball once he holds it.

use glam::Vec2;

use super::prediction::SAMPLE_DT;
use super::{Analysis, Difficulty, MatchView, Plan};
use crate::game::{Kick, KickKind, KickTarget};
use crate::geometry::pitch::{GOAL_HALF_WIDTH, HALF_LENGTH, in_penalty_area};
use crate::player::nearest_distance;

/// Ticks a keeper holds the ball before distributing it.
const HOLD_TICKS: u64 = 60;
/// After this many ticks holding it he plays it even to a marked team-mate (GRF: 4 s).
const HOLD_LIMIT_TICKS: u64 = 400;
/// A team-mate with no opponent this near (m) is free to receive the keeper's ball (GRF: 10 m).
const FREE_OF: f32 = 10.0;
/// How far in front of his goal line the keeper stands (m), GRF's 0.7 m.
const KEEPER_LINE: f32 = 0.7;
/// With his team on the ball, the share of the way out to it the keeper stands (GRF: 0.3).
const OUT_IN_POSSESSION: f32 = 0.3;
/// A carrier's shooting point lies this far from goal on his line to it (m), GRF's 20 m.
const SHOOTING_DISTANCE: f32 = 20.0;
/// A team-mate this near the carrier (m) is on him: the keeper leaves the carrier to him. GRF's
/// keepers do not come out for a carrier with defenders at his back (measured: an idle carrier at
/// the centre spot with five defenders round him keeps the ball from the keeper for 400 steps in
/// 94 % of academy_run_to_score_with_keeper episodes).
const ENGAGED: f32 = 10.0;
/// A rushing keeper goes for the spot this far short of the ball (m), on its goal side.
const RUSH_SHORT_OF_BALL: f32 = 0.5;
/// How far in front of his goal line (m) the keeper waits while the ball is in the other half
/// (GRF 2.10's keeper line distance).
const OTHER_HALF_LINE: f32 = 10.0;
/// Where the keeper looks for the ball to judge which half it is in: this far ahead on its path
/// (s), plus [`LOOK_AHEAD_PER_REACH`] of his own time to reach it (GRF 2.10's keeper).
const LOOK_AHEAD: f32 = 0.6;
const LOOK_AHEAD_PER_REACH: f32 = 0.2;
/// GRF 2.10's designation margins, which stand in for its memory of who was sent: the keeper goes
/// for a loose ball outside his area only when (his time + 0.01 s) is under 0.85 × (the quickest
/// opponent's + 0.01 s) (the match's designated player, GRF's 10 ms and 15 %) and (his time +
/// 0.5 s) is under 0.8 × (his quickest team-mate's + 0.5 s) (the team's).
const MATCH_MARGIN: (f32, f32) = (0.01, 0.85);
const TEAM_MARGIN: (f32, f32) = (0.5, 0.8);
/// A keeper not sent for a loose ball in the other half stops when he and an opponent would both
/// meet it sooner than this (s): GRF's AI plays a ball it needs under a second to reach.
const NOT_SENT_WAITS: f32 = 1.0;
/// A keeper with nobody to give the ball to clears it this far along his facing (m): GRF's high
/// pass at input power 0.5.
const CLEARANCE: f32 = 30.0;

/// The plan for goalkeeper `g` (not holding the ball: see [`distribute`]).
pub fn plan(view: &MatchView, g: usize, analysis: &Analysis, _difficulty: &Difficulty) -> Plan {
    let me = &view.players[g];
    let frame = analysis.frame;
    let ball = view.ball.xy();
    let ball_t = frame.vec2(ball);
    let me_t = frame.vec2(me.position);
    let goal_t = Vec2::new(-HALF_LENGTH, 0.0);
    // When and where he can meet the ball, as the team AI reckons its outfield players' times.
    let (t_keeper, meet) = analysis.path.intercept(me.position, me.max_speed * 0.9, 1.0);

    // A ball on its way into the goal: get across to where it crosses the line.
    if view.owner.is_none() {
        if let Some((t, crossing_t)) = into_goal(analysis) {
            let target_t = Vec2::new(-HALF_LENGTH + 0.8, crossing_t.y.clamp(-GOAL_HALF_WIDTH, GOAL_HALF_WIDTH));
            let target = frame.vec2(target_t);
            let lateral = (target_t - me_t).length();
            // Too far to step across in time: dive.
            let slide = lateral > 1.2 && t < 0.6;
            return Plan { slide, ..Plan::go(target, me.max_speed, ball - me.position) };
        }
        // A loose ball in the area that he reaches before any opponent: come and claim it.
        if let Some((_, _, meet)) = analysis.chaser {
            let meet_t = frame.vec2(meet);
            let (t_keeper, at) = analysis.path.intercept(me.position, me.max_speed, 2.5);
            if in_penalty_area(meet_t.x, meet_t.y, -1.0) && t_keeper < analysis.opponent_time * 0.9 {
                return Plan::go(at, me.max_speed, ball - me.position);
            }
        }
        // Anywhere else, a loose ball he reaches first of all 22 players: he goes for it like any
        // other player (GRF's team AI sends the quickest to the ball, keeper or not), and plays
        // it first time when an opponent is close behind (`clearance`).
        if sent_for_the_ball(t_keeper, analysis)
            && analysis.chaser.is_none_or(|(_, mate, _)| clearly_quicker(t_keeper, mate, TEAM_MARGIN))
        {
            return Plan::go(meet, me.max_speed, ball - me.position);
        }
    }

    // With the ball bound for the other half he takes his spot 10 m in front of his goal (GRF's
    // keeper works out his place on the ball-goal line, and the rush below, only while the ball,
    // as he sees it 0.6 s on plus a fifth of his own time to it, is in his half).
    if !ball_in_own_half(t_keeper, analysis) {
        let contested = t_keeper.max(analysis.opponent_time) < NOT_SENT_WAITS;
        if view.owner.is_none() && contested && !sent_for_the_ball(t_keeper, analysis) {
            // A loose ball an opponent is about to reach as soon as he can, which he was not sent
            // for: GRF's keeper never plays it (only the player sent for a ball controls it) and
            // lets it run past; touchline's would take it by running onto it, so he waits.
            return Plan::go(me.position, 0.0, ball - me.position);
        }
        let target = frame.vec2(Vec2::new(-HALF_LENGTH + OTHER_HALF_LINE, 0.0));
        let speed = (target.distance(me.position) * 3.0).min(me.max_speed);
        return Plan::go(target, speed, ball - me.position);
    }

    // GRF's rush rule: against a carrier (or the opponent nearest a loose ball) whose shooting
    // point no team-mate covers, come out all the way to the ball.
    // With the ball loose, the threat is the opponent nearest to it.
    let threat = match view.owner {
        Some(o) if view.players[o].side != me.side => Some(view.players[o].position),
        Some(_) => None,
        // Loose: the opponent nearest to it, when they get there first.
        None if analysis.chaser.is_some_and(|(_, ours, _)| ours <= analysis.opponent_time) => None,
        None => view
            .team(me.side.opponent())
            .iter()
            .filter(|p| p.active)
            .min_by(|a, b| a.position.distance_squared(ball).total_cmp(&b.position.distance_squared(ball)))
            .map(|p| p.position),
    };
    if let Some(threat) = threat
        && !covered(view, g, frame, frame.vec2(threat))
    {
        let at_t = ball_t + (goal_t - ball_t).normalize_or(Vec2::NEG_X) * RUSH_SHORT_OF_BALL;
        return Plan::go(frame.vec2(at_t), me.max_speed, ball - me.position);
    }

    // Positioning on the ball–goal line, a little in front of the goal line; with his team on the
    // ball he stands up to 30 % of the way out to it (GRF's keeper positioning).
    let ours = view.owner_side() == Some(me.side);
    let to_ball = ball_t - goal_t;
    let dist = to_ball.length();
    let depth = KEEPER_LINE + if ours { OUT_IN_POSSESSION * (dist - 0.5).max(0.0) } else { 0.0 };
    let target_t = goal_t + to_ball.normalize_or(Vec2::X) * depth.min(dist * 0.5).max(KEEPER_LINE.min(dist));
    let target = frame.vec2(target_t);
    // GRF's keeper moves at a pace that grows with the distance to his spot, up to a sprint.
    let speed = (target.distance(me.position) * 3.0).min(me.max_speed);
    Plan::go(target, speed, ball - me.position)
}

/// When (s) and where (team frame, m) the loose ball's predicted path crosses the deciding team's
/// own goal line between the posts (a metre's grace each side) and under 3 m: a ball on its way
/// into the goal. `None` when it crosses wide, high or not at all.
pub(crate) fn into_goal(analysis: &Analysis) -> Option<(f32, Vec2)> {
    let frame = analysis.frame;
    let (k, p) =
        analysis.path.at().iter().enumerate().find(|(_, p)| frame.vec2(p.truncate()).x < -HALF_LENGTH + 1.0)?;
    let p_t = frame.vec2(p.truncate());
    (p_t.y.abs() < GOAL_HALF_WIDTH + 1.0 && p.z < 3.0).then_some((SAMPLE_DT * (k + 1) as f32, p_t))
}

/// Whether a time to the ball of `t` (s) beats `other`'s by the `(pad, share)` margin: (t + pad) <
/// share × (other + pad).
fn clearly_quicker(t: f32, other: f32, (pad, share): (f32, f32)) -> bool {
    t + pad < share * (other + pad)
}

/// Whether a keeper who needs `t` (s) to reach the loose ball is the one GRF would send for it
/// ahead of every opponent: [`MATCH_MARGIN`] quicker than the quickest of them. GRF's keeper
/// plays the ball, or runs for it like an outfielder, only as the match's designated player; a
/// keeper merely level with an opponent leaves it (GRF: the side already sent stays sent).
pub(crate) fn sent_for_the_ball(t: f32, analysis: &Analysis) -> bool {
    clearly_quicker(t, analysis.opponent_time, MATCH_MARGIN)
}

/// Whether the ball, as GRF's keeper looks ahead at it, is in his own half: where it will be
/// [`LOOK_AHEAD`] on plus [`LOOK_AHEAD_PER_REACH`] of his time to reach it (the last sample of its
/// path if later). `t_keeper`: his time to reach it (s).
fn ball_in_own_half(t_keeper: f32, analysis: &Analysis) -> bool {
    let ahead = LOOK_AHEAD + LOOK_AHEAD_PER_REACH * t_keeper;
    let samples = analysis.path.at();
    let k = ((ahead / SAMPLE_DT).round() as usize).clamp(1, samples.len()) - 1;
    analysis.frame.vec2(samples[k].truncate()).x < 0.0
}

/// Whether a team-mate of keeper `g` covers the shooting point of a carrier at `carrier_t` (team
/// frame): the point 20 m out on the carrier's line to goal (the carrier himself when nearer).
/// Covered when some outfield team-mate is at least 1 m nearer to it than the carrier (GRF's rush
/// rule compares times at equal pace).
fn covered(view: &MatchView, g: usize, frame: crate::geometry::TeamFrame, carrier_t: Vec2) -> bool {
    let goal_t = Vec2::new(-HALF_LENGTH, 0.0);
    let to_carrier = carrier_t - goal_t;
    let point = if to_carrier.length() > SHOOTING_DISTANCE {
        goal_t + to_carrier.normalize() * SHOOTING_DISTANCE
    } else {
        carrier_t
    };
    let carrier_distance = carrier_t.distance(point);
    let me = &view.players[g];
    view.team(me.side).iter().filter(|p| p.active && !p.is_keeper()).any(|p| {
        let at = frame.vec2(p.position);
        at.distance(point) + 1.0 < carrier_distance || at.distance(carrier_t) < ENGAGED
    })
}

/// The keeper holds the ball: wait a moment, then play it to the most open team-mate (short if
/// he is close and free, long otherwise).
pub fn distribute(view: &MatchView, g: usize, held_for: u64, analysis: &Analysis) -> Plan {
    let me = &view.players[g];
    let ball = view.ball.xy();
    if held_for < HOLD_TICKS {
        // Alone, he keeps facing the way he came: that is where his clearance goes.
        let alone = !view.team(me.side).iter().any(|p| p.active && p.index != me.index);
        return Plan::go(me.position, 0.0, if alone { me.facing } else { frame_forward(analysis) });
    }
    let opponents = view.team(me.side.opponent());
    let mut best = None;
    let mut best_value = f32::NEG_INFINITY;
    let mut anyone = false;
    for mate in view.team(me.side) {
        if !mate.active || mate.index == me.index {
            continue;
        }
        anyone = true;
        let free = nearest_distance(opponents, mate.position);
        if free < FREE_OF && held_for < HOLD_LIMIT_TICKS {
            // GRF's keeper waits rather than give the ball to a marked team-mate.
            continue;
        }
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
        None if anyone => Plan::go(me.position, 0.0, frame_forward(analysis)),
        None => {
            // Nobody to give it to: a high ball along the way he faces (GRF), which can be over
            // his own line if he ran out towards it.
            let at = ball + me.facing * CLEARANCE;
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
