//! Difficulty θ ∈ [0, 1]: how quickly and how well a team's AI decides (GRF: easy 0.05, medium
//! 0.6, hard 0.95; docs/grf-compatibility.md#scenario-settings, #controlled-players).

/// How much of his ability a player of a team of difficulty θ shows, 0.3 + 0.7·θ: defined with
/// the players' stats, which it scales, and used by the AI for its reach too.
pub use crate::player::difficulty_scale;

/// Noise on the value of the AI's options, at every θ (see [`Difficulty::decision_noise`]).
const DECISION_NOISE: f32 = 0.2;

/// The parameters a team's θ sets. All are smooth in θ.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Difficulty {
    /// θ itself.
    pub theta: f32,
    /// Ticks between decisions: 5 + 10·(1 − θ), i.e. 50 ms at θ = 1 to 150 ms at θ = 0. GRF adds
    /// (1 − θ)·100 ms of reaction time (docs/grf-compatibility.md#controlled-players). Fractional: the AI
    /// carries the remainder from one decision to the next, so the mean interval is exactly this and smooth in θ.
    pub reaction_ticks: f32,
    /// Amplitude of the noise added to the value of each option (pass, shot, dribble). The same
    /// at every θ: GRF's AI has no decision noise tied to θ, its choices are as random at any θ
    /// and worse only through the players' weaker stats. Zero in deterministic scenarios (the
    /// match RNG returns no noise).
    pub decision_noise: f32,
}

impl Difficulty {
    /// Parameters for θ (clamped into [0, 1]).
    pub fn new(theta: f32) -> Difficulty {
        let theta = theta.clamp(0.0, 1.0);
        Difficulty { theta, reaction_ticks: 5.0 + 10.0 * (1.0 - theta), decision_noise: DECISION_NOISE }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn harder_means_faster_and_sharper() {
        let easy = Difficulty::new(0.05);
        let hard = Difficulty::new(0.95);
        assert!(hard.reaction_ticks < easy.reaction_ticks);
        assert_eq!(hard.decision_noise, easy.decision_noise);
        assert_eq!(Difficulty::new(1.0).reaction_ticks, 5.0);
        assert!(Difficulty::new(0.61).reaction_ticks < Difficulty::new(0.6).reaction_ticks);
        assert_eq!(Difficulty::new(7.0).theta, 1.0);
    }
}
