//! Applying one definition's statements on top of what it extends, with the checks that need
//! only the statement itself: settings (unknown keys, values of the wrong type), `team` (unknown
//! roles and formations, places), `ball`, `require`, `reward`, `end` and `start with`. Checks on
//! the merged scenario (team sizes, one goalkeeper, positions within the rim) are in `check.rs`.

use std::collections::HashMap;

use touchline_engine::scenario::{Body, EndCondition, Require, RewardKind, RewardTerm};
use touchline_engine::{PlayerEntry, Role, Scenario};

use super::condition::Context;
use super::origins::{Loc, Origins};
use super::value::{Frame, Reader, suggest_help};
use super::{behaviour, condition, pitch};
use crate::diagnostic::{Code, Diagnostic};
use crate::suggest;
use crate::syntax::{self, Condition, Definition, Expr, ExprKind, Flag, Span, StatementKind};

/// Words that begin a statement (for "is the team block's `}` missing?").
const STATEMENT_KEYWORDS: [&str; 8] = ["ball", "team", "require", "reward", "end", "on", "extends", "behaviour"];

/// Parts of a body read once its teams are in place, because they name players.
#[derive(Default)]
struct Deferred<'d> {
    /// Behaviours of player lines: (side, index in the team, behaviour).
    players: Vec<(syntax::Side, usize, &'d syntax::Behaviour)>,
    /// `behaviour PLAYER does …` statements.
    statements: Vec<(&'d Expr, &'d syntax::Behaviour)>,
    /// `end when` conditions of the condition language: (index in `end_when`, condition).
    ends: Vec<(usize, &'d Condition)>,
    /// Places relative to another body (`at left.CF + (-5 m, 0)`), read once the teams are set.
    places: Vec<super::relative::Deferred<'d>>,
}

/// The configuration keys and what they hold.
const KEYS: [&str; 15] = [
    "game_duration",
    "deterministic",
    "game_engine_random_seed",
    "real_time",
    "reverse_team_processing",
    "offsides",
    "end_episode_on_score",
    "end_episode_on_out_of_play",
    "end_episode_on_possession_change",
    "left_team_difficulty",
    "right_team_difficulty",
    "difficulty",
    "second_half",
    "control_all_players",
    "swap_teams_on_odd_episodes",
];

/// Whether `name` is a configuration key.
pub(crate) fn is_key(name: &str) -> bool {
    KEYS.contains(&name)
}

/// Applies `def`'s statements (except `extends`, which the caller resolved) to `s`.
pub(crate) fn apply(def: &Definition, s: &mut Scenario, origins: &mut Origins, r: &mut Reader<'_>) {
    let mut seen: HashMap<String, Span> = HashMap::new();
    let mut rewards_cleared = false;
    let mut requires = Vec::new();
    let mut deferred = Deferred::default();
    let (mut start_with_span, mut start_from_span) = (None, None);
    let inherited = super::reindex::Inherited::of(s, origins);
    for st in &def.statements {
        let key = match &st.kind {
            StatementKind::Extends(_) => "extends".to_owned(),
            StatementKind::Ball(_) => "ball".to_owned(),
            StatementKind::OddBall(_) => "on odd episodes ball".to_owned(),
            StatementKind::SwapTeams => "on odd episodes swap teams".to_owned(),
            StatementKind::Team(t) => format!("team {}", side_name(t.side.value)),
            StatementKind::End(_) => "end when".to_owned(),
            StatementKind::StartFrom(_) => "start from".to_owned(),
            StatementKind::StartWith(_) => "start with".to_owned(),
            // `difficulty` is another name for `right_team_difficulty`: giving both is a duplicate.
            StatementKind::Setting { key, .. } if key.value == "difficulty" => "right_team_difficulty".to_owned(),
            StatementKind::Setting { key, .. } => key.value.clone(),
            StatementKind::Behaviour { player, .. } => {
                format!("behaviour {}", r.source.inner().get(player.span.start..player.span.end).unwrap_or_default())
            }
            StatementKind::Curriculum(_) => "curriculum".to_owned(),
            StatementKind::Advance(_) => "advance when".to_owned(),
            // Parameters are gathered (and checked for duplicates) before the body is applied.
            StatementKind::Require { .. }
            | StatementKind::Reward { .. }
            | StatementKind::RewardOn(_)
            | StatementKind::Param { .. }
            | StatementKind::Assign { .. } => String::new(),
        };
        // A team block may be long: its first line (`team left …`) stands for it.
        let head = match &st.kind {
            StatementKind::Team(t) => Span { start: st.span.start, end: t.side.span.end },
            _ => st.span,
        };
        if !key.is_empty() {
            if let Some(first) = seen.get(&key) {
                r.diags.push(
                    Diagnostic::new(Code::Duplicate, format!("`{key}` is given twice"), r.source, head, "again here")
                        .with_label(*first, "first given here")
                        .with_help("a definition states each thing once; remove one of them"),
                );
                continue;
            }
            seen.insert(key, head);
        }
        match &st.kind {
            StatementKind::Extends(_) => {}
            StatementKind::Setting { key, value } => setting(s, key, value, r),
            StatementKind::Ball(place) if super::relative::is_relative(place) => {
                let syntax::Place::At(expr) = place else { continue };
                deferred.places.retain(|d| d.target != super::relative::Target::Ball);
                deferred.places.push(super::relative::Deferred { target: super::relative::Target::Ball, expr });
                origins.ball = Some(Loc { source: r.source.clone(), span: st.span });
            }
            StatementKind::Ball(place) => {
                deferred.places.retain(|d| d.target != super::relative::Target::Ball);
                if let Some((nominal, random)) = r.place(place, Frame::Ball) {
                    s.ball_position = nominal;
                    s.ball_random = random;
                    origins.ball = Some(Loc { source: r.source.clone(), span: st.span });
                }
            }
            StatementKind::OddBall(place) => super::relative::odd_ball(place, s, r, &mut deferred.places),
            StatementKind::SwapTeams => s.swap_teams_on_odd_episodes = true,
            StatementKind::Team(t) => team(t, s, origins, r, &mut deferred),
            StatementKind::Behaviour { player, behaviour } => deferred.statements.push((player, behaviour)),
            StatementKind::Require { .. } => requires.push(st),
            StatementKind::Reward { terms, weight } => {
                if !rewards_cleared {
                    s.rewards.clear();
                    rewards_cleared = true;
                }
                let weight = weight.as_ref().map_or(Some(1.0), |w| reward_number(r, w, "a weight"));
                for term in terms {
                    if let (Some(reward), Some(weight)) = (reward_kind(term, r), weight) {
                        s.rewards.push(RewardTerm { reward, weight });
                    }
                }
            }
            StatementKind::RewardOn(ro) => {
                if !rewards_cleared {
                    s.rewards.clear();
                    rewards_cleared = true;
                }
                if let Some(term) = super::events::reward_on(ro, r) {
                    s.rewards.push(term);
                }
            }
            StatementKind::End(conditions) => deferred.ends = condition::end_when(conditions, s, r),
            StatementKind::StartFrom(path) => {
                if let Some(with) = start_with_span {
                    super::start::both_starts(with, st.span, r);
                    continue;
                }
                start_from_span = Some(st.span);
                s.start_with = None;
                origins.start_with = None;
                super::start::start_from(path, s, r);
            }
            StatementKind::StartWith(w) => {
                if let Some(from) = start_from_span {
                    super::start::both_starts(st.span, from, r);
                    continue;
                }
                start_with_span = Some(st.span);
                s.start_state = None;
                origins.start_with = Some(Loc { source: r.source.clone(), span: st.span });
                super::start::start_with(w, st.span, s, r);
            }
            // Read by the compiler: parameters before the body, a curriculum and its criteria
            // after the scenario is complete.
            StatementKind::Param { .. }
            | StatementKind::Assign { .. }
            | StatementKind::Curriculum(_)
            | StatementKind::Advance(_) => {}
        }
    }
    // Behaviours, conditions, requires and relative places name players, so they are read once
    // this body's teams are in place.
    super::relative::resolve(&deferred.places, s, r);
    super::start::ball_on_the_spot(s);
    behaviours(&deferred, s, r);
    for &(k, c) in &deferred.ends {
        if let Some(c) = condition::condition(c, Context::End, s, r) {
            s.end_when[k] = EndCondition::When(c);
        }
    }
    let written = super::reindex::Written {
        ball: seen.contains_key("ball"),
        odd_ball: seen.contains_key("on odd episodes ball"),
        requires: !requires.is_empty(),
        // A team with errors is incomplete: its indices say nothing.
        team: [("team left", 0), ("team right", 1)]
            .map(|(k, i)| seen.get(k).copied().filter(|_| !origins.team_errors[i])),
    };
    if !requires.is_empty() {
        s.requires.clear();
        origins.requires.clear();
    }
    for st in requires {
        if let StatementKind::Require { lhs, at_least, rhs } = &st.kind
            && let Some(req) = require(lhs, *at_least, rhs, s, r)
        {
            s.requires.push(req);
            origins.requires.push(Loc { source: r.source.clone(), span: st.span });
        }
    }
    inherited.check(s, origins, &written, r);
}

fn side_name(side: syntax::Side) -> &'static str {
    match side {
        syntax::Side::Left => "left",
        syntax::Side::Right => "right",
    }
}

