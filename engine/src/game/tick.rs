//! [`Match::tick`]: one 10 ms step of the world.

use glam::Vec2;

use crate::geometry::Side;

use super::kick::{launch, pass_choice};
use super::{GOAL_DEAD_TICKS, GameMode, KickKind, Match, OUT_DEAD_TICKS, Phase, PlayerInput};
use crate::game::input::Kick;
use crate::physics::{MotionLimits, Stride, Strides, TICK_SECONDS, separate_players};
use crate::player::{DRIBBLE_SPEED, Player};
use crate::rules::{self, Restart, Stoppage};
use crate::stats::Event;

/// Ticks after a kick before anyone can touch the ball (see `Match::unreachable_ticks`).
const REACTION_TICKS: u16 = 5;
/// Ticks a player cannot touch the ball after kicking it.
const KICK_COOLDOWN: u16 = 25;
/// The largest turn (rad) from his facing to a high pass's target that a standing player makes.
const HIGH_PASS_TURN: f32 = 0.8 * std::f32::consts::PI;
/// Wind-up of a shot and of a pass (ticks) before any turning (see `Match::wind_up_ticks`).
const SHOT_WIND_UP: f32 = 17.0;
const PASS_WIND_UP: f32 = 10.0;
/// How long (ticks) after its wind-up an agent's kick asked for at a loose ball waits for his first
/// touch before it is forgotten (GRF's human controller buffers a command 1,000 ms).
pub(crate) const QUEUED_KICK_WINDOW: u16 = 100;
/// Within this distance (m) of a loose ball an agent's player steps to it by himself, whatever his
/// stick says (GRF's automatic ball control: the academy drills' carriers start up to 1.4 m from
/// the ball). Beyond it the magnet takes over (see `Match::find_magnet`).
pub(super) const BALL_CONTROL_RANGE: f32 = 3.0;
/// How far ahead (s) an agent's player's automatic ball control aims: where the ball will be at
/// his touch (GRF's ball-control movement: 250 ms plus its 80 ms touch offset).
const BALL_CONTROL_AHEAD: f32 = 0.33;
/// Fastest ball (m/s, relative to him) an agent's player's automatic ball control goes for (GRF
/// refuses a ball-control command above 15 m/s).
const BALL_CONTROL_SPEED: f32 = 15.0;
/// GRF's `distanceToVelocityMultiplier`: a player running to a point d metres off asks for
/// 2.6·d m/s, up to his top speed.
pub(super) const DISTANCE_TO_VELOCITY: f32 = 2.6;
/// A loose ball nearer than this (m) is at an idle player's feet already: he does not step to it
/// (GRF shows such a ball owned by nobody until he plays it).
const AT_FEET: f32 = 0.7;
/// Most players in a match (11 a side).
const MAX_PLAYERS: usize = 22;
/// A player's turning rate (rad per tick), as `physics::player_motion` turns him.
const TURN_PER_TICK: f32 = 0.12;
/// Sliding tackle: duration (ticks) and initial speed (m/s).
const SLIDE_TICKS: u16 = 50;
const SLIDE_SPEED: f32 = 7.5;
/// Goalkeeper's dive: duration (ticks) and lateral speed (m/s).
const DIVE_TICKS: u16 = 35;
const DIVE_SPEED: f32 = 6.5;
/// Fatigue is updated every this many ticks of play (0.1 s).
const FATIGUE_EVERY: u64 = 10;
const FATIGUE_SECONDS: f32 = FATIGUE_EVERY as f32 * TICK_SECONDS;
/// Where a dribbler keeps the ball: this far ahead of him (m).
const CARRY_DISTANCE: f32 = 0.5;
/// Top speed with the ball at one's feet (m/s): the ball slows a sprinter down a little.
const BALL_CARRIER_SPRINT: f32 = 7.2;

