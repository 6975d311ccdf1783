//! Which player each agent controller drives (docs/grf-compatibility.md#controlled-players).
//!
//! With as many controllers as controllable players the mapping is fixed: controller i drives the
//! i-th controllable player. With fewer ("dynamic selection"), control follows the ball: to the
//! team-mate a pass is meant for as it is played (the goalkeeper too), and to the team's
//! designated player when he has the ball or takes a set piece, or when he could reach the ball
//! more than three times sooner than the controlled player farthest from it (never the
//! goalkeeper). Times to a moving free ball are along its predicted path, as GRF's time needed to
//! get to the ball (a player behind a pass that runs away from him is far from it); to an owned
//! or slow ball, straight; and either way with GRF's start from his present run ([`Reach`]).

use std::cell::OnceCell;

use crate::ai::BallPath;
use crate::game::Match;
use crate::game::kick::STANDING_RUN;
use crate::geometry::Side;
use crate::player::MAX_PLAYERS_PER_TEAM;
use crate::stats::Event;

/// Highest ball (m) that counts as reached in the time-to-ball estimate (head height).
const REACH_HEIGHT: f32 = 2.0;

/// The ball's predicted path, worked out when first needed (most steps a team's ball carrier
/// is simply kept under control and it never is).
pub(crate) type LazyPath = OnceCell<BallPath>;

/// A free ball slower than this (m/s) is as good as where it lies for the time-to-ball estimate
/// (the predicted path is worked out only for a faster one: it is most of this module's cost).
const SLOW_BALL: f32 = 5.0;

/// Seconds `p` needs to get to the ball: along its predicted `path` while it runs free (the first
/// predicted position he can be at in time), straight to it while someone has it at his feet (it
/// goes where he goes) or it is slow. Each time is GRF's ([`Reach`]).
fn time_to_ball(game: &Match, path: &LazyPath, p: &crate::player::Player) -> f32 {
    // With no time to beat every sample is tested: always an answer (the fallback is unused).
    time_to_ball_before(game, path, p, f32::INFINITY).unwrap_or(f32::INFINITY)
}

/// [`time_to_ball`] where it is below `before` (s); `None` where along the path the samples before
/// `before` are all out of his reach, so that his time is `before` or later (the time after the
/// last sample is no less than its time). [`fastest`] skips the samples the runners after the
/// quickest so far cannot win on.
fn time_to_ball_before(game: &Match, path: &LazyPath, p: &crate::player::Player, before: f32) -> Option<f32> {
    let reach = Reach::of(p);
    let ball = game.ball();
    if straight_to_ball(game) {
        return Some(reach.time_to(ball.xy()));
    }
    let path = path.get_or_init(|| game.paths.path(game.ball()));
    let mut last = (0.0, ball.xy());
    for (k, at) in path.at().iter().enumerate() {
        let t = crate::ai::SAMPLE_DT * (k + 1) as f32;
        if t >= before {
            return None;
        }
        last = (t, at.truncate());
        if at.z <= REACH_HEIGHT && reach.by(at.truncate(), t) {
            return Some(t);
        }
    }
    Some(last.0 + reach.time_to(last.1))
}

/// Whether times to the ball are taken straight to where it is: someone has it at his feet, or it
/// is slower than [`SLOW_BALL`].
fn straight_to_ball(game: &Match) -> bool {
    game.owner().is_some() || game.ball().velocity.length_squared() < SLOW_BALL * SLOW_BALL
}

