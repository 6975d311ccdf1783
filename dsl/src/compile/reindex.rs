//! A `team` statement replaces its side's list wholesale, but what the parent says about that
//! list's players (a relative place, `require`) is compiled to an index in it: `left.CF` is
//! `left[1]`. When a child's list puts another role at that index, or has no player there, the
//! parent's place or constraint would silently move to someone else: `tl::E155`, on the child's
//! `team` statement.

use touchline_engine::scenario::{Body, Require, Spot};
use touchline_engine::{Role, Scenario};

use super::origins::{Loc, Origins};
use super::value::Reader;
use crate::diagnostic::{Code, Diagnostic};
use crate::syntax::Span;

/// What the parent scenario says about players by index, before a body applies.
pub(crate) struct Inherited {
    /// The parent's roles of each side's list.
    roles: [Vec<Role>; 2],
    /// (what names a player, the player it names).
    refs: Vec<(Naming, Body)>,
    /// Where each of `refs` was written, when known.
    locs: Vec<Option<Loc>>,
}

/// Something of the parent that names a player by index.
#[derive(Clone, Copy, PartialEq)]
enum Naming {
    /// The `ball` place.
    Ball,
    /// The `on odd episodes ball` place.
    OddBall,
    /// The place of this player.
    Player(Body),
    /// A `require`.
    Require,
}

/// What a body wrote itself, so no longer inherited.
pub(crate) struct Written {
    pub(crate) ball: bool,
    pub(crate) odd_ball: bool,
    pub(crate) requires: bool,
    /// The head (`team left`) of each side's `team` statement.
    pub(crate) team: [Option<Span>; 2],
}

impl Inherited {
    pub(crate) fn of(s: &Scenario, origins: &Origins) -> Inherited {
        let mut refs = Vec::new();
        let mut locs = Vec::new();
        let anchor = |spot: Option<&Spot>| match spot {
            Some(Spot::Relative(a)) => Some(a.of),
            _ => None,
        };
        let mut add = |naming: Naming, named: Body, loc: Option<&Loc>| {
            refs.push((naming, named));
            locs.push(loc.cloned());
        };
        if let Some(b) = anchor(s.ball_random.as_ref()) {
            add(Naming::Ball, b, origins.ball.as_ref());
        }
        if let Some(b) = anchor(s.odd_episode_ball_random.as_ref()) {
            add(Naming::OddBall, b, None);
        }
        for (side, team) in [&s.left_team, &s.right_team].into_iter().enumerate() {
            for (i, e) in team.iter().enumerate() {
                let body = if side == 0 { Body::Left(i) } else { Body::Right(i) };
                if let Some(b) = anchor(e.random.as_ref()) {
                    add(Naming::Player(body), b, origins.players[side].get(i));
                }
            }
        }
        for (k, r) in s.requires.iter().enumerate() {
            let (Require::MinDistance { a, b, .. } | Require::MaxDistance { a, b, .. }) = r;
            add(Naming::Require, *a, origins.requires.get(k));
            add(Naming::Require, *b, origins.requires.get(k));
        }
        let roles = |team: &[touchline_engine::PlayerEntry]| team.iter().map(|e| e.role).collect();
        Inherited { roles: [roles(&s.left_team), roles(&s.right_team)], refs, locs }
    }

    /// `tl::E155` for each player the parent names by index whose index, in a list this body
    /// replaced, now holds another role or no one (once per player).
    pub(crate) fn check(&self, s: &Scenario, origins: &Origins, written: &Written, r: &mut Reader<'_>) {
        let mut reported: Vec<Body> = Vec::new();
        let now = Inherited::of(s, origins);
        for (&(naming, named), loc) in self.refs.iter().zip(&self.locs) {
            let still_inherited = now.refs.contains(&(naming, named))
                && match naming {
                    Naming::Ball => !written.ball,
                    Naming::OddBall => !written.odd_ball,
                    Naming::Require => !written.requires,
                    Naming::Player(Body::Left(_)) => written.team[0].is_none(),
                    Naming::Player(_) => written.team[1].is_none(),
                };
            let (side, i) = match named {
                Body::Ball => continue,
                Body::Left(i) => (0, i),
                Body::Right(i) => (1, i),
            };
            let Some(head) = written.team[side] else { continue };
            if !still_inherited || reported.contains(&named) {
                continue;
            }
            let Some(&before) = self.roles[side].get(i) else { continue };
            let team = if side == 0 { &s.left_team } else { &s.right_team };
            let now = team.get(i).map(|e| e.role);
            if now == Some(before) {
                continue;
            }
            reported.push(named);
            let name = ["left", "right"][side];
            let there = now.map_or_else(|| format!("no one (it has {} players)", team.len()), |r| r.to_string());
            let what = match naming {
                Naming::Ball => "`ball` place".to_owned(),
                Naming::OddBall => "`on odd episodes ball` place".to_owned(),
                Naming::Require => "`require`".to_owned(),
                Naming::Player(Body::Left(k)) => format!("place of left[{k}]"),
                Naming::Player(Body::Right(k)) => format!("place of right[{k}]"),
                Naming::Player(Body::Ball) => "place".to_owned(),
            };
            let mut d = Diagnostic::new(
                Code::TeamReordered,
                format!("the parent's {what} names {name}[{i}] ({before}), and this `team {name}` puts {there} there"),
                r.source,
                head,
                format!("{name}[{i}] is {there} here"),
            )
            .with_help(format!(
                "places and constraints name a player by his index in the list (`{name}.{before}` too): keep \
                 {before} at index {i} of this list, or write the parent's {what} again in this definition so \
                 that it names this list"
            ));
            if let Some(loc) = loc.as_ref().filter(|l| std::sync::Arc::ptr_eq(&l.source, r.source)) {
                d = d.with_label(loc.span, format!("names {name}[{i}] ({before})"));
            }
            r.diags.push(d);
        }
    }
}