impl Match {
    /// Advances the match by one tick (10 ms). In play: the built-in AI decides for every player no
    /// agent drives, kicks and tackles happen, players and ball move, possession is settled and the
    /// referee judges goals and balls out of play. In dead time: players walk to their places and
    /// the restart is set up when the time is up.
    pub fn tick(&mut self) {
        match self.phase {
            Phase::Play => self.tick_in_play(),
            Phase::Dead { ticks_left, restart } => self.tick_dead(ticks_left, restart),
        }
    }

    fn tick_in_play(&mut self) {
        self.in_play_ticks += 1;
        self.run_ai();
        self.apply_kicks_and_tackles();
        self.move_players();
        separate_players(&mut self.players, self.owner, &mut self.contacts);
        self.trip_players();
        let before = self.ball.position;
        self.move_ball();
        let owner_before = self.owner;
        self.settle_possession();
        if self.owner.is_some() {
            self.touch_tick = self.in_play_ticks;
        }
        self.owner_ticks = if self.owner.is_some() && self.owner == owner_before { self.owner_ticks + 1 } else { 0 };
        if let Some(g) = self.owner.or(self.last_touch) {
            self.stats.teams[self.players[g].side.index()].possession_ticks += 1;
        }
        if let Some(stoppage) = self.whistle.take() {
            self.stop_play(stoppage);
        } else if let Some(stoppage) =
            rules::judge(before, self.ball.position, self.last_touch.map(|g| self.players[g].side))
        {
            self.stop_play(stoppage);
        } else if let Some(stoppage) = rules::fouls::advantage(self) {
            self.stop_play(stoppage);
        }
        let loose = self.owner.is_none();
        for p in &mut self.players {
            p.touch_cooldown = p.touch_cooldown.saturating_sub(1);
            p.interfere_ticks = p.interfere_ticks.saturating_sub(1);
            p.dive_ticks = p.dive_ticks.saturating_sub(1);
            if let Some((kick, left)) = p.queued_kick {
                // Forgotten once someone has the ball, or a second after its wind-up if he has
                // not reached the ball by then (GRF's 1,000 ms command buffer).
                p.queued_kick = (loose && left > 1).then_some((kick, left - 1));
            }
        }
        if self.mode != GameMode::Normal {
            self.set_piece_ticks += 1;
        }
    }

    fn run_ai(&mut self) {
        // Without behaviours none of this runs: such matches play exactly as before.
        let behaviours = !self.behaviours.is_empty();
        if behaviours {
            self.prepare_behaviours();
        }
        let view = crate::ai::MatchView {
            players: &self.players,
            ranges: &self.ranges,
            ball: &self.ball,
            owner: self.owner,
            last_touch: self.last_touch,
            mode: self.mode,
            taker: self.taker,
            set_piece_ticks: self.set_piece_ticks,
            tick: self.in_play_ticks,
            owner_ticks: self.owner_ticks,
            offsides: self.offsides,
            agent_driven: &self.agent_driven,
            paths: &self.paths,
        };
        for side in 0..2 {
            if behaviours && self.nobody_for_ai(side) {
                continue;
            }
            let range = self.ranges[side].clone();
            self.ai[side].drive(
                &view,
                &mut self.rng,
                &mut self.inputs[range.clone()],
                &self.agent_driven[range.clone()],
                &self.native[range],
            );
        }
        if behaviours {
            self.behaviour_inputs();
        }
    }

