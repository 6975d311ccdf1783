//! Ball control: trapping and catching a loose ball, deflections when it comes too fast, and
//! standing and sliding tackles on the player who has it.

use glam::Vec3;

use super::steal::duel_likeliness;
use super::{GameMode, Match, POSSESSION_REACH, interfere};
use crate::geometry::pitch::{BALL_RADIUS, in_penalty_area};
use crate::physics::TICK_SECONDS;
use crate::player::DRIBBLE_SPEED;
use crate::rules::{self, Stoppage, fouls};
use crate::stats::Event;

/// Horizontal reach (m) of an outfield player for a loose ball.
const FOOT_REACH: f32 = 0.7;
/// Reach (m) for a ball moving slower than [`SLOW_BALL`] (m/s) relative to the player.
const STILL_BALL_REACH: f32 = 1.15;
const SLOW_BALL: f32 = 3.0;
/// Highest ball (m) an outfield player controls (head height).
const FOOT_HEIGHT: f32 = 1.9;
/// Above this height (m) control is with chest or head, and only of slower balls.
const CHEST_HEIGHT: f32 = 0.9;
/// Goalkeeper's reach (m) inside his area, standing and diving; highest catch (m).
const HAND_REACH: f32 = 1.1;
const DIVE_REACH: f32 = 1.8;
const HAND_HEIGHT: f32 = 2.7;
/// Fastest ball (m/s, relative) an outfield player at difficulty 1 traps; a keeper catches.
const TRAP_SPEED: f32 = 13.0;
const CATCH_SPEED: f32 = 24.0;
/// Fastest ball (m/s, relative to him, or vertically) a player can touch at all: GRF refuses
/// a ball-control command above 15 m/s.
const TOUCH_SPEED: f32 = 15.0;
/// Ticks after an opponent's touch during which a player's body blocks a ball he cannot play
/// (GRF: 200 ms).
const BODY_BLOCK_TICKS: u64 = 20;
/// A ball coming at a keeper faster than this (m/s) is a shot he may not reach.
const SHOT_SPEED: f32 = 12.0;
/// How near (m) a loose ball must be for an agent's button to count before he has touched it.
const AT_LOOSE_BALL: f32 = 2.0;
/// No button counts during an episode's first env step (10 ticks): GRF's first step plays the
/// kickoff, and a pass or shot pressed in it does nothing (measured, GRF 2.10).
const FIRST_STEP_TICKS: u64 = 10;
/// An agent's player does not take the ball placed at his feet before this tick of the episode.
/// GRF 2.10, measured with the random agent in academy_run_to_score_with_keeper: our centre back
/// walks onto the ball and shows as its owner from env step 3, 4 or 5 (median 3.5), and a pass or
/// shot pressed on steps 2-4, before that, is struck with his first touch: half the episodes
/// never show him with the ball before his first kick.
const FIRST_TOUCH_TICK: u64 = 35;
/// How near (m) a challenger must be to the carrier's ball to trip him.
const TACKLE_RANGE: f32 = 0.9;
/// Sliding tackle reach (m).
const SLIDE_REACH: f32 = 1.3;
/// The chance a keeper gets his hands to a shot that passes within hand reach of him, by the
/// ball's flight time t (s) since it was struck: a + b·t (sure from about 0.65 s). Measured in GRF
/// 2.10.2, a shot with no direction from 11, 16 and 21 m straight at a keeper standing on his line
/// beat him in 8, 2 and 0 of 30 episodes; with these values touchline's in 22, 5 and 0 of 90
/// (docs/grf-compatibility.md, "a keeper stops the shots he gets his hands to in time").
const KEEPER_IN_TIME: (f32, f32) = (0.3, 1.1);
// Every reach from a player's position is within a keeper's dive (`Match::control_loose_ball`'s
// early test).
const _: () = assert!(FOOT_REACH <= DIVE_REACH && HAND_REACH <= DIVE_REACH && SLIDE_REACH <= DIVE_REACH);
/// Distance between two players' centres (m) at which a slide meets the man.
const BODY_CONTACT: f32 = 0.9;
/// A challenger gets to the ball round the carrier only this likely or more (GRF: 0.2).
const MIN_DUEL_LIKELINESS: f32 = 0.2;
/// Ticks a dispossessed player cannot touch the ball.
const TACKLED_COOLDOWN: u16 = 40;