fn setting(s: &mut Scenario, key: &syntax::Spanned<String>, value: &Expr, r: &mut Reader<'_>) {
    let k = key.value.as_str();
    match k {
        "game_duration" => s.game_duration = r.steps(value, k, 1).unwrap_or(s.game_duration),
        "second_half" => s.second_half = r.steps(value, k, 0).unwrap_or(s.second_half),
        "game_engine_random_seed" => {
            s.game_engine_random_seed = r.steps(value, k, 0).map_or(s.game_engine_random_seed, u64::from);
        }
        // GRF keys about its renderer's pacing and internal update order: accepted for
        // compatibility, with a warning that they change nothing here.
        "real_time" | "reverse_team_processing" => {
            if r.boolean(value).is_some() {
                r.diags.push(
                    Diagnostic::new(
                        Code::NoEffect,
                        format!("`{k}` has no effect in touchline"),
                        r.source,
                        key.span,
                        "ignored",
                    )
                    .with_help(
                        "touchline never sleeps to pace play and updates both teams symmetrically; remove the line",
                    ),
                );
            }
        }
        "left_team_difficulty" => s.left_team_difficulty = r.fraction(value, k).unwrap_or(s.left_team_difficulty),
        "right_team_difficulty" | "difficulty" => {
            s.right_team_difficulty = r.fraction(value, k).unwrap_or(s.right_team_difficulty);
        }
        _ => {
            let target = match k {
                "deterministic" => &mut s.deterministic,
                "offsides" => &mut s.offsides,
                "end_episode_on_score" => &mut s.end_episode_on_score,
                "end_episode_on_out_of_play" => &mut s.end_episode_on_out_of_play,
                "end_episode_on_possession_change" => &mut s.end_episode_on_possession_change,
                "control_all_players" => &mut s.control_all_players,
                "swap_teams_on_odd_episodes" => &mut s.swap_teams_on_odd_episodes,
                _ => {
                    let close = suggest::closest(k, &KEYS);
                    r.error_help(
                        Code::UnknownKey,
                        format!("unknown key `{k}`"),
                        key.span,
                        "not a configuration key",
                        suggest_help(&close, &format!("the keys are {}", KEYS.join(", "))),
                    );
                    return;
                }
            };
            if let Some(b) = r.boolean(value) {
                *target = b;
            }
        }
    }
}

