//! Rewards with GRF's semantics (docs/grf-compatibility.md#rewards): Scoring (always on) and Checkpoints; and event
//! rewards (`reward on …`), paid from the match's event stream.

mod checkpoints;
mod events;
mod plan;
mod scoring;

pub use checkpoints::{CHECKPOINT_COUNT, CHECKPOINT_REWARD, CheckpointTracker, checkpoint_threshold};
pub use events::{EventProgress, EventRewards, Viewpoint};
pub(crate) use plan::RewardPlan;
pub use scoring::scoring_reward;
