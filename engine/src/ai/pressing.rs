//! Pressing: the team's quickest player goes for a loose ball; a carrier is hunted by one of the
//! two players nearest him, GRF's way (no man to mark, within his hunting distance, not yet
//! goal-side of him), and held off by the rest.

use glam::Vec2;

use super::prediction::INTERCEPT_REACH;
use super::{Analysis, Difficulty, MatchView, Plan};
use crate::geometry::pitch::HALF_LENGTH;
use crate::player::{Player, SPRINT_SPEED, difficulty_scale};

/// Where presser `p` runs to close down `carrier` with the ball at `ball` (m, global). GRF's
/// hunter (docs/grf-compatibility.md#team-ai): he runs at the ball only while he is not yet goal-side of
/// the carrier ([`needs_defending_movement`]); once he stands between the carrier and his goal,
/// more than about 2.6 m off, he holds that line and waits for the carrier to come to him (GRF's
/// defenders stand 3-6 m off an idle carrier and never dive in). Shared with the `press`
/// behaviour. The flag says whether to run through the point at full speed (going for the ball)
/// rather than arrive on it and stand (holding the line).
pub(crate) fn close_down(p: &Player, carrier: &Player, ball: Vec2) -> (Vec2, bool) {
    let sign = p.side.attack_sign();
    let own_goal = Vec2::new(-sign * HALF_LENGTH, 0.0);
    if !needs_defending_movement(p.position, defend_point(p.position, carrier, own_goal), sign) {
        // Goal-side: hold the line from the carrier to goal, no further off than 6 m.
        let to_goal = (own_goal - carrier.position).normalize_or_zero();
        let off = p.position.distance(carrier.position).clamp(GUARD_MIN, GUARD_MAX);
        return (carrier.position + to_goal * off, false);
    }
    (go_for_ball(p, carrier, ball), true)
}

/// Where a presser who is not yet goal-side runs: within 2.5 m of the carrier, at the ball on the
/// far side of it from him; further off, to where he meets the ball if it goes on with the
/// carrier's run ([`meeting_point`]). GRF's hunter moves with its to-ball movement in haste, which
/// rates each point of the ball's predicted path by how soon he can be there and takes the
/// soonest (docs/grf-compatibility.md#team-ai, "the hunter runs at the ball"). Aimed goal-side of
/// the carrier instead, touchline's hunter racing back in academy_counterattack_hard met the idle
/// carrier's shoulder on the side away from the ball and stayed there.
fn go_for_ball(p: &Player, carrier: &Player, ball: Vec2) -> Vec2 {
    if p.position.distance(carrier.position) < 2.5 {
        // At the ball, on the far side of it from the carrier: GRF's to-ball movement, which
        // comes round a carrier from behind.
        ball + (ball - carrier.position).normalize_or_zero() * 0.3
    } else {
        meeting_point(p.position, p.max_speed, ball, carrier.velocity)
    }
}

/// Longest look ahead (s) along a carried ball's run for a meeting point: GRF's ball prediction
/// reaches 2 s.
const MEETING_HORIZON: f32 = 2.0;

/// Where a player at `at` running at `speed` (m/s) first meets a ball at `ball` moving on at
/// `velocity` (m/s): the soonest t with |ball + velocity·t − at| = speed·t, no later than
/// [`MEETING_HORIZON`]; a ball as quick as he is he chases to that horizon.
fn meeting_point(at: Vec2, speed: f32, ball: Vec2, velocity: Vec2) -> Vec2 {
    let offset = ball - at;
    // speed²t² = |offset + velocity·t|²  →  a·t² − 2b·t − c = 0 with a, c ≥ 0.
    let a = speed * speed - velocity.length_squared();
    let b = offset.dot(velocity);
    let c = offset.length_squared();
    let t = if a > 1e-3 { (b + (b * b + a * c).sqrt()) / a } else { MEETING_HORIZON };
    ball + velocity * t.min(MEETING_HORIZON)
}

/// Nearest (m) a goal-side presser holds off a carrier he waits for: where GRF's hunter, straight
/// goal-side, stops needing to move ([`needs_defending_movement`] flips at about 2.6 m).
const GUARD_MIN: f32 = 2.8;
/// Furthest (m) a goal-side presser holds off a carrier: he closes to this.
const GUARD_MAX: f32 = 6.0;

/// GRF's defend point against `carrier` for a defender at `at` (m, global; `own_goal` the goal he
/// defends): the point on the carrier's line to that goal as far from the defender as from the
/// carrier (clamped to the segment), plus 0.1 s of a sprint towards goal and 0.14 s of the
/// carrier's run. Where the defender would meet him cutting across.
pub(crate) fn defend_point(at: Vec2, carrier: &Player, own_goal: Vec2) -> Vec2 {
    let to_goal = own_goal - carrier.position;
    let from_carrier = at - carrier.position;
    let along = to_goal.dot(from_carrier);
    // The point carrier + u·to_goal on the perpendicular bisector of defender and carrier.
    let u = if along > 1e-6 { (from_carrier.length_squared() / (2.0 * along)).clamp(0.0, 1.0) } else { 0.0 };
    carrier.position + to_goal * u + to_goal.normalize_or_zero() * SPRINT_SPEED * 0.1 + carrier.velocity * 0.14
}