impl Match {
    /// Settles who has the ball after everything moved this tick.
    pub(crate) fn settle_possession(&mut self) {
        if self.mode != GameMode::Normal {
            // During a set piece only the taker, who holds the ball, may touch it.
            return;
        }
        match self.owner {
            Some(owner) => self.challenge(owner),
            None => self.control_loose_ball(),
        }
    }

    /// `g`'s skill for `stat` after difficulty and fatigue, in [0, 1].
    fn skill_of(&self, g: usize, stat: f32) -> f32 {
        let p = &self.players[g];
        p.skill(stat, self.theta(g))
    }

    /// `q`'s tackling skill after difficulty and fatigue: worked out in [`Match::challenge`] only
    /// for a slide or a trip (for every opponent every tick, its θ look-up was a tenth of the
    /// loop).
    fn tackling(&self, q: usize) -> f32 {
        self.skill_of(q, self.players[q].attributes.tackling)
    }

    /// Opponents near the owner try to take the ball: standing challenges win it or trip the
    /// carrier (a foul); a slide's first contact is judged for a foul (Law 12, [`rules::fouls`]).
    fn challenge(&mut self, owner: usize) {
        if self.in_hands || self.steal(owner) {
            return;
        }
        let side = self.players[owner].side;
        let ball = self.ball.xy();
        let range = self.ranges[side.opponent().index()].clone();
        for q in range {
            let p = &self.players[q];
            if !p.active || p.touch_cooldown > 0 {
                continue;
            }
            let d2 = p.position.distance_squared(ball);
            let sliding = p.is_sliding();
            let body = p.position.distance_squared(self.players[owner].position) < BODY_CONTACT * BODY_CONTACT;
            if sliding && (d2 < SLIDE_REACH * SLIDE_REACH || body) {
                let tackling = self.tackling(q);
                let roll = self.rng.unit();
                let severity = fouls::sliding_severity(&self.players[q], &self.players[owner], ball, tackling, roll);
                self.tackled(owner, q);
                if severity > fouls::FOUL_SEVERITY {
                    self.whistle = fouls::commit(self, q, owner, severity);
                }
                return;
            }
            if sliding {
                continue;
            }
            if p.is_keeper()
                && in_penalty_area(p.position.x, p.position.y, -p.side.attack_sign())
                && d2 < DIVE_REACH * DIVE_REACH
                && self.ball.position.z < HAND_HEIGHT
            {
                // A keeper in his own area takes a dribbled ball with his hands, diving at the
                // carrier's feet if he must: nobody holds it (GRF's keeper claims any ball no one
                // retains with his deflect and dive animations, and a slow one he always catches).
                self.claimed(owner, q);
                return;
            }
            let in_reach = d2 < interfere::REACH * interfere::REACH;
            let starts = p.interfere_ticks == 0
                && interfere::starts(p.position, p.velocity, ball, self.ball.velocity.truncate());
            if !in_reach && !starts {
                continue;
            }
            if p.is_keeper() && p.velocity.length_squared() > KEEPER_TACKLE_SPEED * KEEPER_TACKLE_SPEED {
                // GRF's keeper challenges only from a stand (his interfere asks for no movement
                // of its own): running back to his line past a carrier, he leaves the ball.
                continue;
            }
            let carrier_at = self.players[owner].position;
            if duel_likeliness(p.position, carrier_at, ball) < MIN_DUEL_LIKELINESS {
                // Behind the carrier, with his body between him and the ball: no way to it.
                continue;
            }
            match p.interfere_ticks {
                0 if starts => {
                    // GRF's standing tackle (its interfere): started when its touch would meet
                    // the ball, which lands 150-250 ms later.
                    let wind_up = interfere::draw_ticks(interfere::WIND_UP_TICKS, self.rng.unit());
                    self.players[q].interfere_ticks = wind_up;
                }
                1 if in_reach => {
                    // The touch: nearer the ball than the carrier, he takes it cleanly; else he
                    // knocks it away from himself.
                    if d2 < carrier_at.distance_squared(ball) {
                        self.players[owner].touch_cooldown = TACKLED_COOLDOWN;
                        self.take_ball(q);
                    } else {
                        self.tackled(owner, q);
                    }
                    return;
                }
                _ => {}
            }
            if d2 >= TACKLE_RANGE * TACKLE_RANGE {
                continue;
            }
            let trip = fouls::trip_chance(&self.players[q], &self.players[owner], self.tackling(q));
            if self.rng.unit() < trip {
                // A trip: the carrier stumbles and may lose the ball; the referee plays advantage.
                let severity = fouls::standing_severity(&self.players[q], &self.players[owner], self.rng.unit());
                self.players[q].touch_cooldown = TACKLED_COOLDOWN;
                let carrier = &mut self.players[owner];
                carrier.velocity *= 0.3;
                if self.rng.chance(0.5) {
                    self.ball.velocity = (carrier.velocity + carrier.facing * 2.0).extend(0.0);
                    self.owner = None;
                    carrier.touch_cooldown = 30;
                }
                self.whistle = fouls::commit(self, q, owner, severity);
                return;
            }
        }
    }