/// Compiles the deferred behaviours into the players' entries: those of player lines first, then
/// `behaviour` statements (which replace them).
fn behaviours(deferred: &Deferred<'_>, s: &mut Scenario, r: &mut Reader<'_>) {
    for &(side, k, b) in &deferred.players {
        let side = engine_side(side);
        if let Some(stages) = behaviour::behaviour(b, side, k, s, r) {
            team_mut(s, side)[k].behaviour = stages;
        }
    }
    for &(player, b) in &deferred.statements {
        let Some((side, k)) = condition::player(player, s, r) else { continue };
        if let Some(stages) = behaviour::behaviour(b, side, k, s, r) {
            team_mut(s, side)[k].behaviour = stages;
        }
    }
}

fn engine_side(side: syntax::Side) -> touchline_engine::Side {
    match side {
        syntax::Side::Left => touchline_engine::Side::Left,
        syntax::Side::Right => touchline_engine::Side::Right,
    }
}

fn team_mut(s: &mut Scenario, side: touchline_engine::Side) -> &mut Vec<PlayerEntry> {
    match side {
        touchline_engine::Side::Left => &mut s.left_team,
        touchline_engine::Side::Right => &mut s.right_team,
    }
}

fn team<'d>(
    t: &'d syntax::Team,
    s: &mut Scenario,
    origins: &mut Origins,
    r: &mut Reader<'_>,
    deferred: &mut Deferred<'d>,
) {
    let side = t.side.value;
    let errors_before = r.diags.errors().count();
    let mut entries = Vec::new();
    let mut locs = Vec::new();
    if let Some(name) = &t.formation {
        match pitch::formation(&name.value) {
            Some(players) => {
                for &(role, x, y) in players {
                    entries.push(PlayerEntry::new(role, x, y));
                    locs.push(Loc { source: r.source.clone(), span: name.span });
                }
            }
            None => {
                let close = suggest::closest(&name.value, &pitch::FORMATION_NAMES);
                r.error_help(
                    Code::UnknownFormation,
                    format!("unknown formation `{}`", name.value),
                    name.span,
                    "not a formation",
                    suggest_help(&close, &format!("the formations are {}", pitch::FORMATION_NAMES.join(", "))),
                );
            }
        }
    }
    for p in &t.players {
        let role = Role::from_name(&p.role.value);
        if role.is_none() {
            let names: Vec<&str> = Role::ALL.iter().map(|r| r.name()).collect();
            let upper = p.role.value.to_ascii_uppercase();
            let close =
                if Role::from_name(&upper).is_some() { vec![] } else { suggest::closest(&p.role.value, &names) };
            let help = if Role::from_name(&upper).is_some() {
                format!("roles are upper case: `{upper}`")
            } else if STATEMENT_KEYWORDS.contains(&p.role.value.as_str()) {
                format!("`{}` starts a statement: is the `}}` closing this team block missing above it?", p.role.value)
            } else {
                suggest_help(&close, &format!("the roles are {}", names.join(" ")))
            };
            r.error_help(
                Code::UnknownRole,
                format!("unknown role `{}`", p.role.value),
                p.role.span,
                "not a role",
                help,
            );
        }
        let relative = super::relative::is_relative(&p.place);
        let place = if relative { Some(([0.0, 0.0], None)) } else { r.place(&p.place, Frame::Player) };
        let (Some(role), Some((nominal, random))) = (role, place) else { continue };
        if let (true, syntax::Place::At(expr)) = (relative, &p.place) {
            let target = match side {
                syntax::Side::Left => super::relative::Target::Left(entries.len()),
                syntax::Side::Right => super::relative::Target::Right(entries.len()),
            };
            deferred.places.push(super::relative::Deferred { target, expr });
        }
        let mut e = PlayerEntry::new(role, nominal[0], nominal[1]);
        e.random = random;
        for f in &p.flags {
            match &f.value {
                Flag::Lazy => e.lazy = true,
                Flag::Controllable => e.controllable = true,
                Flag::NotControllable => e.controllable = false,
                Flag::Facing(value) => e.facing = super::start::facing(value, r),
            }
        }
        if let Some(b) = &p.behaviour {
            deferred.players.push((side, entries.len(), b));
        }
        entries.push(e);
        locs.push(Loc { source: r.source.clone(), span: p.span });
    }
    let i = usize::from(side == syntax::Side::Right);
    origins.team[i] = Some(Loc { source: r.source.clone(), span: t.side.span });
    origins.team_errors[i] = r.diags.errors().count() > errors_before;
    origins.players[i] = locs;
    match side {
        syntax::Side::Left => s.left_team = entries,
        syntax::Side::Right => s.right_team = entries,
    }
}

