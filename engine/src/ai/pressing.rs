//! Pressing and covering: when the team does not have the ball, the player who reaches it first
//! goes for it (within the difficulty's hunt distance) and the next one covers between the ball
//! and the goal.

use glam::Vec2;

use super::{Analysis, Difficulty, MatchView, Plan};
use crate::geometry::pitch::HALF_LENGTH;
use crate::player::{Player, WALK_SPEED};

/// Where presser `p` runs to close down `carrier` with the ball at `ball` (m, global): a little
/// ahead of him and goal-side, then, within 2.5 m, at the ball itself in front of him (standing
/// off goal-side, a still carrier could shield it for ever). Shared with the `press` behaviour.
pub(crate) fn close_down(p: &Player, carrier: &Player, ball: Vec2) -> Vec2 {
    if p.position.distance(carrier.position) < 2.5 {
        if crate::game::duel_likeliness(p.position, carrier.position, ball) < 0.2
            && carrier.velocity.length() < WALK_SPEED
        {
            // Behind a carrier who stands, his body between us and the ball: stay on his back
            // (GRF's defender does not run round a still carrier; contact draws him round slowly,
            // if at all). A carrier on the run he chases down to the ball and comes round.
            return carrier.position + (p.position - carrier.position).normalize_or_zero() * 0.8;
        }
        ball + (ball - carrier.position).normalize_or_zero() * 0.3
    } else {
        let own_goal = Vec2::new(-p.side.attack_sign() * HALF_LENGTH, 0.0);
        carrier.position + carrier.velocity * 0.3 + (own_goal - carrier.position).normalize_or_zero() * 0.6
    }
}

/// A pressing or covering plan for player `g`, or `None` when he should hold his place.
pub fn plan(view: &MatchView, g: usize, analysis: &Analysis, difficulty: &Difficulty) -> Option<Plan> {
    let p = &view.players[g];
    let ball = view.ball.xy();
    let ours = view.owner_side() == Some(p.side);
    if ours {
        return None;
    }
    let (mut chaser, _, meet) = analysis.chaser?;
    if view.owner.is_some() && view.agent_driven.get(chaser) == Some(&true) {
        // The team-mate nearest the carrier is an agent's player, whom the AI cannot send: the
        // next one presses (GRF's AI hunts a carrier with the two players nearest him).
        chaser = analysis.second.unwrap_or(chaser);
    }
    if chaser == g {
        let loose = view.owner.is_none();
        if loose || p.position.distance(ball) <= difficulty.hunt_distance {
            let target = match view.owner {
                // Close down the carrier: aim a little ahead of him, goal-side.
                Some(o) => close_down(p, &view.players[o], ball),
                // Close to a loose ball: go straight at it.
                None if p.position.distance(ball) < 3.0 => ball + view.ball.velocity.truncate() * 0.1,
                None => meet,
            };
            return Some(Plan { run_through: true, ..Plan::go(target, p.max_speed, ball - p.position) });
        }
    }
    if analysis.second == Some(g) && view.owner.is_some() && difficulty.theta >= 0.3 {
        // Cover: between the ball and our goal, six metres off the ball.
        let own_goal = Vec2::new(-p.side.attack_sign() * HALF_LENGTH, 0.0);
        let target = ball + (own_goal - ball).normalize_or_zero() * 6.0;
        return Some(Plan::go(target, p.max_speed * 0.85, ball - p.position));
    }
    None
}
