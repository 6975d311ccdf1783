//! The match: the world (ball, two teams, referee state, built-in AI) and [`Match::tick`], which
//! advances it 10 ms. `match` is a keyword, so the module is `game`.

mod action;
mod input;
mod interfere;
pub(crate) mod kick;
mod magnet;
mod mode;
mod possession;
mod steal;
mod tick;
mod touch;
mod trip;

use std::ops::Range;
use std::sync::Arc;

pub use action::{Action, ActionSet, DIRECTIONS};
pub use input::{Kick, KickKind, KickTarget, PlayerInput};
pub use mode::GameMode;
pub(crate) use steal::duel_likeliness;

use crate::ai::TeamAi;
use crate::geometry::coords::{ball_start_to_world, formation_to_world};
use crate::geometry::{Side, TeamFrame};
use crate::physics::{Ball, PitchColliders};
use crate::player::Player;
use crate::rng::MatchRng;
use crate::rules::fouls::PendingFoul;
use crate::rules::offside::Watch;
use crate::rules::{Restart, Stoppage};
use crate::scenario::{Placement, Scenario};
use crate::stats::{Event, EventLog, MatchStats};

/// Whether the ball is in play or the match is waiting for a restart.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Phase {
    /// Ball in play (possibly a set piece waiting for its taker: see [`Match::mode`]).
    Play,
    /// Dead ball after a goal or the ball leaving the pitch; players walk to their places and the
    /// restart is set up when `ticks_left` reaches 0. These ticks are not env steps
    /// (docs/grf-compatibility.md#time-base).
    Dead {
        /// Ticks until the restart is ready.
        ticks_left: u16,
        /// The restart that follows.
        restart: Restart,
    },
}

/// Ticks of dead time after a goal before the kickoff (GRF without rendering: about 0.6 s).
pub(crate) const GOAL_DEAD_TICKS: u16 = 60;
/// Ticks of dead time after the ball leaves the pitch before the set piece is ready.
pub(crate) const OUT_DEAD_TICKS: u16 = 100;
/// GRF's possession test behind [`Match::observed_owner`]
/// (docs/grf-compatibility.md#raw-observation): the highest ball (m, its centre) and the most the
/// ball's velocity may differ from the player's (m/s).
const OBSERVED_POSSESSION_HEIGHT: f32 = 0.5;
const OBSERVED_POSSESSION_SPEED: f32 = 6.0;
/// GRF's possession test's reach (m) from a player's [`Player::possession_point`]: the observed
/// owner's, and a slow loose ball's for a player to take it.
pub(super) const POSSESSION_REACH: f32 = 1.0;

