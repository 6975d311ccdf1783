//! The goalkeeper (GRF 2.10's keeper, docs/grf-compatibility.md#team-ai): with the ball in his
//! half he stands on the line between ball and goal centre and comes off it as the ball comes
//! closer; with the ball in the other half he waits 10 m out. He moves across (and dives) to
//! shots heading into goal, rushes out at a carrier nobody covers, goes for loose balls he
//! reaches clearly first, and distributes the ball once he holds it.

use glam::Vec2;

use super::prediction::SAMPLE_DT;
use super::{Analysis, Difficulty, MatchView, Plan};
use crate::game::{Kick, KickKind, KickTarget};
use crate::geometry::TeamFrame;
use crate::geometry::pitch::{GOAL_HALF_WIDTH, HALF_LENGTH, in_penalty_area};
use crate::player::{Player, nearest_distance};

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
/// The shooting threshold of the rush rule (m): the threat's shooting point lies on his line to
/// goal, this far from goal when he is twice as far out or more, and halfway when nearer (GRF
/// 2.10's keeper, docs/grf-compatibility.md#team-ai, "the keeper's rush rule").
const SHOOTING_DISTANCE: f32 = 20.0;
/// The same for the second opponent, the one nearest the goal (GRF 2.10's 24 m).
const HELPER_SHOOTING_DISTANCE: f32 = 24.0;
/// How far ahead (s) the keeper reckons an opponent's and a team-mate's places in the rush rule:
/// GRF 2.10's 0.32 s for opponents, 0.24 s for his team-mates.
const OPPONENT_AHEAD: f32 = 0.32;
const MATE_AHEAD: f32 = 0.24;
/// The centre of the keeper's own goal, in his team's frame (m).
const OWN_GOAL: Vec2 = Vec2::new(-HALF_LENGTH, 0.0);
/// A rushing keeper goes for the spot this far short (m) of the point he rushes at.
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
    // point no team-mate covers, come out towards the ball, less far when a second opponent
    // near goal is uncovered too.
    // With the ball loose, the threat is the opponent nearest to it.
    let threat = match view.owner {
        Some(o) if view.players[o].side != me.side => Some(&view.players[o]),
        Some(_) => None,
        // Loose: the opponent nearest to it, when they get there first.
        None if analysis.chaser.is_some_and(|(_, ours, _)| ours <= analysis.opponent_time) => None,
        None => view
            .team(me.side.opponent())
            .iter()
            .filter(|p| p.active)
            .min_by(|a, b| a.position.distance_squared(ball).total_cmp(&b.position.distance_squared(ball))),
    };
    if let Some(threat) = threat {
        let bias = rush_bias(view, g, frame, threat);
        if bias > 0.0 {
            // Along the line from his goal line to the ball, out to `bias` of the way to 0.5 m
            // short of it. GRF aims at a point between the ball 0.6 s ahead and the threat 0.32 s
            // ahead; touchline's keeper, who challenges only from a stand, would run alongside
            // the carrier there, so he goes for the ball as it is.
            let line_t = line_point(ball_t);
            let out = ((ball_t.distance(line_t) - RUSH_SHORT_OF_BALL).max(0.0) * bias).max(KEEPER_LINE);
            let at_t = line_t + (ball_t - line_t).normalize_or(Vec2::X) * out;
            return Plan::go(frame.vec2(at_t), me.max_speed, ball - me.position);
        }
    }

    // Positioning on the ball–goal line, a little in front of the goal line; with his team on the
    // ball he stands up to 30 % of the way out to it (GRF's keeper positioning).
    let ours = view.owner_side() == Some(me.side);
    let to_ball = ball_t - OWN_GOAL;
    let dist = to_ball.length();
    let depth = KEEPER_LINE + if ours { OUT_IN_POSSESSION * (dist - 0.5).max(0.0) } else { 0.0 };
    let target_t = OWN_GOAL + to_ball.normalize_or(Vec2::X) * depth.min(dist * 0.5).max(KEEPER_LINE.min(dist));
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

/// Where the line from `from_t` (team frame) towards the centre of the goal meets the line
/// [`KEEPER_LINE`] in front of the goal line, kept between the posts (GRF's keeper stands on the
/// line between the ball and his goal).
fn line_point(from_t: Vec2) -> Vec2 {
    let x = -HALF_LENGTH + KEEPER_LINE;
    let depth = from_t.x + HALF_LENGTH;
    let y = if depth > KEEPER_LINE { from_t.y * KEEPER_LINE / depth } else { from_t.y };
    Vec2::new(x, y.clamp(-GOAL_HALF_WIDTH, GOAL_HALF_WIDTH))
}

/// An opponent's shooting point (team frame) for a threshold of `threshold` m, with his distance
/// to it: on his line to goal, `threshold` from goal when he is `2 × threshold` out or further, and
/// halfway to goal when nearer.
fn shooting_point(at_t: Vec2, threshold: f32) -> (f32, Vec2) {
    let d = at_t.distance(OWN_GOAL);
    let to_point = (d - threshold * (d / (2.0 * threshold)).min(1.0)).clamp(0.0, HALF_LENGTH);
    (to_point, at_t + (OWN_GOAL - at_t).normalize_or_zero() * to_point)
}

/// How far keeper `g`'s team-mate nearest to `point` (team frame) will be from it shortly (m);
/// infinite with no outfield team-mate.
fn nearest_mate_to(view: &MatchView, g: usize, frame: TeamFrame, point: Vec2) -> f32 {
    let me = &view.players[g];
    view.team(me.side)
        .iter()
        .filter(|p| p.active && p.index != me.index)
        .min_by(|a, b| {
            frame.vec2(a.position).distance_squared(point).total_cmp(&frame.vec2(b.position).distance_squared(point))
        })
        .map_or(f32::INFINITY, |p| frame.vec2(p.position + p.velocity * MATE_AHEAD).distance(point))
}

