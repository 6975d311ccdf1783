//! Support play off the ball, GRF's way (docs/grf-compatibility.md#team-ai; GRF 2.10's off-the-ball
//! strategies and its support force field): a player of the team on the ball does not stand on
//! his place in the shape but steers by a field of attractors and repellers: his place, pushed up
//! the pitch in the lane away from the ball; the carrier, whom he keeps 12-21 m from; the ball's
//! path, which he keeps out of; his team-mates, whom he spreads from; and the nearest opponents,
//! whose passing shadow he leaves. One player at a time supports just ahead of the carrier, and
//! one makes a run for goal when the space in front of him is free. How far a player follows the
//! field rather than his place grows with the team's fading possession: a team that has just won
//! the ball takes a second or so to push on.

use glam::Vec2;

use super::force_field::ForceField;
use super::{Analysis, MatchView};
use crate::game::GameMode;
use crate::geometry::Side;
use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};
use crate::player::{MAX_PLAYERS_PER_TEAM, Role};

/// Ticks between two choices of the forward support player (GRF: 1.5 s).
const FORWARD_SUPPORT_TICKS: u64 = 150;
/// Ticks between two looks for an attacking runner (GRF: 0.5 s).
const RUN_CHECK_TICKS: u64 = 50;
/// How long an attacking run lasts (ticks; GRF: 4 s).
const RUN_TICKS: u64 = 400;
/// A run is made when the runner's conditions rate at least this (GRF's 0.5).
const RUN_RATING: f32 = 0.5;
/// Ticks after which the field's answers are worked out again, at the team's next decision (so
/// every second decision for θ above 0.5, every decision below; the field for every player at
/// every decision was a third of a match's step), and at once when the ball changes hands (a
/// carrier found or lost).
const FIELD_TICKS: u64 = 10;
/// Pulls of the support field are damped within this distance (m), GRF's support field's.
const SUPPORT_DAMPING: f32 = 7.0;
/// The fading possession from which team-mates spread from each other (GRF's 1.02).
const SPREAD_FADING: f32 = 1.02;
/// The fading possession from which players keep out of the ball's path (GRF's 1.06).
const CLEAR_PATH_FADING: f32 = 1.06;
/// Share of the fading possession's distance to its target left after `ticks` ticks, 0.995 to
/// that power: from a table for the few ticks between two decisions (a power per team decision was
/// a fiftieth of an Academy drill's step), the same value as `libm::powf` gives.
fn fading_keep(ticks: u64) -> f32 {
    const TABLED: usize = 32;
    static KEEP: std::sync::OnceLock<[f32; TABLED]> = std::sync::OnceLock::new();
    match usize::try_from(ticks) {
        Ok(t) if t < TABLED => KEEP.get_or_init(|| std::array::from_fn(|t| libm::powf(0.995, t as f32)))[t],
        _ => libm::powf(0.995, ticks as f32),
    }
}

/// When the ball's path is kept out of (s ahead; GRF's).
const BALL_PATH_TIMES: [f32; 4] = [0.2, 0.35, 0.5, 0.65];

/// One team's support state: its fading possession and who supports and who runs.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub(crate) struct Support {
    /// The team.
    side: Side,
    /// GRF's fading team possession, in [0.5, 1.5]: how sure the team is that the ball is its own,
    /// following the ratio of the teams' times to the ball over about two seconds.
    fading: f32,
    /// Tick of the last update of `fading`.
    updated: u64,
    /// The player (global index) who supports just ahead of the carrier.
    forward: Option<usize>,
    /// Tick of the next choice of `forward`.
    next_forward: u64,
    /// The attacking runner (global index) and the tick his run ends.
    runner: Option<(usize, u64)>,
    /// Tick of the next look for a runner.
    next_run_check: u64,
    /// Per player of the team (by index in it): where the field took him last (m, global).
    #[serde(default)]
    fields: Vec<Option<Vec2>>,
    /// Tick at which the fields are next worked out afresh.
    #[serde(default)]
    next_fields: u64,
    /// Whether this decision works them out afresh.
    #[serde(default)]
    refresh: bool,
    /// The carrier (global index) when they were last worked out.
    #[serde(default)]
    fields_owner: Option<usize>,
    /// Every player of the match (by global index) as this decision sees him, in the team's frame
    /// (filled by [`Support::update`]; scratch, no allocation: a team has at most
    /// [`MAX_PLAYERS_PER_TEAM`] players).
    #[serde(skip)]
    seen: [Seen; 2 * MAX_PLAYERS_PER_TEAM],
    /// Where the ball is predicted at [`BALL_PATH_TIMES`] (m, team frame; filled by
    /// [`Support::update`]).
    #[serde(skip)]
    ball_path: [Vec2; 4],
}

