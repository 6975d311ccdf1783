//! [`Env::step`]: one env step — the agents' actions through sticky actions and anti-stalling,
//! behaviour scripts, ten ticks of play, then rewards (scoring, checkpoints, event and script
//! terms), end conditions and observations.

use super::*;

impl Env {
    /// Decodes action indices of the configured action set and steps.
    ///
    /// # Errors
    /// As [`Env::step`], plus [`EngineError::UnknownAction`] for an index outside the set.
    pub fn step_indices(&mut self, actions: &[u32]) -> Result<StepOutcome, EngineError> {
        if actions.len() != self.state.controllers.len() {
            return Err(EngineError::ActionCount { expected: self.state.controllers.len(), got: actions.len() });
        }
        // At most 22 controllers: decode on the stack, no allocation.
        let mut decoded = [Action::Idle; 22];
        for (slot, &a) in decoded.iter_mut().zip(actions) {
            *slot = self.config.action_set.decode(a)?;
        }
        self.step(&decoded[..actions.len()])
    }

    /// Plays one step: applies one action per controller (left controllers first; actions of
    /// right-team controllers are in their own frame), simulates 10 ticks of play (plus any dead
    /// time, after which control returns at the restart), then computes rewards, end conditions
    /// and observations.
    ///
    /// # Errors
    /// [`EngineError::ActionCount`] when `actions.len()` differs from [`Env::num_controllers`];
    /// [`EngineError::EpisodeOver`] after the episode ended.
    pub fn step(&mut self, actions: &[Action]) -> Result<StepOutcome, EngineError> {
        if actions.len() != self.state.controllers.len() {
            return Err(EngineError::ActionCount { expected: self.state.controllers.len(), got: actions.len() });
        }
        if let Some(e) = &self.state.hook_error {
            // The hooks failed at reset (which returned this error): the episode cannot be
            // played, and says why until the next reset.
            return Err(e.clone());
        }
        if self.state.done {
            return Err(EngineError::EpisodeOver);
        }
        self.state.fresh = false;
        self.state.game.clear_events();
        // A player control switched away from goes back to the AI (or his behaviour).
        for side in Side::BOTH {
            let (start, len) = self.controller_span(side);
            self.state.game.release_uncontrolled(side, &self.state.controlled[start..start + len]);
        }
        for (i, &action) in actions.iter().enumerate() {
            let action = self.anti_stalling(i, action);
            self.taken[i] = action;
            self.apply_action(i, action);
        }
        self.state.game.set_env_steps(self.state.steps);
        self.step_behaviours()?;
        let mut ticks = 0;
        for _ in 0..TICKS_PER_STEP {
            self.state.game.tick();
            ticks += 1;
            if !self.state.game.in_play() {
                while !self.state.game.in_play() && ticks < MAX_TICKS_PER_STEP {
                    self.state.game.tick();
                    ticks += 1;
                }
                break;
            }
        }
        self.state.steps += 1;
        // GRF counts engine steps from the second env step (the first one also plays the
        // kickoff whistle), so half-time follows env step `second_half + 1`
        // (docs/grf-compatibility.md#episode-length, #half-time).
        if self.state.steps == self.scenario.second_half.saturating_add(1) {
            self.state.game.start_second_half();
        }
        self.state.waiting_for_game =
            if self.state.game.mode() == GameMode::Normal { 0 } else { self.state.waiting_for_game + 1 };
        for side in Side::BOTH {
            let (start, len) = self.controller_span(side);
            control::update(
                &self.state.game,
                side,
                &mut self.state.controlled[start..start + len],
                self.fixed_control[side.index()],
            );
        }
        for (previous, obs) in self.state.previous_ball.iter_mut().zip(&self.state.observations) {
            *previous = [obs.ball[0], obs.ball[1]];
        }
        self.refresh_observations();

        let score = self.state.game.score();
        let diff = score[0] as i32 - score[1] as i32;
        let scoring = scoring_reward(self.state.score_diff, diff);
        self.state.score_diff = diff;
        let mut checkpoint_total = 0.0;
        let plan = self.reward_plan;
        for i in 0..self.state.controllers.len() {
            let r = if self.state.controllers[i].side == Side::Left { scoring } else { -scoring };
            let bonus = match plan.checkpoints {
                Some(c) => {
                    c.weight * self.state.checkpoints[i].reward_with(c.count, c.value, r, &self.state.observations[i])
                }
                None => 0.0,
            };
            checkpoint_total += bonus;
            self.state.rewards[i] = plan.scoring * r + bonus;
        }
        // A save is judged from the whole step, then paid and ended on like the match's events.
        let saved = self.state.end.save(&mut self.state.game);
        let event_total = self.pay_event_rewards();
        let terminated = self.state.end.terminated(&self.scenario, &self.state.game, self.state.steps, saved);
        let truncated = self.state.steps > self.scenario.game_duration;
        let (hooks_end, script_reward, script_errors) = self.run_hooks()?;
        let terminated = terminated || hooks_end;
        self.state.done = terminated || truncated;
        if self.curriculum.is_some() {
            self.record_lesson_step(diff);
        }
        self.state.info = StepInfo {
            score,
            steps_left: self.steps_left(),
            game_mode: self.state.game.mode(),
            score_reward: scoring,
            checkpoint_reward: checkpoint_total,
            event_reward: event_total,
            script_reward,
            script_errors: self.state.info.script_errors + script_errors,
            steps: self.state.steps,
            episode: self.state.episode,
            lesson: self.state.lessons.lesson,
        };
        Ok(StepOutcome { terminated, truncated })
    }

