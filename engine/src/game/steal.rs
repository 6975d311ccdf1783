//! Taking the ball off a carrier with a ball-control touch (GRF's possession contest).
//!
//! GRF keeps no owner for a dribbled ball: between the carrier's touches it runs free, and the
//! other team's designated player (its quickest to the ball) keeps asking for ball control while
//! he could win the duel for it (GRF's duel likeliness at least 0.25). When the ball comes within
//! his reach he traps it and it is his. An agent's idle player does the same: GRF's human
//! controller issues the ball-control command whatever the stick says. Measured in GRF 2.10.2
//! (11_vs_11_stochastic, idle agent, seeds 100-103; docs/grf-compatibility.md, "the idle player
//! takes the ball"): when their carrier's ball passes within 0.8 m of our idle player he has it
//! within 0.1-0.2 s in 76 % of those approaches, 19 a match; touchline's standing tackle, the
//! only way it had, won 28 %.

use super::Match;
use crate::geometry::pitch::in_penalty_area;

/// Reach (m) of a ball-control touch on a carrier's ball: from where the challenger's body is
/// going (0.05 s of his run on, 0.1 m ahead along his facing), as GRF's possession test measures
/// it. GRF's test allows 1 m; its trap animations meet the ball within about 0.8 m of the body
/// (the measured wins above fall off beyond it).
const REACH: f32 = 0.8;
/// Highest ball (m) the touch takes (GRF's possession test: 0.5 m).
const HEIGHT: f32 = 0.5;
/// Fastest (m/s) the ball may move relative to the challenger (GRF's possession test: 6 m/s).
const RELATIVE_SPEED: f32 = 6.0;
/// The challenger must be at least this likely to win the duel round the carrier (GRF asks
/// 0.25 for the ball-control command of a team's designated player).
const MIN_LIKELINESS: f32 = 0.25;
/// Ticks the carrier who lost the ball this way cannot touch it: GRF's dispossessed carrier first
/// moves after the ball 200 ms on.
const LOST_TICKS: u16 = 20;

impl Match {
    /// The opponent of `owner` who takes his ball with a ball-control touch this tick, if one does
    /// (and then he has it): the other team's player nearest the ball (GRF's designated player,
    /// who may be the keeper), with the ball within his [`REACH`], low, not too fast for him,
    /// nearer to him than to the carrier, and no body between him and it. A keeper in his own
    /// penalty area takes it in his hands, as he does a dribbled ball he dives for.
    pub(super) fn steal(&mut self, owner: usize) -> bool {
        let ball = self.ball.xy();
        if self.ball.position.z > HEIGHT {
            return false;
        }
        let carrier = self.players[owner].position;
        let side = self.players[owner].side.opponent();
        let Some(q) = self.ranges[side.index()].clone().filter(|&q| self.players[q].active).min_by(|&a, &b| {
            let d = |g: usize| self.players[g].position.distance_squared(ball);
            d(a).total_cmp(&d(b))
        }) else {
            return false;
        };
        let p = &self.players[q];
        if p.touch_cooldown > 0 || p.is_sliding() || p.interfere_ticks > 0 {
            return false;
        }
        let foot = p.position + p.velocity * 0.05 + p.facing * 0.1;
        let takes = foot.distance_squared(ball) < REACH * REACH
            && p.position.distance_squared(ball) < carrier.distance_squared(ball)
            && (self.ball.velocity.truncate() - p.velocity).length_squared() < RELATIVE_SPEED * RELATIVE_SPEED
            && duel_likeliness(p.position, carrier, ball) >= MIN_LIKELINESS;
        if takes && p.is_keeper() && in_penalty_area(p.position.x, p.position.y, -p.side.attack_sign()) {
            self.claimed(owner, q);
        } else if takes {
            self.players[owner].touch_cooldown = LOST_TICKS;
            self.take_ball(q);
        }
        takes
    }
}

