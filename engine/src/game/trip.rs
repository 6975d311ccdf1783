//! Trips in body contact (GRF 2.10's `Match::CheckHumanoidCollision`; docs/grf-compatibility.md#team-ai).
//! Each of two players whose bodies meet has a sensitivity, from how he faces the other, how fast
//! he runs, whether he has the ball, his balance, how hard he is being pushed, how deep the bodies
//! will meet and how near the ball is. Above one threshold he stumbles, above a higher one he
//! falls; either way he cannot steer or touch the ball until he is up, and a carrier loses the
//! ball. Balance is a stat, so a team's difficulty decides who goes down: in GRF the θ = 0.05 side
//! of an easy match goes down about 80 times, the θ = 1 side about 5. A fall near the ball of the
//! team on it, against an opponent going in with a standing tackle, is a foul (GRF's referee).

use glam::Vec2;

use super::{GameMode, Match};
use crate::physics::{Contact, MIN_DIST, TICK_SECONDS};
use crate::player::SPRINT_SPEED;
use crate::rules::fouls;

/// Every player's balance before difficulty and fatigue. GRF's 11-v-11 and academy players have
/// their stats from one database profile per slot; their balance averages 0.79 over the eleven
/// slots (0.6-1.0; GRF 2.10.2, measured 2026-11-27). touchline gives every slot that mean.
const BALANCE: f32 = 0.79;
/// The sensitivity's parts are summed and divided by this (GRF's 5 + 3 + 6: five parts weigh 1,
/// balance 3 and the bodies' depth 6).
const WEIGHTS: f32 = 14.0;
/// Above this sensitivity he stumbles; above the second he falls (GRF's trip thresholds).
const STUMBLE: f32 = 0.48;
const FALL: f32 = 0.58;
/// How long (ticks) a stumble and a fall keep him from playing, from a stand and at a sprint
/// (GRF's trip animations: 0.25-0.35 s standing to 0.45-0.9 s sprinting for a stumble,
/// 0.45-0.6 s to 0.95 s for a fall).
const STUMBLE_TICKS: (f32, f32) = (30.0, 70.0);
const FALL_TICKS: (f32, f32) = (50.0, 95.0);
/// A fall is a foul only with the ball this near the fallen man (m; GRF's referee).
const FOULED_NEAR: f32 = 2.0;
/// The ball counts as at his feet from this near (m), fully at 0.
const BALL_NEAR: f32 = 0.7;

impl Match {
    /// Trips the players this tick's contacts unbalanced (in normal play only).
    pub(super) fn trip_players(&mut self) {
        if self.mode != GameMode::Normal {
            return;
        }
        for k in 0..self.contacts.as_slice().len() {
            let c = self.contacts.as_slice()[k];
            let (i, j) = (usize::from(c.i), usize::from(c.j));
            if self.players[i].is_sliding() || self.players[j].is_sliding() {
                // A slide's contact is the slide's own (`Match::challenge` judges it).
                continue;
            }
            let si = self.sensitivity(i, j, &c);
            let sj = self.sensitivity(j, i, &c);
            for (g, other, s) in [(i, j, si), (j, i, sj)] {
                if s > FALL && self.whistle.is_none() && self.pending_foul.is_none() && self.brought_down(g, other) {
                    let severity = fouls::standing_severity(&self.players[other], &self.players[g], self.rng.unit());
                    self.whistle = fouls::commit(self, other, g, severity);
                }
            }
            self.trip(i, si);
            self.trip(j, sj);
        }
    }

    /// Whether `g`, falling in a contact with `other`, was fouled (GRF's referee on a fall): his
    /// team has the ball, it is within 2 m of him, and `other` is an opponent going in with a
    /// standing tackle.
    fn brought_down(&self, g: usize, other: usize) -> bool {
        let (p, q) = (&self.players[g], &self.players[other]);
        let theirs = self.owner.is_some_and(|o| self.players[o].side == p.side);
        theirs && q.side != p.side && q.interfere_ticks > 0 && self.ball.xy().distance(p.position) < FOULED_NEAR
    }

    /// Player `g`'s sensitivity in his contact `c` with `other`: GRF's sum of seven parts over 14.
    fn sensitivity(&self, g: usize, other: usize, c: &Contact) -> f32 {
        let p = &self.players[g];
        let away = (p.position - self.players[other].position).normalize_or(Vec2::Y);
        // Facing the other man is the worst: 1; facing away, 0.
        let facing = 1.0 - (p.facing.dot(away) * 0.5 + 0.5).clamp(0.0, 1.0);
        let pace = (p.velocity.length() / SPRINT_SPEED).clamp(0.0, 1.0);
        let on_ball = if self.owner == Some(g) { 1.0 } else { 0.0 };
        let balance = (1.0 - p.skill(BALANCE, self.theta(g))) * 3.0;
        // GRF counts the pushes of the last moments; touchline the one of this contact, his half
        // of the overlap, ten to the metre.
        let pushed = ((MIN_DIST - c.apart) * 0.5 * 10.0).clamp(0.0, 1.0);
        let depth = libm::powf(1.0 - (c.ahead / MIN_DIST).clamp(0.0, 1.0), 0.4) * 6.0;
        let ball = self.ball.position.truncate() + self.ball.velocity.truncate() * TICK_SECONDS;
        let near_ball = 1.0 - (ball.distance(p.position) / BALL_NEAR).clamp(0.0, 1.0);
        (facing + pace + on_ball + balance + pushed + depth + near_ball) / WEIGHTS
    }

