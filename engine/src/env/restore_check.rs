//! Range checks on a decoded snapshot, before an env takes it.
//!
//! The checksum only catches accidents: bytes edited with a consistent checksum decode into any
//! values the types allow. Stepping then indexes players, controllers and sequence steps with the
//! saved numbers, and encodes the saved positions into observations; so a restore first checks that
//! every position and speed is finite and inside a bound no match reaches, and that every index
//! points where it should. A state that fails is refused with the first problem found.
//! The built-in AI checks its own per-player state ([`crate::ai::TeamAi`]'s plans and marks).

use super::{Env, EnvState};
use crate::game::{DIRECTIONS, Match};
use crate::geometry::Side;
use crate::reward::EventRewards;
use crate::scenario::Scenario;

/// Bound on any saved coordinate or speed (m, m/s): far beyond anything a match reaches (the
/// pitch is 105 m long, shots stay under 40 m/s), close enough that arithmetic on it stays finite.
const MAX_COORDINATE: f32 = 10_000.0;

fn finite(what: &str, values: &[f32]) -> Result<(), String> {
    match values.iter().find(|v| !(v.is_finite() && v.abs() <= MAX_COORDINATE)) {
        Some(v) => Err(format!("{what} is {v}, not a finite number within ±{MAX_COORDINATE}")),
        None => Ok(()),
    }
}

fn index(what: &str, i: Option<usize>, len: usize) -> Result<(), String> {
    match i {
        Some(i) if i >= len => Err(format!("{what} is player {i} of {len}")),
        _ => Ok(()),
    }
}

fn length(what: &str, found: usize, expected: usize) -> Result<(), String> {
    if found == expected { Ok(()) } else { Err(format!("{what} has {found} entries, expected {expected}")) }
}

/// Checks a saved match whose teams have `sizes` players `[left, right]`.
pub(super) fn check_match(game: &Match, sizes: [usize; 2]) -> Result<(), String> {
    let n = sizes[0] + sizes[1];
    length("the player list", game.players.len(), n)?;
    if game.ranges != [0..sizes[0], sizes[0]..n] {
        return Err(format!("the team ranges {:?} do not split {n} players {}+{}", game.ranges, sizes[0], sizes[1]));
    }
    for (s, side) in Side::BOTH.into_iter().enumerate() {
        for (i, p) in game.players[game.ranges[s].clone()].iter().enumerate() {
            if p.side != side || p.index != i {
                return Err(format!(
                    "player {i} of the {} team is saved as player {} of the {}",
                    side.name(),
                    p.index,
                    p.side.name()
                ));
            }
            let (a, b, c, h) = (p.position, p.velocity, p.facing, p.home);
            finite(
                &format!("{} player {i}'s position or speed", side.name()),
                &[a.x, a.y, b.x, b.y, c.x, c.y, h.x, h.y],
            )?;
            finite(&format!("{} player {i}'s fitness", side.name()), &[p.fatigue, p.max_speed, p.fresh_speed])?;
        }
        for [x, y] in &game.formations[s] {
            finite("a formation place", &[*x, *y])?;
        }
    }
    finite("a team's difficulty", &game.difficulty)?;
    if !game.difficulty.iter().all(|d| (0.0..=1.0).contains(d)) {
        return Err(format!("the difficulties {:?} are not in [0, 1]", game.difficulty));
    }
    let ball = &game.ball;
    finite("the ball's position", &ball.position.to_array())?;
    finite("the ball's velocity or spin", &[ball.velocity.to_array(), ball.spin.to_array()].concat())?;
    finite("the ball's start", &game.ball_start.to_array())?;
    finite("the ball's carry distance", &[game.carry_distance])?;
    index("the ball's owner", game.owner, n)?;
    index("the last player to touch the ball", game.last_touch, n)?;
    index("the last player in possession", game.possessor, n)?;
    index("the set piece's taker", game.taker, n)?;
    index("the passer", game.pending_pass, n)?;
    index("the foul's offender", game.pending_foul.as_ref().map(|f| f.offender), n)?;
    if let Some(f) = &game.pending_foul {
        finite("the foul's spot", &f.spot.to_array())?;
    }
    for (s, ai) in game.ai.iter().enumerate() {
        ai.check(sizes[s], n)?;
    }
    length("the player inputs", game.inputs.len(), n)?;
    length("the agent flags", game.agent_driven.len(), n)?;
    if !game.behaviours.is_empty() {
        length("the behaviours", game.behaviours.len(), n)?;
        length("the behaviour flags", game.native.len(), n)?;
    }
    for (i, b) in game.behaviours.iter().enumerate() {
        if b.stage > b.stages.len() {
            return Err(format!("player {i}'s behaviour is at stage {} of {}", b.stage, b.stages.len()));
        }
        finite("a behaviour's anchor", &b.anchor.to_array())?;
        sticky_direction(b.sticky.direction)?;
    }
    Ok(())
}

fn sticky_direction(direction: Option<u8>) -> Result<(), String> {
    match direction {
        Some(d) if usize::from(d) >= DIRECTIONS.len() => {
            Err(format!("a held direction is {d}, one of {} expected", DIRECTIONS.len()))
        }
        _ => Ok(()),
    }
}

