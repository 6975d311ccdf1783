//! Team shape: each player's place in the formation, shifted with the ball and with possession;
//! midfielders near the ball make support runs, forwards run in behind but stay onside; without
//! the ball, players near an opponent in their zone mark him.

use glam::Vec2;

use super::{Analysis, Difficulty, MatchView, marking};
use crate::geometry::TeamFrame;
use crate::geometry::pitch::{CENTRE_CIRCLE_RADIUS, HALF_LENGTH, HALF_WIDTH};
use crate::player::Role;

/// An opponent this close (m) to a player's place in the shape is marked by him.
const MARK_RADIUS: f32 = 9.0;
/// A midfielder whose place is this close (m) to the ball makes a support run.
const SUPPORT_RANGE: f32 = 25.0;
/// How far goal-side of his man a marker stands (m).
const MARK_DISTANCE: f32 = 1.8;

/// How far behind the offside line (m) a player of difficulty θ keeps: 1.5 m at θ = 1, and
/// about a metre beyond it at θ = 0 (weak teams stray offside).
pub fn onside_margin(theta: f32) -> f32 {
    2.5 * theta - 1.0
}

/// Where player `g` should stand now (m, global frame): his home position, compressed towards the
/// ball, pushed up when his team has the ball and dropped back when it defends. Forwards in
/// possession make runs towards goal ahead of the ball, but stay onside; defending players mark an
/// opponent in their zone, goal-side of him, more tightly at higher θ; a player the team's man
/// marking gave a man (`man`, global index) marks him instead ([`marking::position`]).
pub fn position(view: &MatchView, g: usize, analysis: &Analysis, difficulty: &Difficulty, man: Option<usize>) -> Vec2 {
    let frame = analysis.frame;
    let p = &view.players[g];
    let ball = frame.vec2(view.ball.xy());
    let ours = match view.owner {
        Some(o) => view.players[o].side == p.side,
        None => view.last_touch.is_some_and(|t| view.players[t].side == p.side),
    };
    let loose = view.owner.is_none() && view.last_touch.is_none();
    let mut y = block_y(
        p.role,
        p.home,
        ball,
        if ours {
            1.0
        } else if loose {
            0.5
        } else {
            0.0
        },
    );
    // Depth: touchline's own, which follows the ball further than GRF's block (GRF's depth alone
    // left touchline's attack without runners ahead of the ball: 0.7 shots a match).
    let home = p.home;
    let mut x = if ours { 0.5 * home.x + 0.6 * ball.x + 8.0 } else { 0.6 * home.x + 0.45 * ball.x - 6.0 };
    if ours && p.role.is_attacker() && p.home.x > -0.25 * HALF_LENGTH {
        // Off-the-ball run: get ahead of the ball, towards the goal.
        x = x.max(ball.x + 8.0);
    }
    if ours && view.owner != Some(g) && !p.role.is_defender() && !p.role.is_attacker() && !p.is_keeper() {
        // Support run: a midfielder near the ball offers a pass ahead of it, on his side of it.
        if Vec2::new(x, y).distance(ball) < SUPPORT_RANGE {
            let lateral = if p.home.y >= ball.y { 1.0 } else { -1.0 };
            let support = Vec2::new(ball.x + 4.0, ball.y + lateral * 8.0);
            let w = 0.1 + 0.2 * difficulty.theta;
            x += (support.x - x) * w;
            y += (support.y - y) * w;
        }
    }
    if ours && view.owner != Some(g) {
        // Stay onside: the offside line, less a margin that shrinks with θ.
        x = x.min(analysis.defensive_line - onside_margin(difficulty.theta));
    }
    if !ours && (p.role.is_defender() || x < ball.x) {
        // The back line stays goal-side of the ball, and anyone goal-side of it stays four metres
        // off it: only a hunter or a marker goes closer (GRF's defenders wait 3-6 m off).
        x = x.min(ball.x - 4.0);
    }
    x = x.clamp(-HALF_LENGTH + 4.0, HALF_LENGTH - 10.0);
    y = y.clamp(-HALF_WIDTH + 2.0, HALF_WIDTH - 2.0);
    let mut target = Vec2::new(x, y);
    if !ours && view.mode == crate::game::GameMode::Normal && !p.is_keeper() {
        target = match man {
            Some(m) => marking::position(p, &view.players[m], view.owner == Some(m), target, frame, difficulty.theta),
            None => mark(view, target, p.side.opponent(), frame, difficulty.theta),
        };
    }
    // At an opponents' set piece keep the distance the laws ask for.
    if view.mode != crate::game::GameMode::Normal && !ours {
        let away = target - ball;
        if away.length() < CENTRE_CIRCLE_RADIUS + 0.5 {
            target = ball + away.normalize_or(Vec2::new(-1.0, 0.0)) * (CENTRE_CIRCLE_RADIUS + 0.5);
        }
    }
    frame.vec2(target)
}