    /// The keeper `q` took the ball in his hands from the dribbler `owner`.
    pub(super) fn claimed(&mut self, owner: usize, q: usize) {
        self.players[owner].touch_cooldown = TACKLED_COOLDOWN;
        self.take_ball(q);
        self.in_hands = self.owner == Some(q);
    }

    /// `g` takes the ball where it lies and brings it to his feet (the touch is judged first: it
    /// may be offside).
    pub(super) fn take_ball(&mut self, g: usize) {
        self.last_touch = Some(g);
        self.touched(g);
        if self.whistle.is_some() {
            return;
        }
        let to_ball = self.ball.xy() - self.players[g].position;
        self.carry_distance = to_ball.length().clamp(0.3, STILL_BALL_REACH);
        self.owner = Some(g);
        self.in_hands = false;
        self.gained(g);
        self.ball.velocity = self.players[g].velocity.extend(0.0);
        self.ball.position.z = BALL_RADIUS;
    }

    /// `q` knocked the ball off `owner` (a standing challenge or a slide): GRF's interfere touch
    /// pokes it on at half the tackler's pace plus 4 m/s away from him (6 m/s from a slide), and
    /// lifts it 0.5–1.5 m/s off the grass in a stochastic match. Where it goes is open: often to
    /// the tackler's team, sometimes back to the carrier's; a standing tackler himself cannot
    /// play it until his tackle ends ([`interfere::FOLLOW_THROUGH_TICKS`]).
    fn tackled(&mut self, owner: usize, q: usize) {
        let ball = self.ball.xy();
        let tackler = &self.players[q];
        let away = (ball - tackler.position).normalize_or(tackler.facing);
        let sliding = tackler.is_sliding();
        let push = if sliding { 6.0 } else { 4.0 };
        let lift = 1.0 + self.rng.noise(0.5);
        self.ball.velocity = (tackler.velocity * 0.5 + away * push).extend(lift);
        self.owner = None;
        self.last_touch = Some(q);
        self.touch_tick = self.in_play_ticks;
        if sliding {
            // Brought down or beaten by the slide; a standing tackle's knock leaves the carrier
            // free to play the ball again at once (GRF's interfere).
            self.players[owner].touch_cooldown = TACKLED_COOLDOWN;
        } else {
            // The tackle's animation goes on: he cannot play the ball he knocked until it ends.
            self.players[q].touch_cooldown = interfere::draw_ticks(interfere::FOLLOW_THROUGH_TICKS, self.rng.unit());
        }
        self.touched(q);
    }

    /// Bookkeeping of a touch of the ball by `g`: completes a team-mate's pass, and calls offside
    /// when `g` was noted in an offside position at the last kick.
    fn touched(&mut self, g: usize) {
        let side = self.players[g].side;
        if rules::offside::judge_touch(self, g) {
            self.pending_pass = None;
            let index = self.players[g].index;
            self.record(Event::Offside { side, player: index });
            let restart = rules::free_kick::restart(side.opponent(), self.players[g].position);
            self.whistle = Some(Stoppage::Offside { restart, offender: (side, index) });
            return;
        }
        if let Some(passer) = self.pending_pass.take()
            && passer != g
        {
            let (passing, player) = (self.players[passer].side, self.players[passer].index);
            if passing == side {
                self.record(Event::PassCompleted { side, player });
            } else {
                self.record(Event::PassIntercepted { side: passing, player, by: self.players[g].index });
            }
        }
    }

