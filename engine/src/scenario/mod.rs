//! The engine's only input: a [`Scenario`], plain serde data.
//!
//! Every field of GRF's `ScenarioConfig` is here with GRF's default (docs/grf-compatibility.md#scenario-config,
//! #scenario-semantics). Positions use GRF's normalised pitch coordinates: x in [-1, 1] from the left goal to the
//! right goal, y in [-0.42, 0.42] (positive y towards the bottom of the screen). Players are given in
//! their **own team's frame** (own goal at x = -1, attacking towards +1); the ball in the global frame.
//! The scenario language compiles `.tl` text into this value; a compiled scenario is this value
//! serialised to JSON.

mod behaviour;
mod condition;
mod curriculum;
mod event_reward;
mod placement;
mod random;
mod start;
mod terms;

use serde::{Deserialize, Serialize};

pub use behaviour::{Behaviour, PassKind, Stage};
pub use condition::{Comparison, Condition, Owner, Target};
pub use curriculum::{Criterion, Curriculum, EpisodeResult, Lesson, Metric, Threshold};
pub use event_reward::{EventAtom, EventKind, EventReward, EventStep, EventTeam, MAX_EVENT_GROUP, MAX_EVENT_SEQUENCE};
pub use placement::{Anchor, Body, MAX_PLACEMENT_TRIES, Placement, Require, relative_cycle};
pub use random::{Distribution, PITCH_HALF_LENGTH, PITCH_HALF_WIDTH, Region, Sample, Shared, Spot};
pub use start::{Facing, StartRestart};
pub use terms::{EndCondition, RewardKind, RewardTerm};

pub use crate::player::MAX_PLAYERS_PER_TEAM;

use crate::error::EngineError;
use crate::player::Role;

/// Version of the compiled-scenario format this engine writes and reads. A scenario with a newer
/// version is refused (its fields may mean something this engine does not know).
pub const SCENARIO_FORMAT_VERSION: u32 = 1;