/// How fast (m/s) player `p` goes to his place in the shape: flat out near the play, lazier the
/// further he is from the ball (from 20 m, fully at 65 m, both shorter when tired) and the more
/// his role leans away from the phase (forwards when the team defends, defenders when it
/// attacks): GRF's laziness. The last metres are slowed by the arrival in `TeamAi::drive`
/// (GRF's 2.6 × distance).
pub fn pace(view: &MatchView, p: &crate::player::Player) -> f32 {
    let fresh = 1.0 - p.fatigue;
    let start = 20.0 * (0.8 * fresh + 0.2);
    let end = 65.0 * (0.5 * fresh + 0.5);
    let far = ((p.position.distance(view.ball.xy()) - start) / (end - start)).clamp(0.0, 1.0);
    // GRF's fading team possession above one half: about 0.75 in possession, 0.1 without.
    let possession = match view.owner_side() {
        Some(s) if s == p.side => 0.75,
        Some(_) => 0.1,
        None => 0.4,
    };
    let mind_set = marking::mind_set(p.role);
    let by_role = mind_set + possession * (1.0 - 2.0 * mind_set);
    p.max_speed * (1.0 - far * (0.5 + 0.5 * by_role))
}

/// A player's place across the pitch (team frame, m) in GRF's moving block (GRF 2.10's team AI),
/// before marking: the block's width is lerped between the defending and attacking tactics by
/// the possession bias `p` (1: the ball is ours, 0: theirs), the back four a little wider with the
/// ball; its centre follows the ball, shrunk towards the middle; the formation's place (`home`, m)
/// maps linearly into it. Then players drift across towards the ball's side (GRF's y-focus). With
/// the ball, the full backs and the wide midfielders take the width of the pitch (at least 60 %
/// and 80 % of the half-width out): play that looks like football, beyond GRF's narrower shape.
fn block_y(role: Role, home: Vec2, ball: Vec2, p: f32) -> f32 {
    let lerp = |defence: f32, offence: f32| defence + (offence - defence) * p;
    let wide_midfield = matches!(role, Role::LM | Role::RM);
    let width = 0.95 * if role.is_defender() { lerp(0.8, 1.0) } else { lerp(0.8, 0.9) };
    let centre_y = ball.y * ((1.0 - width) * 0.9 + 0.1);
    // Formation places in GRF's [-1, 1] units: y over 36 m.
    let hy = home.y / 36.0;
    let mut y = centre_y + hy * width * HALF_WIDTH;
    if p > 0.5 && (matches!(role, Role::LB | Role::RB) || wide_midfield) {
        let out = if wide_midfield { 0.85 } else { 0.7 } * HALF_WIDTH * (2.0 * p - 1.0);
        if y.abs() < out {
            y = out.copysign(if hy != 0.0 { hy } else { y });
        }
    }
    // Drift across towards the ball's side: stronger with the ball and when it is wide.
    let across = (0.5 * p + 0.2 * (1.0 - p))
        * (1.0 - (ball.y - y).abs() / (2.0 * HALF_WIDTH)).max(0.0)
        * (0.2 + 0.8 * ball.y.abs() / HALF_WIDTH);
    y + (ball.y - y) * across * 0.25
}

/// Moves a defending player's place `target` (team frame) towards the goal side of the nearest
/// opponent in his zone, if any.
fn mark(view: &MatchView, target: Vec2, opponents: crate::geometry::Side, frame: TeamFrame, theta: f32) -> Vec2 {
    let own_goal = Vec2::new(-HALF_LENGTH, 0.0);
    let mut best = None;
    let mut best_d2 = MARK_RADIUS * MARK_RADIUS;
    for g in view.ranges[opponents.index()].clone() {
        let o = &view.players[g];
        if !o.active || o.is_keeper() || view.owner == Some(g) {
            continue;
        }
        let at = frame.vec2(o.position);
        let d2 = at.distance_squared(target);
        if d2 < best_d2 {
            best_d2 = d2;
            best = Some(at);
        }
    }
    let Some(man) = best else { return target };
    let spot = man + (own_goal - man).normalize_or(Vec2::NEG_X) * MARK_DISTANCE;
    target.lerp(spot, 0.3 + 0.6 * theta)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn better_teams_keep_further_onside() {
        assert!(onside_margin(1.0) > 1.0);
        assert!(onside_margin(0.0) < 0.0);
        assert!(onside_margin(0.6) > onside_margin(0.3));
    }
}