    fn apply_kicks_and_tackles(&mut self) {
        let mut from = 0;
        // Only a player asking for a kick or a slide or winding up a kick has anything to do here.
        let kicks_or_tackles = |(p, input): (&Player, &PlayerInput)| {
            p.active && (input.kick.is_some() || input.slide || p.pending_kick.is_some())
        };
        while let Some(g) = first_from(from, &self.players, &self.inputs, kicks_or_tackles) {
            from = g + 1;
            let input = self.inputs[g];
            if let Some(kick) = input.kick {
                // Only the player on the ball, or an agent's player at a loose ball not yet his
                // (below), can start a kick: GRF drops any other press rather than buffering it
                // into a later kick. One kick at a time.
                if self.players[g].pending_kick.is_none() && self.may_play(g) {
                    self.take_to_play(g);
                }
                if self.owner == Some(g) && self.players[g].pending_kick.is_none() && self.turns_out_of_reach(g, &kick)
                {
                    // No lofted kick turned right round from a stand: GRF has no such move and
                    // drops the button.
                } else if self.owner == Some(g) && self.players[g].pending_kick.is_none() {
                    let ticks = self.wind_up_ticks(g, &kick);
                    self.players[g].pending_kick = Some((kick, ticks));
                    self.players[g].ready_kick();
                } else if self.owner.is_none() && self.agent_driven[g] && self.at_loose_ball(g) {
                    // GRF's buttons at a loose ball not yet his: the kick, shot or pass, waits for
                    // his first touch and is that touch (measured, GRF 2.10: a shot pressed at
                    // env step 2-3 leaves 3 steps later, a pass 5 steps later, back to the keeper,
                    // and his team never shows as the ball's owner).
                    let ticks = self.wind_up_ticks(g, &kick);
                    self.players[g].queued_kick = Some((kick, ticks + QUEUED_KICK_WINDOW));
                }
                // A kick is a one-tick request.
                self.inputs[g].kick = None;
            }
            if let Some((kick, left)) = self.players[g].pending_kick {
                if self.owner != Some(g) {
                    // Dispossessed during the wind-up: the kick never happens.
                    self.players[g].pending_kick = None;
                } else if left <= 1 {
                    self.execute_kick(g, kick);
                } else {
                    self.players[g].pending_kick = Some((kick, left - 1));
                }
            }
            if input.slide {
                self.inputs[g].slide = false;
            }
            let p = &self.players[g];
            if input.slide
                && self.owner != Some(g)
                && p.slide_ticks == 0
                && p.dive_ticks == 0
                && self.mode == GameMode::Normal
                && !self.has_best_possession(p.side)
            {
                self.start_slide(g, input.velocity);
            }
        }
    }

    /// Whether `side` is the team with the ball: it has it at a player's feet, or the ball is loose
    /// and one of its players reaches it no later than any opponent. GRF accepts the sliding button
    /// only from a team without it (its "possession context" below zero); with it, the button is a
    /// pass or shot button and a slide never pushes a team's own ball on.
    fn has_best_possession(&self, side: Side) -> bool {
        if let Some(o) = self.owner {
            return self.players[o].side == side;
        }
        let ball = self.ball.xy();
        let mut best = [f32::INFINITY; 2];
        for p in self.players.iter().filter(|p| p.active) {
            let t = p.position.distance(ball) / p.max_speed.max(1.0);
            best[p.side.index()] = best[p.side.index()].min(t);
        }
        best[side.index()] <= best[side.opponent().index()]
    }

    /// Starts `g`'s sliding tackle (a keeper in his area dives instead) in the direction of
    /// `velocity`; without one, at a ball within reach, else where he faces.
    fn start_slide(&mut self, g: usize, velocity: Vec2) {
        let to_ball = self.ball.xy() - self.players[g].position;
        let p = &mut self.players[g];
        let dir = if velocity.length_squared() > 0.01 {
            velocity.normalize()
        } else if to_ball.length_squared() < 25.0 {
            to_ball.normalize_or(p.facing)
        } else {
            p.facing
        };
        let own_goal = -p.side.attack_sign();
        if p.is_keeper() && crate::geometry::pitch::in_penalty_area(p.position.x, p.position.y, own_goal) {
            p.dive_ticks = DIVE_TICKS;
            p.velocity = dir * DIVE_SPEED;
        } else {
            p.slide_ticks = SLIDE_TICKS;
            p.facing = dir;
            p.velocity = dir * SLIDE_SPEED;
        }
    }

