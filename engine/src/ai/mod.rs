//! The built-in AI: one per team, driving every player no agent controls (goalkeepers included).
//!
//! Every few ticks (the team's reaction time) the AI analyses the ball's path and who can reach it
//! first, then gives each player a plan: hold the team shape ([`team_shape`]), press or cover
//! ([`pressing`]), carry, pass or shoot ([`ball_carrier`]), keep goal ([`goalkeeper`]) or take a
//! set piece ([`set_piece`]). Each tick the plans become [`PlayerInput`]s. Difficulty θ ∈ [0, 1]
//! ([`difficulty`]) sets reaction time, pressing reach and decision noise.

pub mod ball_carrier;
mod clearance;
pub mod difficulty;
mod force_field;
pub mod goalkeeper;
pub mod marking;
mod pass_choice;
mod power;
pub mod prediction;
pub mod pressing;
pub mod set_piece;
mod sliding;
mod support;
pub mod team_shape;

use std::ops::Range;

use glam::Vec2;

pub use difficulty::Difficulty;
pub use prediction::{BallPath, SAMPLE_DT};

use crate::game::{GameMode, Kick, KickTarget, PlayerInput};
use crate::geometry::{Side, TeamFrame};
use crate::physics::Ball;
use crate::player::Player;
use crate::rng::MatchRng;

/// What the AI sees of the match (read-only).
pub struct MatchView<'a> {
    /// All players, left team first.
    pub players: &'a [Player],
    /// Global index ranges of the two teams.
    pub ranges: &'a [Range<usize>; 2],
    /// The ball.
    pub ball: &'a Ball,
    /// Ball owner (global index).
    pub owner: Option<usize>,
    /// Last player to touch the ball (global index).
    pub last_touch: Option<usize>,
    /// Game mode.
    pub mode: GameMode,
    /// Set-piece taker (global index) while `mode` is not Normal.
    pub taker: Option<usize>,
    /// Ticks the current set piece has waited.
    pub set_piece_ticks: u32,
    /// In-play tick counter.
    pub tick: u64,
    /// Ticks the current owner has had the ball.
    pub owner_ticks: u32,
    /// Whether the offside law applies.
    pub offsides: bool,
    /// Per player (global index): driven by an agent, so the AI cannot send him anywhere.
    pub agent_driven: &'a [bool],
    /// The free ball's predicted path, shared by everyone who asks in this tick.
    pub paths: &'a prediction::BallPathMemo,
}

impl MatchView<'_> {
    /// One team's players.
    pub fn team(&self, side: Side) -> &[Player] {
        &self.players[self.ranges[side.index()].clone()]
    }

    /// Which team has the ball at a player's feet.
    pub fn owner_side(&self) -> Option<Side> {
        self.owner.map(|g| self.players[g].side)
    }

    /// The offside line `side`'s attackers must stay behind, in their team frame (m along their
    /// attack); infinite when offside does not apply.
    pub fn offside_line(&self, side: Side) -> f32 {
        if !self.offsides {
            return f32::INFINITY;
        }
        self.defensive_line(side)
    }

    /// Where the opponents' second-last player stands, as [`MatchView::offside_line`] computes it
    /// but whether or not offside is called: the AI keeps its runners behind it always (GRF's
    /// team AI positions by its offside line whatever the scenario's offside flag).
    pub fn defensive_line(&self, side: Side) -> f32 {
        let sign = side.attack_sign();
        crate::rules::offside::line(self.team(side.opponent()), sign, self.ball.position.x * sign)
            .unwrap_or(f32::INFINITY)
    }
}

/// A player's current plan; turned into a [`PlayerInput`] every tick.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Plan {
    /// Where to go (m, global frame).
    pub target: Vec2,
    /// How fast to go there (m/s); the player slows down on arrival.
    pub speed: f32,
    /// Where to look while standing (global direction).
    pub look: Vec2,
    /// Hold the dribble button.
    pub dribble: bool,
    /// A kick to make now (sent once).
    pub kick: Option<Kick>,
    /// Slide (or, for a keeper, dive) now (sent once).
    pub slide: bool,
    /// Run through the target at full speed instead of slowing down to stop on it (chasing a
    /// ball).
    pub run_through: bool,
    /// A kick to strike first time at the loose ball he is going for (the AI's clearance module).
    #[serde(default)]
    pub first_time: Option<Kick>,
}