/// The world: ball, both teams, score, game mode and referee state, and the built-in AI.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct Match {
    pub(crate) players: Vec<Player>,
    pub(crate) ranges: [Range<usize>; 2],
    pub(crate) formations: [Vec<[f32; 2]>; 2],
    pub(crate) difficulty: [f32; 2],
    pub(crate) ball: Ball,
    /// The scenario's ball start (m): the second half kicks off from it (docs/grf-compatibility.md#half-time).
    pub(crate) ball_start: glam::Vec2,
    /// The team with a player nearest the ball at the start; the other kicks off the second half.
    pub(crate) first_kickoff: Side,
    /// Fixed geometry, shared by every match: not part of a snapshot.
    #[serde(skip, default = "PitchColliders::shared")]
    pub(crate) colliders: Arc<PitchColliders>,
    /// Player (global index) with the ball at his feet.
    pub(crate) owner: Option<usize>,
    /// Ticks the current owner has had the ball.
    pub(crate) owner_ticks: u32,
    /// The owner is a goalkeeper holding the ball in his hands: nobody may challenge him
    /// (Law 12: preventing a keeper from releasing the ball is an offence; GRF's ball retainer).
    #[serde(default)]
    pub(crate) in_hands: bool,
    /// How far ahead of the owner the ball is (m); eases to half a metre after a trap.
    pub(crate) carry_distance: f32,
    /// Player who touched the ball last.
    pub(crate) last_touch: Option<usize>,
    /// The in-play tick of that touch (a kick, trap, tackle or deflection, or the owner's carry
    /// while he has the ball): a player's body blocks a ball only soon after an opponent touched
    /// it (see `Match::control_loose_ball`).
    pub(crate) touch_tick: u64,
    /// GRF's magnet for each team (see `Match::find_magnet`): the agent's player it pulls to the
    /// loose ball, where he meets it and how hard, as last worked out, and the in-play tick it
    /// was worked out at. It is worked out again every `magnet::MAGNET_EVERY` ticks and after
    /// every touch of the ball.
    pub(crate) magnet: [Option<magnet::Pull>; 2],
    pub(crate) magnet_tick: u64,
    /// The free ball's last predicted path (see `BallPathMemo`): a cache, not part of a snapshot.
    #[serde(skip)]
    pub(crate) paths: crate::ai::prediction::BallPathMemo,
    /// This tick's body contacts (see `Match::trip_players`): scratch, not part of a snapshot.
    #[serde(skip)]
    pub(crate) contacts: crate::physics::Contacts,
    /// Player who last had the ball at his feet (cleared at kickoffs): a trap by an opponent of
    /// his is a [`Event::PossessionWon`].
    pub(crate) possessor: Option<usize>,
    pub(crate) score: [u32; 2],
    pub(crate) mode: GameMode,
    pub(crate) phase: Phase,
    /// Taker of the pending set piece (global index) while `mode` is not Normal.
    pub(crate) taker: Option<usize>,
    /// Ticks the set piece has been waiting for its taker.
    pub(crate) set_piece_ticks: u32,
    pub(crate) inputs: Vec<PlayerInput>,
    pub(crate) agent_driven: Vec<bool>,
    pub(crate) ai: [TeamAi; 2],
    pub(crate) rng: MatchRng,
    pub(crate) in_play_ticks: u64,
    pub(crate) dead_ticks: u64,
    /// The last stoppage seen (goal, ball out, offside, foul), kept for the env and the tests.
    pub(crate) last_stoppage: Option<Stoppage>,
    /// Whether the offside law applies (the scenario's `offsides`).
    pub(crate) offsides: bool,
    /// Players noted in an offside position at the last kick.
    pub(crate) offside_watch: Watch,
    /// A foul waiting for the advantage.
    pub(crate) pending_foul: Option<PendingFoul>,
    /// The passer (global index) of a pass not yet received.
    pub(crate) pending_pass: Option<usize>,
    /// A stoppage the referee called during this tick's ball handling (offside, a foul in the
    /// area), acted on at the end of the tick.
    pub(crate) whistle: Option<Stoppage>,
    /// Ticks left during which nobody can touch the ball just kicked: a player needs GRF's
    /// reaction time (its mental-image delay, 40–80 ms) before he can play a ball struck next to
    /// him.
    #[serde(default)]
    pub(crate) unreachable_ticks: u16,
    /// The match statistics so far.
    pub(crate) stats: MatchStats,
    /// Events since the env's last step began.
    pub(crate) events: EventLog,
    /// Per-player behaviour state (global index); empty when no player has a behaviour.
    pub(crate) behaviours: Vec<crate::behaviour::PlayerBehaviour>,
    /// Players the behaviours drive this tick (global index; all false without behaviours).
    pub(crate) native: Vec<bool>,
    /// Env steps taken this episode, as the env last told (behaviour conditions' `steps`).
    pub(crate) env_steps: u32,
}

impl Match {
    /// Sets up a match from a (validated) scenario for 0-based episode `episode`: players at their
    /// formation places, ball at its start, play on (GRF's initial kickoff counts as taken on the
    /// first tick, docs/grf-compatibility.md#game-modes). `seed` picks the random stream; deterministic
    /// scenarios use their `game_engine_random_seed` (42 by default).
    pub fn new(scenario: &Scenario, episode: u64, seed: u64) -> Match {
        Match::from_placement(scenario, scenario.draw(seed, episode), episode, seed)
    }