    /// `g` has taken the ball at his feet in open play: a possession won when a player of the
    /// other team had it last.
    fn gained(&mut self, g: usize) {
        let side = self.players[g].side;
        if let Some(last) = self.possessor
            && self.players[last].side != side
        {
            let (player, from) = (self.players[g].index, self.players[last].index);
            self.record(Event::PossessionWon { side, player, from });
        }
        self.possessor = Some(g);
    }

    /// Whether `g` may play the ball now: he has it, or it lies loose, slow and low at his feet
    /// (within [`FOOT_REACH`]) and nobody is nearer (GRF's designated possession player, whose pass and shot buttons
    /// count though he has not touched it yet).
    pub(crate) fn may_play(&self, g: usize) -> bool {
        if self.owner == Some(g) {
            return true;
        }
        if self.owner.is_some() || self.mode != GameMode::Normal || !self.players[g].active {
            return false;
        }
        let ball = self.ball;
        let p = &self.players[g];
        let d2 = p.position.distance_squared(ball.xy());
        ball.position.z < CHEST_HEIGHT
            && d2 < FOOT_REACH * FOOT_REACH
            && (ball.velocity.truncate() - p.velocity).length_squared() < SLOW_BALL * SLOW_BALL
            && !self.players.iter().any(|q| q.active && q.position.distance_squared(ball.xy()) < d2)
    }

    /// Whether `g` is his team's man at a loose ball at his feet: low, slow, within
    /// [`AT_LOOSE_BALL`] m and no team-mate nearer. GRF's buttons count for the designated
    /// possession player before he has touched the ball: a shot is struck at his first touch, a
    /// pass fails.
    pub(crate) fn at_loose_ball(&self, g: usize) -> bool {
        if self.owner.is_some()
            || self.mode != GameMode::Normal
            || !self.players[g].active
            || self.in_play_ticks < FIRST_STEP_TICKS
        {
            return false;
        }
        let ball = self.ball;
        let p = &self.players[g];
        let d2 = p.position.distance_squared(ball.xy());
        ball.position.z < 0.5
            && d2 < AT_LOOSE_BALL * AT_LOOSE_BALL
            && (ball.velocity.truncate() - p.velocity).length_squared() < 36.0
            && !self.players.iter().any(|q| q.active && q.side == p.side && q.position.distance_squared(ball.xy()) < d2)
    }

    /// `g` plays a loose ball he [may play](Match::may_play) without having touched it: he takes
    /// it now, so that the kick he asks for can follow.
    pub(crate) fn take_to_play(&mut self, g: usize) {
        if self.owner == Some(g) {
            return;
        }
        let to_ball = self.ball.xy() - self.players[g].position;
        self.players[g].facing = to_ball.normalize_or(self.players[g].facing);
        self.take_ball(g);
    }

    /// Whether a loose ball too fast for `g` to play still meets his body (and rebounds off it,
    /// see [`Match::control_loose_ball`]). For an opponent of the player who touched it last,
    /// only in the [`BODY_BLOCK_TICKS`] after that touch: GRF's ball passes through players
    /// otherwise (its body-ball collision needs an opponent's touch in the last 200 ms), so a
    /// chaser no longer cuts out a hard pass running away from him. A team-mate of the last
    /// toucher always meets it, unlike in GRF: the rebound stands in for GRF's poor first touch
    /// of a hard pass (letting team-mates' passes through measured 11-v-11 passes down from
    /// about 50 to 39 a match, and back passes rolling into the goal).
    fn blocks(&self, g: usize) -> bool {
        match self.last_touch {
            Some(t) if self.players[t].side != self.players[g].side => {
                self.in_play_ticks.saturating_sub(self.touch_tick) <= BODY_BLOCK_TICKS
            }
            _ => true,
        }
    }

