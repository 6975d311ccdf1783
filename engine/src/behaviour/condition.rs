//! Evaluating a [`Condition`] against a [`Match`]: the `until` of a behaviour stage (every tick)
//! and `end when` (after every env step).

use glam::Vec2;

use crate::game::Match;
use crate::geometry::coords::{obs_to_world, world_to_obs};
use crate::geometry::{Side, TeamFrame};
use crate::scenario::{Condition, Owner, Target};

/// Where a condition is read: the frame of its points and regions, the player `me` stands for,
/// the done flag of the stage it ends and the env step count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Scope {
    /// Frame of points and regions: `Side::Left` is the global frame (the left team attacks
    /// +x); `Side::Right` turns them by 180° (the right team's own frame).
    pub frame: Side,
    /// The behaving player (side, index in team); `None` in `end when`, where `me` matches
    /// nothing.
    pub me: Option<(Side, usize)>,
    /// The current behaviour stage has finished by itself (`Condition::Done`).
    pub done: bool,
    /// Env steps taken this episode (`Condition::Steps`).
    pub steps: u32,
}

impl Scope {
    /// The scope of `end when`: global frame, no `me`, never done.
    pub fn global(steps: u32) -> Scope {
        Scope { frame: Side::Left, me: None, done: false, steps }
    }

    /// The scope of a behaviour of `side`'s player `index`: his team's frame.
    pub fn player(side: Side, index: usize, done: bool, steps: u32) -> Scope {
        Scope { frame: side, me: Some((side, index)), done, steps }
    }

    /// A target as a player (side, index in team), when it is one.
    pub fn player_of(&self, target: Target) -> Option<(Side, usize)> {
        match target {
            Target::Me => self.me,
            Target::Left(i) => Some((Side::Left, i)),
            Target::Right(i) => Some((Side::Right, i)),
            Target::Ball | Target::Point(_) => None,
        }
    }

    /// Where a target is (m, global frame); `None` for `me` without a player or a player index
    /// the match does not have.
    pub fn position(&self, game: &Match, target: Target) -> Option<Vec2> {
        match target {
            Target::Ball => Some(game.ball().xy()),
            Target::Point([x, y]) => Some(self.point(x, y)),
            _ => {
                let (side, i) = self.player_of(target)?;
                game.team(side).get(i).map(|p| p.position)
            }
        }
    }

    /// A point in this scope's frame (normalised observation units: x · 54.4 m, y · 83.6 m, as
    /// observations and `ball in` regions) in metres, global frame.
    pub fn point(&self, x: f32, y: f32) -> Vec2 {
        TeamFrame::of(self.frame).vec2(obs_to_world(x, y))
    }
}

impl Condition {
    /// Whether the condition holds in `game`, read in `scope`. A target that does not exist
    /// (`me` in `end when`, a player index beyond the team) makes its comparison false.
    pub fn holds(&self, game: &Match, scope: &Scope) -> bool {
        match self {
            Condition::All(all) => all.iter().all(|c| c.holds(game, scope)),
            Condition::Any(any) => any.iter().any(|c| c.holds(game, scope)),
            Condition::Not(c) => !c.holds(game, scope),
            Condition::Distance { a, b, op, metres } => match (scope.position(game, *a), scope.position(game, *b)) {
                (Some(a), Some(b)) => op.holds(a.distance(b), *metres),
                _ => false,
            },
            Condition::In { what, region } => scope.position(game, *what).is_some_and(|at| {
                let [x, y] = world_to_obs(TeamFrame::of(scope.frame).vec2(at));
                region.contains(x, y)
            }),
            Condition::Owner(owner) => {
                let now = game.owner();
                match owner {
                    Owner::Nobody => now.is_none(),
                    Owner::Team(side) => now.is_some_and(|(s, _)| s == *side),
                    Owner::Player(target) => scope.player_of(*target).is_some_and(|p| now == Some(p)),
                }
            }
            Condition::Mode(mode) => game.mode() == *mode,
            Condition::Steps { op, steps } => op.compare(scope.steps, *steps),
            Condition::Score { side, op, goals } => op.compare(game.score()[side.index()], *goals),
            Condition::Done => scope.done,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::game::GameMode;
    use crate::player::Role;
    use crate::scenario::{Comparison, PlayerEntry, Region, Scenario};

    /// Left: GK, CF at (0.5, 0) own frame = 27.5 m; right: GK, CB at (-0.5, 0.2) own frame =
    /// (27.5, -17.0) m global. Ball at (0.5, 0) = 27.2 m.
    fn game() -> Match {
        let s = Scenario {
            left_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CF, 0.5, 0.0)],
            right_team: vec![PlayerEntry::new(Role::GK, -1.0, 0.0), PlayerEntry::new(Role::CB, -0.5, 0.2)],
            ball_position: [0.5, 0.0],
            deterministic: true,
            ..Scenario::default()
        };
        Match::new(&s, 0, 1)
    }