/// How likely a challenger at `challenger` gets to the ball at `ball` played by the carrier at
/// `carrier`, GRF's duel likeliness 1 − (dot·0.5 + 0.5) in [0, 1]: 0 when the carrier stands
/// straight between him and the ball, 1 when he faces the carrier across the ball.
pub(crate) fn duel_likeliness(challenger: glam::Vec2, carrier: glam::Vec2, ball: glam::Vec2) -> f32 {
    let from_ball = (challenger - ball).normalize_or_zero();
    let carrier_side = (carrier - ball).normalize_or_zero();
    1.0 - (from_ball.dot(carrier_side) * 0.5 + 0.5)
}

#[cfg(test)]
mod tests {
    use glam::Vec2;

    use super::*;
    use crate::player::Role;
    use crate::scenario::{PlayerEntry, Scenario};

    /// Our centre midfielder on the ball at the centre spot, walking along +x with it 0.6 m ahead;
    /// their centre midfielder standing at `at`, facing him.
    fn approach(at: Vec2) -> Match {
        approach_from(Vec2::ZERO, Role::CM, at)
    }

    /// Our centre midfielder on the ball at `from`, walking along +x with it 0.6 m ahead; their
    /// `role` standing at `at`, facing him.
    fn approach_from(from: Vec2, role: Role, at: Vec2) -> Match {
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::CM, -0.5, 0.0)],
            right_team: vec![PlayerEntry::new(role, -0.5, 0.0)],
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 0);
        m.players[0].position = from;
        m.players[0].velocity = Vec2::new(3.0, 0.0);
        m.players[0].facing = Vec2::X;
        m.players[1].position = at;
        m.players[1].velocity = Vec2::ZERO;
        m.players[1].facing = Vec2::NEG_X;
        m.ball.position = (from + Vec2::new(0.6, 0.0)).extend(crate::geometry::pitch::BALL_RADIUS);
        m.ball.velocity = glam::Vec3::new(3.0, 0.0, 0.0);
        m.owner = Some(0);
        m
    }

    #[test]
    fn a_standing_player_takes_a_ball_dribbled_into_his_reach() {
        // 0.45 m from the ball, nearer it than the carrier.
        let mut m = approach(Vec2::new(1.0, 0.2));
        assert!(m.steal(0));
        assert_eq!(m.owner, Some(1));
        assert!(m.players[0].touch_cooldown > 0, "the carrier is left behind for a moment");
    }

    #[test]
    fn a_keeper_in_his_area_takes_it_in_his_hands_and_outside_it_at_his_feet() {
        let offset = Vec2::new(1.0, 0.2);
        // Their keeper 14 m from his goal line, inside his penalty area (16.5 m).
        let from = Vec2::new(40.0, 0.0);
        let mut inside = approach_from(from, Role::GK, from + offset);
        assert!(inside.steal(0));
        assert_eq!(inside.owner, Some(1));
        assert!(inside.in_hands);
        let from = Vec2::new(30.0, 0.0);
        let mut outside = approach_from(from, Role::GK, from + offset);
        assert!(outside.steal(0));
        assert!(!outside.in_hands);
    }

    #[test]
    fn a_ball_out_of_reach_or_behind_the_carrier_stays_his() {
        // 1.4 m beyond the ball: too far.
        assert!(!approach(Vec2::new(2.0, 0.0)).steal(0));
        // Within reach but no nearer the ball than the carrier.
        assert!(!approach(Vec2::new(1.1, 0.4)).steal(0));
        // Behind the carrier, the carrier's body between him and the ball.
        assert!(!approach(Vec2::new(-0.6, 0.0)).steal(0));
    }

    #[test]
    fn a_challenger_behind_the_carrier_cannot_get_to_the_ball() {
        // Carrier at the origin, the ball half a metre ahead of him along +x.
        let (carrier, ball) = (Vec2::ZERO, Vec2::new(0.5, 0.0));
        assert!(duel_likeliness(Vec2::new(-0.7, 0.0), carrier, ball) < 0.01);
        assert!(duel_likeliness(Vec2::new(1.3, 0.0), carrier, ball) > 0.99);
        // Round at his side, level with the ball: a fair chance.
        let beside = duel_likeliness(Vec2::new(0.45, 0.6), carrier, ball);
        assert!((0.3..0.7).contains(&beside), "{beside}");
    }
}
