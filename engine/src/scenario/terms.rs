//! A scenario's reward terms and extra episode-end conditions, as the language declares them
//! (`reward scoring + checkpoint(count: 10, value: 0.1)`, `end when steps >= 200 or ball in …`).

use serde::{Deserialize, Serialize};

use super::event_reward::EventReward;
use super::random::Region;

/// One weighted reward term; a controller's reward is the sum of `weight × term` over the terms.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RewardTerm {
    /// What is rewarded.
    pub reward: RewardKind,
    /// Multiplier (default 1).
    #[serde(default = "one")]
    pub weight: f32,
}

fn one() -> f32 {
    1.0
}

/// A reward a scenario can name.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RewardKind {
    /// GRF's SCORING: +1 for a goal scored, −1 for one conceded (docs/grf-compatibility.md#scoring-reward).
    Scoring,
    /// GRF's CHECKPOINTS: `count` zones in the opponent half, `value` each, the first time the
    /// controlled player carries the ball into one; a goal pays the rest
    /// (docs/grf-compatibility.md#checkpoint-reward; GRF uses count 10, value 0.1).
    Checkpoints {
        /// Number of zones (1–100).
        count: u8,
        /// Reward per zone.
        value: f32,
    },
    /// A rhai script's reward (run through the env's hooks; `path` as written in the source,
    /// relative to the scenario file).
    Script {
        /// Script path.
        path: String,
    },
    /// The term's weight, paid when a pattern of match events completes (`reward on …`).
    Event(EventReward),
}

/// An episode-end condition beyond GRF's three flags (score, out of play, possession change).
/// Each terminates the episode (`terminated`, not `truncated`) after the step where it holds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum EndCondition {
    /// At least this many steps have been taken in the episode.
    Steps(u32),
    /// The ball is in the region (global frame, normalised units; the left team attacks +x).
    BallIn(Region),
    /// A rhai script says the episode ends (run through the env's hooks).
    Script {
        /// Script path, relative to the scenario file.
        path: String,
    },
    /// A condition of the condition language holds (global frame; `Target::Me` and
    /// `Condition::Done` are not allowed here).
    When(super::Condition),
    /// A goalkeeper saved a shot: the shot of one team, touched by nobody else since, was caught,
    /// taken, parried out or deflected away from goal by the other team's keeper (`.tl`: `save`).
    Save,
    /// A goalkeeper holds the ball in his hands (`.tl`: `keeper_holds_ball`).
    KeeperHoldsBall,
    /// The pending restart was taken: the game mode was a set piece after the previous step (or
    /// at the episode's start) and is open play now (`.tl`: `restart_taken`). A kickoff counts as
    /// taken on its first tick (see `rules::kickoff`), so it never ends an episode this way.
    RestartTaken,
}

impl RewardTerm {
    /// Largest weight (and checkpoint value) a term may have, in magnitude. A step's reward sums
    /// the terms in f32: four scoring terms of weight 1e38 sum to inf and pay NaN (inf × 0) every
    /// step. Bounded by 1e6, any number of terms a scenario can hold sums finitely.
    pub const MAX_WEIGHT: f32 = 1e6;

    /// GRF's default reward: scoring with weight 1.
    pub fn scoring() -> RewardTerm {
        RewardTerm { reward: RewardKind::Scoring, weight: 1.0 }
    }

    /// Checks parameters: a finite weight of at most [`RewardTerm::MAX_WEIGHT`] in magnitude,
    /// 1–100 checkpoints with a value as bounded.
    pub(crate) fn check(&self) -> Result<(), String> {
        if !self.weight.is_finite() {
            return Err(format!("reward weight {} is not finite", self.weight));
        }
        if self.weight.abs() > RewardTerm::MAX_WEIGHT {
            return Err(format!(
                "reward weight {} is larger than {:e} in magnitude; summed with other terms it could overflow",
                self.weight,
                RewardTerm::MAX_WEIGHT
            ));
        }
        match &self.reward {
            RewardKind::Checkpoints { count, value }
                if !(1..=100).contains(count) || !value.is_finite() || value.abs() > RewardTerm::MAX_WEIGHT =>
            {
                Err(format!(
                    "checkpoints need a count in 1..=100 and a value of at most {:e} in magnitude (got {count}, {value})",
                    RewardTerm::MAX_WEIGHT
                ))
            }
            RewardKind::Event(reward) => reward.check(),
            _ => Ok(()),
        }
    }
}
