//! The ball carrier's choice, in the order GRF's on-the-ball AI makes it (GRF 2.10): under
//! pressure in his own third, a clearance (the only choice with decision noise, weighed against
//! dribbling on); else a pass to a better-placed team-mate (`ai::pass_choice`); else, near the ideal
//! spot with a lane to goal, a shot; else he dribbles towards goal, bending round opponents.

use glam::Vec2;

use super::clearance::TIME_MARGIN;
use super::pass_choice::{self, Rivals, passing_odds};
use super::{Analysis, Difficulty, MatchView, Plan, goalkeeper};
use crate::game::{Kick, KickKind, KickTarget};
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};
use crate::player::{Player, nearest_distance};
use crate::rng::MatchRng;

/// Distance (m) from `p` to the segment `a`–`b`.
pub(crate) fn distance_to_segment(p: Vec2, a: Vec2, b: Vec2) -> f32 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_squared().max(1e-6)).clamp(0.0, 1.0);
    p.distance(a + ab * t)
}

/// Whether the carrier at `from` (team frame, m), running at `velocity` (team frame, m/s), takes
/// on a shot at all: GRF's AI shoots only near its ideal spot and with a lane to goal (GRF 2.10's
/// on-the-ball AI). The spot is 7 m out in front of goal; closeness to it, 1 − d/16 m, smoothed
/// by a sine, must exceed 0.1 (within about 12.7 m of it). The lane is the best of three aims, at
/// the posts and the centre a metre behind the line: each opponent who could get to the ball's
/// line before it (ball at a third of a pass's pace, he at sprint pace) adds danger, and the odds
/// are 1 − danger. He shoots when √odds + U(0, 0.5) > 0.5, at the lane with the best odds (the
/// centre unless a post's are better): `Some(y)` of that lane (team frame, m), else `None`.
fn takes_on_shot(
    from: Vec2,
    velocity: Vec2,
    opponents: &[Player],
    frame: crate::geometry::TeamFrame,
    rng: &mut MatchRng,
) -> Option<f32> {
    let closeness = 1.0 - (from.distance(Vec2::new(HALF_LENGTH - 7.0, 0.0)) / 16.0).clamp(0.0, 1.0);
    let ideal = libm::sinf((closeness - 0.5) * std::f32::consts::PI) * 0.5 + 0.5;
    if ideal <= 0.1 {
        return None;
    }
    let origin = from + velocity * 0.12;
    let rivals = Rivals::of(opponents, frame);
    let lane_odds = |y: f32| passing_odds(origin, Vec2::new(HALF_LENGTH + 1.0, y), KickKind::Shot, &rivals, 3.0);
    let (mut odds, mut lane) = (lane_odds(0.0), 0.0);
    for y in [-SHOT_LANE, SHOT_LANE] {
        let o = lane_odds(y);
        if o > odds {
            (odds, lane) = (o, y);
        }
    }
    (odds.sqrt() + 0.5 * rng.unit() > 0.5).then_some(lane)
}

/// Where the AI's shot goes (team frame, m), GRF's on-the-ball AI: a metre behind the goal line
/// at the chosen lane, `lane_y` (the centre, or just inside a post: [`SHOT_AIM`]), plus up to
/// 1 − shooting skill metres either way (none in a deterministic match). Aimed at a post, a shot
/// from a weaker shooter often goes wide, and the goal kicks of a match come from such shots.
fn shot_aim(lane_y: f32, skill: f32, rng: &mut MatchRng) -> Vec2 {
    let y = if lane_y == 0.0 { 0.0 } else { SHOT_AIM.copysign(lane_y) };
    let spread = 1.0 - skill.clamp(0.0, 1.0);
    Vec2::new(HALF_LENGTH + 1.0, y + rng.noise(spread))
}

