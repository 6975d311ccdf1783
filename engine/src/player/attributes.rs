//! Per-slot player attributes (docs/grf-compatibility.md#player-stats): GRF gives team slot i a fixed profile
//! from its player database, the same for both teams, so slot 0 (normally the keeper) always has the keeper-like
//! profile. touchline keeps that rule with its own eleven profiles (GRF's database values are not
//! copied): slots follow the order of GRF's 11-v-11 formations (GK, RM, CF, LB, CB, CB, RB, CM,
//! CM, CM, LM). Scenarios with fewer players use the first slots.

use serde::{Deserialize, Serialize};

/// How much of his ability a player of a team of difficulty `theta` (in [0, 1]) shows: GRF
/// multiplies every stat by 0.3 + 0.7·θ, so the easiest side plays at 30 % and the
/// hardest at 100 %. The AI's reach (hunting distance, marking) scales the same way.
#[inline]
pub fn difficulty_scale(theta: f32) -> f32 {
    0.3 + 0.7 * theta
}

/// A player's abilities, each in [0, 1] (1 = the best). The team's difficulty θ and the player's
/// fatigue scale them in play (docs/grf-compatibility.md#controlled-players): every stat is multiplied by
/// (0.3 + 0.7·θ).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Attributes {
    /// Top speed: 8 m/s · (0.9 + 0.1·speed) (docs/grf-compatibility.md#player-stats).
    pub speed: f32,
    /// How quickly he reaches top speed: 6–8 m/s².
    pub acceleration: f32,
    /// How slowly he tires: fatigue grows with (2 − stamina) (docs/grf-compatibility.md#player-stats).
    pub stamina: f32,
    /// Pass accuracy.
    pub passing: f32,
    /// Shot accuracy and power.
    pub shooting: f32,
    /// Fastest ball he traps cleanly; how hard he is to dispossess.
    pub ball_control: f32,
    /// Chance of winning a standing tackle; clean timing of sliding tackles.
    pub tackling: f32,
    /// How fast the built-in AI reacts for him (a tick or two at most).
    pub reaction: f32,
    /// How well the built-in AI keeps him in his zone and onside.
    pub positioning: f32,
}

impl Attributes {
    /// The same value for every attribute.
    pub const fn uniform(v: f32) -> Attributes {
        Attributes {
            speed: v,
            acceleration: v,
            stamina: v,
            passing: v,
            shooting: v,
            ball_control: v,
            tackling: v,
            reaction: v,
            positioning: v,
        }
    }

    /// The profile of team slot `slot` (0-based, the scenario's order); slots past 10 reuse 10.
    pub fn for_slot(slot: usize) -> Attributes {
        SLOT_PROFILES[slot.min(SLOT_PROFILES.len() - 1)]
    }
}

const fn profile(v: [f32; 9]) -> Attributes {
    Attributes {
        speed: v[0],
        acceleration: v[1],
        stamina: v[2],
        passing: v[3],
        shooting: v[4],
        ball_control: v[5],
        tackling: v[6],
        reaction: v[7],
        positioning: v[8],
    }
}

/// The eleven slot profiles: speed, acceleration, stamina, passing, shooting, ball control,
/// tackling, reaction, positioning.
const SLOT_PROFILES: [Attributes; 11] = [
    // 0: goalkeeper — reactions and positioning.
    profile([0.55, 0.65, 0.70, 0.60, 0.30, 0.75, 0.40, 0.90, 0.90]),
    // 1: wide midfielder (RM in GRF's 11-v-11 formations).
    profile([0.85, 0.85, 0.85, 0.75, 0.65, 0.80, 0.55, 0.75, 0.70]),
    // 2: centre forward.
    profile([0.85, 0.80, 0.75, 0.65, 0.85, 0.80, 0.45, 0.80, 0.75]),
    // 3: left back.
    profile([0.80, 0.75, 0.85, 0.65, 0.45, 0.65, 0.80, 0.70, 0.80]),
    // 4–5: centre backs.
    profile([0.70, 0.65, 0.80, 0.65, 0.40, 0.65, 0.90, 0.70, 0.85]),
    profile([0.70, 0.65, 0.80, 0.65, 0.40, 0.65, 0.90, 0.70, 0.85]),
    // 6: right back.
    profile([0.80, 0.75, 0.85, 0.65, 0.45, 0.65, 0.80, 0.70, 0.80]),
    // 7–9: midfielders.
    profile([0.75, 0.75, 0.90, 0.85, 0.60, 0.80, 0.65, 0.80, 0.75]),
    profile([0.70, 0.70, 0.90, 0.90, 0.65, 0.85, 0.70, 0.80, 0.80]),
    profile([0.75, 0.75, 0.90, 0.85, 0.60, 0.80, 0.65, 0.80, 0.75]),
    // 10: wide midfielder.
    profile([0.85, 0.85, 0.85, 0.75, 0.65, 0.80, 0.55, 0.75, 0.70]),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_profile_is_in_range() {
        for slot in 0..12 {
            let a = Attributes::for_slot(slot);
            for v in [
                a.speed,
                a.acceleration,
                a.stamina,
                a.passing,
                a.shooting,
                a.ball_control,
                a.tackling,
                a.reaction,
                a.positioning,
            ] {
                assert!((0.0..=1.0).contains(&v), "slot {slot}");
            }
        }
        assert!(Attributes::for_slot(0).reaction > Attributes::for_slot(4).reaction);
    }
}