impl Plan {
    /// Go to `target` at `speed`, looking at `look`.
    pub fn go(target: Vec2, speed: f32, look: Vec2) -> Plan {
        Plan { target, speed, look, ..Plan::default() }
    }
}

/// Shared analysis of one decision: the ball's path and who of this team reaches it first.
pub struct Analysis {
    /// Team frame of the deciding team.
    pub frame: TeamFrame,
    /// Predicted ball path.
    pub path: BallPath,
    /// This team's fastest player to the ball (global index), its time (s) and meeting point.
    pub chaser: Option<(usize, f32, Vec2)>,
    /// Second fastest (global index).
    pub second: Option<usize>,
    /// The opponents' fastest time to the ball (s).
    pub opponent_time: f32,
    /// The line this team's runners keep behind ([`MatchView::defensive_line`]), worked out once
    /// per decision rather than once per player placed in the shape.
    pub defensive_line: f32,
    /// GRF's micro-focus strength for this team as the ball is now
    /// (`team_shape::micro_focus_strength`), worked out once per decision.
    pub micro_focus_strength: f32,
}

/// One team's built-in AI.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct TeamAi {
    side: Side,
    difficulty: Difficulty,
    plans: Vec<Plan>,
    next_think: u64,
    /// Fraction of a tick carried over to the next decision interval.
    think_carry: f32,
    /// Tick at which this team's keeper took hold of the ball.
    keeper_since: Option<u64>,
    /// Per-player θ of `builtin(θ)` behaviours (empty until one is set; `None`: the team's).
    #[serde(default)]
    player_difficulty: Vec<Option<Difficulty>>,
    /// Per player: the opponent (global index) he marks man to man ([`marking`]).
    #[serde(default)]
    marks: Vec<Option<usize>>,
    /// Tick of the next man-marking assignment.
    #[serde(default)]
    next_marking: u64,
    /// The carrier (global index) at the last man-marking assignment: a new one (or the ball
    /// coming loose) is marked afresh at once.
    #[serde(default)]
    marking_owner: Option<usize>,
    /// Support play off the ball ([`support`]; `None` in a state saved before it, made at the
    /// next decision).
    #[serde(default)]
    support: Option<support::Support>,
    /// Per player: the first-time kick he committed to, the ball's last toucher then and the tick
    /// ([`COMMIT_TICKS`]).
    #[serde(default)]
    committed: Vec<Option<(Kick, Option<usize>, u64)>>,
    /// Per player: the tick of his last decision (`u64::MAX`: none yet), for [`TeamAi::due`].
    #[serde(default)]
    planned: Vec<u64>,
}

/// How long (ticks) a player keeps a first-time kick he decided on while the ball comes to him:
/// GRF's kick animation, once started, plays out to its touch (0.2-0.4 s in) whatever the
/// possession amount then says, so the decision taken about a second from the ball stands.
const COMMIT_TICKS: u64 = 50;

/// How long (ticks) the man on the ball keeps a decision: GRF's carrier dribbles in touch
/// animations (a touch every 400-700 ms, measured in GRF 2.10.2: docs/grf-compatibility.md, "the
/// man on the ball decides") and re-decides within one only while its touch is still to come,
/// so a pass, a shot or a new way to run waits for the rest of it to play out (`humanoid.cpp`'s
/// re-queue test). He decides at once when he gets the ball.
const CARRIER_DECISION_TICKS: u64 = 30;

/// A player further than this (m) from the ball decides anew only every [`FAR_DECISION_TICKS`]
/// ([`TeamAi::due`]; docs/grf-compatibility.md, "how often a player decides").
const FAR_FROM_BALL: f32 = 10.0;
/// How often (ticks) a player far from the ball decides anew: GRF's 240 ms.
const FAR_DECISION_TICKS: u64 = 24;

impl TeamAi {
    /// The AI of `side` at difficulty `theta` for `players` players.
    pub fn new(side: Side, theta: f32, players: usize) -> TeamAi {
        TeamAi {
            side,
            difficulty: Difficulty::new(theta),
            plans: vec![Plan::default(); players],
            next_think: 0,
            think_carry: 0.0,
            keeper_since: None,
            player_difficulty: Vec::new(),
            marks: vec![None; players],
            next_marking: 0,
            marking_owner: None,
            support: Some(support::Support::new(side, players)),
            committed: vec![None; players],
            planned: vec![u64::MAX; players],
        }
    }