    fn dist(a: Target, b: Target, op: Comparison, metres: f32) -> Condition {
        Condition::Distance { a, b, op, metres }
    }

    #[test]
    fn distances_are_in_metres_between_targets() {
        let g = game();
        let scope = Scope::global(0);
        // CF at 27.5 m, ball at 27.2 m.
        assert!(dist(Target::Ball, Target::Left(1), Comparison::Lt, 0.5).holds(&g, &scope));
        assert!(!dist(Target::Ball, Target::Left(1), Comparison::Lt, 0.2).holds(&g, &scope));
        // Right CB at (27.5, -17.0): 17 m from the left CF.
        assert!(dist(Target::Left(1), Target::Right(1), Comparison::Ge, 16.9).holds(&g, &scope));
        assert!(dist(Target::Left(1), Target::Right(1), Comparison::Le, 17.1).holds(&g, &scope));
        // A point is read in the scope's frame: (-0.5, 0) of the right team is +27.2 m global.
        let right = Scope::player(Side::Right, 1, false, 0);
        assert!(dist(Target::Ball, Target::Point([-0.5, 0.0]), Comparison::Lt, 0.01).holds(&g, &right));
        assert!(dist(Target::Ball, Target::Point([0.5, 0.0]), Comparison::Lt, 0.01).holds(&g, &scope));
        // `me` is the right CB in his scope and nothing in `end when`.
        assert!(dist(Target::Me, Target::Right(1), Comparison::Eq, 0.0).holds(&g, &right));
        assert!(!dist(Target::Me, Target::Ball, Comparison::Ge, 0.0).holds(&g, &scope));
        assert!(!dist(Target::Left(7), Target::Ball, Comparison::Ne, 1.0).holds(&g, &scope));
    }

    #[test]
    fn regions_follow_the_frame() {
        let g = game();
        let right_half = Region::Rect { x: [0.0, 1.0], y: [-0.42, 0.42] };
        let in_right_half = |what| Condition::In { what, region: right_half.clone() };
        assert!(in_right_half(Target::Ball).holds(&g, &Scope::global(0)));
        // In the right team's frame the ball is in its own half (x < 0).
        assert!(!in_right_half(Target::Ball).holds(&g, &Scope::player(Side::Right, 1, false, 0)));
        assert!(!in_right_half(Target::Left(0)).holds(&g, &Scope::global(0)));
        let circle = Condition::In { what: Target::Right(1), region: Region::Circle { x: 0.5, y: -0.2, r: 0.02 } };
        assert!(circle.holds(&g, &Scope::global(0)));
    }

    #[test]
    fn owner_mode_steps_score_and_done() {
        let mut g = game();
        let scope = Scope::global(12);
        assert!(Condition::Owner(Owner::Nobody).holds(&g, &scope));
        assert!(Condition::Mode(GameMode::Normal).holds(&g, &scope));
        assert!(!Condition::Mode(GameMode::Corner).holds(&g, &scope));
        assert!(Condition::Steps { op: Comparison::Ge, steps: 12 }.holds(&g, &scope));
        assert!(!Condition::Steps { op: Comparison::Gt, steps: 12 }.holds(&g, &scope));
        assert!(Condition::Score { side: Side::Right, op: Comparison::Eq, goals: 0 }.holds(&g, &scope));
        g.score = [2, 0];
        assert!(Condition::Score { side: Side::Left, op: Comparison::Ge, goals: 2 }.holds(&g, &scope));
        g.owner = Some(g.global_index(Side::Left, 1));
        assert!(Condition::Owner(Owner::Team(Side::Left)).holds(&g, &scope));
        assert!(!Condition::Owner(Owner::Team(Side::Right)).holds(&g, &scope));
        assert!(Condition::Owner(Owner::Player(Target::Left(1))).holds(&g, &scope));
        let me = Scope::player(Side::Left, 1, true, 0);
        assert!(Condition::Owner(Owner::Player(Target::Me)).holds(&g, &me));
        assert!(!Condition::Owner(Owner::Player(Target::Me)).holds(&g, &scope));
        assert!(Condition::Done.holds(&g, &me) && !Condition::Done.holds(&g, &scope));
    }

    #[test]
    fn connectives() {
        let g = game();
        let scope = Scope::global(5);
        let yes = Condition::Steps { op: Comparison::Eq, steps: 5 };
        let no = Condition::Steps { op: Comparison::Ne, steps: 5 };
        assert!(Condition::All(vec![yes.clone(), yes.clone()]).holds(&g, &scope));
        assert!(!Condition::All(vec![yes.clone(), no.clone()]).holds(&g, &scope));
        assert!(Condition::Any(vec![no.clone(), yes.clone()]).holds(&g, &scope));
        assert!(!Condition::Any(vec![no.clone()]).holds(&g, &scope));
        assert!(Condition::Not(Box::new(no)).holds(&g, &scope));
        assert!(Condition::All(vec![]).holds(&g, &scope) && !Condition::Any(vec![]).holds(&g, &scope));
    }
}
