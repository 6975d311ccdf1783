//! Behaviours that play the ball: `dribble_to` (then shoot), `pass_to` and `press`. They reuse
//! the built-in AI's pieces: its ball-path prediction to run onto a loose ball, its closing-down
//! point against a carrier, and the kick aiming of [`Match::execute_kick`](crate::game::Match)
//! (shots aimed away from the keeper).

use glam::Vec2;

use super::movement::{arrive, hold, idle};
use crate::ai::BallPath;
use crate::ai::pressing::close_down;
use crate::game::{Kick, KickKind, KickTarget, PlayerInput};
use crate::geometry::TeamFrame;
use crate::geometry::pitch::HALF_LENGTH;
use crate::physics::Ball;
use crate::player::Player;
use crate::scenario::PassKind;

/// How far (m) opponents stand off the ball at a restart (Law 13: 9.15 m).
pub(crate) const RESTART_DISTANCE: f32 = 9.15;
/// A dribbler this close (m) to his point has arrived (and shoots, when asked).
pub(crate) const DRIBBLE_ARRIVED: f32 = 1.5;
/// Within this distance (m) of a loose ball a player runs straight at it instead of where the
/// predicted path meets him.
const STRAIGHT_AT_BALL: f32 = 3.0;
/// Highest ball (m) a runner plans to meet: what he can control with his feet or chest.
const MEET_HEIGHT: f32 = 1.9;

/// Run through `target` at full speed (chasing: no slowing down on arrival).
#[inline]
fn run_through(p: &Player, target: Vec2, look: Vec2) -> PlayerInput {
    let velocity = (target - p.position).normalize_or_zero() * p.max_speed;
    PlayerInput { velocity, look, ..PlayerInput::default() }
}

/// Ticks a runner keeps the meeting point he chose on a loose ball before choosing again (the
/// built-in AI's quickest reaction, 50 ms): predicting the ball's path is the costly part of
/// chasing it.
const REPLAN_TICKS: u64 = 5;

/// What a player chasing a loose ball works from this tick: the ball's predicted path (made once
/// a tick, by the first player who needs it, and shared) and his own last meeting point with the
/// tick he chose it (kept in his behaviour state, so snapshots keep it).
pub(crate) struct Chase<'a> {
    /// This tick's prediction, if made.
    pub(crate) path: &'a mut Option<BallPath>,
    /// The player's meeting point (m) and the in-play tick it was chosen at.
    pub(crate) meet: &'a mut Option<(Vec2, u64)>,
    /// The current in-play tick.
    pub(crate) tick: u64,
}

/// Go and get a ball nobody of the other team has: straight at it when close, else to where its
/// predicted path ([`BallPath`]) meets him, chosen again every [`REPLAN_TICKS`].
pub(crate) fn fetch(p: &Player, ball: &Ball, chase: &mut Chase) -> PlayerInput {
    let at = ball.xy();
    let target = if p.position.distance(at) < STRAIGHT_AT_BALL {
        *chase.meet = None;
        at + ball.velocity.truncate() * 0.1
    } else {
        match *chase.meet {
            Some((meet, since)) if chase.tick < since + REPLAN_TICKS => meet,
            _ => {
                let path = chase.path.get_or_insert_with(|| BallPath::predict(ball));
                let meet = path.intercept(p.position, p.max_speed, MEET_HEIGHT).1;
                *chase.meet = Some((meet, chase.tick));
                meet
            }
        }
    };
    run_through(p, target, at - p.position)
}