/// A player as a support decision sees him (m, team frame).
#[derive(Clone, Copy, Debug, Default)]
struct Seen {
    /// Where he is.
    at: Vec2,
    /// Where he will be 0.1 s on at his velocity (GRF's look ahead).
    ahead: Vec2,
    /// Whether he plays (not sent off).
    active: bool,
}

impl Support {
    /// The state of `side`'s `players` at kickoff (GRF starts both teams' fading possession at 1).
    pub(crate) fn new(side: Side, players: usize) -> Support {
        Support {
            side,
            fading: 1.0,
            updated: 0,
            forward: None,
            next_forward: 0,
            runner: None,
            next_run_check: 0,
            fields: vec![None; players],
            next_fields: 0,
            refresh: true,
            fields_owner: None,
            seen: [Seen::default(); 2 * MAX_PLAYERS_PER_TEAM],
            ball_path: [Vec2::ZERO; 4],
        }
    }

    /// The team's fading possession, in [0.5, 1.5] (see the field's doc).
    pub(crate) fn fading(&self) -> f32 {
        self.fading
    }

    /// Checks a decoded state against a team of `players`: the kept fields finite and on the
    /// pitch's scale, no more of them than players (for [`super::TeamAi::check`]).
    pub(crate) fn check(&self, players: usize) -> Result<(), String> {
        if self.fields.len() > players {
            return Err(format!("{} support fields for a team of {players}", self.fields.len()));
        }
        let sane = |v: &Vec2| v.is_finite() && v.abs().max_element() <= 10_000.0;
        if !self.fields.iter().flatten().all(sane) || !self.fading.is_finite() {
            return Err("a support field or the fading possession is not finite".into());
        }
        Ok(())
    }

    /// Brings the state up to `view.tick` for the team whose analysis is `analysis`: the fading
    /// possession, the forward support player and the attacking runner. Called once per
    /// decision.
    pub(crate) fn update(&mut self, view: &MatchView, analysis: &Analysis) {
        let side = self.side;
        self.refresh = view.tick >= self.next_fields || view.owner != self.fields_owner;
        if self.refresh {
            self.next_fields = view.tick.saturating_add(FIELD_TICKS);
            self.fields_owner = view.owner;
        }
        let frame = analysis.frame;
        for (seen, q) in self.seen.iter_mut().zip(view.players) {
            *seen =
                Seen { at: frame.vec2(q.position), ahead: frame.vec2(q.position + q.velocity * 0.1), active: q.active };
        }
        for (spot, t) in self.ball_path.iter_mut().zip(BALL_PATH_TIMES) {
            *spot = frame.vec2(ball_at(analysis, t));
        }
        let ours = view.owner_side() == Some(side);
        let ticks = view.tick.saturating_sub(self.updated);
        self.updated = view.tick;
        let keeper_holds = view.owner.is_some_and(|o| view.players[o].is_keeper());
        if view.mode != GameMode::Normal || keeper_holds {
            // GRF's ball retainer or set piece: the team that has it is sure of it.
            let has = match view.taker {
                Some(t) if view.mode != GameMode::Normal => view.players[t].side == side,
                _ => ours,
            };
            self.fading = if has { 1.5 } else { 0.5 };
        } else {
            let own_time = if ours { 0.0 } else { analysis.chaser.map_or(f32::INFINITY, |c| c.1) };
            let their_time = if view.owner.is_some() && !ours { 0.0 } else { analysis.opponent_time };
            let target = possession_ratio(own_time, their_time);
            // GRF moves it 0.5 % of the way each 10 ms tick.
            let keep = fading_keep(ticks);
            self.fading = target + (self.fading - target) * keep;
        }
        let Some(main) = main_man(view, side, analysis) else {
            self.forward = None;
            self.runner = None;
            return;
        };
        if view.tick >= self.next_forward {
            self.next_forward = view.tick.saturating_add(FORWARD_SUPPORT_TICKS);
            // The team-mate nearest a point 1.5 m ahead of the carrier.
            let at = view.players[main].position + Vec2::new(side.attack_sign() * 1.5, 0.0);
            self.forward = nearest(view, side, at, Some(main));
        }
        if self.runner.is_some_and(|(_, until)| view.tick >= until) {
            self.runner = None;
        }
        if self.runner.is_none() && view.tick >= self.next_run_check {
            self.next_run_check = view.tick.saturating_add(RUN_CHECK_TICKS);
            if ours {
                self.runner = attacking_run(view, &self.seen, side, analysis, main)
                    .map(|r| (r, view.tick.saturating_add(RUN_TICKS)));
            }
        }
    }