fn reward_kind(term: &syntax::RewardTerm, r: &mut Reader<'_>) -> Option<RewardKind> {
    let e = match term {
        syntax::RewardTerm::Script(path) => return Some(RewardKind::Script { path: path.value.clone() }),
        syntax::RewardTerm::Expr(e) => e,
    };
    let (name, args) = match &e.kind {
        ExprKind::Path { head, field: None } => (head, &[][..]),
        ExprKind::Call { name, args } => (name, args.as_slice()),
        _ => {
            r.error_help(
                Code::WrongType,
                format!("expected a reward, found {}", e.describe()),
                e.span,
                "not a reward",
                "the rewards are scoring, checkpoint(count, value) and script \"file.rhai\"",
            );
            return None;
        }
    };
    match name.value.as_str() {
        "scoring" if args.is_empty() => Some(RewardKind::Scoring),
        "scoring" => {
            r.error_help(
                Code::Arguments,
                "`scoring` takes no arguments",
                e.span,
                "no arguments here",
                "write `scoring`; to scale it, add `weight W` to the reward statement",
            );
            None
        }
        "checkpoint" | "checkpoints" => {
            let (mut count, mut value) = (10u8, 0.1f32);
            for (i, a) in args.iter().enumerate() {
                let which = a.name.as_ref().map_or(if i == 0 { "count" } else { "value" }, |n| n.value.as_str());
                match which {
                    "count" => {
                        let n = r.steps(&a.value, "the checkpoint count", 1)?;
                        if n > 100 {
                            r.error_help(
                                Code::OutOfRange,
                                format!("at most 100 checkpoints, found {n}"),
                                a.value.span,
                                "too many",
                                "write a count from 1 to 100 (GRF uses 10)",
                            );
                            return None;
                        }
                        count = n as u8;
                    }
                    "value" => value = reward_number(r, &a.value, "the checkpoint value")?,
                    other => {
                        let span = a.name.as_ref().map_or(a.value.span, |n| n.span);
                        r.error_help(
                            Code::Arguments,
                            format!("`checkpoint` has no argument `{other}`"),
                            span,
                            "unknown argument",
                            "write `checkpoint(count: 10, value: 0.1)`",
                        );
                        return None;
                    }
                }
            }
            Some(RewardKind::Checkpoints { count, value })
        }
        other => {
            let close = suggest::closest(other, &["scoring", "checkpoint"]);
            r.error_help(
                Code::UnknownFunction,
                format!("unknown reward `{other}`"),
                name.span,
                "not a reward",
                suggest_help(&close, "the rewards are scoring, checkpoint(count, value) and script \"file.rhai\""),
            );
            None
        }
    }
}