    /// The difficulty in force.
    pub fn difficulty(&self) -> &Difficulty {
        &self.difficulty
    }

    /// Re-plans when the reaction time has passed (a player far from the ball only every 240 ms:
    /// [`TeamAi::due`]), then writes this tick's inputs for the team's players that no agent
    /// drives. `inputs`, `agent_driven` and `native` are the team's slices;
    /// players marked `native` are driven by their behaviours (`crate::behaviour`): the AI
    /// neither plans for them nor writes their inputs.
    pub(crate) fn drive(
        &mut self,
        view: &MatchView,
        rng: &mut MatchRng,
        inputs: &mut [PlayerInput],
        agent_driven: &[bool],
        native: &[bool],
    ) {
        let first = view.ranges[self.side.index()].start;
        // An event that needs an instant reaction: the ball changed hands or a set piece began.
        if view.tick >= self.next_think {
            self.think(view, rng, native);
            let interval = self.difficulty.reaction_ticks + self.think_carry;
            let whole = interval.floor();
            self.think_carry = interval - whole;
            self.next_think = view.tick.saturating_add(whole as u64);
        }
        // The team's slices walked together (indexing each by the slot checked every bound).
        let players = &view.players[first..first + self.plans.len()];
        let slots = self.plans.iter_mut().zip(inputs.iter_mut()).zip(agent_driven.iter().zip(native)).zip(players);
        for (((plan, input), (&agent, &native)), p) in slots {
            if agent || native {
                continue;
            }
            let to = plan.target - p.position;
            let dist = to.length();
            // Arrive: slow down within the last metres so players settle on their spots.
            let speed = if plan.run_through { plan.speed } else { plan.speed.min(dist * 2.5) };
            let velocity = if dist > 0.15 { to * (speed / dist) } else { Vec2::ZERO };
            // Every field of the input, written in place: built as a whole `PlayerInput` and
            // copied, it went through the stack in pieces that a wide load then read back, a
            // store-forwarding stall that cost more than the rest of this loop.
            input.velocity = velocity;
            input.look = plan.look;
            input.dribble = plan.dribble;
            input.slide = std::mem::take(&mut plan.slide);
            // The kicks (rarely any) copied only where there is one to copy or to clear: copied
            // whole every tick, each went through the stack.
            if plan.kick.is_some() || input.kick.is_some() {
                input.kick = plan.kick.take();
            }
            if plan.first_time.is_some() || input.first_time.is_some() {
                input.first_time = plan.first_time;
            }
        }
    }

    /// Checks a decoded AI state against a team of `players` players in a match of `total`: every
    /// per-player list as long as the team, every marked man a player of the match, every plan
    /// finite, every θ in [0, 1]. For [`crate::Env::restore`]'s range checks: the AI indexes
    /// these lists and steers by these numbers.
    pub(crate) fn check(&self, players: usize, total: usize) -> Result<(), String> {
        let side = self.side.name();
        if self.plans.len() != players || !(self.marks.is_empty() || self.marks.len() == players) {
            return Err(format!("the {side} AI's plans or marks do not fit a team of {players}"));
        }
        if self.player_difficulty.len() > players {
            return Err(format!(
                "the {side} AI has {} per-player θ for {players} players",
                self.player_difficulty.len()
            ));
        }
        if let Some(m) = self.marks.iter().flatten().find(|&&m| m >= total) {
            return Err(format!("a {side} player marks player {m} of {total}"));
        }
        if !(self.planned.is_empty() || self.planned.len() == players) {
            return Err(format!("the {side} AI's decision times do not fit a team of {players}"));
        }
        if !(self.committed.is_empty() || self.committed.len() == players) {
            return Err(format!("the {side} AI's first-time kicks do not fit a team of {players}"));
        }
        let kick_fits = |(kick, touch, _): &(Kick, Option<usize>, u64)| {
            let aim = match kick.target {
                KickTarget::Point(v) | KickTarget::Direction(v) => v,
            };
            aim.is_finite() && kick.power.is_finite() && kick.height.is_finite() && touch.is_none_or(|t| t < total)
        };
        if !self.committed.iter().flatten().all(kick_fits) {
            return Err(format!("a {side} AI first-time kick is out of range"));
        }
        let thetas = std::iter::once(&self.difficulty).chain(self.player_difficulty.iter().flatten());
        if thetas.clone().any(|d| !(0.0..=1.0).contains(&d.theta) || !d.reaction_ticks.is_finite()) {
            return Err(format!("the {side} AI's difficulty is out of range"));
        }
        let finite = |v: Vec2| v.is_finite() && v.abs().max_element() <= 10_000.0;
        if !self
            .plans
            .iter()
            .all(|p| finite(p.target) && finite(p.look) && p.speed.is_finite() && p.speed.abs() <= 100.0)
        {
            return Err(format!("a {side} AI plan is not finite"));
        }
        if !self.think_carry.is_finite() {
            return Err(format!("the {side} AI's timing is not finite"));
        }
        if let Some(support) = &self.support {
            support.check(players).map_err(|e| format!("the {side} AI: {e}"))?;
        }
        Ok(())
    }

