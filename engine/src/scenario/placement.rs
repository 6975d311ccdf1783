//! Drawing a scenario's starting placement: randomised spots, spots relative to another body's
//! drawn position ([`Anchor`]), the even/odd episode variants, and `require` constraints honoured
//! by bounded rejection sampling.

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::random::{PITCH_HALF_LENGTH, PITCH_HALF_WIDTH, SharedDraws, Spot};
use super::{PlayerEntry, Scenario};
use crate::geometry::Side;
use crate::geometry::TeamFrame;
use crate::geometry::coords::{
    FORMATION_X_SCALE, FORMATION_Y_SCALE, OBS_X_SCALE, OBS_Y_SCALE, ball_start_to_world, formation_to_world,
};
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

impl Body {
    /// The same body with the teams' lists exchanged (the odd-episode swap).
    pub fn swapped(self) -> Body {
        match self {
            Body::Ball => Body::Ball,
            Body::Left(i) => Body::Right(i),
            Body::Right(i) => Body::Left(i),
        }
    }
}

/// Where a relative spot stands: `offset` metres from where `of` was drawn in the same placement,
/// in `of`'s frame (a player's team frame, x towards the goal he attacks; the global frame for the
/// ball), then a point drawn uniformly within `radius` metres of that. A point outside the lines
/// is moved onto them. `.tl`: `at left.CF`, `at left.CF + (-5 m, 0)`, `at behind(left.CF, 5 m)`,
/// `at near(left.CF, 3 m)`.
///
/// JSON: `{"of": <Body>, "offset": [dx, dy], "radius": r}` (`radius` may be left out: 0).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Anchor {
    /// The body measured from: its team's list as written (with the odd-episode team swap the
    /// list moves to the other side, and the anchor with it).
    pub of: Body,
    /// Metres from it, in its frame.
    pub offset: [f32; 2],
    /// Radius in metres of the disc a point is drawn in (0: exactly at the offset).
    #[serde(default)]
    pub radius: f32,
}

impl Anchor {
    /// Checks parameters: a finite offset, a finite radius ≥ 0.
    pub(crate) fn check(&self) -> Result<(), String> {
        if !self.offset.iter().all(|v| v.is_finite()) {
            return Err("a relative spot needs a finite offset".into());
        }
        if !(self.radius.is_finite() && self.radius >= 0.0) {
            return Err(format!("a relative spot's radius {} must be finite and >= 0", self.radius));
        }
        Ok(())
    }
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

    /// Writes the normalised position of `body` from a point `world` in metres (moved onto the
    /// pitch's lines when outside them).
    fn set_world(&mut self, body: Body, world: Vec2) {
        let clamp = |[x, y]: [f32; 2]| {
            [x.clamp(-PITCH_HALF_LENGTH, PITCH_HALF_LENGTH), y.clamp(-PITCH_HALF_WIDTH, PITCH_HALF_WIDTH)]
        };
        let own = |side: Side| {
            let v = TeamFrame::of(side).vec2(world);
            clamp([v.x / FORMATION_X_SCALE, v.y / FORMATION_Y_SCALE])
        };
        match body {
            Body::Ball => self.ball = clamp([world.x / OBS_X_SCALE, world.y / OBS_Y_SCALE]),
            Body::Left(i) => {
                if let Some(e) = self.left.get_mut(i) {
                    [e.x, e.y] = own(Side::Left);
                }
            }
            Body::Right(i) => {
                if let Some(e) = self.right.get_mut(i) {
                    [e.x, e.y] = own(Side::Right);
                }
            }
        }
    }