/// How hard the AI strikes a shot from `distance` m out, GRF's desired power: U(0.7, 1) × (0.6 +
/// 0.4 × the distance over 32 m), so a close shot is placed rather than blasted (the mean, 0.85,
/// in a deterministic match).
fn shot_power(distance: f32, rng: &mut MatchRng) -> f32 {
    (0.85 + rng.noise(0.15)) * (0.6 + 0.4 * (distance / 32.0).clamp(0.0, 1.0))
}

/// The lanes a shooter weighs (m off centre, a metre behind the goal line) and where he aims in a
/// post's lane (GRF 2.10's on-the-ball AI).
const SHOT_LANE: f32 = 3.6;
const SHOT_AIM: f32 = 3.5;

/// GRF's AI takes its on-the-ball decision for the player designated to a loose ball once he
/// needs under this long to reach it (s); a pass or a shot decided then is struck with his
/// first touch, so he never shows as the ball's owner.
const DECIDE_WITHIN: f32 = 1.0;
/// A ball crossing the keeper's goal line within this long (s) is a shot he saves rather than a
/// ball he plays: GRF's keeper counts a ball bound for goal by its first 800 ms.
const BOUND_FOR_GOAL: f32 = 0.8;
/// A keeper plays a loose ball with his feet only while his possession amount (the opponents'
/// time to the ball over his, each plus [`TIME_MARGIN`]) is at least this; below it GRF's keeper
/// asks for his hands first.
const KEEPER_FEET: f32 = 3.4;
/// Ticks a carrier who just got the ball runs with it before he thinks of a pass or shot (unless
/// pressed).
const FIRST_TOUCH_TICKS: u32 = 12;

/// The kick `g`, the first of his team to a loose ball and less than [`DECIDE_WITHIN`] from it,
/// strikes with his first touch: the pass or shot he would choose with the ball at his feet
/// (GRF 2.10's on-the-ball AI decides before the touch). `None` when he would rather run with
/// it, or is not the one to play it.
///
/// A keeper decides so too when he is sent for a loose ball (the match's first to it and before
/// his outfield players) that is not bound for his goal ([`BOUND_FOR_GOAL`]) and that no opponent
/// contests ([`KEEPER_FEET`]). GRF's keeper asks for his hands only for a contested ball, and
/// otherwise plays the on-the-ball commands of any designated player: coming out for a ball
/// rolling into his area, he passes it first time to a team-mate placed better (measured in GRF
/// 2.10.2, academy_run_to_score_with_keeper, random agent: in 40 episodes he never held such a
/// ball; docs/grf-compatibility.md, "the keeper plays an uncontested loose ball with his feet").
/// With nobody to pass to he controls it as before; his panic clearance comes first
/// (`clearance`).
pub(crate) fn first_touch(
    view: &MatchView,
    g: usize,
    analysis: &Analysis,
    difficulty: &Difficulty,
    rng: &mut MatchRng,
) -> Option<Kick> {
    if view.owner.is_some() {
        return None;
    }
    if view.players[g].is_keeper() {
        let (t, _) = analysis.path.intercept(view.players[g].position, view.players[g].max_speed, 1.0);
        let sent = t < DECIDE_WITHIN
            && goalkeeper::sent_for_the_ball(t, analysis)
            && analysis.chaser.is_none_or(|(_, mate, _)| t <= mate);
        // GRF's keeper reaches for his hands while an opponent is anywhere near as quick to the
        // ball: a possession amount under 3.4.
        let uncontested = analysis.opponent_time + TIME_MARGIN >= KEEPER_FEET * (t + TIME_MARGIN);
        if !sent || !uncontested || goalkeeper::into_goal(analysis).is_some_and(|(t, _)| t <= BOUND_FOR_GOAL) {
            return None;
        }
    } else {
        match analysis.chaser {
            Some((chaser, t, _)) if chaser == g && t < DECIDE_WITHIN => {}
            _ => return None,
        }
    }
    // As if he had it, past the first touch a carrier takes on receiving it.
    let on_the_ball = MatchView { owner: Some(g), owner_ticks: FIRST_TOUCH_TICKS, ..*view };
    plan(&on_the_ball, g, analysis, difficulty, rng).kick
}

