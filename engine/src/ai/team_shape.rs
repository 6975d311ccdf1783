//! Team shape, GRF's way (GRF 2.10's team AI): each player takes a slot of GRF's default
//! formation, whatever the scenario's positions; the slot maps into a block that follows the ball
//! and the possession, and the micro-focus draws players near the ball towards it. With the ball,
//! runners stay onside (the support field, `ai/support.rs`, moves them off this place);
//! without it, players near an opponent in their zone mark him.

use glam::Vec2;

use super::{Analysis, Difficulty, MatchView};
use crate::geometry::TeamFrame;
use crate::geometry::pitch::{CENTRE_CIRCLE_RADIUS, HALF_LENGTH, HALF_WIDTH};
use crate::player::Role;

/// GRF's default formation (GRF 2.10's team data: 0.6 × its database place + 0.4 × the role's
/// default place, pushed at least half a unit apart), in GRF's formation units: x from -1 at the
/// team's own goal to 1 at the other, y across, 1 on the first full back's side (a slot's home is
/// 55 m × x along and -36 m × y across, in the team's frame). Its team AI places the i-th player
/// of every scenario by slot i, whatever the scenario's positions, which only say where he
/// starts.
const FORMATION: [[f32; 2]; 11] = [
    [-1.0, 0.0],
    [-0.74, 0.77],
    [-1.0, 0.25],
    [-1.0, -0.25],
    [-0.74, -0.77],
    [0.0526, 0.4157],
    [-0.2252, 0.0],
    [0.0526, -0.4157],
    [0.36, 0.85],
    [1.0, 0.0],
    [0.36, -0.85],
];

/// Gives each player of a team his place in GRF's formation ([`FORMATION`]), written into his
/// `home` (team frame, m). `players` is one team, in scenario order. A team of n players uses the
/// formation's first n slots, as GRF's does; the keeper takes the keeper's slot and the others the
/// rest, each nearest his position now (shortest pairs first; GRF re-pairs players and slots by
/// distance as the match goes, and its scenario order is not its formation's). A team of more than
/// eleven keeps the scenario's places.
pub(crate) fn assign_formation(players: &mut [crate::player::Player], frame: TeamFrame) {
    let n = players.len();
    if n > FORMATION.len() {
        return;
    }
    let slot_home = |k: usize| Vec2::new(FORMATION[k][0] * HALF_LENGTH, -FORMATION[k][1] * HALF_WIDTH);
    let mut taken = [false; 11];
    let mut placed = [false; 11];
    for (i, p) in players.iter().enumerate() {
        // Sent off: off the field, in no slot.
        placed[i] = !p.active;
    }
    if let Some(k) = players.iter().position(|p| p.is_keeper() && p.active) {
        players[k].home = slot_home(0);
        taken[0] = true;
        placed[k] = true;
    }
    // Greedy by distance: at most 11 × 10 pairs, once per kickoff.
    loop {
        let mut best: Option<(f32, usize, usize)> = None;
        for (i, p) in players.iter().enumerate().filter(|(i, _)| !placed[*i]) {
            let at = frame.vec2(p.position);
            for k in (0..n).filter(|&k| !taken[k]) {
                let d = at.distance_squared(slot_home(k));
                if best.is_none_or(|(bd, _, _)| d < bd) {
                    best = Some((d, i, k));
                }
            }
        }
        let Some((_, i, k)) = best else { break };
        players[i].home = slot_home(k);
        placed[i] = true;
        taken[k] = true;
    }
}

/// An opponent this close (m) to a player's place in the shape is marked by him.
const MARK_RADIUS: f32 = 9.0;
/// How far goal-side of his man a marker stands (m).
const MARK_DISTANCE: f32 = 1.8;

/// How far behind the offside line (m) a player of difficulty θ keeps: 1.5 m at θ = 1, and
/// about a metre beyond it at θ = 0 (weak teams stray offside).
pub fn onside_margin(theta: f32) -> f32 {
    2.5 * theta - 1.0
}

