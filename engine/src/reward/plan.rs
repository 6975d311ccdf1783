//! Which reward terms an env pays, resolved once from the scenario's `rewards` and the env's
//! configuration.

use crate::env::EnvConfig;
use crate::error::EngineError;
use crate::scenario::{RewardKind, Scenario};

use super::{CHECKPOINT_COUNT, CHECKPOINT_REWARD};

/// Weighted checkpoint parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CheckpointTerm {
    pub(crate) count: u8,
    pub(crate) value: f32,
    pub(crate) weight: f32,
}

/// The built-in reward terms of an env: the scoring weight and an optional checkpoint term.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RewardPlan {
    pub(crate) scoring: f32,
    pub(crate) checkpoints: Option<CheckpointTerm>,
}

impl RewardPlan {
    /// A scenario without `rewards` pays GRF's scoring, plus GRF's checkpoints (10 × 0.1) when
    /// the env config asks; a scenario with `rewards` pays exactly its terms (the config's
    /// checkpoints are added only when the scenario has none).
    ///
    /// # Errors
    /// [`EngineError::InvalidScenario`] for a script term when the env has no hooks (scripts
    /// need the hooks of `touchline_dsl`) or more than one checkpoint term.
    pub(crate) fn new(scenario: &Scenario, config: &EnvConfig, hooks: bool) -> Result<RewardPlan, EngineError> {
        let grf = CheckpointTerm { count: CHECKPOINT_COUNT, value: CHECKPOINT_REWARD, weight: 1.0 };
        if scenario.rewards.is_empty() {
            return Ok(RewardPlan { scoring: 1.0, checkpoints: config.checkpoints.then_some(grf) });
        }
        let mut plan = RewardPlan { scoring: 0.0, checkpoints: None };
        for term in &scenario.rewards {
            match &term.reward {
                RewardKind::Scoring => plan.scoring += term.weight,
                RewardKind::Checkpoints { count, value } => {
                    if plan.checkpoints.is_some() {
                        return Err(EngineError::InvalidScenario {
                            reason: "more than one checkpoint reward term".into(),
                        });
                    }
                    plan.checkpoints = Some(CheckpointTerm { count: *count, value: *value, weight: term.weight });
                }
                // The env's hooks pay script terms.
                RewardKind::Script { .. } if hooks => {}
                // The env's event rewards ([`super::EventRewards`]) pay event terms.
                RewardKind::Event(_) => {}
                RewardKind::Script { path } => {
                    return Err(EngineError::InvalidScenario {
                        reason: format!(
                            "the reward script \"{path}\" needs script hooks; build the env through \
                             touchline_dsl, which runs scripts"
                        ),
                    });
                }
            }
        }
        if plan.checkpoints.is_none() && config.checkpoints {
            plan.checkpoints = Some(grf);
        }
        Ok(plan)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::RewardTerm;

    #[test]
    fn default_and_declared_terms() {
        let config = EnvConfig { checkpoints: true, ..EnvConfig::default() };
        let plain = RewardPlan::new(&Scenario::default(), &config, false).unwrap();
        assert_eq!(plain.scoring, 1.0);
        assert_eq!(plain.checkpoints.unwrap().count, 10);
        let s = Scenario {
            rewards: vec![
                RewardTerm { reward: RewardKind::Scoring, weight: 2.0 },
                RewardTerm { reward: RewardKind::Checkpoints { count: 5, value: 0.2 }, weight: 0.5 },
            ],
            ..Scenario::default()
        };
        let plan = RewardPlan::new(&s, &EnvConfig::default(), false).unwrap();
        assert_eq!(plan.scoring, 2.0);
        assert_eq!(plan.checkpoints, Some(CheckpointTerm { count: 5, value: 0.2, weight: 0.5 }));
    }

    #[test]
    fn scripts_need_hooks() {
        let s = Scenario {
            rewards: vec![RewardTerm { reward: RewardKind::Script { path: "x.rhai".into() }, weight: 1.0 }],
            ..Scenario::default()
        };
        assert!(RewardPlan::new(&s, &EnvConfig::default(), false).unwrap_err().to_string().contains("x.rhai"));
    }
}