fn require(lhs: &Expr, at_least: bool, rhs: &Expr, s: &Scenario, r: &mut Reader<'_>) -> Option<Require> {
    let ExprKind::Call { name, args } = &lhs.kind else {
        r.error_help(
            Code::WrongType,
            format!("expected `distance(a, b)`, found {}", lhs.describe()),
            lhs.span,
            "not a constraint",
            "constraints are `distance(a, b) >= D m` and `distance(a, b) <= D m`",
        );
        return None;
    };
    if name.value != "distance" {
        let close = suggest::closest(&name.value, &["distance"]);
        r.error_help(
            Code::UnknownFunction,
            format!("unknown constraint `{}`", name.value),
            name.span,
            "not a constraint",
            suggest_help(&close, "constraints are `distance(a, b) >= D m` and `distance(a, b) <= D m`"),
        );
        return None;
    }
    if args.len() != 2 {
        r.error_help(
            Code::Arguments,
            format!("`distance` takes 2 arguments, found {}", args.len()),
            lhs.span,
            "wrong number of arguments",
            "write `distance(a, b)` with a and b the ball, `left[i]`, `right[i]` or `left.ROLE`",
        );
        return None;
    }
    let a = body(&args[0].value, s, r);
    let b = body(&args[1].value, s, r);
    let metres = r.metres(rhs);
    let (a, b, metres) = (a?, b?, metres?);
    Some(if at_least { Require::MinDistance { a, b, metres } } else { Require::MaxDistance { a, b, metres } })
}

/// `ball`, `left[i]`, `right[i]`, `left.ROLE` (the only player of that role).
pub(crate) fn body(e: &Expr, s: &Scenario, r: &mut Reader<'_>) -> Option<Body> {
    match &e.kind {
        ExprKind::Path { head, field: None } if head.value == "ball" => Some(Body::Ball),
        ExprKind::Index { name, .. } | ExprKind::Path { head: name, field: Some(_) }
            if matches!(name.value.as_str(), "left" | "right") =>
        {
            condition::player(e, s, r).map(|(side, i)| match side {
                touchline_engine::Side::Left => Body::Left(i),
                touchline_engine::Side::Right => Body::Right(i),
            })
        }
        _ => {
            r.error_help(
                Code::UnknownPlayer,
                format!("`{}` is not a player or the ball", e.describe()),
                e.span,
                "here",
                "name the ball, `left[i]`, `right[i]` (0-based, in the team's order) or `left.ROLE`",
            );
            None
        }
    }
}

/// A plain number that a reward pays or multiplies (a weight, an event reward, a checkpoint
/// value), at most [`RewardTerm::MAX_WEIGHT`] in magnitude (`tl::E149` at its text otherwise): the
/// terms of a step are summed in f32, and four weights of 1e38 would sum to inf and pay NaN.
pub(crate) fn reward_number(r: &mut Reader<'_>, e: &Expr, what: &str) -> Option<f32> {
    let v = r.plain_number(e, what)?;
    if v.abs() > f64::from(RewardTerm::MAX_WEIGHT) {
        r.error_help(
            Code::RewardTooLarge,
            format!("{what} of {v:e} is too large: a reward weight or value is at most 1e6 in magnitude"),
            e.span,
            "too large",
            "rewards are summed in 32-bit floats; scale every term down together (e.g. weights 1 and 0.1, not 1e38)",
        );
        return None;
    }
    Some(v as f32)
}