/// Where player `g` should stand now (m, global frame): his formation slot (`home`) in the block
/// (`block_x`, `block_y`) drawn towards the ball (`micro_focus`). Players in possession
/// stay onside; defending players mark an opponent in their zone, goal-side of him, more
/// tightly at higher θ, unless the team's man marking gave them a man (`marks_a_man`): that
/// marking is laid over the place after the support field ([`super::marking::position`]).
pub fn position(view: &MatchView, g: usize, analysis: &Analysis, difficulty: &Difficulty, marks_a_man: bool) -> Vec2 {
    let frame = analysis.frame;
    let p = &view.players[g];
    let ball = frame.vec2(view.ball.xy());
    let bias = possession_bias(view, p.side);
    let ours = bias == 1.0;
    let mut y = block_y(p.role, p.home, ball, bias);
    let home = p.home;
    let mut x = block_x(p.role, home.x / HALF_LENGTH, ball.x, bias);
    let focal = match view.owner {
        Some(o) if !ours => 0.5 * (ball + frame.vec2(view.players[o].position)),
        _ => ball,
    };
    let strength = analysis.micro_focus_strength;
    (x, y) = micro_focus(Vec2::new(x, y), ball, focal, bias, strength);
    if ours && view.owner != Some(g) {
        // Stay onside: the offside line, less a margin that shrinks with θ.
        x = x.min(analysis.defensive_line - onside_margin(difficulty.theta));
    }
    if !ours && (p.role.is_defender() || x < ball.x) {
        // The back line stays goal-side of the ball, and anyone goal-side of it stays four metres
        // off it: only a hunter or a marker goes closer (GRF's defenders wait 3-6 m off).
        x = x.min(ball.x - 4.0);
    }
    x = x.clamp(-HALF_LENGTH + 4.0, HALF_LENGTH - 10.0);
    y = y.clamp(-HALF_WIDTH + 2.0, HALF_WIDTH - 2.0);
    let mut target = Vec2::new(x, y);
    if !ours && view.mode == crate::game::GameMode::Normal && !p.is_keeper() && !marks_a_man {
        target = mark(view, target, p.side.opponent(), frame, difficulty.theta);
    }
    // At an opponents' set piece keep the distance the laws ask for.
    if view.mode != crate::game::GameMode::Normal && !ours {
        let away = target - ball;
        if away.length() < CENTRE_CIRCLE_RADIUS + 0.5 {
            target = ball + away.normalize_or(Vec2::new(-1.0, 0.0)) * (CENTRE_CIRCLE_RADIUS + 0.5);
        }
    }
    frame.vec2(target)
}

/// How fast (m/s) player `p` goes to his place in the shape: flat out near the play, lazier the
/// further he is from the ball (from 20 m, fully at 65 m, both shorter when tired) and the more
/// his role leans away from the phase (forwards when the team defends, defenders when it
/// attacks): GRF's laziness. The last metres are slowed by the arrival in `TeamAi::drive`
/// (GRF's 2.6 × distance).
pub fn pace(view: &MatchView, p: &crate::player::Player) -> f32 {
    let fresh = 1.0 - p.fatigue;
    let start = 20.0 * (0.8 * fresh + 0.2);
    let end = 65.0 * (0.5 * fresh + 0.5);
    let far = ((p.position.distance(view.ball.xy()) - start) / (end - start)).clamp(0.0, 1.0);
    // GRF's fading team possession above one half: about 0.75 in possession, 0.1 without.
    let possession = match view.owner_side() {
        Some(s) if s == p.side => 0.75,
        Some(_) => 0.1,
        None => 0.4,
    };
    let mind_set = p.role.mind_set();
    let by_role = mind_set + possession * (1.0 - 2.0 * mind_set);
    p.max_speed * (1.0 - far * (0.5 + 0.5 * by_role))
}

