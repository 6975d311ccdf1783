//! Which player each agent controller drives (docs/grf-compatibility.md#controlled-players).
//!
//! With as many controllers as controllable players the mapping is fixed: controller i drives the
//! i-th controllable player. With fewer ("dynamic selection"), control follows the ball: to the
//! team-mate a pass is meant for as it is played (the goalkeeper too), and to the team's
//! designated player when he has the ball or takes a set piece, or when he could reach the ball
//! more than three times sooner than the controlled player farthest from it (never the
//! goalkeeper). Times to a moving free ball are along its predicted path, as GRF's time needed to
//! get to the ball (a player behind a pass that runs away from him is far from it); to an owned
//! or slow ball, straight.

use std::cell::OnceCell;

use crate::ai::BallPath;
use crate::game::Match;
use crate::geometry::Side;
use crate::stats::Event;

/// Highest ball (m) that counts as reached in the time-to-ball estimate (head height).
const REACH_HEIGHT: f32 = 2.0;

/// The ball's predicted path, worked out when first needed (most steps a team's ball carrier
/// is simply kept under control and it never is).
pub(crate) type LazyPath = OnceCell<BallPath>;

/// A free ball slower than this (m/s) is as good as where it lies for the time-to-ball estimate
/// (the predicted path is worked out only for a faster one: it is most of this module's cost).
const SLOW_BALL: f32 = 5.0;

/// Seconds `p` needs to get to the ball: along its predicted `path` while it runs free, straight
/// to it while someone has it at his feet (it goes where he goes) or it is slow.
fn time_to_ball(game: &Match, path: &LazyPath, p: &crate::player::Player) -> f32 {
    let speed = p.max_speed.max(0.1);
    let ball = game.ball();
    if game.owner().is_some() || ball.velocity.length_squared() < SLOW_BALL * SLOW_BALL {
        return p.position.distance(ball.xy()) / speed;
    }
    path.get_or_init(|| game.paths.path(game.ball())).intercept(p.position, speed, REACH_HEIGHT).0
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
    // Each candidate's time worked out once (`min_by` worked out both times of every pair it
    // compared, and this runs every step); the first of equal times wins, as with `min_by`.
    let mut best: Option<(usize, f32)> = None;
    for i in
        (0..team.len()).filter(|&i| team[i].active && team[i].controllable && (!any_outfield || !team[i].is_keeper()))
    {
        let t = time_to_ball(game, path, &team[i]);
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
