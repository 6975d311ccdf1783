//! Curricula: lessons played in order, each a complete [`Scenario`], and the criterion over a
//! moving window of finished episodes that moves an env from one lesson to the next
//! (ML-Agents' curriculum, declared in the scenario).

use serde::{Deserialize, Serialize};

use super::Scenario;

/// The lessons of a scenario's curriculum, in the order they are played.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Curriculum {
    /// At least one lesson; an env starts on the first and stays on the last.
    pub lessons: Vec<Lesson>,
}

/// One lesson: a name, the scenario it plays and when to move on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lesson {
    /// The lesson's name (`near`, `far`).
    pub name: String,
    /// The complete scenario the lesson plays (no curriculum of its own).
    pub scenario: Scenario,
    /// When the env moves to the next lesson; `None` stays on this one (the last lesson's is
    /// never used).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub advance: Option<Criterion>,
}

/// "Move on when every threshold holds over the last `window` episodes of this lesson, judged
/// once at least `min_episodes` of them are played."
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Criterion {
    /// The episodes the metrics average over: the last `window` finished in this lesson (>= 1).
    pub window: u32,
    /// Episodes the window must hold before the criterion is judged (1 ..= `window`).
    pub min_episodes: u32,
    /// Every one must hold (at least one).
    pub thresholds: Vec<Threshold>,
}

/// `metric >= value` (or `<=` when `at_least` is false).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Threshold {
    /// What is measured over the window.
    pub metric: Metric,
    /// `>=` (true) or `<=` (false).
    pub at_least: bool,
    /// The bound.
    pub value: f64,
}

/// A measure of the episodes in a window.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    /// Mean episode return: per episode, the rewards of the left team's agent controllers summed
    /// over the steps and averaged over those controllers (all controllers when no agent plays
    /// on the left).
    MeanReward,
    /// Mean final score difference, left goals minus right goals.
    MeanScore,
    /// Fraction of episodes, in [0, 1], that ended with the left team ahead (a positive score
    /// difference; in a drill that ends on a goal: the left team scored).
    SuccessRate,
}

impl Metric {
    /// The name the scenario language uses.
    pub fn name(self) -> &'static str {
        match self {
            Metric::MeanReward => "mean_reward",
            Metric::MeanScore => "mean_score",
            Metric::SuccessRate => "success_rate",
        }
    }

    /// The metric named `name` in the scenario language.
    pub fn from_name(name: &str) -> Option<Metric> {
        [Metric::MeanReward, Metric::MeanScore, Metric::SuccessRate].into_iter().find(|m| m.name() == name)
    }

    /// Every metric's name.
    pub const NAMES: [&'static str; 3] = ["mean_reward", "mean_score", "success_rate"];
}

/// What the criterion knows about one finished episode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EpisodeResult {
    /// The episode's return (see [`Metric::MeanReward`]).
    pub reward: f32,
    /// Final score difference, left minus right.
    pub score_diff: i32,
}

impl EpisodeResult {
    fn measure(&self, metric: Metric) -> f64 {
        match metric {
            Metric::MeanReward => f64::from(self.reward),
            Metric::MeanScore => f64::from(self.score_diff),
            Metric::SuccessRate => f64::from(u8::from(self.score_diff > 0)),
        }
    }
}

impl Criterion {
    /// Whether the criterion holds for `results`, the episodes in the window (at most `window`).
    pub fn met<'r>(&self, results: impl Iterator<Item = &'r EpisodeResult> + Clone) -> bool {
        let n = results.clone().count();
        if n == 0 || n < self.min_episodes as usize {
            return false;
        }
        self.thresholds.iter().all(|t| {
            let mean = results.clone().map(|r| r.measure(t.metric)).sum::<f64>() / n as f64;
            if t.at_least { mean >= t.value } else { mean <= t.value }
        })
    }

    /// Checks what the env relies on: a window of at least one episode, `min_episodes` in
    /// `1..=window`, at least one finite threshold.
    ///
    /// # Errors
    /// The problem, in words.
    pub fn check(&self) -> Result<(), String> {
        if self.window == 0 {
            return Err("a criterion's window must hold at least 1 episode".into());
        }
        if self.min_episodes == 0 || self.min_episodes > self.window {
            return Err(format!(
                "min_episodes {} must be in 1..={} (the window): the window never holds more",
                self.min_episodes, self.window
            ));
        }
        if self.thresholds.is_empty() {
            return Err("a criterion needs at least one threshold".into());
        }
        if let Some(t) = self.thresholds.iter().find(|t| !t.value.is_finite()) {
            return Err(format!("the {} threshold {} is not finite", t.metric.name(), t.value));
        }
        Ok(())
    }
}

impl Curriculum {
    /// Checks every lesson: at least one, each scenario valid and without a curriculum of its
    /// own, each criterion sound.
    ///
    /// # Errors
    /// The problem, in words.
    pub fn check(&self) -> Result<(), String> {
        if self.lessons.is_empty() {
            return Err("a curriculum needs at least one lesson".into());
        }
        for l in &self.lessons {
            if l.scenario.curriculum.is_some() {
                return Err(format!("lesson `{}` has a curriculum of its own", l.name));
            }
            l.scenario.validate().map_err(|e| format!("lesson `{}`: {e}", l.name))?;
            if let Some(c) = &l.advance {
                c.check().map_err(|e| format!("lesson `{}`: {e}", l.name))?;
            }
        }
        Ok(())
    }

    /// The largest window of any lesson's criterion (0 without criteria).
    pub fn max_window(&self) -> usize {
        self.lessons.iter().filter_map(|l| l.advance.as_ref()).map(|c| c.window as usize).max().unwrap_or(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn result(reward: f32, score_diff: i32) -> EpisodeResult {
        EpisodeResult { reward, score_diff }
    }

    #[test]
    fn a_criterion_waits_for_min_episodes_then_averages() {
        let c = Criterion {
            window: 4,
            min_episodes: 2,
            thresholds: vec![Threshold { metric: Metric::SuccessRate, at_least: true, value: 0.5 }],
        };
        assert!(!c.met([result(1.0, 1)].iter()), "one episode is below min_episodes");
        assert!(c.met([result(1.0, 1), result(0.0, 0)].iter()));
        assert!(!c.met([result(1.0, 1), result(0.0, 0), result(0.0, -1)].iter()));
        let reward = Criterion {
            thresholds: vec![
                Threshold { metric: Metric::MeanReward, at_least: true, value: 0.5 },
                Threshold { metric: Metric::MeanScore, at_least: false, value: 0.0 },
            ],
            ..c
        };
        assert!(reward.met([result(1.0, 0), result(0.5, 0)].iter()));
        assert!(!reward.met([result(1.0, 1), result(0.5, 0)].iter()), "mean score 0.5 > 0");
    }

    #[test]
    fn checks_name_the_problem() {
        let mut c = Criterion {
            window: 3,
            min_episodes: 4,
            thresholds: vec![Threshold { metric: Metric::MeanScore, at_least: true, value: 0.0 }],
        };
        assert!(c.check().unwrap_err().contains("never holds more"));
        c.min_episodes = 3;
        assert!(c.check().is_ok());
        assert_eq!(Metric::from_name("success_rate"), Some(Metric::SuccessRate));
        assert!(Curriculum { lessons: vec![] }.check().is_err());
    }
}