/// A player's depth (team frame, m) in GRF's moving block (GRF 2.10's team AI), `fx` his
/// formation place along the pitch in [-1, 1] and `p` the possession bias (1: the ball is ours):
/// the block is 0.45 × (0.71 defending, 0.868 attacking; AM and CF 0.835 defending) of the
/// half-length deep either side of its centre; the centre is the ball's x pulled by the side
/// focus (0.332 or 0.176, more for defensive roles when defending and attacking ones when
/// attacking, less 0.15) towards the side x, plus the own-half offset, shrunk towards the middle;
/// midfielders are drawn towards the middle of the block (midfield focus 0.776 or 0.828). The
/// factors are GRF's base tactics moved by its default team's tactics (x 2 × 0.1-0.3 of their
/// distance from 0.5), as its team AI uses them.
fn block_x(role: Role, fx: f32, ball_x: f32, p: f32) -> f32 {
    let lerp = |defence: f32, offence: f32| defence + (offence - defence) * p;
    let mind_set = role.mind_set();
    let depth = 0.45 * lerp(if matches!(role, Role::AM | Role::CF) { 0.835 } else { 0.71 }, 0.868);
    let own_half = match role {
        Role::LB | Role::RB => lerp(0.465, 0.42),
        Role::LM | Role::RM => lerp(0.49, 0.42),
        _ => lerp(0.54, 0.52),
    };
    let side_focus = lerp(
        (0.332 + (0.5 - mind_set) * 0.2 - 0.15).clamp(0.0, 1.0),
        (0.176 + (mind_set - 0.5) * 0.2 - 0.15).clamp(0.0, 1.0),
    );
    // GRF's side x: a fifth of the way towards the end the team plays to (its own with p = 0),
    // plus 0.8 × the average possession side, which in GRF 2.10 comes out as the far end for
    // both teams whoever has the ball (measured with its team AI instrumented: -1.0 all match,
    // each team's side read in its own frame), so 33 m ahead defending and 55 m attacking.
    let side_x = (0.2 * (2.0 * p - 1.0) + 0.8) * HALF_LENGTH;
    let centre = (ball_x * (1.0 - side_focus) + side_x * side_focus - HALF_LENGTH * (2.0 * own_half - 1.0))
        .clamp(-HALF_LENGTH, HALF_LENGTH)
        * ((1.0 - depth) * 0.95 + 0.05);
    let follow = ((ball_x / HALF_LENGTH + 0.8) / 1.6).clamp(0.0, 1.0);
    let focus = (lerp(0.776, 0.828) * 0.7 + follow * 0.3) * 2.0 - 1.0;
    let fx = fx.clamp(-1.0, 1.0);
    let stretch = curve((1.0 - (fx * 1.2).abs()).clamp(0.0, 1.0), 1.0) * 0.35;
    centre + (fx + (focus - fx) * stretch) * depth * HALF_LENGTH
}

/// GRF's micro-focus (GRF 2.10's team AI): a player's place `pure` (team frame, m) is drawn
/// towards a spot by the ball, strongly near it (a binary-ish curve of 1 − distance over 50 m,
/// with a small bump at 7.5 m), across only 60 % of the way. With the ball (`p` = 1) the spot is a
/// metre ahead of the ball and the pull grows as the ball goes up the pitch; without it, the spot
/// is 2 m goal-side of `focal` (between the ball and its carrier) and the pull grows as the ball
/// comes towards the team's goal.
fn micro_focus(pure: Vec2, ball: Vec2, focal: Vec2, p: f32, strength: f32) -> (f32, f32) {
    let attacking = Vec2::new(ball.x + 1.0, ball.y * 0.9);
    let defending = Vec2::new(focal.x - 2.0, focal.y * 0.9);
    let spot = defending.lerp(attacking, p);
    let dist = ((spot - pure) * Vec2::new(1.0, 0.8)).length() / 50.0;
    if dist >= 1.0 {
        return (pure.x, pure.y);
    }
    let bias =
        (curve(1.0 - dist, 0.3) + (1.0 - ((dist - 0.15).abs() / 0.25).min(1.0)) * 0.1).clamp(0.0, 1.0) * strength;
    (pure.x + (spot.x - pure.x) * bias, pure.y + 0.6 * (spot.y - pure.y) * bias)
}