    /// Gives the team's player `index` his own θ (a `builtin(θ)` behaviour), or back the team's
    /// (`None`): his decisions (noise, pressing reach, aim) follow it.
    pub(crate) fn set_player_difficulty(&mut self, index: usize, theta: Option<f32>) {
        if self.player_difficulty.len() < self.plans.len() {
            self.player_difficulty.resize(self.plans.len(), None);
        }
        self.player_difficulty[index] = theta.map(Difficulty::new);
    }

    /// Whether player `g`, who last decided at tick `planned` (`u64::MAX`: never), decides again at
    /// this team decision or keeps his plan: GRF 2.10's re-decision cadence (its players re-queue a
    /// command as their movement animation ends; measured in GRF 2.10.2 over
    /// 11_vs_11_easy_stochastic's first 1,500 steps, its defence and midfield strategies re-decide a
    /// median 40-50 ms apart within 5 m of the ball, 80 ms within 10 m and 240 ms beyond). A player
    /// more than [`FAR_FROM_BALL`] off the ball decides every [`FAR_DECISION_TICKS`], and the man
    /// on the ball when he gets it and then every [`CARRIER_DECISION_TICKS`]; everyone nearer, the
    /// team's two quickest to it, the keeper, a man marker (`marking`) and everyone at a set piece
    /// decide at every team decision, whose interval
    /// (50-150 ms by θ) stands in for GRF's shorter ones near the ball (ported too, they made the
    /// drills' duels worse).
    fn due(view: &MatchView, g: usize, analysis: &Analysis, marking: bool, planned: u64) -> bool {
        let p = &view.players[g];
        if planned == u64::MAX
            || marking
            || view.mode != GameMode::Normal
            || p.is_keeper()
            || analysis.chaser.is_some_and(|(c, _, _)| c == g)
            || analysis.second == Some(g)
        {
            return true;
        }
        if view.owner == Some(g) {
            // Decided before he had the ball: now; else once his touch is played out.
            let since = view.tick.saturating_sub(planned);
            return since > u64::from(view.owner_ticks) || since >= CARRIER_DECISION_TICKS;
        }
        let ball = view.ball.xy() + view.ball.velocity.truncate() * 0.1;
        let near = (p.position + p.velocity * 0.1).distance(ball);
        let every = if near < FAR_FROM_BALL { 0 } else { FAR_DECISION_TICKS };
        view.tick >= planned.saturating_add(every)
    }

