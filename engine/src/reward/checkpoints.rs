//! Checkpoint reward (docs/grf-compatibility.md#checkpoint-reward): the opponent half is cut into 10 zones by
//! distance to the opponent goal; the first time a controlled player carries the ball into each zone pays 0.1. A
//! goal pays every checkpoint not yet collected, so a goal is always worth 2.0 in total.

use crate::obs::RawObservation;

/// Number of checkpoints (GRF `_num_checkpoints`).
pub const CHECKPOINT_COUNT: u8 = 10;
/// Reward per checkpoint (GRF `_checkpoint_reward`).
pub const CHECKPOINT_REWARD: f32 = 0.1;

/// Distance (normalised units, to the opponent goal centre (1, 0)) within which checkpoint `k`
/// (0-based) is collected: 0.99 - 0.8/9 · k → 0.99, 0.9011, …, 0.19.
pub fn checkpoint_threshold(k: u8) -> f32 {
    0.99 - (0.8 / 9.0) * f32::from(k)
}

/// Collected checkpoints of one controller, for one episode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct CheckpointTracker {
    collected: u8,
}

impl CheckpointTracker {
    /// Checkpoints collected so far (0..=10).
    pub fn collected(&self) -> u8 {
        self.collected
    }

    /// The checkpoint reward for a step in which this controller's scoring reward was `scoring`
    /// and whose resulting observation (in the controller's frame) is `obs`.
    pub fn reward(&mut self, scoring: f32, obs: &RawObservation) -> f32 {
        self.reward_with(CHECKPOINT_COUNT, CHECKPOINT_REWARD, scoring, obs)
    }

    /// As [`CheckpointTracker::reward`] with `count` zones (1–100) worth `value` each: zone `k`
    /// is collected within distance 0.99 − 0.8·k/(count − 1) of the opponent goal.
    pub fn reward_with(&mut self, count: u8, value: f32, scoring: f32, obs: &RawObservation) -> f32 {
        if scoring == 1.0 {
            let rest = count.saturating_sub(self.collected);
            self.collected = count;
            return value * f32::from(rest);
        }
        if obs.ball_owned_team != 0 || obs.ball_owned_player != obs.active || obs.active < 0 {
            return 0.0;
        }
        let (dx, dy) = (obs.ball[0] - 1.0, obs.ball[1]);
        let d = (dx * dx + dy * dy).sqrt();
        let step = if count > 1 { 0.8 / f32::from(count - 1) } else { 0.0 };
        let mut reward = 0.0;
        while self.collected < count && d <= 0.99 - step * f32::from(self.collected) {
            reward += value;
            self.collected += 1;
        }
        reward
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn owning_at(x: f32, y: f32) -> RawObservation {
        RawObservation {
            ball: [x, y, 0.11],
            ball_owned_team: 0,
            ball_owned_player: 1,
            active: 1,
            ..RawObservation::default()
        }
    }

    #[test]
    fn thresholds_match_grf() {
        let expected = [0.99, 0.901111, 0.812222, 0.723333, 0.634444, 0.545556, 0.456667, 0.367778, 0.278889, 0.19];
        for (k, e) in expected.iter().enumerate() {
            assert!((checkpoint_threshold(k as u8) - e).abs() < 1e-5);
        }
    }

    #[test]
    fn collected_in_order_several_per_step_and_a_goal_pays_the_rest() {
        let mut t = CheckpointTracker::default();
        // d = 0.98 → the first checkpoint.
        assert!((t.reward(0.0, &owning_at(0.02, 0.0)) - 0.1).abs() < 1e-6);
        // Not again at the same place.
        assert_eq!(t.reward(0.0, &owning_at(0.02, 0.0)), 0.0);
        // Jump to d = 0.5: checkpoints 1..=5 (thresholds 0.90 … 0.546) at once.
        assert!((t.reward(0.0, &owning_at(0.5, 0.0)) - 0.5).abs() < 1e-5);
        assert_eq!(t.collected(), 6);
        // Someone else's ball pays nothing.
        let mut o = owning_at(0.9, 0.0);
        o.ball_owned_player = 0;
        assert_eq!(t.reward(0.0, &o), 0.0);
        // A goal pays the 4 left: with the scoring 1.0 that is 1.0 + 0.6 + 0.4 = 2.0 in total.
        assert!((t.reward(1.0, &owning_at(0.0, 0.0)) - 0.4).abs() < 1e-5);
        assert_eq!(t.reward(1.0, &owning_at(0.0, 0.0)), 0.0);
    }
}