/// The possession bias of `side` (GRF's, by who has the ball rather than its fading possession):
/// 1 with the ball or after its own last touch, 0.5 before anyone touched it, else 0.
pub(crate) fn possession_bias(view: &MatchView, side: crate::geometry::Side) -> f32 {
    let ours = match view.owner {
        Some(o) => view.players[o].side == side,
        None => view.last_touch.is_some_and(|t| view.players[t].side == side),
    };
    if ours {
        1.0
    } else if view.owner.is_none() && view.last_touch.is_none() {
        0.5
    } else {
        0.0
    }
}

/// How strongly the micro-focus draws a team (see `micro_focus`) with the ball at `ball_x` (team
/// frame, m) and possession bias `p`: 0.938 defending, 0.826 attacking, × (0.2 + 0.8 × auto), auto
/// growing as the ball comes towards the team's goal when defending and towards the opponents'
/// when attacking. The same for the whole team, so [`crate::ai::Analysis`] works it out once per
/// decision.
pub(crate) fn micro_focus_strength(ball_x: f32, p: f32) -> f32 {
    let side = ((ball_x / HALF_LENGTH + 0.7) / 1.4).clamp(0.0, 1.0) * 0.7 + 0.3;
    let attacking = if p > 0.0 { super::power::pow_unit(side, 0.8) * p } else { 0.0 };
    let defending = if p < 1.0 { super::power::pow_unit(1.0 - side, 0.6) * (1.0 - p) } else { 0.0 };
    let auto = attacking + defending;
    (0.938 + (0.826 - 0.938) * p) * (0.2 + 0.8 * auto)
}

/// GRF's `curve`: `x` in [0, 1] blended with a sine ease (flat at both ends) by `bias`. The sine is
/// a seventh-order polynomial (within 2e-4 over the half period used): the team shape evaluates it
/// for every player at every decision, and libm's sine there cost a tenth of a match's step.
pub(crate) fn curve(x: f32, bias: f32) -> f32 {
    let t = (x - 0.5) * std::f32::consts::PI;
    let t2 = t * t;
    let sine = t * (1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0)));
    (sine * 0.5 + 0.5) * bias + x * (1.0 - bias)
}

/// A player's place across the pitch (team frame, m) in GRF's moving block (GRF 2.10's team AI),
/// before marking: the block's width is lerped between the defending and attacking tactics by
/// the possession bias `p` (1: the ball is ours, 0: theirs), the back four a little wider with the
/// ball; its centre follows the ball, shrunk towards the middle; the formation's place (`home`, m)
/// maps linearly into it. Then players drift across towards the ball's side (GRF's y-focus). With
/// the ball the support field (`ai/support.rs`) spreads the team further.
fn block_y(role: Role, home: Vec2, ball: Vec2, p: f32) -> f32 {
    let lerp = |defence: f32, offence: f32| defence + (offence - defence) * p;
    let width = 0.95 * if role.is_defender() { lerp(0.84, 1.0) } else { lerp(0.84, 0.948) };
    let centre_y = ball.y * ((1.0 - width) * 0.9 + 0.1);
    // Formation places in GRF's [-1, 1] units: y over 36 m.
    let hy = home.y / 36.0;
    let y = centre_y + hy * width * HALF_WIDTH;
    // Drift across towards the ball's side: stronger with the ball and when it is wide.
    let across = (0.5 * p + 0.2 * (1.0 - p))
        * (1.0 - (ball.y - y).abs() / (2.0 * HALF_WIDTH)).max(0.0)
        * (0.2 + 0.8 * ball.y.abs() / HALF_WIDTH);
    y + (ball.y - y) * across * 0.25
}