    /// Sets up a match as [`Match::new`] from an already drawn `placement` of `scenario`.
    pub fn from_placement(scenario: &Scenario, placement: Placement, episode: u64, seed: u64) -> Match {
        let Placement { left, right, ball, .. } = placement;
        let difficulty = [scenario.left_team_difficulty, scenario.right_team_difficulty];
        let mut players = Vec::with_capacity(left.len() + right.len());
        let ball_start = ball_start_to_world(ball[0], ball[1]);
        for (side, entries) in [(Side::Left, &left), (Side::Right, &right)] {
            for (i, e) in entries.iter().enumerate() {
                let position = formation_to_world(side, e.x, e.y);
                let home = TeamFrame::of(side).vec2(position);
                let mut p = Player::new(side, i, e.role, position, home);
                if let Some(facing) = e.facing {
                    p.facing = facing.direction(side, position, ball_start, p.facing);
                }
                p.lazy = e.lazy;
                p.controllable = e.controllable;
                p.attributes = crate::player::Attributes::for_slot(i);
                // Difficulty scales every stat (docs/grf-compatibility.md#controlled-players): top speed
                // 8·(0.9 + 0.1·stat).
                p.fresh_speed = crate::player::top_speed(p.skill(p.attributes.speed, difficulty[side.index()]));
                p.max_speed = p.fresh_speed;
                players.push(p);
            }
        }
        let ranges = [0..left.len(), left.len()..left.len() + right.len()];
        for side in Side::BOTH {
            crate::ai::team_shape::assign_formation(&mut players[ranges[side.index()].clone()], TeamFrame::of(side));
        }
        let (seed, noisy) =
            if scenario.deterministic { (scenario.game_engine_random_seed, false) } else { (seed, true) };
        let n = players.len();
        let nearest = |side: Side| {
            players
                .iter()
                .filter(|p| p.side == side)
                .map(|p| p.position.distance(ball_start))
                .fold(f32::INFINITY, f32::min)
        };
        let first_kickoff = if nearest(Side::Left) <= nearest(Side::Right) { Side::Left } else { Side::Right };
        let mut game = Match {
            ai: [
                TeamAi::new(Side::Left, difficulty[0], left.len()),
                TeamAi::new(Side::Right, difficulty[1], right.len()),
            ],
            players,
            ranges,
            formations: [left.iter().map(|e| [e.x, e.y]).collect(), right.iter().map(|e| [e.x, e.y]).collect()],
            difficulty,
            ball: Ball::at_rest(ball_start),
            ball_start,
            first_kickoff,
            colliders: PitchColliders::shared(),
            owner: None,
            owner_ticks: 0,
            in_hands: false,
            carry_distance: 0.5,
            last_touch: None,
            touch_tick: 0,
            magnet: [None; 2],
            magnet_tick: 0,
            paths: Default::default(),
            contacts: Default::default(),
            possessor: None,
            score: [0, 0],
            mode: GameMode::Normal,
            phase: Phase::Play,
            taker: None,
            set_piece_ticks: 0,
            inputs: vec![PlayerInput::default(); n],
            agent_driven: vec![false; n],
            rng: MatchRng::new(seed, if scenario.deterministic { 0 } else { episode }, noisy),
            in_play_ticks: 0,
            dead_ticks: 0,
            last_stoppage: None,
            offsides: scenario.offsides,
            offside_watch: Watch::default(),
            pending_foul: None,
            pending_pass: None,
            whistle: None,
            unreachable_ticks: 0,
            stats: MatchStats::default(),
            events: EventLog::default(),
            behaviours: Vec::new(),
            native: vec![false; n],
            env_steps: 0,
        };
        game.install_behaviours(&left, &right);
        if let Some(start) = &scenario.start_with {
            game.start_with(start.restart());
        }
        game
    }

