//! GRF's "magnet": while the ball runs free in open play, an agent's player who is the first of
//! all players to it is run to where he meets it, whatever his stick says
//! (docs/grf-compatibility.md#controlled-players).

use glam::Vec2;

use super::tick::BALL_CONTROL_RANGE;
use super::{GameMode, Match};
use crate::ai::BallPath;

/// Highest point (m) of the ball's path the magnet runs an agent's player to: GRF's to-ball
/// movement skips predicted positions 1 m up or higher.
const MAGNET_HEIGHT: f32 = 1.0;
/// How often (ticks) the magnet is worked out again while the ball runs free (GRF: every 10 ms;
/// here every env step, and at once after a touch).
const MAGNET_EVERY: u64 = 10;
/// GRF's `distanceToVelocityMultiplier`: a player running to a point d metres off asks for
/// 2.6·d m/s, up to his top speed.
const DISTANCE_TO_VELOCITY: f32 = 2.6;

impl Match {
    /// Works [`Match::find_magnet`] out again every [`MAGNET_EVERY`] ticks of a free ball and after
    /// every touch (and cheaply, to `None`, while someone has the ball or play is stopped).
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

    /// The run the magnet gives the agent's player `g`, if it pulls him: to where he meets the
    /// ball, at GRF's 2.6 m/s per metre to go up to his top speed. Within ball-control range
    /// his automatic ball control decides instead (a ball at an idle player's feet stays there).
    pub(super) fn magnet_step(&self, g: usize) -> Option<Vec2> {
        let (m, at) = self.magnet?;
        let me = &self.players[g];
        if m != g || self.ball.xy().distance_squared(me.position) <= BALL_CONTROL_RANGE * BALL_CONTROL_RANGE {
            return None;
        }
        let to = at - me.position;
        Some(to.normalize_or_zero() * (to.length() * DISTANCE_TO_VELOCITY).min(me.max_speed))
    }

    /// GRF's "magnet" for a loose ball in open play: the player of either team who can get to it
    /// first and, when he is an agent's, the point where he meets it. GRF's human controller runs
    /// the match's designated possession player (the first to the ball) to the ball whatever his
    /// stick says (its auto bias is 1), so a pass to an agent's player, his keeper included, is
    /// met by him. Measured in GRF 2.10: after a high pass back from academy_empty_goal_close our
    /// keeper, driven by a random agent, runs 19 m out to the ball in 4 s.
    fn find_magnet(&self) -> Option<(usize, Vec2)> {
        if self.owner.is_some() || self.mode != GameMode::Normal || !self.agent_driven.iter().any(|&a| a) {
            return None;
        }
        let path = BallPath::predict(&self.ball);
        let mut best: Option<(f32, usize, Vec2)> = None;
        for (g, p) in self.players.iter().enumerate() {
            if !p.active {
                continue;
            }
            let (t, at) = path.intercept(p.position, p.max_speed.max(0.1), MAGNET_HEIGHT);
            if best.is_none_or(|(bt, _, _)| t < bt) {
                best = Some((t, g, at));
            }
        }
        let (_, g, at) = best?;
        self.agent_driven[g].then_some((g, at))
    }
}