    /// Places `body` from `anchor` (whose body is placed already): the offset turned into the
    /// world frame from the anchor's, and a uniform draw in the disc of its radius.
    fn place_relative(&mut self, body: Body, anchor: &Anchor, swapped: bool, rng: &mut MatchRng) {
        let of = if swapped { anchor.of.swapped() } else { anchor.of };
        let offset = Vec2::from(anchor.offset);
        let offset = match of {
            Body::Ball => offset,
            Body::Left(_) => TeamFrame::of(Side::Left).vec2(offset),
            Body::Right(_) => TeamFrame::of(Side::Right).vec2(offset),
        };
        let mut at = self.world(of) + offset;
        if anchor.radius > 0.0 {
            // Uniform in the disc: the radius grows as the square root of a uniform draw.
            let r = anchor.radius * libm::sqrtf(rng.unit());
            let angle = std::f32::consts::TAU * rng.unit();
            at += Vec2::new(r * libm::cosf(angle), r * libm::sinf(angle));
        }
        self.set_world(body, at);
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
        self.ball_random.is_some()
            || self.odd_episode_ball_random.is_some()
            || self.left_team.iter().chain(&self.right_team).any(|e| e.random.is_some())
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
        let (ball, ball_spot) = self.ball_start(odd);
        let mut placement = Placement { left: left.to_vec(), right: right.to_vec(), ball, tries: 0, satisfied: false };
        if !self.is_randomised() {
            placement.tries = 1;
            placement.satisfied = self.requires.iter().all(|r| placement.meets(r));
            return placement;
        }
        let mut rng = MatchRng::new(seed ^ PLACEMENT_STREAM, episode, true);
        let swapped = odd && self.swap_teams_on_odd_episodes;
        while placement.tries < MAX_PLACEMENT_TRIES {
            placement.tries += 1;
            fill(&mut placement, left, right, ball_spot, swapped, &mut rng);
            if self.requires.iter().all(|r| placement.meets(r)) {
                placement.satisfied = true;
                break;
            }
        }
        placement
    }

    /// The ball's nominal start and the spot it is drawn from in an odd (`odd`) or even episode:
    /// in odd episodes the odd-episode ball when the scenario has one (a fixed point is drawn from
    /// nothing).
    fn ball_start(&self, odd: bool) -> ([f32; 2], Option<&Spot>) {
        if odd && (self.odd_episode_ball_position.is_some() || self.odd_episode_ball_random.is_some()) {
            (self.odd_episode_ball_position.unwrap_or(self.ball_position), self.odd_episode_ball_random.as_ref())
        } else {
            (self.ball_position, self.ball_random.as_ref())
        }
    }

    /// Sets the nominal point of every relative spot (an entry's `x`, `y`; `ball_position`): its
    /// anchor's nominal point moved by the offset (the centre of its disc), in dependency order.
    /// What a reader sees without drawing, and what a scenario without randomness starts from.
    pub fn settle_relative(&mut self) {
        let mut p = Placement {
            left: self.left_team.clone(),
            right: self.right_team.clone(),
            ball: self.ball_position,
            tries: 0,
            satisfied: false,
        };
        let centres: Vec<(Body, Anchor)> = self
            .left_team
            .iter()
            .enumerate()
            .map(|(i, e)| (Body::Left(i), e.random.as_ref()))
            .chain(self.right_team.iter().enumerate().map(|(i, e)| (Body::Right(i), e.random.as_ref())))
            .chain([(Body::Ball, self.ball_random.as_ref())])
            .filter_map(|(body, spot)| match spot {
                Some(Spot::Relative(a)) => Some((body, Anchor { radius: 0.0, ..a.clone() })),
                _ => None,
            })
            .collect();
        let pending = centres.iter().map(|(b, a)| (*b, a)).collect();
        place_pending(&mut p, pending, false, &mut MatchRng::new(0, 0, true));
        for (entry, placed) in self.left_team.iter_mut().zip(&p.left).chain(self.right_team.iter_mut().zip(&p.right)) {
            [entry.x, entry.y] = [placed.x, placed.y];
        }
        self.ball_position = p.ball;
        // The odd-episode ball: from the settled players (or the ball's nominal start).
        if let Some(Spot::Relative(a)) = &self.odd_episode_ball_random {
            let centre = Anchor { radius: 0.0, ..a.clone() };
            p.ball = self.odd_episode_ball_position.unwrap_or(self.ball_position);
            place_pending(&mut p, vec![(Body::Ball, &centre)], false, &mut MatchRng::new(0, 0, true));
            self.odd_episode_ball_position = Some(p.ball);
        }
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
            fill(&mut p, left, right, self.ball_random.as_ref(), false, &mut rng);
            accepted += u32::from(self.requires.iter().all(|r| p.meets(r)));
        }
        accepted as f32 / samples as f32
    }
}