/// A playable situation: configuration keys, ball start and both teams' players.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Scenario {
    /// Compiled-format version ([`SCENARIO_FORMAT_VERSION`]; default 1).
    pub format_version: u32,
    /// Scenario name, e.g. `academy_empty_goal_close`.
    pub name: String,
    /// Human-readable description (the `.tl` file's doc comment).
    pub description: String,
    /// Episode length in env steps (GRF `game_duration`, default 3000 = 90 minutes). The episode
    /// is truncated after `game_duration + 1` steps (docs/grf-compatibility.md#episode-length).
    pub game_duration: u32,
    /// Fixed seed (42) and no noise: identical actions give identical outcomes (default false).
    pub deterministic: bool,
    /// The seed of a deterministic scenario's match (GRF `game_engine_random_seed`, default 42);
    /// stochastic scenarios take the env's seed instead.
    #[serde(skip_serializing_if = "is_default_seed")]
    pub game_engine_random_seed: u64,
    /// Whether the offside law is applied (default true).
    pub offsides: bool,
    /// End the episode when either team scores (default false).
    pub end_episode_on_score: bool,
    /// End the episode when the ball goes out of play: game mode turns from Normal to a set piece
    /// (default false).
    pub end_episode_on_out_of_play: bool,
    /// End the episode when possession passes to the other team (default false).
    pub end_episode_on_possession_change: bool,
    /// Left team difficulty θ in [0, 1] (default 1.0).
    pub left_team_difficulty: f32,
    /// Right team difficulty θ in [0, 1] (default 0.6).
    pub right_team_difficulty: f32,
    /// Step index of the second-half kickoff (default 999 999 999: never).
    pub second_half: u32,
    /// Agents control every controllable player of a side they play (default false).
    pub control_all_players: bool,
    /// Ball start `[x, y]` in the global frame, normalised units (default `[0, 0]`); the nominal
    /// start when `ball_random` is set.
    pub ball_position: [f32; 2],
    /// When set, the ball's start is drawn from this at every reset (global frame).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ball_random: Option<Spot>,
    /// When set, the ball starts here in odd episodes (the 2nd, 4th, … reset), as GRF's test
    /// scenarios that branch on the episode number (docs/grf-compatibility.md#scenario-settings).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub odd_episode_ball_position: Option<[f32; 2]>,
    /// When set, the ball's start in odd episodes is drawn from this at every reset (global frame)
    /// instead of `ball_random`, with `odd_episode_ball_position` its nominal point (`.tl`:
    /// `on odd episodes ball at near(left.CF, 3 m)`). A relative spot's anchor names the lists as
    /// written, as every relative spot's does.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub odd_episode_ball_random: Option<Spot>,
    /// Left team's players, in observation order, in the left team's own frame.
    pub left_team: Vec<PlayerEntry>,
    /// Right team's players, in observation order, in the right team's own frame.
    pub right_team: Vec<PlayerEntry>,
    /// GRF's per-episode formation swap: when true, the two player lists change sides on every
    /// odd episode (the 2nd, 4th, … reset), so the kickoff formation alternates
    /// (docs/grf-compatibility.md#scenario-semantics).
    pub swap_teams_on_odd_episodes: bool,
    /// Constraints every drawn placement meets (bounded rejection sampling, see [`Scenario::draw`]).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub requires: Vec<Require>,
    /// Reward terms; empty means "as the env is configured" (GRF's scoring, plus checkpoints
    /// when the env asks for them).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub rewards: Vec<RewardTerm>,
    /// Episode-end conditions beyond the three `end_episode_on_*` flags.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub end_when: Vec<EndCondition>,
    /// A saved match (the bytes of a [`crate::Snapshot`], hex in JSON) every episode starts from
    /// instead of the placement: players, ball and game mode as saved, the score at 0–0. The
    /// saved match must have as many players a side as the teams here (`.tl`: `start from "file"`).
    #[serde(default, skip_serializing_if = "Option::is_none", with = "start_state_hex")]
    pub start_state: Option<Vec<u8>>,
    /// A restart every episode starts from, set up by the referee's own code once the players
    /// are placed (`.tl`: `start with corner_kick for left at top`); the ball starts on the
    /// restart's spot, whatever `ball_position` says. Not with `start_state`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_with: Option<StartRestart>,
    /// Lessons an env plays in order instead of this scenario, moving on when a lesson's
    /// criterion holds (`.tl`: `curriculum { … }`). The fields above are then the base the
    /// lessons were compiled from; an env plays `lessons[0]` first.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub curriculum: Option<Box<Curriculum>>,
}

/// `start_state` as a hex string in JSON.
mod start_state_hex {
    use serde::{Deserialize, Deserializer, Serializer};

    pub(super) fn serialize<S: Serializer>(bytes: &Option<Vec<u8>>, s: S) -> Result<S::Ok, S::Error> {
        match bytes {
            Some(b) => s.serialize_str(&hex::encode(b)),
            None => s.serialize_none(),
        }
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Vec<u8>>, D::Error> {
        let text: Option<String> = Option::deserialize(d)?;
        text.map(|t| hex::decode(t).map_err(serde::de::Error::custom)).transpose()
    }
}

/// One player of a team: role, position in the team's own frame, and flags.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlayerEntry {
    /// The player's role; exactly one GK per team.
    pub role: Role,
    /// x in the team's own frame, normalised units (own goal at -1).
    pub x: f32,
    /// y in the team's own frame, normalised units.
    pub y: f32,
    /// When set, the position is drawn from this at every reset (team's own frame) and `x`, `y`
    /// are only its nominal value (the distribution's centre).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub random: Option<Spot>,
    /// A lazy player only stands and reacts physically (docs/grf-compatibility.md#scenario-semantics).
    #[serde(default)]
    pub lazy: bool,
    /// Whether an agent may ever control this player (default true).
    #[serde(default = "yes")]
    pub controllable: bool,
    /// What the player does instead of following the built-in AI while no agent controls him:
    /// stages played in order (empty: the built-in AI). `.tl`: `CB at (…) does press`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub behaviour: Vec<Stage>,
    /// Which way he faces at the start (default: the goal he attacks). `.tl`: `facing ball`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub facing: Option<Facing>,
}

