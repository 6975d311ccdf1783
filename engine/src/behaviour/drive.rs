//! The behaviours' part of [`Match::tick`]: stage progression and the inputs of the players the
//! behaviours drive. Allocation-free: everything lives in the match's per-player vectors.

use glam::Vec2;

use super::ball_play::{Chase, dribble, pass, press};
use super::condition::Scope;
use super::movement::{ARRIVED, arrive, follow, hold, idle, mark};
use super::state::PlayerBehaviour;
use crate::env::StickyState;
use crate::game::{GameMode, Match, PlayerInput};
use crate::geometry::Side;
use crate::player::fatigue::speed_factor;
use crate::player::top_speed;
use crate::scenario::{Behaviour, PlayerEntry, Target};

impl Match {
    /// Sets up the behaviours of the players of `left` and `right` (the episode's lists, in
    /// their order): none at all when no player has one, so that such matches run exactly as
    /// before behaviours existed.
    pub(crate) fn install_behaviours(&mut self, left: &[PlayerEntry], right: &[PlayerEntry]) {
        self.behaviours.clear();
        if left.iter().chain(right).all(|e| e.behaviour.is_empty()) {
            return;
        }
        for (g, e) in left.iter().chain(right).enumerate() {
            self.behaviours.push(PlayerBehaviour::new(&e.behaviour, self.players[g].position));
        }
        for g in 0..self.players.len() {
            if self.behaviours[g].builtin().flatten().is_some() {
                self.apply_player_theta(g);
            }
        }
    }

    /// Difficulty θ in force for player `g`: his `builtin(θ)` stage's, else his team's.
    #[inline]
    pub(crate) fn theta(&self, g: usize) -> f32 {
        self.behaviours
            .get(g)
            .and_then(|b| b.builtin().flatten())
            .unwrap_or(self.difficulty[self.players[g].side.index()])
    }

    /// Puts player `g`'s θ into effect: top speed (from his speed attribute, fatigue kept) and
    /// the team AI's decisions for him.
    fn apply_player_theta(&mut self, g: usize) {
        let theta = self.theta(g);
        let own = self.behaviours.get(g).and_then(|b| b.builtin().flatten());
        let p = &mut self.players[g];
        p.fresh_speed = top_speed(p.attributes.speed * crate::player::difficulty_scale(theta));
        p.max_speed = p.fresh_speed * speed_factor(p.fatigue);
        let (side, index) = (p.side, p.index);
        self.ai[side.index()].set_player_difficulty(index, own);
    }

    /// Before the AI decides: moves each behaviour player on to his next stage when the current
    /// one's `until` holds (or, without one, when it has finished), and marks in `native` the
    /// players the behaviours drive this tick. A `builtin` stage is the AI's, and so is a set
    /// piece's taker (the AI's set-piece logic takes it, so a restart never waits on a
    /// behaviour).
    pub(crate) fn prepare_behaviours(&mut self) {
        for g in 0..self.behaviours.len() {
            let b = &self.behaviours[g];
            let Some(stage) = b.stages.get(b.stage) else {
                self.native[g] = false;
                continue;
            };
            let p = &self.players[g];
            let advance = match &stage.until {
                Some(c) => c.holds(self, &Scope::player(p.side, p.index, b.done, self.env_steps)),
                None => b.done,
            };
            if advance {
                let before = self.behaviours[g].builtin().flatten();
                let at = self.players[g].position;
                if self.behaviours[g].advance(at) && self.behaviours[g].builtin().flatten() != before {
                    self.apply_player_theta(g);
                }
            }
            let taking = self.mode != GameMode::Normal && self.taker == Some(g);
            self.native[g] = self.behaviours[g].builtin().is_none() && !taking;
        }
    }

    /// Whether every player of `side` is driven by a behaviour or an agent this tick (the team's
    /// AI then has nothing to do).
    pub(crate) fn nobody_for_ai(&self, side: usize) -> bool {
        self.ranges[side].clone().all(|g| self.native[g] || self.agent_driven[g])
    }

    /// After the AI: writes the inputs of the players the behaviours drive (a lazy one only
    /// stands: lazy wins) and notes the stages that finished.
    pub(crate) fn behaviour_inputs(&mut self) {
        // The ball's predicted path, made once a tick by the first player who needs it.
        let mut path = None;
        for g in 0..self.behaviours.len() {
            if !self.native[g] || self.agent_driven[g] || !self.players[g].active {
                continue;
            }
            let mut meet = self.behaviours[g].meet;
            let mut chase = Chase { path: &mut path, meet: &mut meet, tick: self.in_play_ticks };
            let (input, finished) = self.native_input(g, &mut chase);
            self.behaviours[g].meet = meet;
            if let Some(input) = input {
                self.inputs[g] = input;
            }
            if finished && !self.behaviours[g].done {
                self.behaviours[g].done = true;
                self.behaviours[g].anchor = self.players[g].position;
            }
        }
    }