    /// Sets up `restart` as the referee does when its dead time is over (the players as placed
    /// decide who takes it and who must stand back), as the episode's first moment.
    fn start_with(&mut self, restart: Restart) {
        crate::rules::set_up_restart(self, restart);
        self.set_piece_ticks = 0;
        self.record(Event::Restart { side: restart.side, mode: restart.mode });
    }

    /// Counts `event` in the statistics and lists it in this step's events.
    pub(crate) fn record(&mut self, event: Event) {
        self.stats.record(event);
        self.events.push(event);
    }

    /// The match statistics so far (goals, shots, passes, possession, fouls, cards, offsides,
    /// restarts per team).
    pub fn stats(&self) -> &MatchStats {
        &self.stats
    }

    /// What happened during the last env step (or since the match began, before any step), in
    /// order; at most [`crate::stats::EVENTS_PER_STEP`].
    pub fn events(&self) -> &[Event] {
        self.events.as_slice()
    }

    /// Forgets the listed events (the env calls this as each step begins).
    pub(crate) fn clear_events(&mut self) {
        self.events.clear();
    }

    /// Whether the offside law is applied in this match.
    pub fn offsides(&self) -> bool {
        self.offsides
    }

    /// This match state as the start of an episode of `scenario` (its `start_state`): positions,
    /// velocities and game mode as saved; score and statistics at zero; the scenario's
    /// difficulties; the random stream of `(seed, episode)` as [`Match::new`] draws it.
    pub(crate) fn restarted(&self, scenario: &Scenario, episode: u64, seed: u64) -> Match {
        let mut m = self.clone();
        let difficulty = [scenario.left_team_difficulty, scenario.right_team_difficulty];
        m.difficulty = difficulty;
        m.ai = [
            TeamAi::new(Side::Left, difficulty[0], m.ranges[0].len()),
            TeamAi::new(Side::Right, difficulty[1], m.ranges[1].len()),
        ];
        m.score = [0, 0];
        m.stats = MatchStats::default();
        m.events.clear();
        for p in &mut m.players {
            // Top speed follows the scenario's difficulty; fatigue stays as saved.
            let theta = difficulty[p.side.index()];
            p.fresh_speed = crate::player::top_speed(p.attributes.speed * crate::player::difficulty_scale(theta));
            p.max_speed = p.fresh_speed * crate::player::fatigue::speed_factor(p.fatigue);
        }
        m.offsides = scenario.offsides;
        m.env_steps = 0;
        m.native = vec![false; m.players.len()];
        let (left, right) = scenario.teams_for_episode(episode);
        m.install_behaviours(left, right);
        let (seed, noisy) =
            if scenario.deterministic { (scenario.game_engine_random_seed, false) } else { (seed, true) };
        m.rng = MatchRng::new(seed, if scenario.deterministic { 0 } else { episode }, noisy);
        m
    }

    /// All players, left team first, each team in observation order.
    #[inline]
    pub fn players(&self) -> &[Player] {
        &self.players
    }

    /// One team's players in observation order.
    #[inline]
    pub fn team(&self, side: Side) -> &[Player] {
        &self.players[self.ranges[side.index()].clone()]
    }

    /// Global index of `side`'s player `index`.
    #[inline]
    pub fn global_index(&self, side: Side, index: usize) -> usize {
        self.ranges[side.index()].start + index
    }

    /// The ball.
    #[inline]
    pub fn ball(&self) -> &Ball {
        &self.ball
    }

    /// Goals `[left, right]`.
    #[inline]
    pub fn score(&self) -> [u32; 2] {
        self.score
    }

    /// The pending set piece, or `Normal` in open play.
    #[inline]
    pub fn mode(&self) -> GameMode {
        self.mode
    }

    /// Whether the ball is in play (not in dead time before a restart).
    #[inline]
    pub fn in_play(&self) -> bool {
        matches!(self.phase, Phase::Play)
    }