fn yes() -> bool {
    true
}

/// GRF's default `game_engine_random_seed`.
const DEFAULT_SEED: u64 = 42;

fn is_default_seed(seed: &u64) -> bool {
    *seed == DEFAULT_SEED
}

impl PlayerEntry {
    /// A non-lazy, controllable player.
    pub fn new(role: Role, x: f32, y: f32) -> PlayerEntry {
        PlayerEntry { role, x, y, random: None, lazy: false, controllable: true, behaviour: Vec::new(), facing: None }
    }
}

impl Default for Scenario {
    fn default() -> Scenario {
        Scenario {
            format_version: SCENARIO_FORMAT_VERSION,
            name: String::new(),
            description: String::new(),
            game_duration: 3000,
            deterministic: false,
            game_engine_random_seed: DEFAULT_SEED,
            offsides: true,
            end_episode_on_score: false,
            end_episode_on_out_of_play: false,
            end_episode_on_possession_change: false,
            left_team_difficulty: 1.0,
            right_team_difficulty: 0.6,
            second_half: 999_999_999,
            control_all_players: false,
            ball_position: [0.0, 0.0],
            left_team: Vec::new(),
            right_team: Vec::new(),
            swap_teams_on_odd_episodes: false,
            ball_random: None,
            odd_episode_ball_position: None,
            odd_episode_ball_random: None,
            requires: Vec::new(),
            rewards: Vec::new(),
            end_when: Vec::new(),
            start_state: None,
            start_with: None,
            curriculum: None,
        }
    }
}

/// 0 for the left team, 1 for the right.
fn side_index(side: &str) -> usize {
    usize::from(side == "right")
}

/// Whether `(x, y)` is finite and inside the rim.
fn on_pitch(x: f32, y: f32) -> bool {
    let [rim_x, rim_y] = crate::geometry::coords::SCENARIO_RIM;
    x.is_finite() && y.is_finite() && x.abs() <= rim_x && y.abs() <= rim_y
}

/// A spot's parameters are sound and every draw lands inside the rim.
fn check_spot(spot: &Spot, what: &str) -> Result<(), String> {
    spot.check().map_err(|e| format!("{what}: {e}"))?;
    let [[x0, x1], [y0, y1]] = spot.bounds();
    if !(on_pitch(x0, y0) && on_pitch(x1, y1)) {
        return Err(format!("{what}: draws reach ({x0}..{x1}, {y0}..{y1}), off the pitch"));
    }
    Ok(())
}

