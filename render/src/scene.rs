//! [`Scene`]: what a frame shows, taken from a match (or from a replay's stored step), so that
//! drawing is a pure function of it.

use serde::{Deserialize, Serialize};
use touchline_engine::{Env, GameMode, Match, Role, Side};

/// Game seconds per env step on the scoreboard clock: GRF's 3000-step match is 90 minutes, so one
/// step shows as 1.8 s (docs/grf-compatibility.md#time-base, #episode-length).
pub const CLOCK_SECONDS_PER_STEP: f32 = 5400.0 / 3000.0;

/// One player as drawn.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScenePlayer {
    /// Team, which picks the shirt colour.
    pub side: Side,
    /// Shirt number: 1 + the player's index in his team (observation order).
    pub number: u8,
    /// Goalkeepers wear their own colour.
    pub goalkeeper: bool,
    /// Position on the ground `[x, y]` (m, engine frame: origin at the centre spot, x towards the
    /// right team's goal, y towards the bottom of the image).
    pub position: [f32; 2],
    /// Driven by an agent: drawn with a yellow ring.
    pub controlled: bool,
    /// Has the ball at his feet: drawn with a white marker above him.
    pub has_ball: bool,
    /// Still on the pitch (players sent off are not drawn).
    pub on_pitch: bool,
}

/// Everything a frame shows: players, ball, score, clock and game mode.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// Both teams, left team first.
    pub players: Vec<ScenePlayer>,
    /// Ball centre `[x, y, z]` (m); z = 0.11 on the grass.
    pub ball: [f32; 3],
    /// Goals `[left, right]` as drawn (the viewer's team first in a mirrored scene).
    pub score: [u32; 2],
    /// Env steps played this episode (the clock shows `steps` × [`CLOCK_SECONDS_PER_STEP`]).
    pub steps: u32,
    /// The pending set piece, or `Normal`.
    pub mode: GameMode,
}

impl Scene {
    /// The scene of `env`'s match with every agent-driven player marked.
    pub fn of_env(env: &Env) -> Scene {
        let mut scene = Scene::default();
        scene.capture(env);
        scene
    }

    /// Overwrites `self` with the state of `env`'s match, every agent-driven player marked; reuses
    /// the player buffer (no allocation once sized).
    pub fn capture(&mut self, env: &Env) {
        self.capture_match(env.game(), env.info().steps);
        for (side, &index) in env.controller_sides().zip(env.controlled_players()) {
            let g = env.game().global_index(side, index);
            if let Some(p) = self.players.get_mut(g) {
                p.controlled = true;
            }
        }
    }

    /// Overwrites `self` with controller `controller`'s view of `env` (as the other observations,
    /// docs/grf-compatibility.md#coordinates): for a right-team controller the pitch is turned by 180° and
    /// the teams swap colours and score order, so that the viewer's team is always the left (red) team playing
    /// towards the right. Only that controller's player is marked as controlled. A controller
    /// index out of range marks nobody.
    pub fn capture_view(&mut self, env: &Env, controller: usize) {
        self.capture_match(env.game(), env.info().steps);
        let Some(side) = env.controller_sides().nth(controller) else { return };
        let index = env.controlled_players()[controller];
        let g = env.game().global_index(side, index);
        if let Some(p) = self.players.get_mut(g) {
            p.controlled = true;
        }
        if side == Side::Right {
            self.mirror();
        }
    }

    /// Overwrites `self` with `game`'s players, ball, score and mode, nobody marked as
    /// controlled; `steps` sets the clock.
    pub fn capture_match(&mut self, game: &Match, steps: u32) {
        let owner = game.owner();
        self.players.clear();
        self.players.extend(game.players().iter().map(|p| ScenePlayer {
            side: p.side,
            number: u8::try_from(p.index + 1).unwrap_or(u8::MAX),
            goalkeeper: p.role == Role::GK,
            position: p.position.to_array(),
            controlled: false,
            has_ball: owner == Some((p.side, p.index)),
            on_pitch: p.active,
        }));
        self.ball = game.ball().position.to_array();
        self.score = game.score();
        self.steps = steps;
        self.mode = game.mode();
    }

    /// Turns the scene by 180° and swaps the teams' colours and score order (the right team's
    /// view).
    pub fn mirror(&mut self) {
        for p in &mut self.players {
            p.position = [-p.position[0], -p.position[1]];
            p.side = p.side.opponent();
        }
        self.ball = [-self.ball[0], -self.ball[1], self.ball[2]];
        self.score.swap(0, 1);
    }

    /// The scoreboard clock `MM:SS` (minutes may pass 99 in very long episodes).
    pub fn clock(&self) -> ClockText {
        let seconds = (self.steps as f32 * CLOCK_SECONDS_PER_STEP) as u32;
        ClockText { minutes: seconds / 60, seconds: seconds % 60 }
    }
}

/// A match clock, displayed as `MM:SS`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ClockText {
    /// Whole minutes.
    pub minutes: u32,
    /// Seconds past the minute, 0..60.
    pub seconds: u32,
}

impl std::fmt::Display for ClockText {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:02}:{:02}", self.minutes, self.seconds)
    }
}

/// The scoreboard's name of a game mode (blank in open play).
pub(crate) fn mode_label(mode: GameMode) -> &'static str {
    match mode {
        GameMode::Normal => "",
        GameMode::KickOff => "KICKOFF",
        GameMode::GoalKick => "GOAL KICK",
        GameMode::FreeKick => "FREE KICK",
        GameMode::Corner => "CORNER",
        GameMode::ThrowIn => "THROW-IN",
        GameMode::Penalty => "PENALTY",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clock_counts_90_minutes_in_3000_steps() {
        let at = |steps| Scene { steps, ..Scene::default() }.clock().to_string();
        assert_eq!(at(0), "00:00");
        assert_eq!(at(1), "00:01");
        assert_eq!(at(100), "03:00");
        assert_eq!(at(3000), "90:00");
    }

    #[test]
    fn mirror_turns_and_swaps() {
        let mut scene = Scene {
            players: vec![ScenePlayer {
                side: Side::Left,
                number: 1,
                goalkeeper: true,
                position: [-50.0, 2.0],
                controlled: false,
                has_ball: false,
                on_pitch: true,
            }],
            ball: [1.0, -2.0, 0.5],
            score: [2, 1],
            ..Scene::default()
        };
        scene.mirror();
        assert_eq!(scene.players[0].position, [50.0, -2.0]);
        assert_eq!(scene.players[0].side, Side::Right);
        assert_eq!(scene.ball, [-1.0, 2.0, 0.5]);
        assert_eq!(scene.score, [1, 2]);
    }
}