/// GRF's test of whether a defender at `at` must move to `target` (his defend point) for a team
/// attacking towards `attack_sign`: only when the point lies wider of him than 0.8 × how far it is
/// ahead of him (less half a metre for reaction). A defender already goal-side, straight in
/// front of the point, stays.
pub(crate) fn needs_defending_movement(at: Vec2, target: Vec2, attack_sign: f32) -> bool {
    let ahead = ((target.x - at.x) * attack_sign).max(0.0) - 0.5;
    let wide = (target.y - at.y).abs();
    wide > 0.8 * ahead
}

/// A pressing plan for player `g`, or `None` when he should hold his place in the shape (or his
/// man, if he marks one: `marking`; a marker neither hunts nor covers, as in GRF).
pub fn plan(view: &MatchView, g: usize, analysis: &Analysis, difficulty: &Difficulty, marking: bool) -> Option<Plan> {
    let p = &view.players[g];
    let ball = view.ball.xy();
    match view.owner {
        Some(_) if marking => None,
        Some(o) if view.players[o].side != p.side => {
            if hunts(view, g, o, difficulty) {
                let target = go_for_ball(p, &view.players[o], ball);
                return Some(Plan { run_through: true, ..Plan::go(target, p.max_speed, ball - p.position) });
            }
            cover(view, g, analysis, difficulty)
        }
        Some(_) => None,
        None => {
            // A loose ball: the team's quickest player to it goes for it (GRF gives the run only to
            // the quicker team's man; tried, it starved touchline's attack of loose balls: 0.7
            // goals a match between equal sides instead of 2.8).
            let (chaser, time, meet) = analysis.chaser?;
            if chaser != g {
                return None;
            }
            // Close to it: go straight at it.
            let target =
                if p.position.distance(ball) < 3.0 { ball + view.ball.velocity.truncate() * 0.1 } else { meet };
            // Just in time: GRF's to-ball run asks for the pace that gets him to the meeting
            // point as the ball gets there, his top speed times the time he needs at it over
            // the time the ball takes (`AI_GetToBallMovement`), so a pass coming at him is met,
            // not run into and knocked away. GRF runs flat out instead when an opponent is
            // about as quick to the ball (its haste); that part is not taken
            // (docs/grf-compatibility.md#team-ai, "how fast a player goes for a loose ball").
            let needed = (p.position.distance(meet) - INTERCEPT_REACH).max(0.0) / p.max_speed.max(1e-3);
            let speed = if time > 0.0 { p.max_speed * (needed / time).clamp(0.0, 1.0) } else { p.max_speed };
            Some(Plan { run_through: true, ..Plan::go(target, speed, ball - p.position) })
        }
    }
}

/// GRF's hunting of a carrier (docs/grf-compatibility.md#team-ai): of the team's two players nearest
/// him, one within his hunting distance (markers are left out by [`plan`]) goes for the ball, while
/// he is not yet goal-side of the carrier ([`needs_defending_movement`]). Everyone else holds the
/// shape or his man, so a carrier is met by the defender in front of him only when he comes on.
/// The keeper counts among the two nearest, as in GRF 2.10.2's hunt (its closest-players search
/// leaves no role out): by his own box only one outfield player hunts with him.
fn hunts(view: &MatchView, g: usize, carrier: usize, difficulty: &Difficulty) -> bool {
    let p = &view.players[g];
    let c = &view.players[carrier];
    let aim = c.position + c.velocity * 0.1;
    let d2 = p.position.distance_squared(aim);
    let nearer = view.ranges[p.side.index()]
        .clone()
        .filter(|&h| h != g)
        .map(|h| &view.players[h])
        .filter(|q| q.active && q.position.distance_squared(aim) < d2)
        .count();
    if nearer >= 2 {
        return false;
    }
    let gap = (c.position + c.velocity * 0.12).distance(p.position + p.velocity * 0.04);
    if gap > hunting_distance(p, difficulty.theta) {
        return false;
    }
    let sign = p.side.attack_sign();
    let own_goal = Vec2::new(-sign * HALF_LENGTH, 0.0);
    needs_defending_movement(p.position, defend_point(p.position, c, own_goal), sign)
}

/// Cover: the team's second quickest to the ball stands between the ball and goal, six metres off
/// it.
fn cover(view: &MatchView, g: usize, analysis: &Analysis, difficulty: &Difficulty) -> Option<Plan> {
    if analysis.second != Some(g) || difficulty.theta < 0.3 {
        return None;
    }
    let p = &view.players[g];
    let ball = view.ball.xy();
    let own_goal = Vec2::new(-p.side.attack_sign() * HALF_LENGTH, 0.0);
    let target = ball + (own_goal - ball).normalize_or_zero() * 6.0;
    Some(Plan::go(target, p.max_speed * 0.85, ball - p.position))
}