/// Where a player can get to a ball, GRF 2.10's time needed for a distance: over the first
/// [`Reach::RAMP`] his present run fades out while the pace he can put towards the ball grows
/// from nothing to 0.94 of his top speed, and he reaches a ball 0.28 m off his foot (taken 0.1 m
/// ahead of him); after that he runs straight on. So a standing player of 7.8 m/s top speed needs
/// 0.34 s for a ball 1 m off and 0.83 s for one 4 m off, where top speed alone would say 0.13 s
/// and 0.51 s: the man four times nearer is not three times quicker. GRF steps this in 10 ms; here
/// it is in closed form, and [`Reach::time_to`] searches it to the nearest 10 ms.
struct Reach {
    /// Where he is (m).
    position: glam::Vec2,
    /// Where he starts from (m): his position and the foot's offset.
    from: glam::Vec2,
    /// His run (m/s).
    velocity: glam::Vec2,
    /// Pace (m/s) he can put towards the ball once the ramp is over.
    pace: f32,
    /// Whether he is running (his foot is ahead along his run, else towards the ball).
    running: bool,
    /// How far (m) his foot can reach from him before he moves: see [`Reach::within_limit`].
    slack: f32,
    /// The quicker (m/s) of his run and his pace.
    fastest: f32,
}

impl Reach {
    /// Seconds over which his run fades and his pace towards the ball builds.
    const RAMP: f32 = 0.7;
    /// Reach (m) of a standing foot.
    const FOOT: f32 = 0.28;
    /// The foot's offset (m) ahead of him.
    const AHEAD: f32 = 0.1;

    fn of(p: &crate::player::Player) -> Reach {
        let running = p.velocity.length_squared() > STANDING_RUN * STANDING_RUN;
        // A running player's foot is ahead along his run, one 10 ms step of it already taken.
        let from =
            if running { p.position + p.velocity.normalize() * Self::AHEAD + p.velocity * 0.01 } else { p.position };
        let pace = 0.94 * p.max_speed.max(0.1);
        let run = p.velocity.length();
        let slack = Self::AHEAD + 0.01 * run + Self::FOOT;
        Reach { position: p.position, from, velocity: p.velocity, pace, running, slack, fastest: run.max(pace) }
    }

    /// Where his foot is at `t` s going for a ball at `target` (m), and how far (m) it reaches then.
    fn at(&self, target: glam::Vec2, t: f32) -> (glam::Vec2, f32) {
        let ramp = t.min(Self::RAMP);
        let carried = self.velocity * (ramp - ramp * ramp / (2.0 * Self::RAMP));
        let mut at = self.from + carried;
        if !self.running {
            at += (target - self.from).normalize_or_zero() * Self::AHEAD;
        }
        (at, Self::FOOT + self.pace * (ramp * ramp / (2.0 * Self::RAMP) + (t - ramp)))
    }

    /// How far short (m) of a ball at `target` he is at `t` s (negative: he has it).
    fn short(&self, target: glam::Vec2, t: f32) -> f32 {
        let (at, reach) = self.at(target, t);
        at.distance(target) - reach
    }

    /// Whether he can be at a ball at `target` (m) within `t` s (squared: no square root on the
    /// path's twenty samples for each of the team's players every step).
    fn by(&self, target: glam::Vec2, t: f32) -> bool {
        if !self.within_limit(target, t) {
            // Out of his reach whatever his run: most of the path's samples for most players.
            return false;
        }
        let (at, reach) = self.at(target, t);
        at.distance_squared(target) < reach * reach
    }

    /// A time (s) he cannot beat to a ball at `target` (m): see [`Reach::within_limit`].
    fn lower_bound(&self, target: glam::Vec2) -> f32 {
        let gap = self.position.distance(target) - self.slack;
        (gap / self.fastest * 0.999 - 0.001).max(0.0)
    }

    /// Whether a ball at `target` (m) is within the farthest his foot can be from him at `t` s
    /// (where it is not, [`Reach::by`] is false). His foot starts at most [`Reach::AHEAD`] plus one
    /// 10 ms step of his run from him and reaches [`Reach::FOOT`] further (together `slack`); his
    /// fading run and his building pace towards the ball share the time between them, so
    /// together they carry it no faster than the quicker of the two. A thousandth and a
    /// millimetre are added for rounding.
    fn within_limit(&self, target: glam::Vec2, t: f32) -> bool {
        let limit = (self.slack + self.fastest * t) * 1.001 + 0.001;
        self.position.distance_squared(target) < limit * limit
    }

