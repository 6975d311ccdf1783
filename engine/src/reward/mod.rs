//! Rewards with GRF's semantics (grf.md §6): Scoring (always on) and Checkpoints.

mod checkpoints;
mod scoring;

pub use checkpoints::{checkpoint_threshold, CheckpointTracker, CHECKPOINT_COUNT, CHECKPOINT_REWARD};
pub use scoring::scoring_reward;