    /// The nearest player within reach of a loose ball traps, catches or deflects it.
    fn control_loose_ball(&mut self) {
        if self.unreachable_ticks > 0 {
            self.unreachable_ticks -= 1;
            return;
        }
        let ball = self.ball;
        if ball.position.z > HAND_HEIGHT {
            return;
        }
        let mut best = None;
        let mut best_d2 = f32::INFINITY;
        for (g, p) in self.players.iter().enumerate() {
            if !p.active || p.touch_cooldown > 0 {
                continue;
            }
            if p.position.distance_squared(ball.xy()) >= DIVE_REACH * DIVE_REACH
                && p.possession_point().distance_squared(ball.xy()) >= POSSESSION_REACH * POSSESSION_REACH
            {
                // Out of every reach below (the same squared distances as there, from his position
                // and from his possession point): he would be passed over at the reach test. Most
                // players are, and their keeper, slide and speed tests are not worth making.
                continue;
            }
            if p.queued_kick.is_some_and(|(_, left)| left > super::tick::QUEUED_KICK_WINDOW) {
                // Still winding up the kick he asked for: he strikes the ball, not traps it.
                continue;
            }
            if self.agent_driven[g]
                && self.possessor.is_none()
                && self.in_play_ticks < FIRST_TOUCH_TICK
                && ball.velocity.length_squared() < 0.09
            {
                // The ball as placed at the start: an agent's player takes it only after his
                // first touch has had time (GRF 2.10 shows it his from env step 2-4), so the
                // buttons he presses before then are the ones of a man at a loose ball.
                continue;
            }
            // Law 12: the keeper may not handle a ball a team-mate deliberately kicked to him (GRF's
            // keeper plays such a ball with his feet).
            let back_pass = self.pending_pass.is_some_and(|passer| self.players[passer].side == p.side);
            let keeper_hands =
                p.is_keeper() && !back_pass && in_penalty_area(p.position.x, p.position.y, -p.side.attack_sign());
            let mut from = p.position;
            let (reach, height) = if keeper_hands {
                (if p.dive_ticks > 0 { DIVE_REACH } else { HAND_REACH }, HAND_HEIGHT)
            } else if p.is_sliding() {
                (SLIDE_REACH, FOOT_HEIGHT)
            } else if (ball.velocity.truncate() - p.velocity).length_squared() < SLOW_BALL * SLOW_BALL {
                // A slow ball is easy to step to: GRF's possession test, a metre from his
                // possession point.
                from = p.possession_point();
                (POSSESSION_REACH, FOOT_HEIGHT)
            } else {
                (FOOT_REACH, FOOT_HEIGHT)
            };
            if ball.position.z > height {
                continue;
            }
            if self.agent_driven[g]
                && self.possessor.is_none()
                && p.queued_kick.is_none()
                && resting_at(&ball, self.wanted_velocity(g))
            {
                // An agent's player standing at the ball as it was placed at the start does not
                // touch it: GRF shows it owned by nobody until he moves or plays it (see
                // `Match::take_to_play`).
                continue;
            }
            let d2 = from.distance_squared(ball.xy());
            if d2 >= reach * reach || d2 >= best_d2 {
                continue;
            }
            // Within reach (tested first: it is the cheap test): too fast for him to play and not
            // in his body's way, it goes past him.
            let relative = ball.velocity - p.velocity.extend(0.0);
            let too_fast = !keeper_hands
                && !p.is_sliding()
                && (relative.length_squared() > TOUCH_SPEED * TOUCH_SPEED || relative.z.abs() > TOUCH_SPEED);
            if !too_fast || self.blocks(g) {
                best_d2 = d2;
                best = Some((g, keeper_hands));
            }
        }
        let Some((g, keeper_hands)) = best else { return };
        let p = &self.players[g];
        let relative = (ball.velocity - p.velocity.extend(0.0)).length();
        // GRF's keeper picks a ball up only through a pick-up animation that fits his run: coming
        // out faster than a dribble for a ball that is no shot, he plays the kick he decided on with
        // his feet (docs/grf-compatibility.md, "the keeper plays an uncontested loose ball with his
        // feet").
        let picks_up = keeper_hands && (ball.velocity.length() > SHOT_SPEED || p.velocity.length() <= DRIBBLE_SPEED);
        if keeper_hands && relative > SHOT_SPEED {
            // A shot. One that passes within hand reach of his body he stops, catching or parrying
            // it (below), when he has had time to get his hands there: GRF's keeper stops every
            // ball his deflect animation touches, but a close shot can be past him first. One he
            // must dive for he gets a hand to only with a chance that falls with the ball's speed
            // and with how far he stretches; a miss lets it fly on. The stretch is to where the
            // ball passes him nearest (tried once, on the tick it comes within reach, which is at
            // the edge of his reach for a ball that then flies at him).
            let pass_by = closest_approach(ball.xy() - p.position, relative_xy(&ball, p));
            let chance = if pass_by <= HAND_REACH {
                let flight = self.in_play_ticks.saturating_sub(self.touch_tick) as f32 * TICK_SECONDS;
                KEEPER_IN_TIME.0 + KEEPER_IN_TIME.1 * flight
            } else {
                (1.15 - 0.7 * pass_by / DIVE_REACH - (relative - SHOT_SPEED) / 30.0).clamp(0.05, 0.95)
                    * (0.75 + 0.25 * self.skill_of(g, p.attributes.reaction))
            };
            if chance < 1.0 && !self.rng.chance(chance) {
                self.players[g].touch_cooldown = 30;
                return;
            }
        }
        self.last_touch = Some(g);
        self.touch_tick = self.in_play_ticks;
        self.touched(g);
        if self.whistle.is_some() {
            return;
        }
        if let Some(kick) = self.inputs[g].first_time
            && !picks_up
            && !self.players[g].is_sliding()
        {
            // A first-time kick: the touch is the kick; he never has the ball at his feet.
            self.inputs[g].first_time = None;
            self.players[g].ready_kick();
            self.execute_kick(g, kick);
            return;
        }
        if let Some((kick, _)) = self.players[g].queued_kick.take()
            && !keeper_hands
        {
            // An agent's kick asked for before he had the ball: struck at the first touch.
            self.players[g].ready_kick();
            self.execute_kick(g, kick);
            return;
        }
        let p = &self.players[g];
        let body = if !keeper_hands && ball.position.z > CHEST_HEIGHT { 0.6 } else { 1.0 };
        let control = self.skill_of(g, p.attributes.ball_control);
        let limit = if keeper_hands { CATCH_SPEED } else { TRAP_SPEED } * (0.6 + 0.4 * control) * body;
        if p.is_sliding() && !keeper_hands {
            // A slide knocks the ball on in the slide's direction.
            self.ball.velocity = (p.velocity * 1.2).extend(0.0);
            return;
        }
        if relative <= limit {
            // He takes the ball where it is and brings it to his feet over the next ticks.
            let to_ball = ball.xy() - self.players[g].position;
            self.carry_distance = to_ball.length().clamp(0.3, STILL_BALL_REACH);
            self.players[g].facing = to_ball.normalize_or(self.players[g].facing);
            self.owner = Some(g);
            self.in_hands = keeper_hands;
            self.gained(g);
            self.ball.velocity = self.players[g].velocity.extend(0.0);
            self.ball.position.z = BALL_RADIUS;
            return;
        }
        if keeper_hands {
            // Too fast to hold: GRF's keeper deflection. He palms it away from his goal, along
            // his own run and a little back along the ball's, at 0.3 of the ball's pace plus 2.5
            // of his own, lifted 1.2 m/s, with a random sideways part (GRF 2.10's deflect touch).
            let (ball_run, run) = (ball.velocity.truncate(), p.velocity);
            let away = glam::Vec2::new(p.side.attack_sign(), 0.0);
            let sideways = glam::Vec2::new(0.0, self.rng.noise(1.0));
            let dir = (-0.1 * ball_run + 2.0 * run + 4.0 * away + sideways).normalize_or(away);
            self.ball.velocity = (dir * (0.3 * ball_run.length() + 2.5 * run.length())).extend(1.2);
            self.players[g].touch_cooldown = 15;
            return;
        }
        // Too fast to control: the ball rebounds off the body.
        let normal = (ball.xy() - p.position).normalize_or(-ball.velocity.truncate().normalize_or_zero());
        let n3 = normal.extend(0.0);
        let v = ball.velocity;
        let vn = v.dot(n3);
        let mut out = if vn < 0.0 { v - n3 * (1.4 * vn) } else { v };
        out = Vec3::new(out.x * 0.55, out.y * 0.55, out.z * 0.5);
        out.x += self.rng.noise(1.5);
        out.y += self.rng.noise(1.5);
        self.ball.velocity = out;
        self.players[g].touch_cooldown = 15;
    }
}

