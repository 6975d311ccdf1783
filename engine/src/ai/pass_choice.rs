//! Whom the AI's ball carrier passes to, GRF's on-the-ball AI (GRF 2.10): every player's tactical
//! situation is rated (space ahead of him, space round him, closeness to the opponents' goal, the
//! last weighted by how attacking the carrier's role is), and the carrier passes only to a
//! team-mate rated better than himself by a margin, weighing that gain against the odds the ball
//! gets there past the opponents. A defender wants a clear gain and a safe ball; a forward passes
//! only to someone nearer goal. The longer he keeps the ball, the readier he is to let it go.

use glam::Vec2;

use crate::game::KickKind;
use crate::geometry::TeamFrame;
use crate::geometry::pitch::HALF_LENGTH;
use crate::player::{MAX_PLAYERS_PER_TEAM, Player, SPRINT_SPEED};

/// The opponents as the carrier's ratings and odds see them: each active one where his run takes
/// him in 0.2 s (team frame, m), and whether he plays outfield. Worked out once per decision: a
/// carrier's choice rates his space and each team-mate's and the odds of three passes to each,
/// and every one of those looked at every opponent (a team has at most
/// [`MAX_PLAYERS_PER_TEAM`]).
pub(crate) struct Rivals {
    at: [Vec2; MAX_PLAYERS_PER_TEAM],
    len: usize,
    /// The outfield ones' places alone, in the same order: every rating's free space looks at
    /// them twice, and picking them out of `at` each time cost a test and a branch per opponent.
    outfield: [Vec2; MAX_PLAYERS_PER_TEAM],
    outfield_len: usize,
}

impl Rivals {
    /// The active ones of `opponents`, seen in `frame`.
    pub(crate) fn of(opponents: &[Player], frame: TeamFrame) -> Rivals {
        let mut rivals = Rivals {
            at: [Vec2::ZERO; MAX_PLAYERS_PER_TEAM],
            len: 0,
            outfield: [Vec2::ZERO; MAX_PLAYERS_PER_TEAM],
            outfield_len: 0,
        };
        for o in opponents.iter().filter(|o| o.active).take(MAX_PLAYERS_PER_TEAM) {
            let at = frame.vec2(o.position + o.velocity * 0.2);
            rivals.at[rivals.len] = at;
            rivals.len += 1;
            if !o.is_keeper() {
                rivals.outfield[rivals.outfield_len] = at;
                rivals.outfield_len += 1;
            }
        }
        rivals
    }

    /// Where each one will be, in `opponents`' order.
    fn at(&self) -> &[Vec2] {
        &self.at[..self.len]
    }

    /// Where each outfield one will be, in `opponents`' order.
    fn outfield_at(&self) -> &[Vec2] {
        &self.outfield[..self.outfield_len]
    }
}

/// How free of opponents the point `focus` (team frame, m) will be in `time` s, in [0, 1]: each
/// outfield opponent, from where his run takes him in 0.2 s, sprints towards it for the rest of
/// the time; within 5 m of it he counts 1 − distance/5 m, and 2.5 such counts leave no space
/// (GRF's free space).
fn free_space(focus: Vec2, time: f32, rivals: &Rivals) -> f32 {
    const SAFE: f32 = 5.0;
    let reach = SPRINT_SPEED * (time - 0.2).max(0.0);
    let mut crowd = 0.0;
    for &at in rivals.outfield_at() {
        let gap = (focus - at).length();
        let left = (gap - reach).max(0.0);
        crowd += 1.0 - left.min(SAFE) / SAFE;
    }
    1.0 - (crowd / 2.5).clamp(0.0, 1.0)
}

/// `p`'s tactical situation in [0, 1] as a carrier who weighs closeness to goal by
/// `forward_weight` sees it: 0.4 × the space 4 m ahead of him (half a second's sprint), 0.3 × the
/// space where he stands, `forward_weight` × his closeness to the opponents' goal, (1 − distance
/// over the pitch's length)^1.5, over the weights' sum.
fn tactical_rating(p: &Player, rivals: &Rivals, frame: TeamFrame, forward_weight: f32) -> f32 {
    let at = frame.vec2(p.position);
    let ahead = free_space(at + Vec2::X * SPRINT_SPEED * 0.5, 0.5, rivals);
    let here = free_space(at + frame.vec2(p.velocity) * 0.1, 0.1, rivals);
    (0.4 * ahead + 0.3 * here + forward_weight * closeness_to_goal(at)) / (0.7 + forward_weight)
}