/// GRF 2.10's rush rule for keeper `g` against `threat`: how far out towards him the keeper
/// comes, from 0 (he keeps his line) to 1 (all the way). 0 when a team-mate will be no more than
/// a metre further than the threat from the threat's shooting point; else 1, less when a second
/// opponent (the one nearest the goal) has an uncovered shooting point not much further out
/// (`1 − secondary × helper`, `secondary` growing over 2 m of his lead there and `helper` 0.7
/// for a second opponent as near his point as the threat is to his, down to 0 at 1.5 times).
fn rush_bias(view: &MatchView, g: usize, frame: TeamFrame, threat: &Player) -> f32 {
    let threat_t = frame.vec2(threat.position + threat.velocity * OPPONENT_AHEAD);
    let (threat_to_point, point) = shooting_point(threat_t, SHOOTING_DISTANCE);
    if nearest_mate_to(view, g, frame, point) <= threat_to_point + 1.0 {
        return 0.0;
    }
    let helper = view.team(threat.side).iter().filter(|p| p.active && p.index != threat.index).min_by(|a, b| {
        frame.vec2(a.position).distance_squared(OWN_GOAL).total_cmp(&frame.vec2(b.position).distance_squared(OWN_GOAL))
    });
    let Some(helper) = helper else { return 1.0 };
    let helper_t = frame.vec2(helper.position + helper.velocity * OPPONENT_AHEAD);
    let (helper_to_point, helper_point) = shooting_point(helper_t, HELPER_SHOOTING_DISTANCE);
    let mate_to_helper_point = nearest_mate_to(view, g, frame, helper_point);
    let secondary = ((mate_to_helper_point - helper_to_point) / 2.0).clamp(0.0, 1.0);
    let ratio = helper_to_point / (threat_to_point + 1e-4);
    let helper_weight = (1.0 - ((ratio - 1.0) / 0.5).clamp(0.0, 1.0)) * 0.7;
    (1.0 - secondary * helper_weight).clamp(0.0, 1.0)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::game::Match;
    use crate::geometry::Side;
    use crate::player::Role;
    use crate::scenario::{PlayerEntry, Scenario};

    /// Our keeper, one outfield team-mate and two opponents, at rest where the test puts them.
    fn keeper_and_three(mate: Vec2, threat: Vec2, helper: Vec2) -> Match {
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CB, -0.5, 0.0)],
            right_team: vec![
                PlayerEntry::new(Role::GK, -1.0, 0.0),
                PlayerEntry::new(Role::CF, 0.0, 0.0),
                PlayerEntry::new(Role::AM, 0.0, 0.1),
            ],
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 0);
        m.place_player(Side::Left, 1, mate);
        m.place_player(Side::Right, 1, threat);
        m.place_player(Side::Right, 2, helper);
        m
    }

    #[test]
    fn the_shooting_point_is_twenty_metres_out_or_halfway_for_a_nearer_threat() {
        let (to_point, point) = shooting_point(Vec2::new(-HALF_LENGTH + 50.0, 0.0), SHOOTING_DISTANCE);
        assert!((to_point - 30.0).abs() < 1e-4 && (point.x - (-HALF_LENGTH + 20.0)).abs() < 1e-4);
        let (to_point, point) = shooting_point(Vec2::new(-HALF_LENGTH + 30.0, 0.0), SHOOTING_DISTANCE);
        assert!((to_point - 15.0).abs() < 1e-4 && (point.x - (-HALF_LENGTH + 15.0)).abs() < 1e-4);
    }

    #[test]
    fn the_keeper_comes_out_only_for_an_uncovered_threat_and_less_with_a_second_one_near_goal() {
        let frame = TeamFrame::of(Side::Left);
        let goal = -HALF_LENGTH;
        let threat_at = Vec2::new(goal + 30.0, 0.0);
        let far_helper = Vec2::new(0.0, 30.0);
        let bias = |m: &Match| rush_bias(&crate::ai::test_view(m), 0, frame, &m.team(Side::Right)[1]);
        // The threat's shooting point is 15 m out. A team-mate 1 m further from it than the
        // threat covers it (GRF compares with a metre's grace the threat's way).
        let m = keeper_and_three(Vec2::new(goal + 15.0, 15.9), threat_at, far_helper);
        assert_eq!(bias(&m), 0.0);
        // 2 m further: uncovered, and with the other opponent far off the keeper goes all the way.
        let m = keeper_and_three(Vec2::new(goal + 15.0, 17.0), threat_at, far_helper);
        assert_eq!(bias(&m), 1.0);
        // A second opponent about as near goal (31.2 m out, 15.6 m from his shooting point, 1.04
        // times the threat's 15), unmarked: the keeper comes 1 - 0.7 × (1 - 0.08) = 0.36 of the way.
        let m = keeper_and_three(Vec2::new(goal + 15.0, 17.0), threat_at, Vec2::new(goal + 24.0, -20.0));
        assert!((bias(&m) - 0.358).abs() < 0.005, "{}", bias(&m));
        // The same with our team-mate marking him: all the way again.
        let m = keeper_and_three(Vec2::new(goal + 12.0, -20.0), threat_at, Vec2::new(goal + 24.0, -20.0));
        assert_eq!(bias(&m), 1.0);
    }
}