    fn think(&mut self, view: &MatchView, rng: &mut MatchRng, native: &[bool]) {
        let side = self.side;
        let analysis = prediction::analyse(view, side, &self.difficulty);
        let range = view.ranges[side.index()].clone();
        let keeper_has_ball = view.owner.is_some_and(|o| view.players[o].side == side && view.players[o].is_keeper());
        self.keeper_since = if keeper_has_ball { Some(self.keeper_since.unwrap_or(view.tick)) } else { None };
        let defending = view.owner_side() != Some(side) && view.mode == GameMode::Normal;
        if self.marks.len() != range.len() {
            // A state saved before man marking: size it once.
            self.marks = vec![None; range.len()];
        }
        if !defending {
            self.marks.fill(None);
            self.marking_owner = view.owner;
        } else if view.tick >= self.next_marking || view.owner != self.marking_owner {
            // Not at every decision while the ball is loose: once when it comes loose, then
            // every 400 ms as at any time.
            marking::assign(view, side, &mut self.marks);
            self.next_marking = view.tick.saturating_add(marking::MARKING_TICKS);
            self.marking_owner = view.owner;
        }
        let support = self.support.get_or_insert_with(|| support::Support::new(side, range.len()));
        support.update(view, &analysis);
        if self.planned.len() != range.len() {
            // A state saved before decision times were kept: everyone decides now.
            self.planned = vec![u64::MAX; range.len()];
        }
        for g in range.clone() {
            let i = g - range.start;
            if native[i] {
                continue;
            }
            if !Self::due(view, g, &analysis, self.marks[i].is_some(), self.planned[i]) {
                // Far from the ball, or on it with his touch not played out: he keeps his plan
                // (its one-off kick and slide already spent).
                continue;
            }
            self.planned[i] = view.tick;
            let p = &view.players[g];
            let ball = view.ball.xy();
            let difficulty = self.player_difficulty.get(i).copied().flatten().unwrap_or(self.difficulty);
            let difficulty = &difficulty;
            let mut plan = if !p.active || p.lazy {
                Plan::go(p.position, 0.0, ball - p.position)
            } else if view.mode != GameMode::Normal {
                set_piece::plan(view, g, &analysis, difficulty, rng)
            } else if view.owner == Some(g) && p.is_keeper() {
                goalkeeper::distribute(
                    view,
                    g,
                    view.tick.saturating_sub(self.keeper_since.unwrap_or(view.tick)),
                    &analysis,
                )
            } else if view.owner == Some(g) {
                ball_carrier::plan(view, g, &analysis, difficulty, rng)
            } else if p.is_keeper() {
                goalkeeper::plan(view, g, &analysis, difficulty)
            } else if let Some(plan) = pressing::plan(view, g, &analysis, difficulty, self.marks[i].is_some()) {
                Plan { slide: sliding::should_slide(view, g), ..plan }
            } else {
                let man = self.marks[i];
                let shape = team_shape::position(view, g, &analysis, difficulty, man.is_some());
                let mut target = support.place(view, g, i, &analysis, shape);
                if let Some(m) = man {
                    // GRF's order: the shape, then the support field, then the man to mark.
                    let on_ball = view.owner == Some(m);
                    let (frame, theta, fading) = (analysis.frame, difficulty.theta, support.fading());
                    target = marking::position(p, &view.players[m], on_ball, target, frame, theta, fading);
                }
                // Anyone the carrier runs past may slide in (GRF's sliding command is every
                // AI player's, not the hunter's alone).
                let slide = sliding::should_slide(view, g);
                Plan { slide, ..Plan::go(target, team_shape::pace(view, p), ball - p.position) }
            };
            if view.mode == GameMode::Normal && p.active && !p.lazy {
                plan.first_time = clearance::first_time(view, g, &analysis)
                    .or_else(|| ball_carrier::first_touch(view, g, &analysis, difficulty, rng));
                if self.committed.len() != range.len() {
                    self.committed = vec![None; range.len()];
                }
                let kept = self.committed[i].filter(|&(_, touch, since)| {
                    view.owner.is_none() && view.last_touch == touch && view.tick < since + COMMIT_TICKS
                });
                // A kick still kept overrides "none" now; a fresh decision is played as decided,
                // its window counted from the first one.
                match (plan.first_time, kept) {
                    (None, Some((kick, _, _))) => plan.first_time = Some(kick),
                    (Some(kick), None) => self.committed[i] = Some((kick, view.last_touch, view.tick)),
                    (Some(_), Some(_)) => {}
                    (None, None) => self.committed[i] = None,
                }
                if p.is_keeper() && plan.first_time.is_some() {
                    // A keeper who means to play the ball first time runs onto it, as GRF's to-ball
                    // movement does, rather than slowing to gather it.
                    plan.run_through = true;
                }
            } else if let Some(c) = self.committed.get_mut(i) {
                *c = None;
            }
            self.plans[i] = plan;
        }
    }
}