/// Draws every random spot into `p` (`left` and `right`: the lists as they play this episode):
/// plain spots in list order, then the ball's (`ball`), then relative spots, each once the body it
/// names is placed. The rng is used in that fixed order, so a seed fixes the placement. A cycle
/// of relative spots (which the compiler and `Scenario::validate` refuse) keeps its nominal points.
fn fill(
    p: &mut Placement,
    left: &[PlayerEntry],
    right: &[PlayerEntry],
    ball: Option<&Spot>,
    swapped: bool,
    rng: &mut MatchRng,
) {
    let mut pending: Vec<(Body, &Anchor)> = Vec::new();
    // Shared draws (a `param` holding a distribution) are drawn afresh for every placement.
    let mut shared = SharedDraws::new();
    let teams = [(left, &mut p.left, Body::Left as fn(usize) -> Body), (right, &mut p.right, Body::Right)];
    for (entries, slots, body) in teams {
        for (i, (entry, slot)) in entries.iter().zip(slots.iter_mut()).enumerate() {
            match &entry.random {
                Some(Spot::Relative(anchor)) => pending.push((body(i), anchor)),
                Some(spot) => [slot.x, slot.y] = spot.draw(rng, &mut shared),
                None => {}
            }
        }
    }
    match ball {
        Some(Spot::Relative(anchor)) => pending.push((Body::Ball, anchor)),
        Some(spot) => p.ball = spot.draw(rng, &mut shared),
        None => {}
    }
    place_pending(p, pending, swapped, rng);
}

/// Places each of `pending` once the body its anchor names is placed (not itself pending).
fn place_pending(p: &mut Placement, mut pending: Vec<(Body, &Anchor)>, swapped: bool, rng: &mut MatchRng) {
    while !pending.is_empty() {
        let of = |anchor: &Anchor| if swapped { anchor.of.swapped() } else { anchor.of };
        let Some(k) = pending.iter().position(|(_, a)| !pending.iter().any(|(b, _)| *b == of(a))) else { break };
        let (body, anchor) = pending.remove(k);
        p.place_relative(body, anchor, swapped, rng);
    }
}