/// The plan for the ball carrier `g`.
pub(crate) fn plan(
    view: &MatchView,
    g: usize,
    analysis: &Analysis,
    difficulty: &Difficulty,
    rng: &mut MatchRng,
) -> Plan {
    let me = &view.players[g];
    let frame = analysis.frame;
    let side = me.side;
    let mates = view.team(side);
    let opponents = view.team(side.opponent());
    let pos_t = frame.vec2(me.position);
    let goal_t = Vec2::new(HALF_LENGTH, 0.0);
    let pressure = nearest_distance(opponents, me.position);
    let noise = difficulty.decision_noise;

    // Dribble: towards goal, bending away from opponents in front.
    let mut dir = (goal_t - pos_t).normalize_or(Vec2::X);
    let mut space = 20.0f32;
    for o in opponents.iter().filter(|o| o.active) {
        let rel = frame.vec2(o.position) - pos_t;
        let d = rel.length();
        if d < 10.0 && rel.x > -1.0 {
            space = space.min(d);
            let side_step = if rel.y > 0.0 { Vec2::new(0.0, -1.0) } else { Vec2::new(0.0, 1.0) };
            dir += side_step * (1.0 - d / 10.0) * 1.2;
        }
    }
    if pos_t.y.abs() > HALF_WIDTH - 6.0 {
        dir.y -= pos_t.y.signum() * 0.8;
    }
    let dir = dir.normalize_or(Vec2::X);
    let dribble_value = 0.12 + 0.55 * (space / 20.0) + 0.2 * (1.0 - pos_t.distance(goal_t) / 110.0)
        - if pressure < 2.0 { 0.25 } else { 0.0 }
        + rng.noise(noise);
    let speed = if space > 6.0 { me.max_speed } else { 5.0 };
    let to = frame.vec2(pos_t + dir * 8.0);
    let dribble = Plan { dribble: pressure < 1.8, run_through: true, ..Plan::go(to, speed, to - me.position) };
    // A player who just got the ball takes a touch first, unless an opponent is on him.
    if view.owner_ticks < FIRST_TOUCH_TICKS && pressure > 2.5 {
        return dribble;
    }

    // Clearance: under pressure in his own third, a weaker team hoofs it long towards a wing
    // (GRF's panic pass comes before any other choice).
    if pos_t.x < -HALF_LENGTH + 30.0 && pressure < 3.0 {
        let value = 0.35 + 0.25 * (1.0 - difficulty.theta) + if pressure < 1.8 { 0.2 } else { 0.0 } + rng.noise(noise);
        if value > dribble_value {
            let wing = if pos_t.y >= 0.0 { 24.0 } else { -24.0 };
            let aim = frame.vec2(Vec2::new(pos_t.x + 40.0, wing + rng.noise(8.0)));
            return Plan {
                kick: Some(Kick { kind: KickKind::HighPass, target: KickTarget::Point(aim), height: 0.0, power: 0.8 }),
                ..Plan::go(me.position, 0.0, aim - me.position)
            };
        }
    }

    // Pass: GRF's carrier passes, when a team-mate is better placed, before he thinks of a shot.
    let passing = me.skill(me.attributes.passing, difficulty.theta);
    let ball_velocity = view.ball.velocity.truncate();
    if let Some(choice) = pass_choice::choose(me, mates, opponents, view.owner_ticks, passing, ball_velocity) {
        let mate = &mates[choice.mate];
        let lead = mate.velocity * (mate.position.distance(me.position) / 18.0);
        let aim = mate.position + lead;
        return Plan {
            kick: Some(Kick { kind: choice.kind, target: KickTarget::Point(aim), height: 0.0, power: 0.5 }),
            ..Plan::go(me.position, 0.0, aim - me.position)
        };
    }

    // Shot: near the ideal spot with a lane to goal.
    if let Some(lane) = takes_on_shot(pos_t, frame.vec2(me.velocity), opponents, frame, rng) {
        let skill = me.skill(me.attributes.shooting, difficulty.theta);
        let target = frame.vec2(shot_aim(lane, skill, rng));
        let power = shot_power(pos_t.distance(goal_t), rng);
        return Plan {
            kick: Some(Kick { kind: KickKind::Shot, target: KickTarget::Point(target), height: 0.5, power }),
            ..Plan::go(me.position, 0.0, target - me.position)
        };
    }
    dribble
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shots_are_taken_near_the_ideal_spot_with_a_lane_only() {
        use crate::geometry::{Side, TeamFrame};
        use crate::player::Role;
        let frame = TeamFrame::of(Side::Left);
        let keeper = Player::new(Side::Right, 0, Role::GK, Vec2::new(HALF_LENGTH - 1.0, 0.0), Vec2::ZERO);
        let mut rng = MatchRng::new(1, 0, true);
        for _ in 0..50 {
            // 27 m out, 20 m from the spot 7 m out: GRF's AI never shoots from there.
            let far = Vec2::new(HALF_LENGTH - 27.0, 0.0);
            assert_eq!(takes_on_shot(far, Vec2::ZERO, std::slice::from_ref(&keeper), frame, &mut rng), None);
            // 12 m out in front of goal, only the keeper on his line: always.
            let near = Vec2::new(HALF_LENGTH - 12.0, 0.0);
            assert!(takes_on_shot(near, Vec2::ZERO, std::slice::from_ref(&keeper), frame, &mut rng).is_some());
        }
        // The same spot with three defenders across the lanes a few metres ahead: seldom.
        let wall: Vec<Player> = (0..3)
            .map(|i| {
                Player::new(
                    Side::Right,
                    i + 1,
                    Role::CB,
                    Vec2::new(HALF_LENGTH - 9.0, -1.5 + 1.5 * i as f32),
                    Vec2::ZERO,
                )
            })
            .collect();
        let shots = (0..50)
            .filter(|_| takes_on_shot(Vec2::new(HALF_LENGTH - 12.0, 0.0), Vec2::ZERO, &wall, frame, &mut rng).is_some())
            .count();
        assert!(shots < 10, "{shots} of 50");
    }

    #[test]
    fn a_shot_aims_at_a_post_or_the_centre_and_a_weaker_shooter_spreads_it_wider() {
        let mut rng = MatchRng::new(3, 0, true);
        let spread = |skill: f32, rng: &mut MatchRng| {
            (0..200).map(|_| (shot_aim(SHOT_LANE, skill, rng).y - SHOT_AIM).abs()).fold(0.0f32, f32::max)
        };
        assert!(spread(0.9, &mut rng) <= 0.1 + 1e-5);
        let weak = spread(0.4, &mut rng);
        assert!((0.5..=0.6 + 1e-5).contains(&weak), "{weak}");
        // Centre lane: the goal's middle; a post lane: just inside that post, a metre behind.
        let centre = shot_aim(0.0, 1.0, &mut rng);
        assert_eq!(centre, Vec2::new(HALF_LENGTH + 1.0, 0.0));
        assert_eq!(shot_aim(-SHOT_LANE, 1.0, &mut rng).y, -SHOT_AIM);
        // Power grows with range: placed from close, full from 32 m.
        let close = (0..50).map(|_| shot_power(8.0, &mut rng)).fold(0.0f32, f32::max);
        let far = (0..50).map(|_| shot_power(32.0, &mut rng)).fold(1.0f32, f32::min);
        assert!(close <= 0.7 + 1e-5 && far >= 0.7 - 1e-5, "{close} {far}");
    }

    #[test]
    fn segment_distance() {
        let d = distance_to_segment(Vec2::new(5.0, 3.0), Vec2::ZERO, Vec2::new(10.0, 0.0));
        assert!((d - 3.0).abs() < 1e-5);
        let d = distance_to_segment(Vec2::new(-4.0, 3.0), Vec2::ZERO, Vec2::new(10.0, 0.0));
        assert!((d - 5.0).abs() < 1e-5);
    }
}