    /// Seconds he needs for a ball at `target` (m): the first 10 ms step at which he has it, found
    /// over the ramp in 50 ms steps and then 10 ms ones; after the ramp, straight.
    fn time_to(&self, target: glam::Vec2) -> f32 {
        let mut t = 0.0;
        while t < Self::RAMP {
            let next = t + 0.05;
            if self.by(target, next.min(Self::RAMP)) {
                let mut fine = t;
                while fine < next && !self.by(target, fine) {
                    fine += 0.01;
                }
                return fine;
            }
            t = next;
        }
        Self::RAMP + self.short(target, Self::RAMP).max(0.0) / self.pace
    }
}

/// The player of `side` the team would hand control to: the ball owner if he is on this team,
/// else the player nearest the ball in time (goalkeepers only when no one else can be controlled).
pub(crate) fn designated(game: &Match, side: Side, path: &LazyPath) -> Option<usize> {
    let team = game.team(side);
    if let Some((s, i)) = game.owner()
        && s == side
        && selectable(game, side, i)
    {
        return Some(i);
    }
    let any_outfield = (0..team.len()).any(|i| selectable(game, side, i));
    let eligible = |i: &usize| team[*i].active && team[*i].controllable && (!any_outfield || !team[*i].is_keeper());
    if straight_to_ball(game) {
        // Straight to the ball: each candidate's time is at least his lower bound, so taken in
        // order of their bounds, no one whose bound is past the best time so far can beat it (most
        // steps only the nearest two or three are timed; this runs every step a team is without
        // the ball).
        let mut order = [(0.0_f32, 0_usize); MAX_PLAYERS_PER_TEAM];
        let mut n = 0;
        for i in (0..team.len()).filter(eligible) {
            if n == order.len() {
                // More players than a team can have: time them all.
                return fastest(game, path, team, (0..team.len()).filter(eligible));
            }
            order[n] = (Reach::of(&team[i]).lower_bound(game.ball().xy()), i);
            n += 1;
        }
        let order = &mut order[..n];
        order.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut best: Option<(usize, f32)> = None;
        for &(bound, i) in order.iter() {
            if best.is_some_and(|(_, bt)| bound > bt) {
                break;
            }
            let t = time_to_ball(game, path, &team[i]);
            // The first of equal times wins, as in team order.
            if best.is_none_or(|(bi, bt)| t.total_cmp(&bt).then(i.cmp(&bi)).is_lt()) {
                best = Some((i, t));
            }
        }
        return best.map(|(i, _)| i);
    }
    fastest(game, path, team, (0..team.len()).filter(eligible))
}

/// Of `candidates`, the player of `team` with the shortest time to the ball (the first of equal
/// times). Each candidate's time is worked out once (`min_by` worked out both times of every pair
/// it compared).
fn fastest(
    game: &Match,
    path: &LazyPath,
    team: &[crate::player::Player],
    candidates: impl Iterator<Item = usize>,
) -> Option<usize> {
    let mut best: Option<(usize, f32)> = None;
    for i in candidates {
        // Only a time below the best so far wins: a candidate who cannot beat it is not timed.
        let before = best.map_or(f32::INFINITY, |(_, bt)| bt);
        let Some(t) = time_to_ball_before(game, path, &team[i], before) else { continue };
        if best.is_none_or(|(_, bt)| t.total_cmp(&bt).is_lt()) {
            best = Some((i, t));
        }
    }
    best.map(|(i, _)| i)
}

fn selectable(game: &Match, side: Side, i: usize) -> bool {
    let p = &game.team(side)[i];
    p.active && p.controllable && !p.is_keeper()
}

