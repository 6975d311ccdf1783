//! Drawing a scenario's starting placement: randomised spots, the even/odd episode variants, and
//! `require` constraints honoured by bounded rejection sampling.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::{PlayerEntry, Scenario};
use crate::geometry::Side;
use crate::geometry::coords::{ball_start_to_world, formation_to_world};
use crate::rng::MatchRng;

/// Most placements drawn at one reset before giving up on the `require` constraints (the last
/// draw is then kept). The scenario compiler rejects constraints whose estimated acceptance makes
/// running out more likely than 1 in 10⁹, so in practice the budget never runs out.
pub const MAX_PLACEMENT_TRIES: u32 = 1_000;

/// Salt that separates the placement stream from the match's own stream of the same seed.
const PLACEMENT_STREAM: u64 = 0x5EED_0F97_ACE5;

/// Something a constraint measures: the ball or a player (index in the team's list, after the
/// episode's team swap).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Body {
    /// The ball.
    Ball,
    /// Left player `i`.
    Left(usize),
    /// Right player `i`.
    Right(usize),
}

/// A condition every drawn placement must meet. Distances are in metres on the pitch.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Require {
    /// `a` and `b` at least `metres` apart.
    MinDistance {
        /// First body.
        a: Body,
        /// Second body.
        b: Body,
        /// Distance in metres.
        metres: f32,
    },
    /// `a` and `b` at most `metres` apart.
    MaxDistance {
        /// First body.
        a: Body,
        /// Second body.
        b: Body,
        /// Distance in metres.
        metres: f32,
    },
}

/// A drawn starting placement: both teams' entries with concrete positions (after the episode's
/// team swap) and the ball's start, normalised units.
#[derive(Clone, Debug, PartialEq)]
pub struct Placement {
    /// Left team, in the left team's own frame.
    pub left: Vec<PlayerEntry>,
    /// Right team, in the right team's own frame.
    pub right: Vec<PlayerEntry>,
    /// Ball start, global frame.
    pub ball: [f32; 2],
    /// Draws it took (1 when nothing is random).
    pub tries: u32,
    /// Whether every `require` holds (false only when the budget ran out).
    pub satisfied: bool,
}

impl Placement {
    /// Where `body` stands, metres in the world frame.
    fn world(&self, body: Body) -> Vec2 {
        match body {
            Body::Ball => ball_start_to_world(self.ball[0], self.ball[1]),
            Body::Left(i) => self.left.get(i).map_or(Vec2::ZERO, |e| formation_to_world(Side::Left, e.x, e.y)),
            Body::Right(i) => self.right.get(i).map_or(Vec2::ZERO, |e| formation_to_world(Side::Right, e.x, e.y)),
        }
    }

    fn meets(&self, require: &Require) -> bool {
        match *require {
            Require::MinDistance { a, b, metres } => self.world(a).distance(self.world(b)) >= metres,
            Require::MaxDistance { a, b, metres } => self.world(a).distance(self.world(b)) <= metres,
        }
    }
}

impl Scenario {
    /// Whether anything is drawn at reset (a random spot or a random ball).
    pub fn is_randomised(&self) -> bool {
        self.ball_random.is_some() || self.left_team.iter().chain(&self.right_team).any(|e| e.random.is_some())
    }