/// How far (m) from a carrier player `p` of a team of difficulty `theta` still hunts him (GRF's
/// hunt distance): 20 m for a fresh centre back standing, 10 m for a centre forward, half that at
/// a sprint (GRF's average speed term: a defender racing back does not turn on the carrier until
/// he is near), less when tired, all scaled by 0.3 + 0.7θ.
fn hunting_distance(p: &Player, theta: f32) -> f32 {
    let pace = (p.velocity.length() / SPRINT_SPEED).min(1.0);
    (10.0 + 10.0 * (1.0 - p.role.mind_set())) * (0.5 * (1.0 - p.fatigue) + 0.5 * (1.0 - pace)) * difficulty_scale(theta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;

    #[test]
    fn a_hunter_runs_to_where_he_meets_the_ball_on_the_carriers_run() {
        // A ball at rest: at it.
        let at = Vec2::new(-10.0, 0.0);
        assert_eq!(meeting_point(at, 7.0, Vec2::ZERO, Vec2::ZERO), Vec2::ZERO);
        // Carried straight away from him at 4 m/s from 6 m off: he gains 3 m/s, meets it in 2 s.
        let away = meeting_point(Vec2::new(-6.0, 0.0), 7.0, Vec2::ZERO, Vec2::new(4.0, 0.0));
        assert!(away.distance(Vec2::new(8.0, 0.0)) < 1e-4, "{away}");
        // Carried across him 10 m off: ahead of the carrier, where his run and the ball's meet.
        let across = meeting_point(Vec2::new(0.0, -10.0), 7.0, Vec2::ZERO, Vec2::new(4.0, 0.0));
        let t = across.x / 4.0;
        assert!(t > 0.0 && (across.distance(Vec2::new(0.0, -10.0)) - 7.0 * t).abs() < 1e-3, "{across}");
        // A ball as quick as he is: chased to the 2 s horizon.
        let quick = meeting_point(Vec2::new(-6.0, 0.0), 7.0, Vec2::ZERO, Vec2::new(7.0, 0.0));
        assert_eq!(quick, Vec2::new(14.0, 0.0));
    }

    #[test]
    fn the_keeper_counts_among_the_two_players_nearest_the_carrier() {
        use crate::game::Match;
        use crate::scenario::{PlayerEntry, Scenario};
        // Their carrier 12 m from our goal (we defend -x); our keeper 6 m from him, a centre
        // back 8 m and a right back 9.5 m from him, all goal-side and to his right.
        let s = Scenario {
            left_team: vec![
                PlayerEntry::new(Role::GK, -1.0, 0.0),
                PlayerEntry::new(Role::CB, -0.5, 0.0),
                PlayerEntry::new(Role::RB, -0.5, 0.1),
            ],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CF, -0.5, 0.0)],
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 0);
        let carrier = Vec2::new(-HALF_LENGTH + 12.0, 0.0);
        let at = [(-HALF_LENGTH + 7.0, 3.0), (-HALF_LENGTH + 8.0, 7.0), (-HALF_LENGTH + 9.0, 9.0)];
        for (p, (x, y)) in m.players[0..3].iter_mut().zip(at) {
            p.position = Vec2::new(x, y);
            p.velocity = Vec2::ZERO;
        }
        m.players[4].position = carrier;
        m.players[4].velocity = Vec2::ZERO;
        m.owner = Some(4);
        let view = crate::ai::test_view(&m);
        let difficulty = Difficulty::new(1.0);
        let hunters: Vec<usize> = (1..3).filter(|&g| hunts(&view, g, 4, &difficulty)).collect();
        assert_eq!(hunters, vec![1], "the centre back hunts; the right back, third nearest, holds");
    }

    #[test]
    fn a_defender_straight_goal_side_of_the_carrier_waits_unless_he_is_close() {
        // Right team defends the goal at +x; the carrier stands at the origin.
        let carrier = Player::new(Side::Left, 0, Role::CF, Vec2::ZERO, Vec2::ZERO);
        let own_goal = Vec2::new(HALF_LENGTH, 0.0);
        let sign = Side::Right.attack_sign();
        let wait = |at: Vec2| !needs_defending_movement(at, defend_point(at, &carrier, own_goal), sign);
        assert!(wait(Vec2::new(5.0, 0.0)), "5 m straight goal-side: hold");
        assert!(!wait(Vec2::new(2.0, 0.0)), "2 m goal-side: go for the ball");
        assert!(!wait(Vec2::new(5.0, 3.0)), "5 m off but 3 m wide: get across");
        assert!(!wait(Vec2::new(-3.0, 0.0)), "behind him: go for the ball");
    }
}