    /// Whether `kick` is a high pass by agent's player `g` standing (his stick asking for less
    /// than 1.8 m/s, however others shove him) and facing more than [`HIGH_PASS_TURN`] away from
    /// where it goes. GRF 2.10 plays no such kick:
    /// academy_run_to_score, the CB standing on the ball facing the opponents' goal, a high pass
    /// pressed at env step 15 (its target his keeper, straight behind) is never struck (8 of 8, the
    /// harness's `high_pass_at_step_15` probe), while a short or long pass is, 5 steps later.
    fn turns_out_of_reach(&self, g: usize, kick: &Kick) -> bool {
        let p = &self.players[g];
        if kick.kind != KickKind::HighPass
            || !self.agent_driven[g]
            || self.wanted_velocity(g).length_squared() > 1.8 * 1.8
        {
            return false;
        }
        let aim = self.kick_target(g, kick) - p.position;
        aim.length_squared() > 1e-6 && super::kick::signed_angle(p.facing, aim).abs() > HIGH_PASS_TURN
    }

    /// Ticks from the request of `kick` by the owner `g` to the ball leaving his foot: the kick's
    /// own wind-up plus the time to turn to its target at his turning rate. GRF's ball leaves the
    /// foot 20–30 ticks after a shot is asked for by a player facing the goal, and 40 ticks after
    /// a pass played straight back (GRF 2.10, measured; the button's 10 ticks come on top, see
    /// `env`). A stochastic match adds up to 6 ticks either way.
    fn wind_up_ticks(&mut self, g: usize, kick: &Kick) -> u16 {
        let base = if kick.kind == KickKind::Shot { SHOT_WIND_UP } else { PASS_WIND_UP };
        let aim = self.kick_target(g, kick) - self.players[g].position;
        let turn = if aim.length_squared() > 1e-6 {
            super::kick::signed_angle(self.players[g].facing, aim).abs() / TURN_PER_TICK
        } else {
            0.0
        };
        (base + turn + 3.0 + self.rng.noise(3.0)).round().max(1.0) as u16
    }

    /// Where `kick` by `g` goes: its point, or for a direction the goal (a shot) or the receiver
    /// chosen as GRF chooses for an agent's pass.
    fn kick_target(&self, g: usize, kick: &Kick) -> Vec2 {
        self.kick_aim(g, kick).0
    }

    /// [`Match::kick_target`] and, for a pass, the team-mate it is meant for (index in his team):
    /// the one GRF's rating picks for a pass in a direction, the one nearest the point for a pass
    /// to a point.
    fn kick_aim(&self, g: usize, kick: &Kick) -> (Vec2, Option<usize>) {
        let kicker = &self.players[g];
        let mates = self.team(kicker.side);
        match kick.target {
            super::KickTarget::Point(p) if kick.kind == KickKind::Shot => (p, None),
            super::KickTarget::Point(p) => {
                let receiver = mates
                    .iter()
                    .filter(|m| m.active && m.index != kicker.index)
                    .min_by(|a, b| a.position.distance_squared(p).total_cmp(&b.position.distance_squared(p)))
                    .map(|m| m.index);
                (p, receiver)
            }
            super::KickTarget::Direction(dir) if kick.kind == KickKind::Shot => {
                (super::kick::aimed_shot_target(kicker, dir), None)
            }
            super::KickTarget::Direction(dir) => pass_choice(kick.kind, kicker, mates, dir, kick.power),
        }
    }

    /// Executes `kick` by the ball owner `g`.
    pub(crate) fn execute_kick(&mut self, g: usize, kick: Kick) {
        let side = self.players[g].side;
        let (target, receiver) = self.kick_aim(g, &kick);
        let kicker = &self.players[g];
        let stat = if kick.kind == KickKind::Shot { kicker.attributes.shooting } else { kicker.attributes.passing };
        let accuracy = kicker.skill(stat, self.theta(g));
        let throw_in = self.mode == GameMode::ThrowIn && self.taker == Some(g);
        launch(&mut self.ball, &self.players[g], &kick, target, accuracy, throw_in, &mut self.rng);
        let p = &mut self.players[g];
        p.touch_cooldown = KICK_COOLDOWN;
        p.pending_kick = None;
        p.kick_run = Vec2::ZERO;
        self.unreachable_ticks = REACTION_TICKS;
        let index = p.index;
        self.owner = None;
        self.last_touch = Some(g);
        self.touch_tick = self.in_play_ticks;
        if kick.kind == KickKind::Shot {
            let on_target = rules::goal::on_target(&self.ball);
            self.record(Event::Shot { side, player: index, on_target });
            self.pending_pass = None;
        } else {
            self.record(Event::Pass { side, player: index, to: receiver });
            self.pending_pass = Some(g);
        }
        // No offside from a throw-in, goal kick or corner kick (Law 11).
        let no_offside = matches!(self.mode, GameMode::ThrowIn | GameMode::GoalKick | GameMode::Corner);
        self.offside_watch = if self.offsides && !no_offside {
            let mask = rules::offside::positions(self, side, g, self.ball.xy());
            rules::offside::Watch { side: Some(side), mask }
        } else {
            rules::offside::Watch::default()
        };
        if self.taker == Some(g) {
            self.end_set_piece();
        }
    }