impl Scenario {
    /// Checks what the engine relies on: 1–11 players a side with exactly one goalkeeper,
    /// finite positions inside the pitch's rim, difficulties in [0, 1], a positive duration.
    ///
    /// # Errors
    /// [`EngineError::InvalidScenario`] naming the first problem found.
    pub fn validate(&self) -> Result<(), EngineError> {
        let bad = |reason: String| Err(EngineError::InvalidScenario { reason });
        if self.game_duration == 0 {
            return bad("game_duration must be at least 1 step".into());
        }
        for (side, d) in [("left", self.left_team_difficulty), ("right", self.right_team_difficulty)] {
            if !(0.0..=1.0).contains(&d) {
                return bad(format!("{side}_team_difficulty {d} is outside [0, 1]"));
            }
        }
        if self.format_version > SCENARIO_FORMAT_VERSION {
            return bad(format!(
                "format_version {} is newer than this touchline reads ({SCENARIO_FORMAT_VERSION})",
                self.format_version
            ));
        }
        for [bx, by] in std::iter::once(self.ball_position).chain(self.odd_episode_ball_position) {
            if !on_pitch(bx, by) {
                return bad(format!("ball position ({bx}, {by}) is off the pitch"));
            }
        }
        if let Some(spot) = &self.ball_random {
            check_spot(spot, "the ball's random start").map_err(|reason| EngineError::InvalidScenario { reason })?;
        }
        if let Some(spot) = &self.odd_episode_ball_random {
            check_spot(spot, "the ball's random start in odd episodes")
                .map_err(|reason| EngineError::InvalidScenario { reason })?;
        }
        for (side, team) in [("left", &self.left_team), ("right", &self.right_team)] {
            if team.is_empty() || team.len() > MAX_PLAYERS_PER_TEAM {
                return bad(format!("{side} team has {} players; 1 to 11 are allowed", team.len()));
            }
            let keepers = team.iter().filter(|p| p.role == Role::GK).count();
            if keepers != 1 {
                return bad(format!("{side} team has {keepers} goalkeepers; exactly one is required"));
            }
            for (i, p) in team.iter().enumerate() {
                for (k, stage) in p.behaviour.iter().enumerate() {
                    stage.check(side_index(side), i, team.len(), self.condition_context(true)).map_err(|e| {
                        EngineError::InvalidScenario { reason: format!("{side} player {i}, behaviour stage {k}: {e}") }
                    })?;
                }
                if !on_pitch(p.x, p.y) {
                    return bad(format!("{side} player {i} ({}) at ({}, {}) is off the pitch", p.role, p.x, p.y));
                }
                if let Some(facing) = &p.facing {
                    facing
                        .check()
                        .map_err(|e| EngineError::InvalidScenario { reason: format!("{side} player {i}: {e}") })?;
                }
                if let Some(spot) = &p.random {
                    check_spot(spot, &format!("{side} player {i} ({})", p.role))
                        .map_err(|reason| EngineError::InvalidScenario { reason })?;
                }
            }
        }
        let spots = self.left_team.iter().chain(&self.right_team).filter_map(|p| p.random.as_ref());
        for spot in spots.chain(self.ball_random.as_ref()).chain(self.odd_episode_ball_random.as_ref()) {
            if let Spot::Relative(anchor) = spot {
                let exists = match anchor.of {
                    Body::Ball => true,
                    Body::Left(i) => i < self.left_team.len(),
                    Body::Right(i) => i < self.right_team.len(),
                };
                if !exists {
                    return bad(format!("a relative spot names {:?}, which does not exist", anchor.of));
                }
            }
        }
        if let Some(cycle) = relative_cycle(&self.left_team, &self.right_team, self.ball_random.as_ref()) {
            return bad(format!("relative spots place each other in a circle: {cycle:?}"));
        }
        // In odd episodes the odd ball's spot stands for the ball's.
        if let Some(odd) = &self.odd_episode_ball_random
            && let Some(cycle) = relative_cycle(&self.left_team, &self.right_team, Some(odd))
        {
            return bad(format!("relative spots place each other in a circle in odd episodes: {cycle:?}"));
        }
        for r in &self.requires {
            let (Require::MinDistance { a, b, metres } | Require::MaxDistance { a, b, metres }) = r;
            for body in [a, b] {
                let (i, team, side) = match *body {
                    Body::Ball => continue,
                    Body::Left(i) => (i, &self.left_team, "left"),
                    Body::Right(i) => (i, &self.right_team, "right"),
                };
                // With the odd-episode swap either list stands on either side.
                let n = if self.swap_teams_on_odd_episodes {
                    self.left_team.len().min(self.right_team.len())
                } else {
                    team.len()
                };
                if i >= n {
                    return bad(format!("require names {side} player {i}, which does not exist"));
                }
            }
            if !(metres.is_finite() && *metres >= 0.0) {
                return bad(format!("require distance {metres} m must be finite and >= 0"));
            }
        }
        for t in &self.rewards {
            t.check().map_err(|reason| EngineError::InvalidScenario { reason })?;
        }
        for c in &self.end_when {
            match c {
                EndCondition::BallIn(region) => {
                    region.check().map_err(|reason| EngineError::InvalidScenario { reason })?;
                }
                EndCondition::When(c) => c
                    .check(self.condition_context(false))
                    .map_err(|e| EngineError::InvalidScenario { reason: format!("end when: {e}") })?,
                _ => {}
            }
        }
        if let Some(start) = &self.start_with {
            start.check().map_err(|e| EngineError::InvalidScenario { reason: format!("start with: {e}") })?;
            if self.start_state.is_some() {
                return bad("a scenario starts either from a saved state or with a restart, not both".into());
            }
        }
        if let Some(c) = &self.curriculum {
            c.check().map_err(|reason| EngineError::InvalidScenario { reason })?;
        }
        Ok(())
    }

