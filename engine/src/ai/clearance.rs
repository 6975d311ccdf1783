//! The first-time clearance, GRF's "panic pass": a keeper or centre back going for a loose ball
//! that an opponent contests does not stop to control it. The kick is decided while he is still
//! running in, so his first touch hoofs it high and away, and he never shows as its owner.
//!
//! GRF 2.10's on-the-ball AI decides for the player designated to the ball once he needs under a
//! second to reach it. A player whose role's mind-set is below 0.25 (GK, CB; see
//! [`Role::mind_set`](crate::player::Role::mind_set)) panics when his possession is weak:
//! possession amount = (opponents' time to the ball + 0.2 s) / (his time + 0.2 s). A keeper panics
//! below 3 (outside his hands' reach; in his area he catches instead). A centre back panics below
//! 0.9 + 0.8·p·c if no team-mate is worth a pass or the best is rated below p·c. Here p = 1 − 2 ×
//! mind-set (proneness) and c is his closeness to his own goal, 1 at 2 m falling to 0 at 16 m.
//! The clearance is a high pass at power 0.7 (42 m) along his facing, flattened in x by 0.8 and
//! bent 0.7 towards the opponents' goal and 0.5 to the side he faces.

use glam::Vec2;

use super::ball_carrier::distance_to_segment;
use super::{Analysis, MatchView};
use crate::game::{Kick, KickKind, KickTarget};
use crate::geometry::pitch::HALF_LENGTH;

/// GRF's AI decides what to do on the ball once the player needs less than this to reach it (s).
const DECIDE_WITHIN: f32 = 1.0;
/// Added to both times to the ball in the possession amount (s), GRF's 200 ms.
pub(crate) const TIME_MARGIN: f32 = 0.2;
/// A keeper clears first time while his possession amount is below this.
const KEEPER_PANIC: f32 = 3.0;
/// How far the clearance is aimed (m): GRF's high pass at input power 0.7 reaches 0.7 × 60 m.
const REACH: f32 = 42.0;
/// A team-mate must be this much further upfield (m) to be worth passing to instead.
const UPFIELD: f32 = 5.0;

/// The first-time clearance `g` strikes at the loose ball, if he is the one to reach it and
/// panics (see the module docs); `None` while the ball is owned or he would control it.
pub(crate) fn first_time(view: &MatchView, g: usize, analysis: &Analysis) -> Option<Kick> {
    if view.owner.is_some() {
        return None;
    }
    let me = &view.players[g];
    let mind_set = me.role.mind_set();
    if mind_set >= 0.25 {
        return None;
    }
    let own_time = if me.is_keeper() {
        let (t, _) = analysis.path.intercept(me.position, me.max_speed, 1.0);
        // The keeper is the one to play the ball only if he gets there before his outfield players.
        if analysis.chaser.is_some_and(|(_, mate, _)| mate < t) {
            return None;
        }
        t
    } else {
        match analysis.chaser {
            Some((chaser, t, _)) if chaser == g => t,
            _ => return None,
        }
    };
    if own_time > DECIDE_WITHIN {
        return None;
    }
    let amount = (analysis.opponent_time + TIME_MARGIN) / (own_time + TIME_MARGIN);
    let panics = if me.is_keeper() {
        amount < KEEPER_PANIC
    } else {
        let proneness = 1.0 - 2.0 * mind_set;
        let own_goal = Vec2::new(-me.side.attack_sign() * HALF_LENGTH, 0.0);
        let closeness = 1.0 - ((me.position.distance(own_goal) - 2.0) / 14.0).clamp(0.0, 1.0);
        let danger = proneness * closeness;
        best_pass_rating(view, g, analysis).is_none_or(|rating| rating < danger) && amount < 0.9 + 0.8 * danger
    };
    if !panics {
        return None;
    }
    let facing = me.facing;
    let flat = Vec2::new(facing.x * 0.8, facing.y).normalize_or(facing);
    let side = if facing.y > 0.0 { 1.0 } else { -1.0 };
    let away = (flat + Vec2::new(me.side.attack_sign() * 0.7, side * 0.5)).normalize_or(flat);
    let from = analysis.chaser.filter(|(c, _, _)| *c == g).map_or(view.ball.xy(), |(_, _, meet)| meet);
    Some(Kick { kind: KickKind::HighPass, target: KickTarget::Point(from + away * REACH), height: 0.0, power: 0.7 })
}

/// How good a pass `g` has instead, in [0, 1]: the best over team-mates (keeper aside) at least
/// [`UPFIELD`] further up the pitch and 5–50 m away, of how clear their lane is (1 when no
/// opponent comes within twice the margin a pass needs). `None` when nobody is worth it: GRF
/// passes only to a team-mate placed better than the passer.
fn best_pass_rating(view: &MatchView, g: usize, analysis: &Analysis) -> Option<f32> {
    let me = &view.players[g];
    let frame = analysis.frame;
    let from = frame.vec2(me.position);
    let opponents = view.team(me.side.opponent());
    let mut best = None;
    for mate in view.team(me.side) {
        if !mate.active || mate.index == me.index || mate.is_keeper() {
            continue;
        }
        let to = frame.vec2(mate.position);
        let d = to.distance(from);
        if to.x < from.x + UPFIELD || !(5.0..=50.0).contains(&d) {
            continue;
        }
        let margin = 1.5 + 0.06 * d;
        let lane = opponents
            .iter()
            .filter(|o| o.active)
            .map(|o| distance_to_segment(frame.vec2(o.position), from, to))
            .fold(f32::INFINITY, f32::min);
        if lane <= margin {
            continue;
        }
        let rating = (lane / (2.0 * margin)).min(1.0);
        best = Some(best.map_or(rating, |b: f32| b.max(rating)));
    }
    best
}
