//! Scoring reward (docs/grf-compatibility.md#scoring-reward): +1 when the left team scores, -1 when it
//! concedes, from the change of the goal difference over the step. Right-team controllers get the negation.

/// The left team's scoring reward for a step that moved the goal difference from `before` to
/// `after` (left goals minus right goals).
pub fn scoring_reward(before: i32, after: i32) -> f32 {
    (after - before) as f32
}