    /// Trips `g` by his sensitivity `s`: a stumble or a fall, unless he is already down, sliding or
    /// holding the ball in his hands. A carrier who goes down leaves the ball running on.
    fn trip(&mut self, g: usize, s: f32) {
        if s <= STUMBLE {
            return;
        }
        let holding = self.in_hands && self.owner == Some(g);
        let p = &mut self.players[g];
        if p.trip_ticks > 0 || p.is_sliding() || holding {
            return;
        }
        let (stand, sprint) = if s > FALL { FALL_TICKS } else { STUMBLE_TICKS };
        let pace = (p.velocity.length() / SPRINT_SPEED).clamp(0.0, 1.0);
        let ticks = (stand + (sprint - stand) * pace) as u16;
        p.trip_ticks = ticks;
        p.touch_cooldown = p.touch_cooldown.max(ticks);
        p.pending_kick = None;
        p.interfere_ticks = 0;
        if self.owner == Some(g) {
            self.ball.velocity = p.velocity.extend(0.0);
            self.owner = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::{Vec2, Vec3};

    use crate::game::Match;
    use crate::physics::Contact;
    use crate::player::Role;
    use crate::scenario::{PlayerEntry, Scenario};

    /// A match of two centre midfielders, the left one at θ = 1 and the right one at `right`,
    /// standing 0.6 m apart on the centre line, the right one running at the left one at `pace`
    /// m/s, the ball 20 m away; the contact as the separation would have noted it.
    fn collision(right: f32, pace: f32) -> (Match, Contact) {
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::CM, -0.5, 0.0)],
            right_team: vec![PlayerEntry::new(Role::CM, -0.5, 0.0)],
            ball_position: [0.0, 0.3],
            right_team_difficulty: right,
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 0);
        m.players[0].position = Vec2::ZERO;
        m.players[0].velocity = Vec2::ZERO;
        m.players[0].facing = Vec2::X;
        m.players[1].position = Vec2::new(0.6, 0.0);
        m.players[1].velocity = Vec2::new(-pace, 0.0);
        m.players[1].facing = Vec2::NEG_X;
        m.ball.position = Vec3::new(0.0, 20.0, 0.11);
        m.ball.velocity = Vec3::ZERO;
        m.owner = None;
        let ahead = 0.6 - pace * 0.03;
        (m, Contact { i: 0, j: 1, apart: 0.6, ahead })
    }

    fn trips(m: &mut Match, c: Contact) -> [u16; 2] {
        m.contacts.clear();
        m.contacts.push(c);
        m.trip_players();
        [m.players[0].trip_ticks, m.players[1].trip_ticks]
    }

    #[test]
    fn an_easy_side_s_player_goes_down_in_a_contact_a_hard_one_rides() {
        // Running in at 4 m/s, face to face: the θ = 0.05 man's balance (a third of his stat)
        // puts him over the stumble line, the θ = 1 man's does not.
        let (mut easy, c) = collision(0.05, 4.0);
        let [standing, runner] = trips(&mut easy, c);
        assert_eq!(standing, 0, "the standing θ = 1 man faces the runner but stays up");
        assert!(runner > 0, "the θ = 0.05 runner stumbles");
        let (mut hard, c) = collision(1.0, 4.0);
        assert_eq!(trips(&mut hard, c), [0, 0]);
        // Down, he can neither steer (see `Match::move_players`) nor touch the ball.
        assert!(easy.players[1].touch_cooldown >= runner);
        // A sprint into him, deeper and faster: a fall, longer than the stumble.
        let (mut sprint, c) = collision(0.05, 7.5);
        let [_, fall] = trips(&mut sprint, c);
        assert!(fall > runner, "{fall} ticks against {runner}");
    }

    #[test]
    fn a_carrier_who_goes_down_leaves_the_ball_running_on() {
        let (mut m, c) = collision(0.05, 7.5);
        m.owner = Some(1);
        m.ball.position = Vec3::new(0.1, 0.0, 0.11);
        assert!(trips(&mut m, c)[1] > 0);
        assert_eq!(m.owner, None);
        assert_eq!(m.ball.velocity, Vec3::new(-7.5, 0.0, 0.0));
    }

    #[test]
    fn nobody_goes_down_outside_normal_play() {
        let (mut m, c) = collision(0.05, 7.5);
        m.mode = crate::game::GameMode::FreeKick;
        assert_eq!(trips(&mut m, c), [0, 0]);
    }
}