/// `dribble_to(point) [then shoot]` for `p`, who has the ball when `owns`. Returns the input and
/// whether the behaviour finished this tick (arrived, or shot on arrival).
pub(crate) fn dribble(
    p: &Player,
    owns: bool,
    ball: &Ball,
    chase: &mut Chase,
    point: Vec2,
    shoot: bool,
) -> (PlayerInput, bool) {
    if !owns {
        return (fetch(p, ball, chase), false);
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
pub(crate) fn pass(
    p: &Player,
    owns: bool,
    ball: &Ball,
    chase: &mut Chase,
    mate: &Player,
    kind: PassKind,
) -> (PlayerInput, bool) {
    if !owns {
        return (fetch(p, ball, chase), false);
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
/// his own team has the ball (standing still if he has it himself). While the other team's set
/// piece waits (`their_restart`), he stands [`RESTART_DISTANCE`] off the ball, goal-side (Law 13).
pub(crate) fn press(
    p: &Player,
    carrier: Option<&Player>,
    ball: &Ball,
    chase: &mut Chase,
    anchor: Vec2,
    their_restart: bool,
) -> PlayerInput {
    let at = ball.xy();
    if their_restart {
        let own_goal = Vec2::new(-p.side.attack_sign() * HALF_LENGTH, 0.0);
        let spot = at + (own_goal - at).normalize_or_zero() * RESTART_DISTANCE;
        return arrive(p, spot, p.max_speed, at - p.position);
    }
    match carrier {
        Some(c) if c.side != p.side => match close_down(p, c, at) {
            (target, true) => run_through(p, target, at - p.position),
            (target, false) => arrive(p, target, p.max_speed, at - p.position),
        },
        Some(c) if c.index == p.index => idle(p, at),
        Some(_) => hold(p, anchor, at),
        None => fetch(p, ball, chase),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;

    fn player(side: Side, index: usize, x: f32, y: f32) -> Player {
        Player::new(side, index, Role::CM, Vec2::new(x, y), Vec2::ZERO)
    }

    #[test]
    fn press_closes_down_an_opponent_and_stands_off_at_his_restart() {
        let presser = player(Side::Left, 1, 0.0, 0.0);
        let carrier = player(Side::Right, 1, 10.0, 0.0);
        let ball = Ball::at_rest(Vec2::new(9.5, 0.0));
        let v = press(
            &presser,
            Some(&carrier),
            &ball,
            &mut Chase { path: &mut None, meet: &mut None, tick: 0 },
            Vec2::ZERO,
            false,
        )
        .velocity;
        assert!(v.x > 7.0 && v.y.abs() < 1e-4, "{v}");
        // At the other team's restart: 9.15 m off the ball towards his own goal (-x).
        let standing = player(Side::Left, 1, 9.5 - RESTART_DISTANCE, 0.0);
        let v = press(
            &standing,
            Some(&carrier),
            &ball,
            &mut Chase { path: &mut None, meet: &mut None, tick: 0 },
            Vec2::ZERO,
            true,
        )
        .velocity;
        assert_eq!(v, Vec2::ZERO);
        // A team-mate on the ball: back to his place.
        let mate = player(Side::Left, 2, 10.0, 0.0);
        let v = press(
            &presser,
            Some(&mate),
            &ball,
            &mut Chase { path: &mut None, meet: &mut None, tick: 0 },
            Vec2::new(-5.0, 0.0),
            false,
        )
        .velocity;
        assert!(v.x < 0.0);
    }

    #[test]
    fn pass_and_dribble_fetch_the_ball_first_and_finish_with_a_kick() {
        let me = player(Side::Right, 1, 0.0, 0.0);
        let mate = player(Side::Right, 2, -20.0, 5.0);
        let ball = Ball::at_rest(Vec2::new(2.0, 0.0));
        let (input, done) =
            pass(&me, false, &ball, &mut Chase { path: &mut None, meet: &mut None, tick: 0 }, &mate, PassKind::High);
        assert!(!done && input.kick.is_none() && input.velocity.x > 0.0);
        let (input, done) =
            pass(&me, true, &ball, &mut Chase { path: &mut None, meet: &mut None, tick: 0 }, &mate, PassKind::High);
        let kick = input.kick.expect("a pass");
        assert!(done && kick.kind == KickKind::HighPass);
        assert_eq!(kick.target, KickTarget::Point(mate.position));
        // The right team shoots at -x.
        let (input, done) = dribble(
            &me,
            true,
            &ball,
            &mut Chase { path: &mut None, meet: &mut None, tick: 0 },
            Vec2::new(1.0, 0.0),
            true,
        );
        assert!(done && input.kick.is_some_and(|k| k.target == KickTarget::Direction(Vec2::NEG_X)));
        let (input, done) = dribble(
            &me,
            true,
            &ball,
            &mut Chase { path: &mut None, meet: &mut None, tick: 0 },
            Vec2::new(-20.0, 0.0),
            true,
        );
        assert!(!done && input.kick.is_none() && input.velocity.x < 0.0);
    }
}