/// Assigns players to the `controlled` slots of `side` at the start of an episode.
pub(crate) fn initial(game: &Match, side: Side, controlled: &mut [usize]) {
    let team = game.team(side);
    let controllable: Vec<usize> = (0..team.len()).filter(|&i| team[i].controllable).collect();
    if controllable.len() == controlled.len() {
        controlled.copy_from_slice(&controllable);
        return;
    }
    // Dynamic: the nearest players to the ball (outfield first).
    let ball = game.ball().xy();
    let mut order = controllable;
    order.sort_by(|&a, &b| {
        let key = |i: usize| (team[i].is_keeper(), team[i].position.distance_squared(ball));
        let (ka, kb) = (key(a), key(b));
        ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
    });
    // `Env` never has more controllers a side than controllable players in any episode
    // (`Scenario::controllable_every_episode`); should that break, the spare slots drive the
    // first player rather than panic.
    for (k, slot) in controlled.iter_mut().enumerate() {
        *slot = order.get(k).copied().unwrap_or(0);
    }
}

/// Moves dynamic control to the designated player when GRF's rules say so. `fixed` is true when
/// every controllable player has a controller.
pub(crate) fn update(game: &Match, side: Side, controlled: &mut [usize], fixed: bool) {
    if fixed || controlled.is_empty() {
        return;
    }
    let team = game.team(side);
    let path = LazyPath::new();
    let time = |i: usize| time_to_ball(game, &path, &team[i]);
    // A pass played this step: control goes to the team-mate it is meant for, the goalkeeper
    // included (GRF selects the target player as the ball leaves), from the passer if he had it.
    let pass = game.events().iter().rev().find_map(|e| match *e {
        Event::Pass { side: s, player, to: Some(to), .. } if s == side => Some((player, to)),
        _ => None,
    });
    if let Some((passer, to)) = pass
        && team[to].active
        && team[to].controllable
    {
        if !controlled.contains(&to) {
            let slot = controlled.iter().position(|&c| c == passer).unwrap_or_else(|| {
                (0..controlled.len()).max_by(|&a, &b| time(controlled[a]).total_cmp(&time(controlled[b]))).unwrap_or(0)
            });
            controlled[slot] = to;
        }
        return;
    }
    let Some(d) = designated(game, side, &path) else { return };
    if controlled.contains(&d) {
        return;
    }
    // The controlled player who is worst placed gives up control.
    let (slot, worst) = controlled
        .iter()
        .enumerate()
        .max_by(|a, b| time(*a.1).total_cmp(&time(*b.1)))
        .map(|(s, &i)| (s, i))
        .expect("controlled is not empty");
    let has_ball = game.owner() == Some((side, d));
    let worst_unusable = !team[worst].active;
    if has_ball || worst_unusable || time(d) * 3.0 < time(worst) {
        controlled[slot] = d;
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec2;

    use super::Reach;
    use crate::geometry::Side;
    use crate::player::{Player, Role};

    fn player(velocity: Vec2) -> Player {
        let mut p = Player::new(Side::Left, 1, Role::CM, Vec2::ZERO, Vec2::ZERO);
        p.velocity = velocity;
        p.max_speed = 7.8;
        p
    }

    #[test]
    fn a_standing_player_needs_time_to_get_going() {
        let reach = Reach::of(&player(Vec2::ZERO));
        let near = reach.time_to(Vec2::new(1.0, 0.0));
        let far = reach.time_to(Vec2::new(4.0, 0.0));
        // GRF's ramp: about a third of a second for 1 m, 0.83 s for 4 m (top speed alone: 0.13 s
        // and 0.51 s), so the man four times nearer is not three times quicker.
        assert!((0.3..0.4).contains(&near), "{near}");
        assert!((0.78..0.88).contains(&far), "{far}");
        assert!(far < 3.0 * near);
        assert_eq!(reach.time_to(Vec2::new(0.2, 0.0)), 0.0, "at his foot");
        let long = reach.time_to(Vec2::new(30.0, 0.0));
        assert!((long - (0.7 + (29.9 - 0.28 - 7.33 * 0.35) / 7.33)).abs() < 0.02, "{long}");
    }

    #[test]
    fn a_player_running_at_the_ball_gets_there_sooner_than_one_running_away() {
        let ball = Vec2::new(4.0, 0.0);
        let towards = Reach::of(&player(Vec2::new(6.0, 0.0))).time_to(ball);
        let standing = Reach::of(&player(Vec2::ZERO)).time_to(ball);
        let away = Reach::of(&player(Vec2::new(-6.0, 0.0))).time_to(ball);
        assert!(towards < standing && standing < away, "{towards} {standing} {away}");
        assert!(Reach::of(&player(Vec2::new(6.0, 0.0))).by(ball, towards + 0.01));
        assert!(!Reach::of(&player(Vec2::new(6.0, 0.0))).by(ball, towards - 0.02));
    }

    /// Uniform in [0, 1), from a fixed xorshift.
    fn uniform(state: &mut u32) -> f32 {
        *state ^= *state << 13;
        *state ^= *state >> 17;
        *state ^= *state << 5;
        (*state % 100_000) as f32 / 100_000.0
    }

    #[test]
    fn the_pruning_bounds_never_rule_out_a_time_he_makes() {
        let mut state = 0x2545_F491;
        for _ in 0..3_000 {
            let mut p = player(Vec2::new(18.0 * uniform(&mut state) - 9.0, 18.0 * uniform(&mut state) - 9.0));
            p.max_speed = 6.0 + 2.5 * uniform(&mut state);
            if uniform(&mut state) < 0.2 {
                p.velocity *= 0.1;
            }
            let target = Vec2::new(60.0 * uniform(&mut state) - 30.0, 40.0 * uniform(&mut state) - 20.0);
            let reach = Reach::of(&p);
            let time = reach.time_to(target);
            assert!(reach.lower_bound(target) <= time, "{} > {time}", reach.lower_bound(target));
            for k in 0..=250 {
                let t = k as f32 * 0.01;
                // `by` without its shortcut: the foot's place and reach themselves.
                let (at, foot) = reach.at(target, t);
                if at.distance_squared(target) < foot * foot {
                    assert!(reach.within_limit(target, t), "{target} at {t} s");
                }
            }
        }
    }

    #[test]
    fn the_designated_player_is_the_quickest_of_all_as_timing_everyone_finds() {
        use crate::game::Match;
        use crate::scenario::{PlayerEntry, Scenario};
        let roles =
            [Role::GK, Role::CB, Role::CB, Role::LB, Role::RB, Role::CM, Role::CM, Role::DM, Role::LM, Role::RM];
        let team = |x: f32| {
            roles.iter().map(|&r| PlayerEntry::new(r, x, 0.0)).chain([PlayerEntry::new(Role::CF, x, 0.0)]).collect()
        };
        let s = Scenario { left_team: team(-0.5), right_team: team(0.5), ..Scenario::default() };
        let mut state = 0x9E37_79B9;
        for round in 0..2_000 {
            let mut m = Match::new(&s, 0, 0);
            for p in &mut m.players {
                p.position = Vec2::new(100.0 * uniform(&mut state) - 50.0, 64.0 * uniform(&mut state) - 32.0);
                p.velocity = Vec2::new(16.0 * uniform(&mut state) - 8.0, 16.0 * uniform(&mut state) - 8.0);
                if round % 3 == 0 {
                    // Two players equally placed, now and then: the first of them wins.
                    p.position = p.position.round();
                    p.velocity = Vec2::ZERO;
                }
            }
            let ball = Vec2::new(80.0 * uniform(&mut state) - 40.0, 50.0 * uniform(&mut state) - 25.0);
            m.ball.position = ball.extend(0.11);
            m.ball.velocity = Vec2::new(6.0 * uniform(&mut state) - 3.0, 0.0).extend(0.0);
            // The ball at an opponent's feet, or slow and loose.
            m.owner = (round % 2 == 0).then_some(11 + round % 11);
            let path = super::LazyPath::new();
            let everyone = super::fastest(&m, &path, &m.players[..11], 1..11);
            assert_eq!(super::designated(&m, Side::Left, &path), everyone, "round {round}");
        }
    }
}
