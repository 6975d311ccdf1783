//! Behaviours that play the ball: `dribble_to` (then shoot), `pass_to` and `press`. They reuse
//! the built-in AI's pieces: its ball-path prediction to run onto a loose ball, its closing-down
//! point against a carrier, and the kick aiming of [`Match::execute_kick`](crate::game::Match)
//! (shots aimed away from the keeper).

use glam::Vec2;

use super::movement::{hold, idle};
use crate::ai::BallPath;
use crate::ai::pressing::close_down;
use crate::game::{Kick, KickKind, KickTarget, PlayerInput};
use crate::geometry::TeamFrame;
use crate::physics::Ball;
use crate::player::Player;
use crate::scenario::PassKind;

/// A dribbler this close (m) to his point has arrived (and shoots, when asked).
pub(crate) const DRIBBLE_ARRIVED: f32 = 1.5;
/// Within this distance (m) of a loose ball a player runs straight at it instead of where the
/// predicted path meets him.
const STRAIGHT_AT_BALL: f32 = 3.0;
/// Highest ball (m) a runner plans to meet: what he can control with his feet or chest.
const MEET_HEIGHT: f32 = 1.9;

/// Run through `target` at full speed (chasing: no slowing down on arrival).
#[inline]
fn chase(p: &Player, target: Vec2, look: Vec2) -> PlayerInput {
    let velocity = (target - p.position).normalize_or_zero() * p.max_speed;
    PlayerInput { velocity, look, ..PlayerInput::default() }
}

/// Go and get a ball nobody of the other team has: straight at it when close, else to where its
/// predicted path ([`BallPath`]) meets him.
pub(crate) fn fetch(p: &Player, ball: &Ball) -> PlayerInput {
    let at = ball.xy();
    let target = if p.position.distance(at) < STRAIGHT_AT_BALL {
        at + ball.velocity.truncate() * 0.1
    } else {
        BallPath::predict(ball).intercept(p.position, p.max_speed, MEET_HEIGHT).1
    };
    chase(p, target, at - p.position)
}

/// `dribble_to(point) [then shoot]` for `p`, who has the ball when `owns`. Returns the input and
/// whether the behaviour finished this tick (arrived, or shot on arrival).
pub(crate) fn dribble(p: &Player, owns: bool, ball: &Ball, point: Vec2, shoot: bool) -> (PlayerInput, bool) {
    if !owns {
        return (fetch(p, ball), false);
    }
    let to = point - p.position;
    let dist = to.length();
    if dist > DRIBBLE_ARRIVED {
        let velocity = to * (p.max_speed / dist);
        return (PlayerInput { velocity, look: to, ..PlayerInput::default() }, false);
    }
    if !shoot {
        return (idle(p, ball.xy() + to), true);
    }
    // At the goal, aimed away from the keeper when the kick is made.
    let at_goal = TeamFrame::of(p.side).vec2(Vec2::X);
    let kick = Kick { kind: KickKind::Shot, target: KickTarget::Direction(at_goal), height: 0.5, power: 0.6 };
    (PlayerInput { kick: Some(kick), look: at_goal, ..PlayerInput::default() }, true)
}

/// `pass_to(mate, kind)` for `p`, who has the ball when `owns`: played at once, aimed where the
/// team-mate will be (as the AI's passes). Returns the input and whether the pass was played.
pub(crate) fn pass(p: &Player, owns: bool, ball: &Ball, mate: &Player, kind: PassKind) -> (PlayerInput, bool) {
    if !owns {
        return (fetch(p, ball), false);
    }
    let d = mate.position.distance(p.position);
    let aim = mate.position + mate.velocity * (d / 18.0);
    let kind = match kind {
        PassKind::Short => KickKind::ShortPass,
        PassKind::Long => KickKind::LongPass,
        PassKind::High => KickKind::HighPass,
    };
    let kick = Kick { kind, target: KickTarget::Point(aim), height: 0.0, power: 0.5 };
    (PlayerInput { kick: Some(kick), look: aim - p.position, ..PlayerInput::default() }, true)
}

/// `press`: close down an opposing `carrier` (the AI's closing-down point; within reach the
/// engine's standing challenge does the tackling), go for a loose ball, and hold `anchor` while
/// his own team has the ball (standing still if he has it himself).
pub(crate) fn press(p: &Player, carrier: Option<&Player>, ball: &Ball, anchor: Vec2) -> PlayerInput {
    let at = ball.xy();
    match carrier {
        Some(c) if c.side != p.side => chase(p, close_down(p, c, at), at - p.position),
        Some(c) if c.index == p.index => idle(p, at),
        Some(_) => hold(p, anchor, at),
        None => fetch(p, ball),
    }
}