    fn move_players(&mut self) {
        let base = MotionLimits::default();
        // Per player: the direction of a kick he is winding up, or the step an idle agent's player
        // takes to a loose ball he is the one to control. At most 22 players: on the stack.
        let mut aims = [None; MAX_PLAYERS];
        let mut controls = [None; MAX_PLAYERS];
        self.refresh_magnet();
        // Only a player winding up a kick or an agent's player has an aim or a control step.
        let mut from = 0;
        let winds_up_or_agents = |(p, &agent): (&Player, &bool)| agent || p.pending_kick.is_some();
        let n = self.players.len().min(MAX_PLAYERS);
        while let Some(g) = first_from(from, &self.players[..n], &self.agent_driven, winds_up_or_agents) {
            from = g + 1;
            if let Some((kick, _)) = self.players[g].pending_kick {
                aims[g] = Some(self.kick_target(g, &kick) - self.players[g].position);
            } else if self.agent_driven[g] {
                controls[g] = self.magnet_step(g).or_else(|| self.ball_control_step(g));
            }
        }
        for (p, step) in self.players.iter_mut().zip(controls) {
            p.controlling_ball = step.is_some();
        }
        let fatigue_tick = self.in_play_ticks.is_multiple_of(FATIGUE_EVERY);
        let mut strides = Strides::new(TICK_SECONDS);
        for g in 0..self.players.len() {
            let theta = self.theta(g);
            let p = &mut self.players[g];
            if !p.active {
                continue;
            }
            if fatigue_tick {
                let speed = p.velocity.length();
                crate::player::fatigue::update(p, speed, FATIGUE_SECONDS, p.attributes.stamina, p.fresh_speed);
            }
            if p.slide_ticks > 0 || p.dive_ticks > 0 || p.trip_ticks > 0 {
                p.slide_ticks = p.slide_ticks.saturating_sub(1);
                p.trip_ticks = p.trip_ticks.saturating_sub(1);
                p.velocity *= 0.96;
                p.position += p.velocity * TICK_SECONDS;
                continue;
            }
            // Acceleration 6–8 m/s² from the attribute (after difficulty and fatigue).
            let limits = MotionLimits {
                acceleration: base.acceleration - 1.0 + 2.0 * p.skill(p.attributes.acceleration, theta),
                ..base
            };
            // The input's velocity and look, by value: copying the whole input (two kicks
            // included) to pass it on cost more than the rest of this loop.
            let input = &self.inputs[g];
            let (mut velocity, mut look) = (input.velocity, input.look);
            if let Some(aim) = aims[g] {
                // Winding up a kick he walks through it: he keeps his run, whichever way the
                // kick goes, and turns to its target. GRF 2.10.2, academy_run_to_score's random
                // agent: of the kicks pressed by a carrier moving at 2 m/s or more, the carrier
                // still moved at 2 m/s or more on the step before the ball left in 25 of 29 along
                // his run, 25 of 28 across it and 21 of 26 back against it.
                velocity = p.velocity;
                look = aim;
            } else if let Some(step) = controls[g] {
                velocity = step;
            }
            if self.taker == Some(g) {
                // A set-piece taker stands at the ball until he plays it.
                velocity = Vec2::ZERO;
            } else {
                let cap = if self.owner == Some(g) {
                    if input.dribble { DRIBBLE_SPEED } else { BALL_CARRIER_SPRINT.min(p.max_speed) }
                } else if input.dribble {
                    DRIBBLE_SPEED
                } else if p.interfere_ticks > 0 {
                    // Winding up a standing tackle he goes in at the tackle's own pace, not at his
                    // run's: he meets the ball without running into the man.
                    super::interfere::PACE.min(p.max_speed)
                } else {
                    p.max_speed
                };
                let speed2 = velocity.length_squared();
                if speed2 > cap * cap {
                    velocity *= cap / speed2.sqrt();
                }
            }
            strides.push(&mut self.players, g, Stride { velocity, look, limits });
        }
        strides.finish(&mut self.players);
    }

