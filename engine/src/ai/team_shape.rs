//! Team shape: each player's place in the formation, shifted with the ball and with possession.

use glam::Vec2;

use super::MatchView;
use crate::geometry::TeamFrame;
use crate::geometry::pitch::{CENTRE_CIRCLE_RADIUS, HALF_LENGTH, HALF_WIDTH};

/// Where player `g` should stand now (m, global frame): his home position, compressed towards the
/// ball, pushed up when his team has the ball and dropped back when it defends. Forwards in
/// possession make runs towards goal ahead of the ball.
pub fn position(view: &MatchView, g: usize, frame: TeamFrame) -> Vec2 {
    let p = &view.players[g];
    let ball = frame.vec2(view.ball.xy());
    let ours = match view.owner {
        Some(o) => view.players[o].side == p.side,
        None => view.last_touch.is_some_and(|t| view.players[t].side == p.side),
    };
    let home = p.home;
    let mut x = if ours { 0.5 * home.x + 0.6 * ball.x + 8.0 } else { 0.6 * home.x + 0.45 * ball.x - 6.0 };
    let mut y = 0.8 * home.y + 0.25 * ball.y;
    if ours && p.role.is_attacker() && home.x > -0.25 * HALF_LENGTH {
        // Off-the-ball run: get ahead of the ball, towards the goal, into the channel.
        x = x.max(ball.x + 8.0);
        y *= 0.7;
    }
    if !ours && p.role.is_defender() {
        // The back line stays goal-side of the ball.
        x = x.min(ball.x - 4.0);
    }
    x = x.clamp(-HALF_LENGTH + 4.0, HALF_LENGTH - 10.0);
    y = y.clamp(-HALF_WIDTH + 2.0, HALF_WIDTH - 2.0);
    let mut target = Vec2::new(x, y);
    // At an opponents' set piece keep the distance the laws ask for.
    if view.mode != crate::game::GameMode::Normal && !ours {
        let away = target - ball;
        if away.length() < CENTRE_CIRCLE_RADIUS + 0.5 {
            target = ball + away.normalize_or(Vec2::new(-1.0, 0.0)) * (CENTRE_CIRCLE_RADIUS + 0.5);
        }
    }
    frame.vec2(target)
}