/// The most [`tactical_rating`] can give `p`: all the space in the world, so only his closeness to
/// goal counts. Cheap (no opponent is looked at): a team-mate whose best is no gain is passed
/// over without rating his space.
fn best_rating(p: &Player, frame: TeamFrame, forward_weight: f32) -> f32 {
    (0.7 + forward_weight * closeness_to_goal(frame.vec2(p.position))) / (0.7 + forward_weight)
}

/// Closeness to the opponents' goal of a player at `at` (team frame, m), in [0, 1]: (1 − distance
/// over the pitch's length)^1.5, as x·√x (a powf per rating was a twentieth of a match's step).
fn closeness_to_goal(at: Vec2) -> f32 {
    let x = 1.0 - (at.distance(Vec2::new(HALF_LENGTH, 0.0)) / (2.0 * HALF_LENGTH)).clamp(0.0, 1.0);
    x * x.sqrt()
}

/// The odds, in [0, 1], that a ball of `kind` played from `origin` to `target` (team frame, m)
/// gets there before an opponent (GRF's passing odds). Each opponent near the ball's line, from
/// where his run takes him in 0.2 s, sprints to the point of it nearest him; the ball takes 0.7 s
/// plus 0.03 s a metre to get there, divided by `pace` (3 for a shot). Every half second he would
/// be early, up to a second, adds danger; one second of danger is no chance. A lofted ball is
/// safe over the middle of its flight, needs 2.5 s more to be controlled in its second half, and
/// carries 0.4 of danger anyway, so that a ground pass is preferred where it can be played.
pub(crate) fn passing_odds(origin: Vec2, target: Vec2, kind: KickKind, rivals: &Rivals, pace: f32) -> f32 {
    let line = target - origin;
    let length2 = line.length_squared().max(1e-6);
    let lofted = kind == KickKind::HighPass;
    let mut danger = if lofted { 0.4 } else { 0.0 };
    for &at in rivals.at() {
        let u = (at - origin).dot(line) / length2;
        if !(0.0..=1.2).contains(&u) || (lofted && (0.2..=0.65).contains(&u)) {
            continue;
        }
        let meet = origin + line * u.min(1.0);
        let his_time = (at.distance(meet) + 1.0) / SPRINT_SPEED;
        let trap = if lofted && u > 0.5 { 2.5 } else { 0.0 };
        let ball_time = (0.7 + (meet - origin).length() * u * 0.03 + trap) / pace;
        danger += (ball_time - his_time + 0.5).clamp(0.0, 1.0);
    }
    1.0 - danger.clamp(0.0, 1.0)
}

/// [`passing_odds`] of a ground pass ([`KickKind::ShortPass`]) and of a lofted one
/// ([`KickKind::HighPass`]) from `origin` to the same `target` at pace 1, in one look at the
/// opponents: the two share each opponent's place along the line, his meeting point and his time
/// to it, and each sum of danger is taken in the same order with the same operations as
/// `passing_odds` takes it (a division by pace 1 and a ground ball's trap of +0 change no
/// positive time, so they are left out), so both odds are
/// the same bit for bit. A carrier weighs both for most team-mates at every decision.
fn ground_and_lofted_odds(origin: Vec2, target: Vec2, rivals: &Rivals) -> (f32, f32) {
    let line = target - origin;
    let length2 = line.length_squared().max(1e-6);
    let (mut ground, mut lofted) = (0.0, 0.4);
    for &at in rivals.at() {
        let u = (at - origin).dot(line) / length2;
        if !(0.0..=1.2).contains(&u) {
            continue;
        }
        let meet = origin + line * u.min(1.0);
        let his_time = (at.distance(meet) + 1.0) / SPRINT_SPEED;
        let flight = 0.7 + (meet - origin).length() * u * 0.03;
        ground += (flight - his_time + 0.5).clamp(0.0, 1.0);
        if !(0.2..=0.65).contains(&u) {
            let trap = if u > 0.5 { 2.5 } else { 0.0 };
            lofted += (flight + trap - his_time + 0.5).clamp(0.0, 1.0);
        }
    }
    (1.0 - ground.clamp(0.0, 1.0), 1.0 - lofted.clamp(0.0, 1.0))
}

/// The pass a carrier chose: to `mate` (his slot in the team), of `kind`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PassChoice {
    /// The receiver's slot in the team (the observation order).
    pub mate: usize,
    /// Ground, driven or lofted.
    pub kind: KickKind,
    /// The odds it gets to him, in [0, 1].
    pub odds: f32,
}

