//! Places relative to another player or the ball (issue 18, item 1): `at left.LM`,
//! `at left.CF + (-5 m, 0)`, `at behind(left.CF, 5 m)`, `at ahead(…)`, `at beside(…)`,
//! `at near(left.CF, 3 m)`.
//!
//! Such a place names a body of the teams, so it is read once the body's teams are in place
//! ([`resolve`], like behaviours and `require`); until then its entry holds the origin. It compiles
//! to the engine's [`Spot::Relative`] ([`Anchor`]): the engine draws the named body first and
//! places this one from where it was drawn, at every reset. Offsets are metres in the named body's
//! frame (a player's: x towards the goal he attacks; the ball's: the global frame); a plain number
//! is in scenario units of the placed body and is converted to metres.

use touchline_engine::Scenario;
use touchline_engine::scenario::{Anchor, Body, Spot, relative_cycle};

use super::pitch::{BALL_X_METRES, BALL_Y_METRES, PLAYER_X_METRES, PLAYER_Y_METRES};
use super::value::{Frame, Reader};
use crate::diagnostic::{Code, Diagnostic};
use crate::syntax::{BinaryOp, Expr, ExprKind, Place, Span};

/// The functions of a relative place.
const FUNCTIONS: [&str; 4] = ["behind", "ahead", "beside", "near"];

/// What a deferred relative place positions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Target {
    Ball,
    /// The ball in odd episodes (`on odd episodes ball at …`).
    OddBall,
    Left(usize),
    Right(usize),
}

/// A relative place read before the teams were complete.
pub(crate) struct Deferred<'a> {
    pub(crate) target: Target,
    pub(crate) expr: &'a Expr,
}

/// Whether `place` is a relative one (so read later by [`resolve`]).
pub(crate) fn is_relative(place: &Place) -> bool {
    match place {
        Place::At(e) => is_relative_expr(e),
        Place::In(_) => false,
    }
}

fn is_relative_expr(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Path { .. } | ExprKind::Index { .. } => is_reference(e),
        ExprKind::Binary { op: BinaryOp::Add | BinaryOp::Sub, lhs, .. } => is_reference(lhs),
        ExprKind::Call { name, .. } => FUNCTIONS.contains(&name.value.as_str()),
        _ => false,
    }
}

/// `ball`, `left.ROLE`, `left[i]`.
fn is_reference(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Path { head, field } => {
            (head.value == "ball" && field.is_none())
                || (matches!(head.value.as_str(), "left" | "right") && field.is_some())
        }
        ExprKind::Index { name, .. } => matches!(name.value.as_str(), "left" | "right"),
        _ => false,
    }
}

/// `on odd episodes ball at PLACE`: a fixed point, a random place, or a relative one (deferred
/// like the others, and placed from the bodies as they are drawn in odd episodes).
pub(crate) fn odd_ball<'a>(place: &'a Place, s: &mut Scenario, r: &mut Reader<'_>, deferred: &mut Vec<Deferred<'a>>) {
    deferred.retain(|d| d.target != Target::OddBall);
    if let (true, Place::At(expr)) = (is_relative(place), place) {
        // Its nominal point is set once the anchor is read.
        s.odd_episode_ball_position = Some(s.ball_position);
        s.odd_episode_ball_random = None;
        deferred.push(Deferred { target: Target::OddBall, expr });
    } else if let Some((nominal, random)) = r.place(place, Frame::Ball) {
        s.odd_episode_ball_position = Some(nominal);
        s.odd_episode_ball_random = random;
    }
}

