//! The match's one source of randomness: a seeded PCG stream. Nothing in the engine draws random
//! numbers any other way, so a scenario, a seed and a sequence of actions fix the trajectory.

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

/// A seeded random stream with the few draws the engine needs. In deterministic scenarios the
/// noise amplitude is zero, so [`MatchRng::noise`] returns 0 whatever the stream holds.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub(crate) struct MatchRng {
    stream: Pcg32,
    noise_scale: f32,
}

impl MatchRng {
    /// A stream for one episode: `seed` and `episode` together pick it.
    pub(crate) fn new(seed: u64, episode: u64, noisy: bool) -> MatchRng {
        // SplitMix-style mixing so that neighbouring seeds give unrelated streams.
        let mut z = seed ^ episode.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        MatchRng { stream: Pcg32::seed_from_u64(z), noise_scale: if noisy { 1.0 } else { 0.0 } }
    }

    /// Uniform in [0, 1).
    #[inline]
    pub(crate) fn unit(&mut self) -> f32 {
        self.stream.random::<f32>()
    }

    /// True with probability `p`.
    #[inline]
    pub(crate) fn chance(&mut self, p: f32) -> bool {
        self.unit() < p
    }

    /// Whether the match is stochastic: [`MatchRng::noise`] is non-zero and kicks vary.
    #[inline]
    pub(crate) fn noisy(&self) -> bool {
        self.noise_scale != 0.0
    }

    /// Symmetric noise in [-amplitude, amplitude]; zero in deterministic mode.
    #[inline]
    pub(crate) fn noise(&mut self, amplitude: f32) -> f32 {
        if self.noise_scale == 0.0 {
            return 0.0;
        }
        (self.unit() * 2.0 - 1.0) * amplitude * self.noise_scale
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_stream_and_seeds_differ() {
        let mut a = MatchRng::new(7, 0, true);
        let mut b = MatchRng::new(7, 0, true);
        let mut c = MatchRng::new(8, 0, true);
        let xa: Vec<f32> = (0..8).map(|_| a.unit()).collect();
        let xb: Vec<f32> = (0..8).map(|_| b.unit()).collect();
        let xc: Vec<f32> = (0..8).map(|_| c.unit()).collect();
        assert_eq!(xa, xb);
        assert_ne!(xa, xc);
        assert!(xa.iter().all(|x| (0.0..1.0).contains(x)));
    }

    #[test]
    fn deterministic_mode_has_no_noise() {
        let mut r = MatchRng::new(1, 0, false);
        assert_eq!(r.noise(5.0), 0.0);
    }
}