/// Moves a defending player's place `target` (team frame) towards the goal side of the nearest
/// opponent in his zone, if any.
fn mark(view: &MatchView, target: Vec2, opponents: crate::geometry::Side, frame: TeamFrame, theta: f32) -> Vec2 {
    let own_goal = Vec2::new(-HALF_LENGTH, 0.0);
    let mut best = None;
    let mut best_d2 = MARK_RADIUS * MARK_RADIUS;
    for g in view.ranges[opponents.index()].clone() {
        let o = &view.players[g];
        if !o.active || o.is_keeper() || view.owner == Some(g) {
            continue;
        }
        let at = frame.vec2(o.position);
        let d2 = at.distance_squared(target);
        if d2 < best_d2 {
            best_d2 = d2;
            best = Some(at);
        }
    }
    let Some(man) = best else { return target };
    let spot = man + (own_goal - man).normalize_or(Vec2::NEG_X) * MARK_DISTANCE;
    target.lerp(spot, 0.3 + 0.6 * theta)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sine_ease_is_grfs_curve() {
        for i in 0..=100 {
            let x = i as f32 / 100.0;
            let exact = libm::sinf((x - 0.5) * std::f32::consts::PI) * 0.5 + 0.5;
            assert!((curve(x, 1.0) - exact).abs() < 2e-4, "{x}");
        }
    }

    #[test]
    fn better_teams_keep_further_onside() {
        assert!(onside_margin(1.0) > 1.0);
        assert!(onside_margin(0.0) < 0.0);
        assert!(onside_margin(0.6) > onside_margin(0.3));
    }

    #[test]
    fn a_defender_takes_the_place_grfs_team_ai_gives_him() {
        // GRF 2.10.2 with its team AI instrumented, academy_run_to_score 3 s in: the right team's
        // centre midfielder, fourth in the scenario and so in the formation's centre-back slot
        // (-1, -0.25), defending with the ball 1.1 m behind the halfway line in his frame: block
        // from -17.0 m, place (-10.6, 5.1) after the micro-focus on (-2.9, 0).
        let home = Vec2::new(-HALF_LENGTH, 0.25 * HALF_WIDTH);
        let ball = Vec2::new(-1.1, 0.0);
        let x = block_x(Role::CM, home.x / HALF_LENGTH, ball.x, 0.0);
        assert!((x + 17.0).abs() < 0.3, "{x}");
        let y = block_y(Role::CM, home, ball, 0.0);
        let (x, y) = micro_focus(Vec2::new(x, y), ball, Vec2::new(-0.9, 0.0), 0.0, micro_focus_strength(ball.x, 0.0));
        assert!((x + 10.6).abs() < 0.5 && (y - 5.1).abs() < 0.5, "({x}, {y})");
    }

    #[test]
    fn players_take_the_nearest_formation_slots_and_a_small_team_the_first_ones() {
        use crate::geometry::Side;
        let frame = TeamFrame::of(Side::Left);
        // A keeper and five outfield players, the CM standing where the right back's slot is.
        let at = [(-55.0, 0.0), (-41.0, -27.0), (-41.0, 27.0), (-54.0, -9.0), (-54.0, 9.0), (0.0, 0.0)];
        let roles = [Role::GK, Role::CM, Role::LB, Role::CB, Role::CB, Role::RB];
        let mut team: Vec<crate::player::Player> = at
            .iter()
            .zip(roles)
            .enumerate()
            .map(|(i, (&(x, y), role))| crate::player::Player::new(Side::Left, i, role, Vec2::new(x, y), Vec2::ZERO))
            .collect();
        assign_formation(&mut team, frame);
        assert_eq!(team[0].home, Vec2::new(-HALF_LENGTH, 0.0));
        // Six players use slots 0-5 only: nobody takes a midfield or forward slot beyond them.
        assert!(
            team.iter().all(|p| p.home.x <= 0.06 * HALF_LENGTH),
            "{:?}",
            team.iter().map(|p| p.home).collect::<Vec<_>>()
        );
        assert!(team[1].home.distance(Vec2::new(-40.7, -27.72)) < 0.1, "{}", team[1].home);
        assert!(team[2].home.distance(Vec2::new(-40.7, 27.72)) < 0.1, "{}", team[2].home);
        // The one far from every back-four slot gets the slot left over: the first central midfielder's.
        assert!(team[5].home.distance(Vec2::new(0.0526 * HALF_LENGTH, -0.4157 * HALF_WIDTH)) < 0.1, "{}", team[5].home);
    }
}