    /// What conditions may name: players every episode fields (with the odd-episode swap,
    /// the smaller list on both sides).
    fn condition_context(&self, in_behaviour: bool) -> condition::CheckContext {
        let n = [self.left_team.len(), self.right_team.len()];
        let players = if self.swap_teams_on_odd_episodes { [n[0].min(n[1]); 2] } else { n };
        condition::CheckContext { in_behaviour, players }
    }

    /// The paths of the scripts players' behaviours name, in player order.
    pub fn script_behaviours(&self) -> impl Iterator<Item = &str> + '_ {
        self.left_team.iter().chain(&self.right_team).flat_map(|p| &p.behaviour).filter_map(|s| match &s.behaviour {
            Behaviour::Script { path } => Some(path.as_str()),
            _ => None,
        })
    }

    /// Number of controllable players on each side `[left, right]` (GRF's
    /// `controllable_left_players` / `controllable_right_players`).
    pub fn controllable_players(&self) -> [usize; 2] {
        [
            self.left_team.iter().filter(|p| p.controllable).count(),
            self.right_team.iter().filter(|p| p.controllable).count(),
        ]
    }

    /// Controllable players each side has in *every* episode `[left, right]`: with the
    /// odd-episode swap either list plays either side, so both sides get the smaller count. The
    /// number of agents a side may have.
    pub fn controllable_every_episode(&self) -> [usize; 2] {
        let n = self.controllable_players();
        if self.swap_teams_on_odd_episodes { [n[0].min(n[1]); 2] } else { n }
    }

    /// The (left, right) player lists for a 0-based episode index, applying the odd-episode swap.
    pub fn teams_for_episode(&self, episode: u64) -> (&[PlayerEntry], &[PlayerEntry]) {
        if self.swap_teams_on_odd_episodes && episode % 2 == 1 {
            (&self.right_team, &self.left_team)
        } else {
            (&self.left_team, &self.right_team)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn minimal() -> Scenario {
        Scenario {
            left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0)],
            ..Scenario::default()
        }
    }

    #[test]
    fn defaults_are_grf_defaults() {
        let s = Scenario::default();
        assert_eq!(s.game_duration, 3000);
        assert!(s.offsides && !s.deterministic);
        assert_eq!((s.left_team_difficulty, s.right_team_difficulty), (1.0, 0.6));
        assert_eq!(s.second_half, 999_999_999);
    }

    #[test]
    fn json_round_trip_and_defaults_fill_in() {
        let s = minimal();
        let text = serde_json::to_string(&s).unwrap();
        let back: Scenario = serde_json::from_str(&text).unwrap();
        assert_eq!(s, back);
        let sparse: Scenario = serde_json::from_str(
            r#"{"left_team":[{"role":"GK","x":-1,"y":0}],"right_team":[{"role":"GK","x":-1,"y":0}]}"#,
        )
        .unwrap();
        assert_eq!(sparse, s);
        assert!(sparse.left_team[0].controllable);
    }

    #[test]
    fn validation_names_the_problem() {
        let mut s = minimal();
        assert!(s.validate().is_ok());
        s.left_team.push(PlayerEntry::new(Role::GK, 0.0, 0.0));
        assert!(s.validate().unwrap_err().to_string().contains("2 goalkeepers"));
        let mut s = minimal();
        s.right_team[0].x = f32::NAN;
        assert!(s.validate().unwrap_err().to_string().contains("off the pitch"));
        let mut s = minimal();
        s.left_team_difficulty = 1.5;
        assert!(s.validate().is_err());
    }
}