/// The ball's velocity relative to player `p` on the ground plane (m/s).
fn relative_xy(ball: &crate::physics::Ball, p: &crate::player::Player) -> glam::Vec2 {
    ball.velocity.truncate() - p.velocity
}

/// How near (m) a ball at `offset` from a player, moving at `relative` to him, passes him within
/// the next 0.2 s (straight-line motion; both keep their pace that long).
fn closest_approach(offset: glam::Vec2, relative: glam::Vec2) -> f32 {
    let speed2 = relative.length_squared();
    let t = if speed2 > 1e-6 { (-offset.dot(relative) / speed2).clamp(0.0, 0.2) } else { 0.0 };
    (offset + relative * t).length()
}

/// Fastest (m/s) a keeper can be moving and still make a standing challenge.
const KEEPER_TACKLE_SPEED: f32 = 3.0;

/// Whether the ball is at rest (below 0.3 m/s) and the player asks to stand still (`wanted`: his
/// input velocity), however others shove him.
fn resting_at(ball: &crate::physics::Ball, wanted: glam::Vec2) -> bool {
    ball.velocity.length_squared() < 0.09 && wanted.length_squared() < 0.09
}

#[cfg(test)]
mod tests {
    use glam::Vec2;

    use super::closest_approach;

    #[test]
    fn a_ball_is_as_near_as_it_passes_within_the_next_fifth_of_a_second() {
        // 1.5 m out and 0.5 m to the side, coming straight in at 20 m/s: passes 0.5 m off.
        let d = closest_approach(Vec2::new(1.5, 0.5), Vec2::new(-20.0, 0.0));
        assert!((d - 0.5).abs() < 1e-5, "{d}");
        // Going away: as near as it is now.
        assert!((closest_approach(Vec2::new(1.0, 0.0), Vec2::new(5.0, 0.0)) - 1.0).abs() < 1e-6);
        // Slow: only 0.2 s of its run counts (1 m/s covers 0.2 m of the 1.5).
        assert!((closest_approach(Vec2::new(1.5, 0.0), Vec2::new(-1.0, 0.0)) - 1.3).abs() < 1e-5);
    }

