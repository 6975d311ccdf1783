//! Set pieces: the taker waits a moment and then plays the ball as GRF's AI does (see `take`:
//! a pass to the team-mate nearest a point drawn by the kind of restart, a shot from a penalty
//! kick); the others take up their places.

use glam::Vec2;

use super::{Analysis, Difficulty, MatchView, Plan, goalkeeper, team_shape};
use crate::game::{GameMode, Kick, KickKind, KickTarget};
use crate::geometry::pitch::HALF_LENGTH;
use crate::player::WALK_SPEED;
use crate::rng::MatchRng;

/// Plan for player `g` while a set piece is pending.
pub(crate) fn plan(
    view: &MatchView,
    g: usize,
    analysis: &Analysis,
    difficulty: &Difficulty,
    rng: &mut MatchRng,
) -> Plan {
    let me = &view.players[g];
    let ball = view.ball.xy();
    if view.taker == Some(g) {
        let wait = 50 + (30.0 * (1.0 - difficulty.theta)) as u32;
        if view.set_piece_ticks < wait {
            return Plan::go(me.position, 0.0, analysis.frame.vec2(Vec2::X));
        }
        return take(view, g, analysis, rng);
    }
    if me.is_keeper() {
        return goalkeeper::plan(view, g, analysis, difficulty);
    }
    let mut target = team_shape::position(view, g, analysis, difficulty, false);
    let ours = view.taker.is_some_and(|t| view.players[t].side == me.side);
    if ours && view.mode == GameMode::Corner && (me.role.is_attacker() || me.role == crate::player::Role::CB) {
        // Attack the cross: spread across the six-yard box and the penalty spot.
        let y = (me.index as f32 * 2.3) % 12.0 - 6.0;
        target = analysis.frame.vec2(Vec2::new(HALF_LENGTH - 9.0, y));
    }
    let d = target.distance(me.position);
    Plan::go(target, if d > 8.0 { me.max_speed * 0.9 } else { WALK_SPEED }, ball - me.position)
}

/// The taker's kick, as GRF 2.10.2's AI chooses it (`ElizaController`'s set-piece branch): a
/// target point by the kind of restart, drawn at random, and the team-mate nearest it to pass
/// to (the keeper included; anyone but the taker). In the team's frame, x towards the goal it
/// attacks:
/// - goal kick: touchline's keeper's distribution (`goalkeeper::distribute`), not GRF's (60 % a
///   high pass to near 0.2 of the half length into their half, else a short pass to near 0.9 of
///   the keeper's x, and always short for a team with an agent; measured, not kept:
///   docs/grf-compatibility.md#formations);
/// - free kick: half a high pass to near their goal line (±10 m across), half a short pass to
///   near the point 10 m ahead of the ball (±10 m across);
/// - corner kick: 70 % a high pass to near 0.87-0.99 of the half length (±10 m across), else a
///   short pass to near (0.8 of the half length, 0.8 of the ball's y);
/// - throw-in (or kickoff): a short pass to the nearest team-mate;
/// - penalty kick: a shot at a point of the goal line up to 5 m either side of the centre, at
///   0.4-1 of full power (so some go wide).
fn take(view: &MatchView, g: usize, analysis: &Analysis, rng: &mut MatchRng) -> Plan {
    let me = &view.players[g];
    let frame = analysis.frame;
    let me_t = frame.vec2(me.position);
    let across = |rng: &mut MatchRng, half: f32| (rng.unit() * 2.0 - 1.0) * half;
    let (kind, point) = match view.mode {
        GameMode::Penalty => {
            let aim = frame.vec2(Vec2::new(HALF_LENGTH, across(rng, 5.0)));
            let power = 0.4 + 0.6 * rng.unit();
            return Plan {
                kick: Some(Kick { kind: KickKind::Shot, target: KickTarget::Point(aim), height: 0.5, power }),
                ..Plan::go(me.position, 0.0, aim - me.position)
            };
        }
        GameMode::GoalKick => return goalkeeper::distribute(view, g, u64::MAX, analysis),
        GameMode::FreeKick => {
            if rng.unit() > 0.5 {
                (KickKind::HighPass, Vec2::new(HALF_LENGTH, across(rng, 10.0)))
            } else {
                (KickKind::ShortPass, me_t + Vec2::new(10.0, across(rng, 10.0)))
            }
        }
        GameMode::Corner => {
            if rng.unit() > 0.3 {
                (KickKind::HighPass, Vec2::new(HALF_LENGTH * (0.99 - 0.12 * rng.unit()), across(rng, 10.0)))
            } else {
                (KickKind::ShortPass, Vec2::new(0.8 * HALF_LENGTH, 0.8 * me_t.y))
            }
        }
        _ => (KickKind::ShortPass, me_t),
    };
    let point = frame.vec2(point);
    let receiver = view
        .team(me.side)
        .iter()
        .filter(|m| m.active && m.index != me.index)
        .min_by(|a, b| a.position.distance_squared(point).total_cmp(&b.position.distance_squared(point)))
        .map_or(point, |m| m.position);
    kick(me.position, kind, receiver)
}

