//! Errors the engine reports to its callers.

use thiserror::Error;

/// Everything that can go wrong when building or stepping an environment.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum EngineError {
    /// The scenario breaks a rule the engine relies on.
    #[error("invalid scenario: {reason}")]
    InvalidScenario {
        /// What is wrong, naming the field or player.
        reason: String,
    },
    /// The environment configuration does not fit the scenario.
    #[error("invalid environment configuration: {reason}")]
    InvalidConfig {
        /// What is wrong.
        reason: String,
    },
    /// `step` got a different number of actions than there are controllers.
    #[error("expected {expected} actions (one per controlled player), got {got}")]
    ActionCount {
        /// Number of controllers.
        expected: usize,
        /// Number of actions passed.
        got: usize,
    },
    /// An action index outside the action set.
    #[error("action index {index} is outside the {set} action set (0..{len})")]
    UnknownAction {
        /// The index passed.
        index: u32,
        /// The action set's name.
        set: &'static str,
        /// The set's size.
        len: usize,
    },
    /// A snapshot taken from an environment on another scenario.
    #[error("this snapshot was taken on another scenario ({snapshot}); this environment plays {env}")]
    SnapshotScenario {
        /// Name of the snapshot's scenario.
        snapshot: String,
        /// Name of this environment's scenario.
        env: String,
    },
    /// Bytes that are not a readable snapshot (truncated, corrupted, or from a newer touchline).
    #[error("not a valid touchline snapshot: {reason}")]
    InvalidSnapshot {
        /// What is wrong.
        reason: String,
    },
    /// A script hook failed (a runtime error or an exhausted limit); the message names the
    /// script, the hook and the line and column.
    #[error("{message}")]
    Script {
        /// The rendered diagnostic.
        message: String,
        /// Its stable code (`tl::S005`, …), for callers that branch on it (Python's
        /// `ScenarioError.code`).
        code: String,
    },
    /// `step` after the episode ended; call `reset` first.
    #[error("the episode has ended; call reset() before step()")]
    EpisodeOver,
}