    /// In how many of 40 stochastic matches a shot at `speed` m/s from `out` m in front of the
    /// left keeper beats him, passing `off` metres wide of him (inside his post, at knee height).
    fn goals_past_the_keeper(out: f32, speed: f32, off: f32) -> usize {
        use crate::game::Match;
        use crate::player::Role;
        use crate::scenario::{PlayerEntry, Scenario};
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CF, -0.5, 0.0)],
            ball_position: [0.0, 0.0],
            deterministic: false,
            ..Scenario::default()
        };
        (0..40)
            .filter(|&seed| {
                let mut m = Match::new(&s, 0, seed);
                let keeper = m.players[0].position;
                m.ball.position = glam::Vec3::new(keeper.x + out, keeper.y + off, 0.4);
                m.ball.velocity = glam::Vec3::new(-speed, 0.0, 0.0);
                m.touch_tick = m.in_play_ticks;
                (0..200).any(|_| {
                    m.tick();
                    m.score()[1] > 0
                })
            })
            .count()
    }

    #[test]
    fn a_keeper_stops_a_shot_at_him_he_has_time_for_and_not_every_close_one() {
        // GRF's keeper holds or palms away every ball his hands get to in time.
        assert_eq!(goals_past_the_keeper(18.0, 20.0, 0.6), 0);
        assert_eq!(goals_past_the_keeper(18.0, 20.0, 1.0), 0);
        // From 6 m at 25 m/s the ball can be past him first (GRF: a shot from the penalty spot
        // at a keeper standing in its way beats him about one time in four).
        let close = goals_past_the_keeper(6.0, 25.0, 0.6);
        assert!((4..=36).contains(&close), "{close} of 40");
        assert!(goals_past_the_keeper(6.0, 25.0, 2.5) > 30, "a shot 2.5 m wide of a standing keeper beats him");
    }
}