    /// Where player `g` (the team's `i`-th) goes in open play, given his place in the shape
    /// `place` (m, global): the place, or, as far as the team's fading possession has it
    /// attacking, a blend with where the support field takes him. Players of a team without the
    /// ball keep `place`.
    pub(crate) fn place(&mut self, view: &MatchView, g: usize, i: usize, analysis: &Analysis, place: Vec2) -> Vec2 {
        let p = &view.players[g];
        let bias = attack_bias(p.role, self.fading);
        if bias <= 0.0 || p.is_keeper() || view.mode != GameMode::Normal {
            return place;
        }
        let Some(main) = main_man(view, self.side, analysis) else { return place };
        if i >= self.fields.len() {
            // A state saved before the fields were kept: size them once.
            self.fields.resize(view.ranges[self.side.index()].len(), None);
        }
        let field = match self.fields.get(i).copied().flatten() {
            Some(field) if !self.refresh => field,
            _ => {
                let runs = self.runner.is_some_and(|(r, _)| r == g) && bias > run_threshold(p.role);
                let field = self.field_position(view, g, main, analysis, place, runs);
                if let Some(slot) = self.fields.get_mut(i) {
                    *slot = Some(field);
                }
                field
            }
        };
        place.lerp(field, bias)
    }

    /// Where the support field takes player `g` (m, global) with `main` the team's man on the ball.
    fn field_position(
        &self,
        view: &MatchView,
        g: usize,
        main: usize,
        analysis: &Analysis,
        place: Vec2,
        runs: bool,
    ) -> Vec2 {
        let frame = analysis.frame;
        let p = &view.players[g];
        let at = self.seen[g].ahead;
        let main_at = self.seen[main].ahead;
        let mind_set = p.role.mind_set();
        let mut field = ForceField::new(at, SUPPORT_DAMPING);

        // His place, pushed up the pitch: by 4-12 m for the forward support player; for the
        // others by up to 22 m in the lane 8 m off the middle on the side away from the carrier.
        let mut origin = frame.vec2(place);
        if self.forward == Some(g) {
            origin.x += (0.3 + 0.7 * mind_set) * 12.0;
        } else {
            let lane_y = -main_at.y.signum() * 8.0;
            let near_lane = 1.0 - ((lane_y - at.y).abs() / 30.0).min(1.0);
            origin.x += mind_set * mind_set.sqrt() * 22.0 * sine_ease(near_lane);
        }
        let pull = 0.7 * (0.3 + 0.7 * (origin.distance(at) / 20.0).min(1.0));
        field.attract_constant(origin, pull);
        if runs {
            field.attract_constant(Vec2::new(HALF_LENGTH, at.y * 0.5), 2.0);
        }

        // The nearest three opponents to a point pulled towards the carrier (GRF's point, which
        // adds the carrier's 0.3 to the player's whole position): keep out of their shadow.
        let probe = main_at * 0.3 + at + Vec2::splat(0.7);
        let (scale, power) = if runs { (2.0, 0.5) } else { (5.0, 1.0) };
        let opponent_power = 0.3 * opponent_repel(p.role) * power;
        let opponents = view.ranges[p.side.opponent().index()].clone();
        for o in nearest_k::<3>(&self.seen, opponents, probe, None) {
            let o_at = self.seen[o].ahead;
            let shadow = o_at + (o_at - main_at).normalize_or_zero() * 2.0;
            field.repel(shadow, opponent_power, scale, 0.7);
        }
        // Team-mates: spread out (the six nearest, himself left out), once the team is sure
        // enough of the ball (GRF: a fading possession of 1.02).
        if self.fading >= SPREAD_FADING {
            for q in nearest_k::<6>(&self.seen, view.ranges[p.side.index()].clone(), at, Some(g)) {
                field.repel(self.seen[q].ahead, 0.4, 10.5, 1.0);
            }
        }
        if main != g && self.fading >= CLEAR_PATH_FADING {
            // Keep out of the ball's way over the next two thirds of a second (GRF: from a fading
            // possession of 1.06).
            for spot in self.ball_path {
                field.repel(spot, 1.0, 2.0, 0.5);
            }
        }
        if main != g {
            // Flock to the carrier, yet not too close.
            field.attract(main_at, 0.45, 21.0);
            field.repel(main_at, 0.45, 12.0, 1.0);
        }
        let mut to = at + field.movement();
        // Never past the offside line (GRF's 240 ms ahead, the ball, the halfway line).
        let offside = analysis.defensive_line.max(0.0) - 0.08;
        to.x = to.x.min(offside).clamp(-HALF_LENGTH, HALF_LENGTH);
        to.y = to.y.clamp(-HALF_WIDTH, HALF_WIDTH);
        frame.vec2(to)
    }
}

