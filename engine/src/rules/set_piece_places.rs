//! Where the players stand when a goal kick is taken: GRF's set-piece preparation puts every
//! outfield player of both teams at his formation place, mapped into a band of the pitch that
//! depends on whether his team takes the kick (GRF 2.10.2's team AI, its set-piece preparation
//! for goal kicks; docs/grf-compatibility.md#formations, "players' places at a goal kick").
//!
//! Measured in GRF 2.10.2 (11_vs_11_stochastic, idle agent, engine seeds 100-103): at the agent
//! team's goal kicks the opponents' outfield players stood a median 10.5 m into their own half
//! on average, the deepest of them 5.3 m into ours, and every goal kick reached one of ours
//! first. touchline left them where the ball went out (their mean 28.8 m into our half, the
//! deepest 42.5 m, inside our penalty area), and more than half of our goal kicks went straight
//! to them.

use glam::Vec2;

use crate::geometry::pitch::{HALF_LENGTH, HALF_WIDTH};

/// The band (team frame, fractions of the half length) the taking team's players are spread
/// over, own end first: from halfway into their own half to a fifth of the way into the other.
const TAKERS_BAND: (f32, f32) = (-0.5, 0.2);
/// The band of the team defending the goal kick: from 0.4 of the way into their own half to a
/// tenth of the way into the takers'.
const DEFENDERS_BAND: (f32, f32) = (-0.4, 0.1);
/// The share of the pitch's half width the places span across.
const WIDTH_SHARE: f32 = 0.7;

/// The place (team frame, m) at a goal kick of a player whose formation place is `home` (team
/// frame, m: x from −55 at his own goal line to 55 at the other, y across), of the team taking
/// the kick (`taking`) or of the other. His place along the pitch keeps its share of his
/// formation's depth within the band; across, it keeps 0.7 of its width.
pub(super) fn goal_kick_place(home: Vec2, taking: bool) -> Vec2 {
    let (back, front) = if taking { TAKERS_BAND } else { DEFENDERS_BAND };
    let depth = (home.x / HALF_LENGTH).clamp(-1.0, 1.0) * 0.5 + 0.5;
    let x = (back + depth * (front - back)) * HALF_LENGTH;
    let y = (home.y / HALF_WIDTH).clamp(-1.0, 1.0) * WIDTH_SHARE * HALF_WIDTH;
    Vec2::new(x, y)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::pitch::PENALTY_AREA_DEPTH;

    #[test]
    fn at_a_goal_kick_the_defending_team_stands_back_in_its_own_half_mostly() {
        // Their centre forward (formation x 1) is the deepest into the takers' half: 5.5 m, far
        // outside the penalty area; their centre backs (x −1) 22 m into their own half.
        let forward = goal_kick_place(Vec2::new(HALF_LENGTH, 0.0), false);
        assert!((forward.x - 5.5).abs() < 1e-4, "{forward}");
        assert!(HALF_LENGTH - forward.x > PENALTY_AREA_DEPTH);
        let back = goal_kick_place(Vec2::new(-HALF_LENGTH, 9.0), false);
        assert!((back.x + 22.0).abs() < 1e-4 && (back.y - 6.3).abs() < 1e-4, "{back}");
    }

    #[test]
    fn at_a_goal_kick_the_taking_team_spreads_from_its_half_to_just_beyond_halfway() {
        let centre_back = goal_kick_place(Vec2::new(-HALF_LENGTH, -9.0), true);
        assert!((centre_back.x + 27.5).abs() < 1e-4, "{centre_back}");
        let full_back = goal_kick_place(Vec2::new(-0.74 * HALF_LENGTH, 0.77 * HALF_WIDTH), true);
        assert!(full_back.y > 19.0 && full_back.y < 20.0, "{full_back}");
        let forward = goal_kick_place(Vec2::new(HALF_LENGTH, 0.0), true);
        assert!((forward.x - 11.0).abs() < 1e-4, "{forward}");
    }
}