    /// Current phase.
    #[inline]
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// The player with the ball at his feet, as (side, index in team).
    pub fn owner(&self) -> Option<(Side, usize)> {
        self.owner.map(|g| (self.players[g].side, self.players[g].index))
    }

    /// The player the observation shows with the ball, as (side, index in team): the player with
    /// it at his feet, or else the last to touch it while he still has possession by GRF's test:
    /// the ball at most 0.5 m up, within 1 m of the point 0.05 s of his run and 0.1 m along his
    /// facing ahead of him, moving within 6 m/s of him, and not his pass on its way (GRF's passer
    /// has no possession during his kick's animation; a shot or clearance leaves him faster than
    /// 6 m/s). GRF 2.10 reports its `ball_owned_team` this way
    /// (docs/grf-compatibility.md#raw-observation), so a standing tackle's knock shows as the
    /// tackler's ball until it has run a metre from him; the possession-change end reads it too.
    ///
    /// A ball the referee placed for a goal kick, corner kick, free kick or penalty kick is
    /// nobody's until the taker plays it, though touchline's taker holds it at his feet: GRF's
    /// test wants the last toucher, who put the ball out or was at the foul, not the taker
    /// (measured in GRF 2.10.2: `ball_owned_team` −1 on every step of those restarts). A
    /// thrower has the ball in his hands, and GRF shows it his.
    pub fn observed_owner(&self) -> Option<(Side, usize)> {
        if self.owner.is_some() {
            let placed =
                matches!(self.mode, GameMode::GoalKick | GameMode::Corner | GameMode::FreeKick | GameMode::Penalty);
            return if placed && self.owner == self.taker { None } else { self.owner() };
        }
        let g = self.last_touch?;
        let p = &self.players[g];
        let holds = p.active
            && self.pending_pass != Some(g)
            && self.ball.position.z <= OBSERVED_POSSESSION_HEIGHT
            && p.possession_point().distance_squared(self.ball.xy()) <= POSSESSION_REACH * POSSESSION_REACH
            && (self.ball.velocity - p.velocity.extend(0.0)).length_squared()
                <= OBSERVED_POSSESSION_SPEED * OBSERVED_POSSESSION_SPEED;
        holds.then_some((p.side, p.index))
    }

    /// The player who touched the ball last, as (side, index in team).
    pub fn last_touch(&self) -> Option<(Side, usize)> {
        self.last_touch.map(|g| (self.players[g].side, self.players[g].index))
    }

    /// The last goal or out-of-play the referee saw this episode.
    pub fn last_stoppage(&self) -> Option<Stoppage> {
        self.last_stoppage
    }

    /// Ticks played with the ball in play.
    pub fn in_play_ticks(&self) -> u64 {
        self.in_play_ticks
    }

    /// Team difficulties `[left, right]`.
    pub fn difficulty(&self) -> [f32; 2] {
        self.difficulty
    }

    /// Whether an agent drives `side`'s player `index` (index in team) this step.
    pub fn is_agent_driven(&self, side: Side, index: usize) -> bool {
        self.agent_driven[self.global_index(side, index)]
    }

    /// Whether `side`'s player `index` may play the ball now: he has it, it lies loose at his feet
    /// and nobody is nearer, or he is his team's man at a loose ball within 2 m (a shot is then
    /// struck at his first touch, a pass fails; see `Match::at_loose_ball`). His pass and shot
    /// buttons count only then.
    pub fn may_play_ball(&self, side: Side, index: usize) -> bool {
        let g = self.global_index(side, index);
        self.may_play(g) || self.at_loose_ball(g)
    }

    /// Gives `side`'s player `index` to an agent (`Some(input)`) or back to the built-in AI (`None`).
    pub fn set_agent_input(&mut self, side: Side, index: usize, input: Option<PlayerInput>) {
        let g = self.global_index(side, index);
        match input {
            Some(i) => {
                self.inputs[g] = i;
                self.agent_driven[g] = true;
            }
            None => self.agent_driven[g] = false,
        }
    }

