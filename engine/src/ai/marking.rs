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

/// How much a marker of `role` gives his marking job over the place the shape and the support
/// field gave him, with his team's fading possession `fading` in [0.5, 1.5] (`ai/support.rs`):
/// GRF 2.10's defensive bias of its defence, midfield and attack strategies,
/// (k − mind-set − fading)^0.7 clamped to [0, 1], with k = 1.9 for the back line, 1.5 for the
/// midfielders (the holding one included) and 1.3 for the centre forward. A team that has just
/// lost the ball (fading near 1) marks loosely and tightens as its possession fades.
fn marking_weight(role: Role, fading: f32) -> f32 {
    let k = match role {
        Role::GK | Role::CB | Role::LB | Role::RB => 1.9,
        Role::CF => 1.3,
        Role::DM | Role::CM | Role::LM | Role::RM | Role::AM => 1.5,
    };
    super::power::pow_unit((k - role.mind_set() - fading).clamp(0.0, 1.0), 0.7)
}

/// Where marker `p` stands (m, global) to mark `man` (of the opponents; `on_ball`: he has the
/// ball), given the place `place` (m, global) his shape and the support field gave him and his
/// team's fading possession `fading`: GRF's defensive component, laid over that place last, as
/// GRF's strategies do. A team of difficulty `theta` gives it 0.3 + 0.7θ of its weight (GRF's own
/// scaling of its defenders' reach): GRF's θ weakens an easy side's marking through its players'
/// stats and reactions, which touchline does not model, and an easy side that marked like a hard
/// one held the θ = 1 side to +1.4 goals a match instead of GRF's +3.4.
pub fn position(
    p: &Player,
    man: &Player,
    on_ball: bool,
    place: Vec2,
    frame: TeamFrame,
    theta: f32,
    fading: f32,
) -> Vec2 {
    let weight = marking_weight(p.role, fading) * difficulty_scale(theta);
    if weight <= 0.0 {
        return place;
    }
    let shape = frame.vec2(place);
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
    frame.vec2(shape.lerp(spot, weight))
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
    fn the_back_line_marks_fully_and_a_team_that_just_lost_the_ball_loosely() {
        // A team long without the ball (fading 0.5): GRF's defence marks fully, its midfield
        // mostly and its centre forward not at all.
        assert_eq!(marking_weight(Role::CB, 0.5), 1.0);
        assert_eq!(marking_weight(Role::LB, 0.5), 1.0);
        assert!((marking_weight(Role::CM, 0.5) - libm::powf(0.5, 0.7)).abs() < 1e-6);
        assert_eq!(marking_weight(Role::CF, 0.5), 0.0);
        // Just lost it (fading 1.2): everyone marks less, the back line included.
        for role in Role::ALL {
            assert!(marking_weight(role, 1.2) <= marking_weight(role, 0.5), "{role:?}");
        }
        assert!(marking_weight(Role::CB, 1.2) < 1.0);
    }
}
