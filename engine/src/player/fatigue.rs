//! Fatigue (docs/grf-compatibility.md#player-stats): it grows with the distance a player runs, faster when
//! sprinting and for players with less stamina, eases a little while he walks or stands, and is restored at each
//! half's kickoff. A tired player is slower and less accurate. Observed as `tired_factor`.
//!
//! GRF takes `distance · 0.00003 · (2 − stamina) / 0.0554` off `fatigue_inv` every tick (0.0554
//! is its match-duration factor), so a player who runs about a kilometre in a 3000-step match ends
//! it with a tired factor around 0.7. touchline uses the same rate, adds 50 % for distance run
//! above 6 m/s (sprinting), and a slow recovery below 2 m/s (GRF has none; without it
//! a keeper and a winger would tire alike over a long match).

use super::Player;

/// GRF's rate per metre, 0.00003 / 0.0554.
const PER_METRE: f32 = 0.000_03 / 0.0554;
/// Extra cost of running above [`SPRINTING`] m/s.
const SPRINT_EXTRA: f32 = 0.5;
/// Speed (m/s) above which a player counts as sprinting.
const SPRINTING: f32 = 6.0;
/// Speed (m/s) below which he recovers.
const RESTING: f32 = 2.0;
/// Recovery per second while resting: 0.1 over a minute of game time standing.
const RECOVERY_PER_SECOND: f32 = 0.1 / 60.0;
/// Most fatigue a player reaches (GRF clamps `fatigue_inv` at 0.01).
pub const MAX_FATIGUE: f32 = 0.99;

/// Fraction of his top speed a player keeps at fatigue `f`: 1 fresh, 0.88 exhausted.
#[inline]
pub fn speed_factor(fatigue: f32) -> f32 {
    1.0 - 0.12 * fatigue
}

/// Fraction of his accuracy a player keeps at fatigue `f`: GRF scales every stat by
/// 0.7 + 0.3·(1 − f) (docs/grf-compatibility.md#controlled-players).
#[inline]
pub fn skill_factor(fatigue: f32) -> f32 {
    1.0 - 0.3 * fatigue
}

/// Updates `p`'s fatigue after he ran at `speed` m/s for `seconds` s, and his top speed from
/// `fresh_speed` (his top speed when fresh). The match calls it every 0.1 s of play with the speed
/// of that moment, which costs a tenth of a per-tick update and tires players alike.
#[inline]
pub(crate) fn update(p: &mut Player, speed: f32, seconds: f32, stamina: f32, fresh_speed: f32) {
    let mut cost = speed * seconds * PER_METRE * (2.0 - stamina);
    if speed > SPRINTING {
        cost *= 1.0 + SPRINT_EXTRA;
    }
    let rest = if speed < RESTING { RECOVERY_PER_SECOND * seconds } else { 0.0 };
    p.fatigue = (p.fatigue + cost - rest).clamp(0.0, MAX_FATIGUE);
    p.max_speed = fresh_speed * speed_factor(p.fatigue);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Side;
    use crate::player::Role;
    use glam::Vec2;

    #[test]
    fn running_tires_sprinting_more_and_resting_recovers() {
        let mut jog = Player::new(Side::Left, 1, Role::CM, Vec2::ZERO, Vec2::ZERO);
        let mut sprint = jog.clone();
        for _ in 0..1000 {
            update(&mut jog, 5.0, 0.01, 0.5, 8.0);
            update(&mut sprint, 7.0, 0.01, 0.5, 8.0);
        }
        assert!(jog.fatigue > 0.0 && sprint.fatigue > jog.fatigue * 1.4);
        assert!(sprint.max_speed < 8.0);
        let before = sprint.fatigue;
        for _ in 0..1000 {
            update(&mut sprint, 0.0, 0.01, 0.5, 8.0);
        }
        assert!(sprint.fatigue < before);
        // About a kilometre of running leaves GRF's ~0.7.
        let mut p = Player::new(Side::Left, 1, Role::CM, Vec2::ZERO, Vec2::ZERO);
        for _ in 0..2_000 {
            update(&mut p, 5.0, 0.1, 0.5, 8.0);
        }
        assert!((0.6..0.9).contains(&p.fatigue), "{}", p.fatigue);
    }
}
