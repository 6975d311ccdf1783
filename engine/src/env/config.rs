//! Environment configuration: who the agents control and which rewards and actions they use.

use serde::{Deserialize, Serialize};

use crate::game::ActionSet;

/// How an [`crate::Env`] is driven (GRF's `create_environment` arguments,
/// docs/grf-compatibility.md#create-environment).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct EnvConfig {
    /// Left players the agents control (GRF `number_of_left_players_agent_controls`, default 1).
    pub left_agents: usize,
    /// Right players the agents control (default 0).
    pub right_agents: usize,
    /// Action set: 19 actions (`default`) or 20 with `builtin_ai` (`v2`).
    pub action_set: ActionSet,
    /// Add the Checkpoint reward to Scoring (GRF `rewards="scoring,checkpoints"`).
    pub checkpoints: bool,
}

impl Default for EnvConfig {
    fn default() -> EnvConfig {
        EnvConfig { left_agents: 1, right_agents: 0, action_set: ActionSet::Default, checkpoints: false }
    }
}