/// GRF's team possession: the ratio of the opponents' time to the ball to the team's, each plus
/// 1.5 s, clamped to [0.5, 1.5] (times in s; infinite when nobody can get there).
fn possession_ratio(own: f32, theirs: f32) -> f32 {
    match (own.is_finite(), theirs.is_finite()) {
        (true, true) => ((theirs + 1.5) / (own + 1.5)).clamp(0.5, 1.5),
        (true, false) => 1.5,
        (false, true) => 0.5,
        (false, false) => 1.0,
    }
}

/// How far a player of `role` follows the support field rather than his place, given the team's
/// fading possession (GRF's attack bias of its defence, midfield and attack strategies).
fn attack_bias(role: Role, fading: f32) -> f32 {
    let (from, over) = match role {
        Role::GK => return 0.0,
        Role::CB | Role::LB | Role::RB => (0.7, 0.7),
        Role::CF => (0.6, 0.5),
        _ => (0.6, 0.6),
    };
    ((fading - from) / over).clamp(0.0, 1.0)
}

/// The attack bias above which the team's runner makes his run (GRF: forwards 0.7, midfielders 0.9;
/// defenders never).
fn run_threshold(role: Role) -> f32 {
    match role {
        Role::CF => 0.7,
        Role::CB | Role::LB | Role::RB | Role::GK => f32::INFINITY,
        _ => 0.9,
    }
}

/// How strongly a player of `role` keeps out of the opponents' shadow (GRF's factors).
fn opponent_repel(role: Role) -> f32 {
    match role {
        Role::CB | Role::LB | Role::RB => 2.2,
        Role::DM => 2.0,
        Role::CM | Role::LM | Role::RM => 1.6,
        Role::AM => 1.2,
        Role::CF | Role::GK => 1.0,
    }
}

/// The team's man on the ball (GRF's designated team possession player): the carrier if he is
/// ours, else the team's quickest to the ball.
fn main_man(view: &MatchView, side: Side, analysis: &Analysis) -> Option<usize> {
    match view.owner {
        Some(o) if view.players[o].side == side => Some(o),
        _ => analysis.chaser.map(|c| c.0),
    }
}

/// The attacking runner, if the conditions are right (GRF's): the team-mate nearest a point 26 m
/// ahead of the carrier `main`, rated by his nearness to him (40 m at most) and by how few
/// opponents are within 15 m of the space 10 m ahead of him.
fn attacking_run(view: &MatchView, seen: &[Seen], side: Side, analysis: &Analysis, main: usize) -> Option<usize> {
    let frame = analysis.frame;
    let m = &view.players[main];
    let focus = m.position + Vec2::new(side.attack_sign() * 26.0, 0.0);
    let runner = nearest(view, side, focus, Some(main))?;
    let r = &view.players[runner];
    let near = (1.0 - (r.position.distance(m.position) / 40.0).min(1.0)).sqrt();
    let space = frame.vec2(r.position) * Vec2::new(1.0, 0.8) + Vec2::new(10.0, 0.0);
    let mut free = 1.0;
    for o in nearest_k::<4>(seen, view.ranges[side.opponent().index()].clone(), space, None) {
        let d = seen[o].at.distance(space);
        free -= sine_ease(1.0 - (d / 15.0).min(1.0)).sqrt() * 0.3;
    }
    (near * free >= RUN_RATING).then_some(runner)
}