    /// Player `g`'s input from his behaviour (`None`: keep the input set from outside, a
    /// script's) and whether the stage finished.
    fn native_input(&self, g: usize, chase: &mut Chase) -> (Option<PlayerInput>, bool) {
        let b = &self.behaviours[g];
        let p = &self.players[g];
        let ball = self.ball.xy();
        if p.lazy {
            return (Some(idle(p, ball)), false);
        }
        let Some(behaviour) = b.current() else { return (None, false) };
        let scope = Scope::player(p.side, p.index, b.done, self.env_steps);
        let owns = self.owner == Some(g);
        let (input, finished) = match behaviour {
            Behaviour::Idle => (idle(p, ball), false),
            Behaviour::HoldPosition => (hold(p, b.anchor, ball), false),
            Behaviour::Follow(target) => match scope.position(self, *target) {
                Some(at) => (follow(p, at, self.target_velocity(&scope, *target), ball), false),
                None => (idle(p, ball), false),
            },
            Behaviour::MoveTo { point } => {
                let to = scope.point(point[0], point[1]);
                (arrive(p, to, p.max_speed, ball - p.position), p.position.distance(to) < ARRIVED)
            }
            // Finished ball-playing stages hold the place where they finished.
            Behaviour::DribbleTo { .. } | Behaviour::PassTo { .. } if b.done => (hold(p, b.anchor, ball), false),
            Behaviour::DribbleTo { point, shoot } => {
                dribble(p, owns, &self.ball, chase, scope.point(point[0], point[1]), *shoot)
            }
            Behaviour::PassTo { player, kind } => match self.team(p.side).get(*player) {
                Some(mate) => pass(p, owns, &self.ball, chase, mate, *kind),
                None => (idle(p, ball), false),
            },
            Behaviour::Mark(target) => match scope.player_of(*target).and_then(|(side, i)| self.team(side).get(i)) {
                Some(man) => (mark(p, man, ball), false),
                None => (idle(p, ball), false),
            },
            Behaviour::Press => {
                let carrier = self.owner.map(|o| &self.players[o]);
                let their_restart =
                    self.mode != GameMode::Normal && self.taker.is_some_and(|t| self.players[t].side != p.side);
                (press(p, carrier, &self.ball, chase, b.anchor, their_restart), false)
            }
            // Not driven here: the AI plays `builtin`, the env sets a script's input each step.
            Behaviour::Builtin { .. } | Behaviour::Script { .. } => return (None, false),
        };
        (Some(input), finished)
    }

    /// How fast a target moves (m/s, ground plane).
    fn target_velocity(&self, scope: &Scope, target: Target) -> Vec2 {
        match target {
            Target::Ball => self.ball.velocity.truncate(),
            Target::Point(_) => Vec2::ZERO,
            _ => {
                scope.player_of(target).and_then(|(side, i)| self.team(side).get(i)).map_or(Vec2::ZERO, |p| p.velocity)
            }
        }
    }

    /// The scripted players the env must ask for an action this step: `side`'s player `index`
    /// and his script's path, when his current stage is a script's and no agent drives him.
    pub(crate) fn scripted_player(&self, g: usize) -> Option<(Side, usize, &str)> {
        let b = self.behaviours.get(g)?;
        match b.current() {
            Some(Behaviour::Script { path }) if !self.agent_driven[g] && self.players[g].active => {
                Some((self.players[g].side, self.players[g].index, path.as_str()))
            }
            _ => None,
        }
    }

    /// Gives scripted player `g` this step's input (global frame); his gamepad state is `sticky`.
    pub(crate) fn set_script_input(&mut self, g: usize, input: PlayerInput, sticky: StickyState) {
        self.inputs[g] = input;
        self.behaviours[g].sticky = sticky;
    }

    /// A scripted player's gamepad (global frame).
    pub(crate) fn script_sticky(&self, g: usize) -> StickyState {
        self.behaviours.get(g).map_or_else(StickyState::default, |b| b.sticky)
    }

    /// The behaviour stage `side`'s player `index` is playing (0-based) and whether it has
    /// finished by itself; `None` for a player of the built-in AI.
    pub fn behaviour_stage(&self, side: Side, index: usize) -> Option<(usize, bool)> {
        let b = self.behaviours.get(self.global_index(side, index))?;
        (!b.stages.is_empty()).then_some((b.stage, b.done))
    }

    /// Tells the match how many env steps the episode has taken (the `steps` of behaviour
    /// conditions).
    pub(crate) fn set_env_steps(&mut self, steps: u32) {
        self.env_steps = steps;
    }
}
