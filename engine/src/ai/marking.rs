//! Man marking, GRF's way (docs/grf-compatibility.md#team-ai; GRF 2.10's team AI): every 400 ms a team
//! without the ball ranks the opponents by danger and gives each of the three most dangerous the
//! outfield player best placed to mark him. A marker does not hunt the ball; he takes a place
//! goal-side of his man, nearer than him to the point from which he would shoot: for the carrier
//! that point is 24 m from goal, so a carrier further out is watched from a few metres off (GRF's
//! defenders wait 3-6 m off an idle carrier there), and one nearer is met at his feet.

use glam::Vec2;

use super::MatchView;
use crate::geometry::pitch::HALF_LENGTH;
use crate::geometry::{Side, TeamFrame};
use crate::player::{MAX_PLAYERS_PER_TEAM, Player, Role, difficulty_scale};

/// How many opponents a team marks man to man (GRF: three).
pub const MARKED: usize = 3;

/// Ticks between two markings (GRF re-assigns every 400 ms).
pub const MARKING_TICKS: u64 = 40;

/// The carrier's shooting distance (m): a marker keeps between him and the point this far from
/// goal on his way there (GRF's 24 m for the player on the ball).
const CARRIER_SHOOTING_DISTANCE: f32 = 24.0;
/// The same for an opponent without the ball (GRF's 8 m).
const SHOOTING_DISTANCE: f32 = 8.0;
/// How much nearer than his man (m) a marker wants to be to that point (GRF's 4 m).
const MARKING_BUFFER: f32 = 4.0;

/// How dangerous opponent `o` is to the team defending the goal at `own_goal` (global, m) with the
/// ball at `ball`: nearness to a point just in front of that goal, pulled a fifth of the way to
/// the ball, and a little more for the man on the ball (GRF's danger factor).
fn danger(o: &Player, own_goal: Vec2, ball: Vec2, on_ball: bool) -> f32 {
    let hot = (own_goal - own_goal.signum() * Vec2::new(2.0, 0.0)) * 0.8 + ball * 0.2;
    let near = 1.0 - (o.position.distance(hot) / (4.0 * HALF_LENGTH)).clamp(0.0, 1.0);
    near * 0.95 + if on_ball { 0.05 } else { 0.0 }
}

/// A candidate marker's line (GRF's marking quality): a line through him across his way back to
/// goal (its half length his distance to goal, kept within 4-14 m); an opponent near that line and
/// near its middle, still in front of it, is his to mark. Its geometry depends on the marker
/// alone, so [`assign`] builds it once per marker rather than once per marker and man.
struct MarkingLine {
    /// The marker's position (m, global).
    at: Vec2,
    /// Half the line's length (m).
    half: f32,
    /// Unit vector from him towards his goal.
    dir: Vec2,
    /// Unit vector along the line.
    across: Vec2,
    /// The line's middle, half a metre behind him.
    centre: Vec2,
}

impl MarkingLine {
    /// The line of a player at `at` defending the goal at `own_goal`.
    fn new(at: Vec2, own_goal: Vec2) -> MarkingLine {
        let to_goal = own_goal - at;
        let half = to_goal.length().clamp(4.0, 14.0);
        let dir = to_goal.normalize_or(Vec2::new(own_goal.x.signum(), 0.0));
        MarkingLine { at, half, dir, across: dir.perp(), centre: at - dir * 0.5 }
    }

    /// How well he marks an opponent at `man` (higher is better). The raw distance breaks ties.
    fn quality(&self, man: Vec2) -> f32 {
        let rel = man - self.centre;
        // Signed distance in front of the line (away from goal) and position along it (-1..1).
        let in_front = -rel.dot(self.dir);
        let along = (rel.dot(self.across) / self.half).clamp(-1.0, 1.0);
        let off_line = if in_front >= 0.0 { (in_front - 2.0).abs() } else { -in_front };
        let mut q = 1.0 - 0.5 * (off_line / 60.0).clamp(0.0, 1.0).sqrt() - 0.5 * along.abs().sqrt();
        q = q.clamp(0.0, 1.0);
        if in_front < 0.0 {
            // He has got past us.
            q *= 0.6;
        }
        q * 0.8 + 0.2 * (1.0 - (self.at.distance(man) / (4.0 * HALF_LENGTH)).clamp(0.0, 1.0))
    }
}