    /// The velocity `g` asks for this tick: his input's, or for an agent's player the step of his
    /// automatic ball control.
    pub(crate) fn wanted_velocity(&self, g: usize) -> Vec2 {
        if self.agent_driven[g] {
            self.ball_control_step(g).unwrap_or(self.inputs[g].velocity)
        } else {
            self.inputs[g].velocity
        }
    }

    /// GRF's automatic ball control for an agent's player, the velocity it gives him if any. When
    /// the ball is loose, slow and low within [`BALL_CONTROL_RANGE`] of him and nobody is nearer to
    /// it, he steps to it and takes it, whichever way his stick points, at his own pace and at least
    /// a dribble's (GRF's human controller issues ball-control and trap commands by itself; the
    /// stick then steers the dribble. Measured in GRF 2.10: holding left, bottom-left or top-left
    /// from the start of academy_empty_goal or academy_run_to_score, our CB owns the ball by step 10
    /// and dribbles it that way). Further off the magnet may run him to it (`Match::magnet_step`).
    fn ball_control_step(&self, g: usize) -> Option<Vec2> {
        if self.owner.is_some() || self.mode != GameMode::Normal {
            return None;
        }
        let ball = self.ball;
        let me = &self.players[g];
        let d2 = (ball.xy() - me.position).length_squared();
        let stick = self.inputs[g].velocity;
        if d2 > BALL_CONTROL_RANGE * BALL_CONTROL_RANGE {
            return None;
        }
        // A ball already at his feet he leaves be, unless he is on his way to it; one too fast
        // for a touch he lets go (GRF refuses ball control above 15 m/s relative).
        let relative = ball.velocity.truncate() - me.velocity;
        if ball.position.z > 0.5
            || (d2 < AT_FEET * AT_FEET && !me.controlling_ball && me.queued_kick.is_none())
            || relative.length_squared() > BALL_CONTROL_SPEED * BALL_CONTROL_SPEED
        {
            return None;
        }
        let nearer = self.players.iter().any(|p| p.active && p.position.distance_squared(ball.xy()) < d2);
        if nearer {
            return None;
        }
        // GRF's ball-control movement: to where the ball will be a touch from now, at 2.6 m/s per
        // metre to go (never slower than his stick or a dribble), so a ball rolling away from
        // him is caught rather than chased.
        let to = ball.xy() + ball.velocity.truncate() * BALL_CONTROL_AHEAD - me.position;
        let pace = (to.length() * DISTANCE_TO_VELOCITY).max(stick.length()).max(DRIBBLE_SPEED);
        Some(to.normalize_or_zero() * pace)
    }