/// The active outfield player of `side` nearest `at` (m, global), `except` left out; agents'
/// players are left out (GRF picks among its AI-controlled players).
fn nearest(view: &MatchView, side: Side, at: Vec2, except: Option<usize>) -> Option<usize> {
    view.ranges[side.index()]
        .clone()
        .filter(|&g| Some(g) != except && !view.agent_driven[g])
        .filter(|&g| view.players[g].active && !view.players[g].is_keeper())
        .min_by(|&a, &b| {
            view.players[a].position.distance_squared(at).total_cmp(&view.players[b].position.distance_squared(at))
        })
}

/// The `K` active players among `players` (global indices into `seen`) nearest `at` (m, team
/// frame), `except` left out, nearest first; fewer when there are fewer. No allocation.
fn nearest_k<const K: usize>(
    seen: &[Seen],
    players: std::ops::Range<usize>,
    at: Vec2,
    except: Option<usize>,
) -> impl Iterator<Item = usize> {
    // Kept sorted, nearest first: a candidate nearer than the last slides in.
    let mut best = [(f32::INFINITY, usize::MAX); K];
    let start = players.start;
    for (i, q) in seen[players].iter().enumerate() {
        let g = start + i;
        if Some(g) == except || !q.active {
            continue;
        }
        let d = q.at.distance_squared(at);
        if d >= best[K - 1].0 {
            continue;
        }
        let mut k = K - 1;
        while k > 0 && best[k - 1].0 > d {
            best[k] = best[k - 1];
            k -= 1;
        }
        best[k] = (d, g);
    }
    best.into_iter().filter(|&(_, g)| g != usize::MAX).map(|(_, g)| g)
}

/// The ball's predicted position `t` s ahead (m, global), between the path's samples.
fn ball_at(analysis: &Analysis, t: f32) -> Vec2 {
    let at = analysis.path.at();
    let k = t / super::prediction::SAMPLE_DT - 1.0;
    let i = (k.floor().max(0.0) as usize).min(at.len() - 2);
    let f = (k - i as f32).clamp(0.0, 1.0);
    at[i].truncate().lerp(at[i + 1].truncate(), f)
}

/// GRF's `curve` with full bias: `x` in [0, 1] through a sine ease, flat at both ends.
fn sine_ease(x: f32) -> f32 {
    super::team_shape::curve(x, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn possession_follows_the_ratio_of_times_to_the_ball() {
        assert_eq!(possession_ratio(0.0, 0.5), (2.0 / 1.5_f32).clamp(0.5, 1.5));
        assert_eq!(possession_ratio(0.0, f32::INFINITY), 1.5);
        assert_eq!(possession_ratio(3.0, 0.0), 0.5);
        assert_eq!(possession_ratio(f32::INFINITY, f32::INFINITY), 1.0);
    }

    #[test]
    fn forwards_attack_first_and_defenders_last() {
        let f = 1.0;
        assert!(attack_bias(Role::CF, f) > attack_bias(Role::CM, f));
        assert!(attack_bias(Role::CM, f) > attack_bias(Role::CB, f));
        assert_eq!(attack_bias(Role::GK, 1.5), 0.0);
        assert_eq!(attack_bias(Role::CM, 0.5), 0.0);
        assert_eq!(attack_bias(Role::CB, 1.5), 1.0);
    }

    #[test]
    fn a_damaged_state_is_refused() {
        let mut support = Support::new(Side::Left, 11);
        assert_eq!(support.check(11), Ok(()));
        support.fields[3] = Some(Vec2::new(f32::NAN, 0.0));
        assert!(support.check(11).is_err_and(|e| e.contains("not finite")));
        support.fields[3] = Some(Vec2::new(1e6, 0.0));
        assert!(support.check(11).is_err());
        support.fields[3] = None;
        assert!(support.check(10).is_err_and(|e| e.contains("11 support fields")));
        support.fading = f32::INFINITY;
        assert!(support.check(11).is_err());
    }
}
