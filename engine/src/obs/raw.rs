//! The raw observation (docs/grf-compatibility.md#raw-observation), one per controlled player, in that
//! player's own frame: a right-team viewer sees the pitch turned by 180° with his team as "left"
//! (docs/grf-compatibility.md#coordinates).

use serde::{Deserialize, Serialize};

use crate::game::{GameMode, Match};
use crate::geometry::coords::{OBS_X_SCALE, OBS_Y_SCALE};
use crate::geometry::{Side, TeamFrame};

/// GRF's raw observation for one controller. Positions in normalised units (x ∈ [-1.01, 1.01],
/// y ∈ [-0.43, 0.43]); the ball's z in metres. Arrays hold every player of the scenario (sent-off
/// players included), in scenario order. GRF gives float64 arrays; touchline keeps f32.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RawObservation {
    /// Ball `[x, y, z]`: x, y normalised, z in metres (0.11 on the grass).
    pub ball: [f32; 3],
    /// Ball movement per step: velocity (m/s) / 10, x and y normalised, z in metres.
    pub ball_direction: [f32; 3],
    /// Ball rotation per step (rad): angular velocity × 1e-4, as GRF's per-ms Euler angles / 10.
    pub ball_rotation: [f32; 3],
    /// -1 nobody, 0 the viewer's team, 1 the opponents.
    pub ball_owned_team: i32,
    /// Index of the owner in his team's arrays, or -1.
    pub ball_owned_player: i32,
    /// Viewer's team positions `(N, 2)`.
    pub left_team: Vec<[f32; 2]>,
    /// Viewer's team movement per step `(N, 2)`.
    pub left_team_direction: Vec<[f32; 2]>,
    /// Viewer's team fatigue in [0, 0.99] `(N,)`.
    pub left_team_tired_factor: Vec<f32>,
    /// Viewer's team: has a card `(N,)`.
    pub left_team_yellow_card: Vec<bool>,
    /// Viewer's team: still on the pitch `(N,)`.
    pub left_team_active: Vec<bool>,
    /// Viewer's team roles (0 GK … 9 CF) `(N,)`.
    pub left_team_roles: Vec<u8>,
    /// Opponents' positions `(M, 2)`.
    pub right_team: Vec<[f32; 2]>,
    /// Opponents' movement per step `(M, 2)`.
    pub right_team_direction: Vec<[f32; 2]>,
    /// Opponents' fatigue `(M,)`.
    pub right_team_tired_factor: Vec<f32>,
    /// Opponents with a card `(M,)`.
    pub right_team_yellow_card: Vec<bool>,
    /// Opponents still on the pitch `(M,)`.
    pub right_team_active: Vec<bool>,
    /// Opponents' roles `(M,)`.
    pub right_team_roles: Vec<u8>,
    /// Goals `[viewer's team, opponents]`.
    pub score: [u32; 2],
    /// Steps left in the episode (`game_duration + 1` at reset, 0 at the time limit).
    pub steps_left: u32,
    /// Game mode 0..6.
    pub game_mode: GameMode,
    /// Index of the player this controller drives, -1 if none.
    pub active: i32,
    /// Index of the team's designated player, -1 if none.
    pub designated: i32,
    /// Sticky actions: 8 directions, sprint, dribble (uint8, 10).
    pub sticky_actions: [u8; 10],
}

/// Per-step movement: m/s → displacement per 0.1 s in normalised units.
#[inline]
fn per_step(v: glam::Vec2) -> [f32; 2] {
    [v.x / 10.0 / OBS_X_SCALE, v.y / 10.0 / OBS_Y_SCALE]
}

impl RawObservation {
    /// Writes the state of `game` as seen by `viewer`'s controller into `self`, reusing its
    /// buffers (no allocation once sized).
    pub fn fill(
        &mut self,
        game: &Match,
        viewer: Side,
        active: Option<usize>,
        designated: Option<usize>,
        sticky: [u8; 10],
        steps_left: u32,
    ) {
        let frame = TeamFrame::of(viewer);
        let ball = game.ball();
        let b = frame.vec3(ball.position);
        let bv = frame.vec3(ball.velocity);
        self.ball = [b.x / OBS_X_SCALE, b.y / OBS_Y_SCALE, b.z];
        self.ball_direction = [bv.x / 10.0 / OBS_X_SCALE, bv.y / 10.0 / OBS_Y_SCALE, bv.z / 10.0];
        self.ball_rotation = (ball.spin * 1e-4).to_array();
        match game.observed_owner() {
            Some((side, i)) => {
                self.ball_owned_team = if side == viewer { 0 } else { 1 };
                self.ball_owned_player = i as i32;
            }
            None => {
                self.ball_owned_team = -1;
                self.ball_owned_player = -1;
            }
        }
        let s = game.score();
        self.score = if viewer == Side::Left { s } else { [s[1], s[0]] };
        self.steps_left = steps_left;
        self.game_mode = game.mode();
        self.active = active.map_or(-1, |i| i as i32);
        self.designated = designated.map_or(-1, |i| i as i32);
        self.sticky_actions = sticky;
        for (own, side) in [(true, viewer), (false, viewer.opponent())] {
            let team = game.team(side);
            let (pos, dir, tired, card, act, roles) = if own {
                (
                    &mut self.left_team,
                    &mut self.left_team_direction,
                    &mut self.left_team_tired_factor,
                    &mut self.left_team_yellow_card,
                    &mut self.left_team_active,
                    &mut self.left_team_roles,
                )
            } else {
                (
                    &mut self.right_team,
                    &mut self.right_team_direction,
                    &mut self.right_team_tired_factor,
                    &mut self.right_team_yellow_card,
                    &mut self.right_team_active,
                    &mut self.right_team_roles,
                )
            };
            let n = team.len();
            pos.resize(n, [0.0; 2]);
            dir.resize(n, [0.0; 2]);
            tired.resize(n, 0.0);
            card.resize(n, false);
            act.resize(n, true);
            roles.resize(n, 0);
            for (i, p) in team.iter().enumerate() {
                let at = frame.vec2(p.position);
                pos[i] = [at.x / OBS_X_SCALE, at.y / OBS_Y_SCALE];
                dir[i] = per_step(frame.vec2(p.velocity));
                tired[i] = p.fatigue;
                card[i] = p.cards > 0;
                act[i] = p.active;
                roles[i] = p.role as u8;
            }
        }
    }
}