impl EnvState {
    /// Checks a decoded state against `env`, the env about to take it (same scenario and
    /// configuration: the fingerprints matched), playing `scenario` (its own, or the lesson the
    /// state was saved in).
    pub(super) fn check_against(&self, env: &Env, scenario: &Scenario) -> Result<(), String> {
        let (left, right) = scenario.teams_for_episode(self.episode);
        check_match(&self.game, [left.len(), right.len()])?;
        let n = env.state.controllers.len();
        length("the controllers", self.controllers.len(), n)?;
        for (i, (saved, own)) in self.controllers.iter().zip(&env.state.controllers).enumerate() {
            if saved.side != own.side {
                return Err(format!("controller {i} is saved on the {} side", saved.side.name()));
            }
            sticky_direction(saved.sticky.direction)?;
        }
        length("the controlled players", self.controlled.len(), n)?;
        for (c, &i) in self.controllers.iter().zip(&self.controlled) {
            let team = if c.side == Side::Left { left.len() } else { right.len() };
            index("a controlled player", Some(i), team)?;
        }
        length("the observations", self.observations.len(), n)?;
        // A step that ends in an error (the episode was over) leaves the saved observations as
        // the ones a caller reads: they must be numbers too.
        for o in &self.observations {
            finite("a saved observation's ball", &[o.ball, o.ball_direction, o.ball_rotation].concat())?;
            for team in [&o.left_team, &o.left_team_direction, &o.right_team, &o.right_team_direction] {
                finite("a saved observation's players", team.as_flattened())?;
            }
            finite(
                "a saved observation's tiredness",
                &[&o.left_team_tired_factor[..], &o.right_team_tired_factor[..]].concat(),
            )?;
        }
        length("the rewards", self.rewards.len(), n)?;
        if let Some(r) = self.rewards.iter().find(|r| !r.is_finite()) {
            return Err(format!("a reward is {r}"));
        }
        length("the checkpoint trackers", self.checkpoints.len(), n)?;
        if let Some(t) = self.checkpoints.iter().find(|t| t.collected() > 10) {
            return Err(format!("{} checkpoints collected, of 10", t.collected()));
        }
        let event_rewards = EventRewards::new(scenario);
        let terms = event_rewards.len();
        length("the event-reward progress", self.events.len(), n * terms)?;
        for (k, p) in self.events.iter().enumerate() {
            let steps = event_rewards.steps(k % terms.max(1));
            if !p.fits(steps) {
                return Err(format!("event reward {} waits for step {} of {steps}", k % terms.max(1), p.step()));
            }
        }
        length("the previous ball positions", self.previous_ball.len(), n)?;
        finite("a previous ball position", self.previous_ball.as_flattened())?;
        let lessons = env.curriculum.as_ref().map_or(1, |c| c.lessons.len());
        self.lessons.check(lessons, env.state.lessons.capacity())?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Env, Snapshot};
    use crate::Action;
    use crate::scenario::Scenario;

    /// FNV-1a, the snapshot checksum: the test reseals what it edits, as someone editing a saved
    /// state by hand would.
    fn reseal(bytes: &mut [u8]) {
        let sum = bytes[24..]
            .iter()
            .fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3));
        bytes[16..24].copy_from_slice(&sum.to_le_bytes());
    }

    fn scenario(name: &str) -> Scenario {
        let text = match name {
            "academy_3_vs_1_with_keeper" => include_str!("../../../stdlib-scenarios/academy_3_vs_1_with_keeper.json"),
            _ => include_str!("../../../stdlib-scenarios/11_vs_11_stochastic.json"),
        };
        serde_json::from_str(text).unwrap()
    }

    /// Issue 17, item 11: bytes edited in the payload and resealed with a consistent checksum
    /// either fail to load or play on: no panic, no NaN in observations or rewards, over steps
    /// and resets, the built-in AI's own state included.
    #[test]
    fn edited_payloads_never_panic_or_give_nan() {
        for name in ["academy_3_vs_1_with_keeper", "11_vs_11_stochastic"] {
            let mut env = Env::new(scenario(name), 3).unwrap();
            // Into play, with the AI's plans and marks set: short of the episode's end.
            for _ in 0..40 {
                let out = env.step(&vec![Action::Right; env.num_controllers()]).unwrap();
                if out.terminated || out.truncated {
                    break;
                }
            }
            let bytes = env.snapshot().to_bytes();
            let mut rng = 0x9e37_79b9_7f4a_7c15u64;
            let mut next = move || {
                rng ^= rng << 13;
                rng ^= rng >> 7;
                rng ^= rng << 17;
                rng
            };
            let (mut loaded, mut refused) = (0, 0);
            for case in 0..600 {
                let mut edited = bytes.clone();
                for _ in 0..1 + next() % 3 {
                    let at = 24 + (next() as usize) % (edited.len() - 24);
                    edited[at] = match next() % 4 {
                        0 => edited[at] ^ (1 << (next() % 8)),
                        1 => 0xff,
                        2 => 0x7f,
                        _ => next() as u8,
                    };
                }
                reseal(&mut edited);
                let outcome = std::panic::catch_unwind(|| {
                    let mut other = Env::new(scenario(name), 7).unwrap();
                    let Ok(snapshot) = Snapshot::from_bytes(&edited) else { return false };
                    if other.restore(&snapshot).is_err() {
                        return false;
                    }
                    for _ in 0..2 {
                        for _ in 0..30 {
                            let out = other.step(&vec![Action::Shot; other.num_controllers()]);
                            assert!(
                                other.observations().iter().all(|o| o.ball.iter().all(|v| v.is_finite())),
                                "NaN ball"
                            );
                            assert!(other.rewards().iter().all(|r| r.is_finite()), "NaN reward");
                            if out.is_err() || out.is_ok_and(|o| o.terminated || o.truncated) {
                                break;
                            }
                        }
                        other.reset().unwrap();
                    }
                    true
                });
                match outcome {
                    Ok(true) => loaded += 1,
                    Ok(false) => refused += 1,
                    Err(_) => panic!("{name}: case {case} panicked"),
                }
            }
            assert!(loaded > 0 && refused > 0, "{name}: {loaded} loaded, {refused} refused");
        }
    }
}