    /// Before the ticks of a step: asks the hooks for each scripted player's action, applied as an
    /// agent's (his own frame, sticky state of his own). A hook error ends the episode and fails
    /// the step.
    fn step_behaviours(&mut self) -> Result<(), EngineError> {
        if self.state.game.behaviours.is_empty() {
            return Ok(());
        }
        for g in 0..self.state.game.players().len() {
            let Some((side, index, path)) = self.state.game.scripted_player(g) else { continue };
            let Some(hooks) = self.hooks.as_mut() else {
                // `Env::build` refuses script behaviours without hooks; a snapshot of another env
                // cannot bring one in (fingerprints differ).
                continue;
            };
            let view = hook_view(&self.state, &self.scenario, &self.taken);
            let action = match hooks.behaviour_action(&view, side, index, path) {
                Ok(action) => action,
                Err(e) => {
                    self.state.done = true;
                    return Err(e);
                }
            };
            let global = if side == Side::Right { action.rotated() } else { action };
            let mut sticky = self.state.game.script_sticky(g);
            let on_ball = self.state.game.may_play_ball(side, index);
            let press = sticky.apply(global, on_ball);
            let input = sticky_input(&sticky, press, &self.state.game.players()[g], on_ball);
            self.state.game.set_script_input(g, input, sticky);
        }
        Ok(())
    }

    /// Adds each controller's event rewards for the step just played; returns their sum.
    fn pay_event_rewards(&mut self) -> f32 {
        let terms = self.event_rewards.len();
        if terms == 0 {
            return 0.0;
        }
        let mut total = 0.0;
        for i in 0..self.state.controllers.len() {
            let view = Viewpoint {
                side: self.state.controllers[i].side,
                player: self.state.controlled[i],
                observation: &self.state.observations[i],
                previous_ball: self.state.previous_ball[i],
            };
            let progress = &mut self.state.events[i * terms..(i + 1) * terms];
            let paid = self.event_rewards.pay(progress, self.state.game.events(), &view);
            self.state.rewards[i] += paid;
            total += paid;
        }
        total
    }

    /// Adds the step's reward to the episode's return (the left agents' mean, or every agent's
    /// when none plays on the left) and, when the episode ended, records its result.
    fn record_lesson_step(&mut self, score_diff: i32) {
        let (left, n) = (self.controller_span(Side::Left).1, self.state.controllers.len());
        let rewards = if left > 0 { &self.state.rewards[..left] } else { &self.state.rewards[..] };
        if n > 0 {
            self.state.lessons.add_reward(rewards.iter().sum::<f32>() / rewards.len() as f32);
        }
        if self.state.done {
            self.state.lessons.finish_episode(score_diff);
        }
    }

    /// Runs the hooks after a step: adds their rewards and returns (end, reward paid, errors
    /// absorbed). A hook error ends the episode and fails the step.
    fn run_hooks(&mut self) -> Result<(bool, f32, u32), EngineError> {
        let Some(hooks) = self.hooks.as_mut() else { return Ok((false, 0.0, 0)) };
        self.hook_rewards.fill(0.0);
        let view = hook_view(&self.state, &self.scenario, &self.taken);
        match hooks.step(&view, &mut self.hook_rewards) {
            Ok(outcome) => {
                let mut total = 0.0;
                for (r, h) in self.state.rewards.iter_mut().zip(&self.hook_rewards) {
                    *r += h;
                    total += h;
                }
                Ok((outcome.end, total, outcome.errors))
            }
            Err(e) => {
                self.state.done = true;
                Err(e)
            }
        }
    }

    /// GRF's anti-stalling rule (docs/grf-compatibility.md#action-effects): after 20 steps waiting at a set
    /// piece every agent action becomes `short_pass`; after that, `idle`, except that the agent-controlled ball owner,
    /// as the observation shows him ([`crate::game::Match::observed_owner`]), is made to run towards the opponents'
    /// goal (and after 30 steps back). `builtin_ai` is left alone: the built-in AI takes set pieces itself.
    fn anti_stalling(&self, i: usize, action: Action) -> Action {
        use std::cmp::Ordering;
        // A player handed to the built-in AI takes the set piece itself; overriding it with `idle`
        // would freeze the restart the rule exists to end.
        if action == Action::BuiltinAi {
            return action;
        }
        match self.state.waiting_for_game.cmp(&20) {
            Ordering::Less => action,
            Ordering::Equal => Action::ShortPass,
            Ordering::Greater => {
                let c = &self.state.controllers[i];
                // GRF's rule reads the observation's owner: a ball placed for a goal kick,
                // corner kick, free kick or penalty kick is nobody's, so its taker is not made to
                // run (else the held direction outlives the restart: an idle agent's later
                // carriers would all run at goal).
                if self.state.game.observed_owner() == Some((c.side, self.state.controlled[i])) {
                    // In the controller's own frame "right" runs at the opponents' goal.
                    if self.state.waiting_for_game < 30 { Action::Right } else { Action::Left }
                } else {
                    Action::Idle
                }
            }
        }
    }

    fn apply_action(&mut self, i: usize, action: Action) {
        let side = self.state.controllers[i].side;
        let global = if side == Side::Right { action.rotated() } else { action };
        let index = self.state.controlled[i];
        let on_ball = self.state.game.may_play_ball(side, index);
        let press = self.state.controllers[i].sticky.apply(global, on_ball);
        let sticky = self.state.controllers[i].sticky;
        if sticky.builtin {
            self.state.game.set_agent_input(side, index, None);
            return;
        }
        let input = sticky_input(&sticky, press, &self.state.game.team(side)[index], on_ball);
        self.state.game.set_agent_input(side, index, Some(input));
    }
}