    /// Hands every player of `side` that an agent drove but no controller drives now
    /// (`controlled`: the team's controlled players, index in team) back to the built-in AI or to
    /// his behaviour, as GRF does when control switches; a kick he was winding up is forgotten.
    pub(crate) fn release_uncontrolled(&mut self, side: Side, controlled: &[usize]) {
        let start = self.ranges[side.index()].start;
        for g in self.ranges[side.index()].clone() {
            if self.agent_driven[g] && !controlled.contains(&(g - start)) {
                self.agent_driven[g] = false;
                self.players[g].pending_kick = None;
            }
        }
    }

    /// Half-time (docs/grf-compatibility.md#half-time): fatigue is restored and the team that did not start
    /// with the ball kicks off from the scenario's ball position, the two teams exchanging formations when they
    /// have as many players. Teams do not change ends, as in GRF.
    pub fn start_second_half(&mut self) {
        crate::rules::kickoff::set_up(self, self.first_kickoff.opponent());
        self.record(Event::Restart { side: self.first_kickoff.opponent(), mode: GameMode::KickOff });
        self.offside_watch = Watch::default();
        self.pending_foul = None;
        self.pending_pass = None;
        self.ball = Ball::at_rest(self.ball_start);
        for p in &mut self.players {
            p.fatigue = 0.0;
            p.max_speed = p.fresh_speed;
        }
        self.last_touch = None;
        self.phase = Phase::Play;
    }

    /// Puts the ball loose at `position` (m) with `velocity` (m/s), as last touched by `last_touch`
    /// (side, index in team). For tests, tools and scenarios that start from a moment of play.
    pub fn place_ball(&mut self, position: glam::Vec3, velocity: glam::Vec3, last_touch: Option<(Side, usize)>) {
        self.ball = Ball { position, velocity, spin: glam::Vec3::ZERO };
        self.owner = None;
        self.owner_ticks = 0;
        self.last_touch = last_touch.map(|(side, i)| self.global_index(side, i));
        self.touch_tick = self.in_play_ticks;
        self.possessor = None;
        self.offside_watch = Watch::default();
        self.pending_pass = None;
    }

    /// Shows `card` to `side`'s player `index` as the referee would after a foul (Law 12): a second
    /// yellow is a red; a red sends him off (`active` false) unless he is his team's last active
    /// player; a sent-off keeper is replaced in goal by the first active team-mate. For tests,
    /// tools and scenarios.
    pub fn show_card(&mut self, side: Side, index: usize, card: crate::rules::cards::Card) {
        let g = self.global_index(side, index);
        crate::rules::cards::show(self, g, card);
    }

    /// Moves `side`'s player `index` to `position` (m), standing still.
    pub fn place_player(&mut self, side: Side, index: usize, position: glam::Vec2) {
        let g = self.global_index(side, index);
        let p = &mut self.players[g];
        p.halt();
        p.position = position;
    }

    /// A 64-bit fingerprint of the dynamic state (positions, velocities, ball, score, mode), for
    /// determinism tests. Equal states give equal hashes on every platform.
    pub fn state_hash(&self) -> u64 {
        // FNV-1a over the exact bit patterns.
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        let mut feed = |x: u32| {
            for b in x.to_le_bytes() {
                h ^= u64::from(b);
                h = h.wrapping_mul(0x0100_0000_01b3);
            }
        };
        for p in &self.players {
            for v in [p.position.x, p.position.y, p.velocity.x, p.velocity.y, p.facing.x, p.facing.y] {
                feed(v.to_bits());
            }
        }
        for v in self.ball.position.to_array().into_iter().chain(self.ball.velocity.to_array()) {
            feed(v.to_bits());
        }
        feed(self.score[0]);
        feed(self.score[1]);
        feed(self.mode as u32);
        feed(self.owner.map_or(u32::MAX, |g| g as u32));
        h
    }
}
