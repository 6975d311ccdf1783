//! GRF's "magnet": while the ball runs free in open play, an agent's player who is the first of
//! all players to it is run to where he meets it, whatever his stick says, and one who is only his
//! team's first is pulled there in part while the race is close
//! (docs/grf-compatibility.md#controlled-players).

use glam::Vec2;
use serde::{Deserialize, Serialize};

use super::kick::{ease, signed_angle};
use super::tick::{BALL_CONTROL_RANGE, DISTANCE_TO_VELOCITY};
use super::{GameMode, Match};

/// Highest point (m) of the ball's path the magnet runs an agent's player to: GRF's to-ball
/// movement skips predicted positions 1 m up or higher.
const MAGNET_HEIGHT: f32 = 1.0;
/// How often (ticks) the magnet is worked out again while the ball runs free (GRF: every 10 ms;
/// here every env step, and at once after a touch).
const MAGNET_EVERY: u64 = 10;

impl Match {
    /// Works [`Match::find_magnet`] out again every [`MAGNET_EVERY`] ticks of a free ball and after
    /// every touch (and cheaply, to nothing, while someone has the ball or play is stopped).
    pub(super) fn refresh_magnet(&mut self) {
        if self.owner.is_some()
            || self.mode != GameMode::Normal
            || self.touch_tick > self.magnet_tick
            || self.in_play_ticks >= self.magnet_tick + MAGNET_EVERY
        {
            self.magnet = self.find_magnet();
            self.magnet_tick = self.in_play_ticks;
        }
    }

    /// The run the magnet gives the agent's player `g`, if it pulls him: towards where he meets
    /// the ball, at GRF's 2.6 m/s per metre to go up to his top speed, blended with his stick by
    /// the pull's share (all of it for the first of all players to the ball). Within
    /// ball-control range his automatic ball control decides instead (a ball at an idle player's
    /// feet stays there).
    pub(super) fn magnet_step(&self, g: usize) -> Option<Vec2> {
        let me = &self.players[g];
        let pull = self.magnet[me.side.index()].filter(|pull| pull.player == g)?;
        if self.ball.xy().distance_squared(me.position) <= BALL_CONTROL_RANGE * BALL_CONTROL_RANGE {
            return None;
        }
        let to = pull.at - me.position;
        let run = to.normalize_or_zero() * (to.length() * DISTANCE_TO_VELOCITY).min(me.max_speed);
        if pull.share >= 1.0 {
            return Some(run);
        }
        // Only his team's first to the ball, an opponent being first: GRF pulls him the more the
        // nearer his stick (his facing when idle) points along the run, and not at all while it
        // points back into his own half.
        let stick = self.inputs[g].velocity;
        let manual = stick.try_normalize().unwrap_or(me.facing);
        let along = 1.0 - signed_angle(run, manual).abs() / std::f32::consts::PI;
        let own_goal = Vec2::new(-me.side.attack_sign(), 0.0);
        let homeward = ((manual.dot(own_goal) + 1.0) * 0.5).clamp(0.0, 1.0);
        let share = (pull.share * ease(0.5 + 0.5 * along, 0.8) * (1.0 - homeward)).clamp(0.0, 1.0);
        (share > 0.0).then(|| stick * (1.0 - share) + run * share)
    }

    /// GRF's "magnet" for a loose ball in open play, for each team: the agent's player it pulls,
    /// where he meets the ball and how much of his run it takes over. GRF's human controller runs
    /// the match's designated possession player (the first of all players to the ball) to the
    /// ball whatever his stick says (auto bias 1), so a pass to an agent's player, his keeper
    /// included, is met by him. Measured in GRF 2.10: after a high pass back from
    /// academy_empty_goal_close our keeper, driven by a random agent, runs 19 m out to the ball
    /// in 4 s. His team's first to the ball, when an opponent is first, is pulled in part: by
    /// sqrt(2·(p − 0.5)) for a possession amount p = (t_opponent + 0.2 s) / (t_his + 0.2 s) above
    /// one half (GRF's playercontroller movement command), scaled by his stick (see
    /// [`Match::magnet_step`]).
    fn find_magnet(&self) -> [Option<Pull>; 2] {
        if self.owner.is_some() || self.mode != GameMode::Normal || !self.agent_driven.iter().any(|&a| a) {
            return [None; 2];
        }
        let path = self.paths.path(&self.ball);
        let mut best: [Option<(f32, usize, Vec2)>; 2] = [None; 2];
        for (g, p) in self.players.iter().enumerate() {
            if !p.active {
                continue;
            }
            let (t, at) = path.intercept(p.position, p.max_speed.max(0.1), MAGNET_HEIGHT);
            let slot = &mut best[p.side.index()];
            if slot.is_none_or(|(bt, _, _)| t < bt) {
                *slot = Some((t, g, at));
            }
        }
        let time = |side: usize| best[side].map_or(f32::INFINITY, |(t, _, _)| t);
        std::array::from_fn(|side| {
            let (t, player, at) = best[side]?;
            if !self.agent_driven[player] {
                return None;
            }
            let theirs = time(1 - side);
            if t <= theirs {
                return Some(Pull { player, at, share: 1.0 });
            }
            let possession = (theirs + 0.2) / (t + 0.2);
            (possession > 0.5).then(|| Pull { player, at, share: ((possession - 0.5) * 2.0).sqrt() })
        })
    }
}

/// GRF's magnet on one agent's player (see [`Match::find_magnet`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Pull {
    /// The player it pulls (global index).
    pub(crate) player: usize,
    /// Where he meets the ball (m).
    pub(crate) at: Vec2,
    /// How much of his run it takes over before his stick is heard, in (0, 1]; 1 for the first
    /// of all players to the ball.
    pub(crate) share: f32,
}