/// Reads every deferred relative place into its entry's [`Spot::Relative`], sets the entries'
/// nominal points, and reports places that depend on each other in a circle (`tl::E151`).
pub(crate) fn resolve(deferred: &[Deferred<'_>], s: &mut Scenario, r: &mut Reader<'_>) {
    let mut spans = Vec::new();
    for d in deferred {
        let frame = if matches!(d.target, Target::Ball | Target::OddBall) { Frame::Ball } else { Frame::Player };
        let Some(anchor) = anchor(d.expr, frame, s, r) else { continue };
        let spot = Some(Spot::Relative(anchor));
        match d.target {
            Target::Ball => s.ball_random = spot,
            Target::OddBall => s.odd_episode_ball_random = spot,
            Target::Left(i) => s.left_team[i].random = spot,
            Target::Right(i) => s.right_team[i].random = spot,
        }
        spans.push((d.target, d.expr.span));
    }
    // In odd episodes the odd ball's place stands for the ball's.
    let circles = [(s.ball_random.as_ref(), Target::Ball), (s.odd_episode_ball_random.as_ref(), Target::OddBall)];
    for (ball, ball_target) in circles {
        if ball_target == Target::OddBall && ball.is_none() {
            continue;
        }
        if let Some(cycle) = relative_cycle(&s.left_team, &s.right_team, ball) {
            report_cycle(&cycle, &spans, ball_target, s, r);
            return;
        }
    }
    s.settle_relative();
}

/// `tl::E151` on the places of `cycle` (the ball's being `ball`'s place), if this body wrote
/// one of them.
fn report_cycle(cycle: &[Body], spans: &[(Target, Span)], ball: Target, s: &Scenario, r: &mut Reader<'_>) {
    let names: Vec<String> = cycle.iter().map(|b| body_name(*b, s)).collect();
    let target_of = |b: Body| match b {
        Body::Ball => ball,
        Body::Left(i) => Target::Left(i),
        Body::Right(i) => Target::Right(i),
    };
    let span_of = |b: Body| spans.iter().find(|(t, _)| *t == target_of(b)).map(|(_, span)| *span);
    let Some(span) = cycle.first().and_then(|b| span_of(*b)) else { return };
    let in_odd = if ball == Target::OddBall { " in odd episodes" } else { "" };
    let mut d = Diagnostic::new(
        Code::PlacementCycle,
        format!("these places depend on each other in a circle{in_odd}: {}", names.join(" → ")),
        r.source,
        span,
        "placed from the next one",
    )
    .with_help("one of them must be placed on its own (`at (x, y)`, `in REGION`) for the others to be drawn from it");
    for b in cycle.iter().skip(1) {
        if let Some(span) = span_of(*b) {
            d = d.with_label(span, "in the circle");
        }
    }
    r.diags.push(d);
}

fn body_name(b: Body, s: &Scenario) -> String {
    match b {
        Body::Ball => "the ball".to_owned(),
        Body::Left(i) => format!("left[{i}] ({})", s.left_team.get(i).map_or("?", |e| e.role.name())),
        Body::Right(i) => format!("right[{i}] ({})", s.right_team.get(i).map_or("?", |e| e.role.name())),
    }
}

/// The anchor of a relative place `e` of a body in `frame`.
fn anchor(e: &Expr, frame: Frame, s: &Scenario, r: &mut Reader<'_>) -> Option<Anchor> {
    match &e.kind {
        ExprKind::Binary { op, lhs, rhs } => {
            let of = super::statements::body(lhs, s, r);
            let offset = offset(rhs, frame, r);
            let (of, [dx, dy]) = (of?, offset?);
            let sign = if *op == BinaryOp::Sub { -1.0 } else { 1.0 };
            Some(Anchor { of, offset: [sign * dx, sign * dy], radius: 0.0 })
        }
        ExprKind::Call { name, args } => {
            let usage = match name.value.as_str() {
                "near" => "near(PLAYER, R m): a point drawn within R metres of the player or the ball",
                "beside" => "beside(PLAYER, D m): D metres to his side (+y in his frame; negative: the other side)",
                _ => "behind(PLAYER, D m) / ahead(PLAYER, D m): D metres towards the goal he defends / attacks",
            };
            if args.len() != 2 {
                r.error_help(
                    Code::Arguments,
                    format!("`{}` takes 2 arguments, found {}", name.value, args.len()),
                    e.span,
                    "wrong number of arguments",
                    format!("write {usage}"),
                );
                return None;
            }
            if name.value == "near" {
                // `near(left.CF + (5 m, 0), 3 m)`: a disc around any relative point.
                let centre = anchor(&args[0].value, frame, s, r);
                let radius = r.metres(&args[1].value);
                return Some(Anchor { radius: radius?, ..centre? });
            }
            let of = super::statements::body(&args[0].value, s, r);
            let d = signed_metres(&args[1].value, r);
            let (of, d) = (of?, d?);
            let (offset, radius) = match name.value.as_str() {
                "behind" => ([-d, 0.0], 0.0),
                "ahead" => ([d, 0.0], 0.0),
                _ => ([0.0, d], 0.0),
            };
            if of == Body::Ball {
                r.error_help(
                    Code::WrongType,
                    format!("`{}` needs a player: the ball attacks no goal", name.value),
                    args[0].value.span,
                    "the ball",
                    "write `ball + (dx, dy)` for an offset from the ball, in the global frame",
                );
                return None;
            }
            Some(Anchor { of, offset, radius })
        }
        _ => super::statements::body(e, s, r).map(|of| Anchor { of, offset: [0.0, 0.0], radius: 0.0 }),
    }
}

/// Metres, possibly negative (`-3 m`: the other side, or the other way).
fn signed_metres(e: &Expr, r: &mut Reader<'_>) -> Option<f32> {
    match &e.kind {
        ExprKind::Negation(inner) => r.metres(inner).map(|m| -m),
        ExprKind::Quantity { value, .. } if *value < 0.0 => {
            let mut positive = e.clone();
            if let ExprKind::Quantity { value, .. } = &mut positive.kind {
                *value = -*value;
            }
            r.metres(&positive).map(|m| -m)
        }
        _ => r.metres(e),
    }
}

/// An offset `(dx, dy)` in metres: each coordinate in metres, or in scenario units of the placed
/// body (converted with its factors).
fn offset(e: &Expr, frame: Frame, r: &mut Reader<'_>) -> Option<[f32; 2]> {
    let ExprKind::Tuple(args) = &e.kind else {
        offset_help(e, r);
        return None;
    };
    if args.len() != 2 {
        offset_help(e, r);
        return None;
    }
    let [x, y] = r.fixed_point(e, frame)?;
    let (mx, my) = match frame {
        Frame::Player => (PLAYER_X_METRES, PLAYER_Y_METRES),
        Frame::Ball => (BALL_X_METRES, BALL_Y_METRES),
    };
    Some([(f64::from(x) * mx) as f32, (f64::from(y) * my) as f32])
}

fn offset_help(e: &Expr, r: &mut Reader<'_>) {
    r.error_help(
        Code::WrongType,
        format!("expected an offset `(dx, dy)`, found {}", e.describe()),
        e.span,
        "not an offset",
        "write `left.CF + (-5 m, 0)`: metres (or scenario units) in the named player's frame",
    );
}