/// The whole match as the AI sees it, for the AI's unit tests (`Match::run_ai` builds its own
/// from the fields it does not borrow mutably).
#[cfg(test)]
pub(crate) fn test_view(m: &crate::game::Match) -> MatchView<'_> {
    MatchView {
        players: &m.players,
        ranges: &m.ranges,
        ball: &m.ball,
        owner: m.owner,
        last_touch: m.last_touch,
        mode: m.mode,
        taker: m.taker,
        set_piece_ticks: m.set_piece_ticks,
        tick: m.in_play_ticks,
        owner_ticks: m.owner_ticks,
        offsides: m.offsides,
        agent_driven: &m.agent_driven,
        paths: &m.paths,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::game::Match;
    use crate::player::Role;
    use crate::scenario::{PlayerEntry, Scenario};

    /// A match in play at tick 100, the ball still at the centre spot; our keeper, two players
    /// next to the ball, one 8 m off it and our centre forward 30 m off.
    fn match_in_play() -> Match {
        let s = Scenario {
            left_team: vec![
                PlayerEntry::new(Role::GK, -1.0, 0.0),
                PlayerEntry::new(Role::CB, -0.5, 0.0),
                PlayerEntry::new(Role::CM, -0.5, 0.1),
                PlayerEntry::new(Role::LM, -0.5, 0.2),
                PlayerEntry::new(Role::CF, -0.5, 0.3),
            ],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 0);
        m.mode = GameMode::Normal;
        m.owner = None;
        m.in_play_ticks = 100;
        m.ball.position = glam::Vec3::new(0.0, 0.0, 0.11);
        m.ball.velocity = glam::Vec3::ZERO;
        let at = [(-2.0, 0.0), (-2.0, 1.5), (-6.0, 5.0), (-30.0, 0.0)];
        for (p, (x, y)) in m.players[1..5].iter_mut().zip(at) {
            p.position = Vec2::new(x, y);
            p.velocity = Vec2::ZERO;
        }
        m
    }

    #[test]
    fn a_player_far_from_the_ball_decides_every_240_ms_and_one_near_it_at_every_decision() {
        let mut m = match_in_play();
        let v = test_view(&m);
        let analysis = prediction::analyse(&v, Side::Left, &Difficulty::new(1.0));
        let (keeper, near, forward) = (0, 3, 4);
        assert!(v.players[near].position.distance(v.ball.xy()) < FAR_FROM_BALL);
        assert!(v.players[forward].position.distance(v.ball.xy()) > FAR_FROM_BALL);
        assert!(analysis.chaser.is_some_and(|(c, _, _)| c != near && c != forward));
        assert!(analysis.second.is_some_and(|s| s != near && s != forward));
        // Never decided: now.
        assert!(TeamAi::due(&v, forward, &analysis, false, u64::MAX));
        // Decided 10 ms ago: the forward keeps his plan for 240 ms, the others decide again.
        assert!(!TeamAi::due(&v, forward, &analysis, false, 99));
        assert!(!TeamAi::due(&v, forward, &analysis, false, 100 - FAR_DECISION_TICKS + 1));
        assert!(TeamAi::due(&v, forward, &analysis, false, 100 - FAR_DECISION_TICKS));
        for g in [keeper, near, analysis.second.unwrap_or(0)] {
            assert!(TeamAi::due(&v, g, &analysis, false, 99), "player {g}");
        }
        // A man marker decides at every decision, wherever he is.
        assert!(TeamAi::due(&v, forward, &analysis, true, 99));
        // At a set piece everyone decides at every decision.
        m.mode = GameMode::FreeKick;
        let v = test_view(&m);
        assert!(TeamAi::due(&v, forward, &analysis, false, 99));
    }

    #[test]
    fn the_man_on_the_ball_decides_when_he_gets_it_then_once_his_touch_is_played_out() {
        let mut m = match_in_play();
        let carrier = 1;
        m.owner = Some(carrier);
        // He has had the ball for 50 ms.
        m.owner_ticks = 5;
        let v = test_view(&m);
        let analysis = prediction::analyse(&v, Side::Left, &Difficulty::new(1.0));
        // Last decided before the ball was his (60 ms ago): now.
        assert!(TeamAi::due(&v, carrier, &analysis, false, 94));
        // Decided since he got it: he keeps that for CARRIER_DECISION_TICKS.
        assert!(!TeamAi::due(&v, carrier, &analysis, false, 96));
        m.owner_ticks = 40;
        let v = test_view(&m);
        assert!(!TeamAi::due(&v, carrier, &analysis, false, 100 - CARRIER_DECISION_TICKS + 1));
        assert!(TeamAi::due(&v, carrier, &analysis, false, 100 - CARRIER_DECISION_TICKS));
        // His team-mate next to him still decides at every team decision.
        assert!(TeamAi::due(&v, 2, &analysis, false, 99));
    }
}