    /// The placement of 0-based episode `episode` under `seed`: the odd-episode team swap and
    /// ball position applied, every random spot drawn from a stream fixed by `(seed, episode)`,
    /// redrawn until the `require` constraints hold (at most [`MAX_PLACEMENT_TRIES`] times).
    ///
    /// Placements vary with the episode in deterministic scenarios too: `deterministic` removes
    /// the noise of play, not the scenario's own randomisation.
    pub fn draw(&self, seed: u64, episode: u64) -> Placement {
        let (left, right) = self.teams_for_episode(episode);
        let odd = episode % 2 == 1;
        let ball = match (odd, self.odd_episode_ball_position) {
            (true, Some(b)) => b,
            _ => self.ball_position,
        };
        let mut placement = Placement { left: left.to_vec(), right: right.to_vec(), ball, tries: 0, satisfied: false };
        if !self.is_randomised() {
            placement.tries = 1;
            placement.satisfied = self.requires.iter().all(|r| placement.meets(r));
            return placement;
        }
        let mut rng = MatchRng::new(seed ^ PLACEMENT_STREAM, episode, true);
        while placement.tries < MAX_PLACEMENT_TRIES {
            placement.tries += 1;
            for (slot, entry) in placement.left.iter_mut().zip(left).chain(placement.right.iter_mut().zip(right)) {
                if let Some(spot) = &entry.random {
                    [slot.x, slot.y] = spot.draw(&mut rng);
                }
            }
            if let (Some(spot), false) = (&self.ball_random, odd && self.odd_episode_ball_position.is_some()) {
                placement.ball = spot.draw(&mut rng);
            }
            if self.requires.iter().all(|r| placement.meets(r)) {
                placement.satisfied = true;
                break;
            }
        }
        placement
    }

    /// The share of `samples` placements (seeds 0.., episode 0) that meet every `require`:
    /// what the compiler uses to tell a constraint that can never hold, or holds too rarely for
    /// the retry budget, from a sound one.
    pub fn require_acceptance(&self, samples: u32) -> f32 {
        if self.requires.is_empty() || samples == 0 {
            return 1.0;
        }
        let mut accepted = 0u32;
        let mut rng = MatchRng::new(PLACEMENT_STREAM, 0, true);
        let (left, right) = self.teams_for_episode(0);
        let mut p = Placement {
            left: left.to_vec(),
            right: right.to_vec(),
            ball: self.ball_position,
            tries: 1,
            satisfied: false,
        };
        for _ in 0..samples {
            for (slot, entry) in p.left.iter_mut().zip(left).chain(p.right.iter_mut().zip(right)) {
                if let Some(spot) = &entry.random {
                    [slot.x, slot.y] = spot.draw(&mut rng);
                }
            }
            if let Some(spot) = &self.ball_random {
                p.ball = spot.draw(&mut rng);
            }
            accepted += u32::from(self.requires.iter().all(|r| p.meets(r)));
        }
        accepted as f32 / samples as f32
    }
}

#[cfg(test)]
mod tests {
    use super::super::random::{Distribution, Sample, Spot};
    use super::*;
    use crate::player::Role;

    fn randomised() -> Scenario {
        let mut cb = PlayerEntry::new(Role::CB, 0.5, 0.0);
        cb.random = Some(Spot::Point {
            x: Sample::Random(Distribution::Uniform(0.3, 0.7)),
            y: Sample::Random(Distribution::Uniform(-0.3, 0.3)),
        });
        Scenario {
            left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), cb],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            ball_position: [0.5, 0.0],
            requires: vec![Require::MinDistance { a: Body::Left(1), b: Body::Ball, metres: 8.0 }],
            ..Scenario::default()
        }
    }

    #[test]
    fn same_seed_same_placement_and_episodes_differ() {
        let s = randomised();
        assert_eq!(s.draw(5, 3), s.draw(5, 3));
        assert_ne!(s.draw(5, 3).left[1], s.draw(5, 4).left[1]);
        assert_ne!(s.draw(5, 3).left[1], s.draw(6, 3).left[1]);
    }

    #[test]
    fn require_is_honoured() {
        let s = randomised();
        for episode in 0..2_000 {
            let p = s.draw(1, episode);
            assert!(p.satisfied);
            let cb = formation_to_world(Side::Left, p.left[1].x, p.left[1].y);
            assert!(cb.distance(ball_start_to_world(0.5, 0.0)) >= 8.0);
        }
        let acceptance = s.require_acceptance(2_000);
        assert!((0.2..1.0).contains(&acceptance), "{acceptance}");
    }

    #[test]
    fn impossible_require_is_measured_as_zero() {
        let mut s = randomised();
        s.requires = vec![Require::MinDistance { a: Body::Left(1), b: Body::Ball, metres: 500.0 }];
        assert_eq!(s.require_acceptance(500), 0.0);
        let p = s.draw(0, 0);
        assert!(!p.satisfied);
        assert_eq!(p.tries, MAX_PLACEMENT_TRIES);
    }
}