/// Gives each of the three most dangerous opponents of `side` a marker: writes into `marks` (one
/// entry per player of `side`, by index in the team) the global index of the man he marks, or
/// `None`. Keepers do not mark; the opponents' keeper may be marked (in a drill with two
/// opponents he takes one of the three jobs, as in GRF).
pub fn assign(view: &MatchView, side: Side, marks: &mut [Option<usize>]) {
    marks.fill(None);
    let own_goal = Vec2::new(-side.attack_sign() * HALF_LENGTH, 0.0);
    let ball = view.ball.xy();
    let mine = view.ranges[side.index()].clone();
    let theirs = view.ranges[side.opponent().index()].clone();
    // The three most dangerous, kept sorted (most dangerous first) in a fixed array: no
    // allocation on the tick path.
    let mut top: [(f32, usize); MARKED] = [(f32::NEG_INFINITY, usize::MAX); MARKED];
    for g in theirs {
        let o = &view.players[g];
        if !o.active {
            continue;
        }
        let d = danger(o, own_goal, ball, view.owner == Some(g));
        if let Some(slot) = top.iter().position(|&(best, _)| d > best) {
            top.copy_within(slot..MARKED - 1, slot + 1);
            top[slot] = (d, g);
        }
    }
    // The team's candidate markers and their lines, built once for the three men (keepers, lazy
    // players and agents' players do not mark). A team has at most MAX_PLAYERS_PER_TEAM players.
    let mut lines: [Option<MarkingLine>; MAX_PLAYERS_PER_TEAM] = Default::default();
    for (g, line) in mine.zip(&mut lines) {
        let p = &view.players[g];
        if p.active && !p.lazy && !p.is_keeper() && !view.agent_driven[g] {
            *line = Some(MarkingLine::new(p.position, own_goal));
        }
    }
    for &(_, man) in top.iter().filter(|(_, g)| *g != usize::MAX) {
        let at = view.players[man].position;
        let best = (0..marks.len())
            .filter(|&i| marks[i].is_none())
            .filter_map(|i| Some((lines[i].as_ref()?.quality(at), i)))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((_, i)) = best {
            marks[i] = Some(man);
        }
    }
}

/// How much a player of `role` gives his marking job over his place in the shape (GRF's
/// defensive bias, `(1.9 − mind-set − fading possession)^0.7`, with the fading possession of a
/// team that has been without the ball a while, 0.6): full for the back line and the holding
/// midfielder, less the further forward he plays.
fn marking_weight(role: Role) -> f32 {
    // libm::powf((1.3 − role.mind_set()).clamp(0.0, 1.0), 0.7) for the five mind-sets, bit for bit
    // (a test checks): a powf per marker and decision was a measurable share of the AI's time.
    match role {
        Role::GK | Role::CB | Role::LB | Role::RB | Role::DM => 1.0,
        Role::CM | Role::LM | Role::RM => 0.855_387_6,
        Role::AM => 0.658_042_4,
        Role::CF => 0.430_511_6,
    }
}

/// Where marker `p` stands (m, team frame) to mark `man` (of the opponents; `on_ball`: he has the
/// ball), given his place in the shape `shape` (team frame): GRF's defensive component. A team of
/// difficulty `theta` gives it 0.3 + 0.7θ of its weight (GRF's own scaling of its defenders' reach):
/// GRF's θ weakens an easy side's marking through its players' stats and reactions, which
/// touchline does not model, and an easy side that marked like a hard one held the θ = 1 side to
/// +1.4 goals a match instead of GRF's +3.4.
pub fn position(p: &Player, man: &Player, on_ball: bool, shape: Vec2, frame: TeamFrame, theta: f32) -> Vec2 {
    let own_goal = Vec2::new(-HALF_LENGTH, 0.0);
    let man_at = frame.vec2(man.position + man.velocity * 0.5);
    let threshold = if on_ball { CARRIER_SHOOTING_DISTANCE } else { SHOOTING_DISTANCE };
    let to_goal = own_goal - man_at;
    let man_to_point = (to_goal.length() - threshold).clamp(0.4, HALF_LENGTH);
    let point = man_at + to_goal.normalize_or(Vec2::NEG_X) * man_to_point;
    // Be MARKING_BUFFER nearer that point than the man is.
    let mut spot = shape;
    let to_point = point - shape;
    let slack = to_point.length() - (man_to_point - MARKING_BUFFER);
    if slack > 0.0 {
        spot += to_point.normalize_or_zero() * slack.min(to_point.length());
    }
    // Too late to get there first: fall back towards goal instead of running at it.
    let now = frame.vec2(p.position + p.velocity * 0.14);
    let late = now.distance(point) - man_to_point;
    if late > 0.0 {
        spot += (own_goal - spot).normalize_or_zero() * late * 0.7;
    }
    shape.lerp(spot, marking_weight(p.role) * difficulty_scale(theta))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_marker_facing_his_man_rates_him_above_one_he_has_let_past() {
        let own_goal = Vec2::new(-HALF_LENGTH, 0.0);
        let at = Vec2::new(-30.0, 0.0);
        let line = MarkingLine::new(at, own_goal);
        let ahead = line.quality(Vec2::new(-24.0, 1.0));
        let past = line.quality(Vec2::new(-36.0, 1.0));
        let wide = line.quality(Vec2::new(-24.0, 20.0));
        assert!(ahead > past, "{ahead} {past}");
        assert!(ahead > wide, "{ahead} {wide}");
    }

    #[test]
    fn the_carrier_near_goal_is_the_most_dangerous() {
        let own_goal = Vec2::new(-HALF_LENGTH, 0.0);
        let near = Player::new(Side::Right, 0, Role::CF, Vec2::new(-35.0, 5.0), Vec2::ZERO);
        let far = Player::new(Side::Right, 1, Role::CF, Vec2::new(0.0, 5.0), Vec2::ZERO);
        assert!(danger(&near, own_goal, near.position, false) > danger(&far, own_goal, near.position, true));
    }

    #[test]
    fn the_marking_weights_are_powf_of_the_mind_set() {
        for role in Role::ALL {
            let powf = libm::powf((1.3 - role.mind_set()).clamp(0.0, 1.0), 0.7);
            assert_eq!(marking_weight(role).to_bits(), powf.to_bits(), "{role:?}");
        }
    }
}
