//! Rewards with GRF's semantics (grf.md §6): Scoring (always on) and Checkpoints.

mod checkpoints;
mod plan;
mod scoring;

pub use checkpoints::{CHECKPOINT_COUNT, CHECKPOINT_REWARD, CheckpointTracker, checkpoint_threshold};
pub(crate) use plan::RewardPlan;
pub use scoring::scoring_reward;