fn kick(from: Vec2, kind: KickKind, target: Vec2) -> Plan {
    Plan {
        kick: Some(Kick { kind, target: KickTarget::Point(target), height: 0.0, power: 0.5 }),
        ..Plan::go(from, 0.0, target - from)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ai::{Difficulty, prediction};
    use crate::game::Match;
    use crate::geometry::Side;
    use crate::player::Role;
    use crate::rules::{Restart, set_up_restart};
    use crate::scenario::{PlayerEntry, Scenario};

    /// Left keeper, centre back, two midfielders, a forward and a left midfielder out wide (the
    /// corner's taker); the right keeper and a defender.
    fn game(mode: GameMode, spot: Vec2) -> Match {
        let s = Scenario {
            left_team: vec![
                PlayerEntry::new(Role::GK, -1.0, 0.0),
                PlayerEntry::new(Role::CB, 0.2, 0.0),
                PlayerEntry::new(Role::CM, 0.5, 0.2),
                PlayerEntry::new(Role::CM, 0.6, -0.2),
                PlayerEntry::new(Role::CF, 0.8, 0.05),
                PlayerEntry::new(Role::LM, 0.9, 0.38),
            ],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CB, -0.8, 0.1)],
            ..Scenario::default()
        };
        let mut m = Match::new(&s, 0, 3);
        set_up_restart(&mut m, Restart { mode, side: Side::Left, spot });
        m
    }

    /// The kicks the left taker plays from `m`'s restart over 200 draws of the match's stream.
    fn kicks(m: &Match) -> Vec<Kick> {
        let view = crate::ai::test_view(m);
        let analysis = prediction::analyse(&view, Side::Left, &Difficulty::new(1.0));
        let taker = m.taker.expect("a taker");
        let mut rng = MatchRng::new(5, 0, true);
        (0..200).filter_map(|_| take(&view, taker, &analysis, &mut rng).kick).collect()
    }

    fn is_mate(m: &Match, at: Vec2) -> bool {
        m.team(Side::Left).iter().any(|p| p.position == at && Some(p.index) != m.taker.map(|t| m.players[t].index))
    }

    #[test]
    fn a_free_kick_in_range_is_a_pass_to_a_team_mate_high_or_short_never_a_shot() {
        let m = game(GameMode::FreeKick, Vec2::new(34.0, 0.0));
        let kicks = kicks(&m);
        assert!(kicks.iter().all(|k| k.kind != KickKind::Shot));
        assert!(kicks.iter().all(|k| matches!(k.target, KickTarget::Point(at) if is_mate(&m, at))));
        let high = kicks.iter().filter(|k| k.kind == KickKind::HighPass).count();
        assert!((70..=130).contains(&high), "{high} high passes of 200 (GRF: half)");
    }

    #[test]
    fn a_corner_is_mostly_a_high_ball_to_the_team_mate_nearest_the_goal_line() {
        let m = game(GameMode::Corner, Vec2::new(HALF_LENGTH, 34.0));
        let kicks = kicks(&m);
        let high: Vec<_> = kicks.iter().filter(|k| k.kind == KickKind::HighPass).collect();
        assert!((115..=165).contains(&high.len()), "{} high balls of 200 (GRF: 70 %)", high.len());
        // The forward, 44 m up, is the nearest to any point near their goal line.
        let forward = m.team(Side::Left)[4].position;
        assert!(high.iter().all(|k| k.target == KickTarget::Point(forward)));
    }

    #[test]
    fn a_penalty_is_a_shot_within_5_m_of_the_centre_of_the_goal_at_40_to_100_percent_power() {
        let m = game(GameMode::Penalty, Vec2::new(HALF_LENGTH - 11.0, 0.0));
        let kicks = kicks(&m);
        assert_eq!(kicks.len(), 200);
        for k in &kicks {
            assert_eq!(k.kind, KickKind::Shot);
            let KickTarget::Point(at) = k.target else { panic!("aimed at a point") };
            assert!(at.x == HALF_LENGTH && at.y.abs() <= 5.0, "{at}");
            assert!((0.4..=1.0).contains(&k.power), "{}", k.power);
        }
        // Some aim outside the posts (3.66 m from the centre), as GRF's do.
        assert!(kicks.iter().any(|k| matches!(k.target, KickTarget::Point(at) if at.y.abs() > 3.66)));
    }
}