    fn move_ball(&mut self) {
        if self.taker.is_some() && self.owner == self.taker {
            // A set piece: the ball stays on its spot until the taker plays it (a taker turning
            // on the touchline must not carry it over the line).
            self.ball.velocity = glam::Vec3::ZERO;
            return;
        }
        if let Some(g) = self.owner {
            let p = &self.players[g];
            if p.pending_kick.is_some() {
                // Winding up a kick he turns, and the ball keeps its place beside him, moving
                // only with his run: GRF's kick animations place the body round the ball
                // (measured in GRF 2.10, a pass played straight back leaves the ball still
                // through the 400 ms of the turn), so a turn never swings the ball behind him
                // into a chaser's path.
                self.ball.position += (p.velocity * TICK_SECONDS).extend(0.0);
                self.ball.velocity = p.velocity.extend(0.0);
                self.carry_distance = p.position.distance(self.ball.xy());
                return;
            }
            // At the owner's feet, half a metre ahead of him.
            self.carry_distance += (CARRY_DISTANCE - self.carry_distance).clamp(-0.01, 0.01);
            let at = p.position + p.facing * self.carry_distance;
            self.ball.position = at.extend(crate::geometry::pitch::BALL_RADIUS);
            self.ball.velocity = p.velocity.extend(0.0);
            return;
        }
        self.ball.integrate(TICK_SECONDS, &self.colliders);
    }

    /// Stops play for a goal or a ball out of play and starts the dead time.
    pub(crate) fn stop_play(&mut self, stoppage: Stoppage) {
        self.last_stoppage = Some(stoppage);
        self.owner = None;
        self.taker = None;
        self.pending_pass = None;
        self.pending_foul = None;
        self.offside_watch = rules::offside::Watch::default();
        let (ticks, restart) = match stoppage {
            Stoppage::Goal { scorer } => {
                self.score[scorer.index()] += 1;
                let player = self.last_touch.filter(|&g| self.players[g].side == scorer).map(|g| self.players[g].index);
                self.record(Event::Goal { side: scorer, player });
                self.mode = GameMode::KickOff;
                (GOAL_DEAD_TICKS, rules::kickoff::after_goal(scorer))
            }
            Stoppage::Out { restart } => {
                // The restart goes against the team that touched the ball last.
                let side = restart.side.opponent();
                let player = self.last_touch.filter(|&g| self.players[g].side == side).map(|g| self.players[g].index);
                self.record(Event::OutOfPlay { side, player });
                self.mode = restart.mode;
                (OUT_DEAD_TICKS, restart)
            }
            Stoppage::Offside { restart, .. } | Stoppage::Foul { restart, .. } => {
                self.mode = restart.mode;
                (OUT_DEAD_TICKS, restart)
            }
        };
        self.record(Event::Restart { side: restart.side, mode: restart.mode });
        for p in &mut self.players {
            p.slide_ticks = 0;
            p.trip_ticks = 0;
            p.pending_kick = None;
        }
        self.phase = Phase::Dead { ticks_left: ticks, restart };
    }

    fn tick_dead(&mut self, ticks_left: u16, restart: Restart) {
        self.dead_ticks += 1;
        // The ball finishes its flight (into the net, over the boards); players slow to a walk.
        self.ball.integrate(TICK_SECONDS, &self.colliders);
        for p in &mut self.players {
            p.velocity *= 0.97;
            p.position += p.velocity * TICK_SECONDS;
            crate::physics::keep_inside_rim(p);
        }
        if ticks_left > 1 {
            self.phase = Phase::Dead { ticks_left: ticks_left - 1, restart };
            return;
        }
        self.phase = Phase::Play;
        self.set_piece_ticks = 0;
        rules::set_up_restart(self, restart);
    }

    /// The taker has played the ball: back to open play.
    pub(crate) fn end_set_piece(&mut self) {
        self.taker = None;
        self.mode = GameMode::Normal;
        self.set_piece_ticks = 0;
    }
}

/// The first index from `from` on at which `wanted` holds for the items of `a` and `b` there: for
/// the per-player passes of the tick that have something to do for a few players only. Walked as
/// zipped slices, a player passed over costs a few instructions; indexed by player, each was
/// bounds-checked and his vectors reloaded, as much as the rest of such a pass.
fn first_from<A, B>(from: usize, a: &[A], b: &[B], wanted: impl FnMut((&A, &B)) -> bool) -> Option<usize> {
    a.get(from..)?.iter().zip(b.get(from..)?).position(wanted).map(|k| from + k)
}