/// The relative spots of a scenario that depend on each other in a circle, as the bodies placed
/// (`a` at `b`, `b` at `a`), or `None`. Anchors naming a body that does not exist count as placed.
pub fn relative_cycle(left: &[PlayerEntry], right: &[PlayerEntry], ball: Option<&Spot>) -> Option<Vec<Body>> {
    let anchor_of = |body: Body| -> Option<Body> {
        let spot = match body {
            Body::Ball => ball,
            Body::Left(i) => left.get(i).and_then(|e| e.random.as_ref()),
            Body::Right(i) => right.get(i).and_then(|e| e.random.as_ref()),
        };
        match spot {
            Some(Spot::Relative(a)) => Some(a.of),
            _ => None,
        }
    };
    let bodies = (0..left.len()).map(Body::Left).chain((0..right.len()).map(Body::Right)).chain([Body::Ball]);
    for start in bodies {
        let mut path = vec![start];
        let mut at = start;
        while let Some(next) = anchor_of(at) {
            if next == start {
                return Some(path);
            }
            if path.contains(&next) || path.len() > left.len() + right.len() + 1 {
                break;
            }
            path.push(next);
            at = next;
        }
    }
    None
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

    /// A defender 5 m behind a randomly placed forward (towards the forward's own goal), and the
    /// ball within 1 m of the defender: drawn after what they name, every episode, both ways round
    /// when the teams swap sides.
    #[test]
    fn relative_spots_follow_their_anchor() {
        let mut s = randomised();
        s.requires.clear();
        let mut cb = PlayerEntry::new(Role::CB, 0.0, 0.0);
        cb.random = Some(Spot::Relative(Anchor { of: Body::Left(1), offset: [-5.0, 0.0], radius: 0.0 }));
        s.right_team.push(cb);
        s.ball_random = Some(Spot::Relative(Anchor { of: Body::Right(1), offset: [0.0, 0.0], radius: 1.0 }));
        s.swap_teams_on_odd_episodes = true;
        for episode in 0..200 {
            let p = s.draw(3, episode);
            let (forward, defender) = if episode % 2 == 0 {
                (p.world(Body::Left(1)), p.world(Body::Right(1)))
            } else {
                (p.world(Body::Right(1)), p.world(Body::Left(1)))
            };
            // Behind the forward: towards the goal he defends (-x for the left team, +x for the right).
            let behind = if episode % 2 == 0 { -5.0 } else { 5.0 };
            assert!((defender - forward - Vec2::new(behind, 0.0)).length() < 1e-3, "episode {episode}");
            let ball = p.world(Body::Ball);
            assert!(ball.distance(defender) <= 1.0 + 1e-3, "episode {episode}: ball {ball} defender {defender}");
        }
        assert!(relative_cycle(&s.left_team, &s.right_team, s.ball_random.as_ref()).is_none());
        s.left_team[1].random = Some(Spot::Relative(Anchor { of: Body::Right(1), offset: [1.0, 0.0], radius: 0.0 }));
        assert_eq!(relative_cycle(&s.left_team, &s.right_team, None), Some(vec![Body::Left(1), Body::Right(1)]));
        assert!(s.validate().is_err());
    }

    /// The odd-episode ball drawn relative to a player: at his feet in odd episodes (moving with
    /// his list when the teams swap), the even ball untouched; a ball placed from itself in odd
    /// episodes is a circle; a scenario without it serialises as before.
    #[test]
    fn odd_episode_ball_follows_its_anchor() {
        let mut s = randomised();
        s.requires.clear();
        assert!(!serde_json::to_string(&s).unwrap().contains("odd_episode_ball_random"));
        s.odd_episode_ball_random = Some(Spot::Relative(Anchor { of: Body::Left(1), offset: [1.0, 0.0], radius: 0.0 }));
        s.settle_relative();
        let [x, y] = s.odd_episode_ball_position.unwrap();
        assert!((ball_start_to_world(x, y) - formation_to_world(Side::Left, 0.5, 0.0) - Vec2::X).length() < 1e-3);
        assert!(s.validate().is_ok());
        for swap in [false, true] {
            s.swap_teams_on_odd_episodes = swap;
            for episode in 0..40 {
                let p = s.draw(7, episode);
                let ball = p.world(Body::Ball);
                if episode % 2 == 0 {
                    assert_eq!(p.ball, [0.5, 0.0], "episode {episode}");
                    continue;
                }
                let (cb, ahead) = if swap { (p.world(Body::Right(1)), -1.0) } else { (p.world(Body::Left(1)), 1.0) };
                assert!((ball - cb - Vec2::new(ahead, 0.0)).length() < 1e-3, "episode {episode}: {ball} {cb}");
            }
        }
        s.odd_episode_ball_random = Some(Spot::Relative(Anchor { of: Body::Ball, offset: [1.0, 0.0], radius: 0.0 }));
        assert!(s.validate().unwrap_err().to_string().contains("odd episodes"));
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