/// Where the odds of a pass to `mate` are judged (team frame): where his run takes him while the
/// ball travels (at most half a second of it), led a fifth of the distance forward for a driven
/// pass (GRF's passing odds to a player).
fn pass_point(from: Vec2, mate: &Player, kind: KickKind, frame: TeamFrame) -> Vec2 {
    let at = frame.vec2(mate.position);
    let distance = at.distance(from);
    let travel = (0.7 + distance * 0.03).clamp(0.0, 0.5);
    let mut point = at + frame.vec2(mate.velocity) * travel;
    if kind == KickKind::LongPass {
        point.x += 0.2 * distance;
    }
    point
}

/// The pass the carrier `me` makes now, if any (GRF's on-the-ball AI). `owned_ticks`: how long he
/// has had the ball; `passing`: his passing skill after difficulty, in [0, 1]; `ball_velocity`:
/// the ball's (global, m/s), which makes a first-time pass harder the more it differs from his run.
pub(crate) fn choose(
    me: &Player,
    mates: &[Player],
    opponents: &[Player],
    owned_ticks: u32,
    passing: f32,
    ball_velocity: Vec2,
) -> Option<PassChoice> {
    let frame = TeamFrame::of(me.side);
    let mindset = me.role.mind_set();
    // Held for 5 s or more, any sensible pass will do.
    let held = (owned_ticks as f32 / 500.0).min(1.0);
    let long_possession = held * held;
    let forward_weight = 2.0 + 6.0 * mindset;
    let improvement = 0.06 * (1.0 - mindset);
    let gain_weight = 1.0 + mindset * mindset * 10.0;
    let least_odds = 0.2 * (1.0 - mindset) - 0.1 * long_possession;
    let threshold = 0.1 - 0.05 * long_possession;
    let mismatch = ((ball_velocity - me.velocity).length() / 10.0).clamp(0.0, 1.0);
    let first_time = mismatch * (1.0 - 0.8 * passing);

    let rivals = Rivals::of(opponents, frame);
    let own = tactical_rating(me, &rivals, frame, forward_weight);
    let origin = frame.vec2(me.position + me.velocity * 0.12);
    let mut best: Option<PassChoice> = None;
    let mut best_total = 0.0;
    for (i, mate) in mates.iter().enumerate() {
        if !mate.active || mate.index == me.index {
            continue;
        }
        // A pass back to the keeper is the last resort.
        let keeper_factor = if mate.is_keeper() { 0.7 } else { 1.0 };
        // (The margin covers rounding: the bound must never pass over a rating that would count.)
        if best_rating(mate, frame, forward_weight) * keeper_factor + 1e-4 <= own + improvement {
            continue;
        }
        let rating = tactical_rating(mate, &rivals, frame, forward_weight) * keeper_factor;
        if rating <= own + improvement {
            continue;
        }
        let distance = mate.position.distance(me.position);
        let from = frame.vec2(me.position);
        // A ground and a lofted pass are judged at the same point (only a driven one is led).
        let point = pass_point(from, mate, KickKind::ShortPass, frame);
        let (short, high) = if distance < 10.0 {
            (passing_odds(origin, point, KickKind::ShortPass, &rivals, 1.0), 0.0)
        } else {
            ground_and_lofted_odds(origin, point, &rivals)
        };
        let long =
            passing_odds(origin, pass_point(from, mate, KickKind::LongPass, frame), KickKind::LongPass, &rivals, 1.0);
        let (mut kind, mut odds) = (KickKind::ShortPass, f32::NEG_INFINITY);
        for (k, o) in [(KickKind::ShortPass, short), (KickKind::LongPass, long), (KickKind::HighPass, high)] {
            if o > odds {
                (kind, odds) = (k, o);
            }
        }
        let total = ((rating - own) * gain_weight + odds - first_time) / (gain_weight + 1.0);
        if total > best_total && total > threshold && odds > least_odds {
            best_total = total;
            best = Some(PassChoice { mate: i, kind, odds });
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;

    fn player(side: Side, index: usize, role: Role, at: Vec2) -> Player {
        Player::new(side, index, role, at, at)
    }

    /// Our keeper, a centre back and a centre forward against one far-off opponent.
    fn teams(carrier: Role, carrier_at: Vec2, mate: Role, mate_at: Vec2) -> (Vec<Player>, Vec<Player>) {
        let mates = vec![
            player(Side::Left, 0, Role::GK, Vec2::new(-52.0, 0.0)),
            player(Side::Left, 1, carrier, carrier_at),
            player(Side::Left, 2, mate, mate_at),
        ];
        let opponents = vec![
            player(Side::Right, 0, Role::GK, Vec2::new(52.0, 0.0)),
            player(Side::Right, 1, Role::CB, Vec2::new(30.0, 30.0)),
        ];
        (mates, opponents)
    }

    #[test]
    fn a_centre_back_passes_forward_to_an_open_midfielder() {
        let (mates, opponents) = teams(Role::CB, Vec2::new(-30.0, 0.0), Role::CM, Vec2::new(-5.0, 5.0));
        let choice = choose(&mates[1], &mates, &opponents, 30, 0.8, Vec2::ZERO).expect("a pass");
        assert_eq!(choice.mate, 2);
        // Nobody near the line: a ground pass, sure to arrive.
        assert_eq!(choice.kind, KickKind::ShortPass);
        assert!(choice.odds > 0.99);
    }

    #[test]
    fn a_centre_forward_passes_only_to_someone_nearer_goal() {
        let (mates, opponents) = teams(Role::CF, Vec2::new(35.0, 0.0), Role::CM, Vec2::new(15.0, 0.0));
        assert_eq!(choose(&mates[1], &mates, &opponents, 30, 0.8, Vec2::ZERO), None);
        let (mates, opponents) = teams(Role::CF, Vec2::new(35.0, 10.0), Role::AM, Vec2::new(46.0, -2.0));
        assert_eq!(choose(&mates[1], &mates, &opponents, 30, 0.8, Vec2::ZERO).map(|c| c.mate), Some(2));
    }

    #[test]
    fn the_right_team_rates_in_its_own_frame() {
        // The same centre back's pass, mirrored: the right team attacks towards -x.
        let mirror = |p: Player| Player { side: Side::Right, position: -p.position, home: -p.home, ..p };
        let (mates, opponents) = teams(Role::CB, Vec2::new(-30.0, 0.0), Role::CM, Vec2::new(-5.0, 5.0));
        let mates: Vec<Player> = mates.into_iter().map(mirror).collect();
        let opponents: Vec<Player> =
            opponents.into_iter().map(|p| Player { side: Side::Left, position: -p.position, ..p }).collect();
        assert_eq!(choose(&mates[1], &mates, &opponents, 30, 0.8, Vec2::ZERO).map(|c| c.mate), Some(2));
    }

    #[test]
    fn an_opponent_on_the_line_spoils_a_ground_pass_but_not_a_lofted_one_over_him() {
        let frame = TeamFrame::of(Side::Left);
        let (from, to) = (Vec2::ZERO, Vec2::new(30.0, 0.0));
        assert_eq!(passing_odds(from, to, KickKind::ShortPass, &Rivals::of(&[], frame), 1.0), 1.0);
        // A lofted ball carries 0.4 of danger anyway.
        assert!((passing_odds(from, to, KickKind::HighPass, &Rivals::of(&[], frame), 1.0) - 0.6).abs() < 1e-6);
        let midway = [player(Side::Right, 1, Role::CB, Vec2::new(12.0, 1.0))];
        assert!(passing_odds(from, to, KickKind::ShortPass, &Rivals::of(&midway, frame), 1.0) < 0.2);
        assert!((passing_odds(from, to, KickKind::HighPass, &Rivals::of(&midway, frame), 1.0) - 0.6).abs() < 1e-6);
        // Far off the line he is no danger; behind the passer neither.
        let wide = [player(Side::Right, 1, Role::CB, Vec2::new(12.0, 25.0))];
        assert_eq!(passing_odds(from, to, KickKind::ShortPass, &Rivals::of(&wide, frame), 1.0), 1.0);
        let behind = [player(Side::Right, 1, Role::CB, Vec2::new(-8.0, 0.0))];
        assert_eq!(passing_odds(from, to, KickKind::ShortPass, &Rivals::of(&behind, frame), 1.0), 1.0);
    }

    #[test]
    fn the_longer_he_holds_it_the_riskier_the_pass_he_plays() {
        // A centre back with an open midfielder ahead, but a forward standing 4 m off him on the
        // ball's line: in his first moments he keeps it; after five seconds on the ball he
        // chances the pass (GRF's least odds fall from 0.2 to 0.1).
        let (mates, mut opponents) = teams(Role::CB, Vec2::new(-30.0, 0.0), Role::CM, Vec2::new(-5.0, 5.0));
        opponents.push(player(Side::Right, 2, Role::CF, Vec2::new(-26.0, 3.0)));
        let early = choose(&mates[1], &mates, &opponents, 20, 0.8, Vec2::ZERO);
        let late = choose(&mates[1], &mates, &opponents, 500, 0.8, Vec2::ZERO).expect("a pass after 5 s");
        assert_eq!(early, None);
        assert!(late.mate == 2 && (0.1..0.2).contains(&late.odds), "{late:?}");
    }
}
