//! Player behaviours (`does A [then shoot] [until COND] then B …`) compiled to the engine's
//! [`Stage`] list, with their checks: known behaviours, arguments of the right kind, passes to a
//! team-mate, and stages that can be reached.
//!
//! Points are in the behaving player's team frame (own goal at x = −1), as his own `at` is
//! written; metres convert as for player positions.

use touchline_engine::scenario::{Behaviour, PassKind, Stage, Target};
use touchline_engine::{Scenario, Side};

use super::condition::{self, Context};
use super::pitch::within_rim;
use super::value::{Frame, Reader, suggest_help};
use crate::diagnostic::{Code, Diagnostic};
use crate::suggest;
use crate::syntax::{self, Action, Argument, Expr, ExprKind, Span};

/// The behaviours, for suggestions and help.
pub(crate) const BEHAVIOURS: [&str; 10] =
    ["idle", "hold_position", "follow", "move_to", "dribble_to", "pass_to", "mark", "press", "builtin", "script"];

/// Whether a behaviour finishes by itself (so that the next stage follows without an `until`).
pub(crate) fn finishes(b: &Behaviour) -> bool {
    matches!(b, Behaviour::MoveTo { .. } | Behaviour::DribbleTo { .. } | Behaviour::PassTo { .. })
}

/// Compiles the behaviour of player `index` of `side`; `None` (with diagnostics) when any part is
/// wrong.
pub(crate) fn behaviour(
    b: &syntax::Behaviour,
    side: Side,
    index: usize,
    s: &Scenario,
    r: &mut Reader<'_>,
) -> Option<Vec<Stage>> {
    let ctx = Context::Behaviour;
    let mut stages = Vec::with_capacity(b.stages.len());
    let mut ok = true;
    for st in &b.stages {
        let behaviour = action(st, side, index, s, r);
        let until = st.until.as_ref().map(|c| condition::condition(c, ctx, s, r));
        match (behaviour, until) {
            (Some(behaviour), None) => stages.push(Stage { behaviour, until: None }),
            (Some(behaviour), Some(Some(c))) => stages.push(Stage { behaviour, until: Some(c) }),
            _ => ok = false,
        }
    }
    if !ok {
        return None;
    }
    unreachable_stages(b, &stages, r);
    Some(stages)
}

/// `tl::W104` on the stage after one that never ends.
fn unreachable_stages(b: &syntax::Behaviour, stages: &[Stage], r: &mut Reader<'_>) {
    for (k, st) in stages.iter().enumerate().take(stages.len().saturating_sub(1)) {
        let never_done = matches!(st.until, None | Some(touchline_engine::scenario::Condition::Done));
        if finishes(&st.behaviour) || !never_done {
            continue;
        }
        let name = action_name(&b.stages[k].action);
        let why = if st.until.is_some() { "`until done` never holds for it" } else { "it has no `until`" };
        r.diags.push(
            Diagnostic::new(
                Code::UnreachableStage,
                "this stage is never reached",
                r.source,
                b.stages[k + 1].span,
                "never reached",
            )
            .with_label(b.stages[k].span, format!("`{name}` never finishes and {why}"))
            .with_help(format!("add `until CONDITION` to `{name}` (e.g. `until steps >= 50`), or remove what follows")),
        );
        // The stages after the first unreachable one are unreachable too; one warning says it.
        return;
    }
}

fn action_name(a: &Action) -> String {
    match a {
        Action::Script(_) => "script".to_owned(),
        Action::Expr(e) => match &e.kind {
            ExprKind::Call { name, .. } | ExprKind::Index { name, .. } => name.value.clone(),
            ExprKind::Path { head, .. } => head.value.clone(),
            _ => e.describe(),
        },
    }
}

fn action(st: &syntax::Stage, side: Side, index: usize, s: &Scenario, r: &mut Reader<'_>) -> Option<Behaviour> {
    let e = match &st.action {
        Action::Script(path) => {
            shoot_misplaced(st, "script", r);
            return Some(Behaviour::Script { path: path.value.clone() });
        }
        Action::Expr(e) => e,
    };
    let (name, args, called) = match &e.kind {
        ExprKind::Path { head, field: None } => (head, &[][..], false),
        ExprKind::Call { name, args } => (name, args.as_slice(), true),
        _ => {
            r.error_help(
                Code::UnknownBehaviour,
                format!("expected a behaviour, found {}", e.describe()),
                e.span,
                "not a behaviour",
                format!("the behaviours are {}", BEHAVIOURS.join(", ")),
            );
            return None;
        }
    };
    if let Some(a) = args.iter().find_map(|a| a.name.as_ref()) {
        arguments_error(r, format!("`{}` takes no named arguments", name.value), a.span, usage(&name.value));
        return None;
    }
    let behaviour = match name.value.as_str() {
        "idle" | "hold_position" | "press" => {
            if called {
                arguments_error(r, format!("`{}` takes no arguments", name.value), e.span, &name.value);
                return None;
            }
            match name.value.as_str() {
                "idle" => Behaviour::Idle,
                "hold_position" => Behaviour::HoldPosition,
                _ => Behaviour::Press,
            }
        }
        "builtin" => match args {
            [] => Behaviour::Builtin { difficulty: None },
            [theta] => Behaviour::Builtin { difficulty: Some(r.fraction(&theta.value, "the difficulty θ")?) },
            _ => {
                arity(r, "builtin", args.len(), e.span);
                return None;
            }
        },
        "follow" | "mark" => {
            let [arg] = args else {
                arity(r, &name.value, args.len(), e.span);
                return None;
            };
            let t = followed(&name.value, &arg.value, side, index, s, r)?;
            if name.value == "follow" { Behaviour::Follow(t) } else { Behaviour::Mark(t) }
        }
        "move_to" | "dribble_to" => {
            let point = point(&name.value, args, e.span, r)?;
            if name.value == "move_to" {
                Behaviour::MoveTo { point }
            } else {
                Behaviour::DribbleTo { point, shoot: false }
            }
        }
        "pass_to" => {
            let (to, kind) = match args {
                [to] => (to, None),
                [to, kind] => (to, Some(kind)),
                _ => {
                    arity(r, "pass_to", args.len(), e.span);
                    return None;
                }
            };
            let player = pass_target(&to.value, side, index, s, r);
            let kind = kind.map_or(Some(PassKind::Short), |k| pass_kind(&k.value, r));
            Behaviour::PassTo { player: player?, kind: kind? }
        }
        "shoot" => {
            r.error_help(
                Code::MisplacedShoot,
                "`shoot` is not a behaviour of its own",
                name.span,
                "not after `dribble_to`",
                "write `dribble_to((x, y)) then shoot` (its `until`, if any, after `shoot`)",
            );
            return None;
        }
        other => {
            let close = suggest::closest(other, &BEHAVIOURS);
            r.error_help(
                Code::UnknownBehaviour,
                format!("unknown behaviour `{other}`"),
                name.span,
                "not a behaviour",
                suggest_help(&close, &format!("the behaviours are {}", BEHAVIOURS.join(", "))),
            );
            return None;
        }
    };
    match behaviour {
        Behaviour::DribbleTo { point, .. } if st.shoot.is_some() => Some(Behaviour::DribbleTo { point, shoot: true }),
        b => {
            shoot_misplaced(st, &name.value, r);
            Some(b)
        }
    }
}

/// `tl::E128` for `then shoot` after anything but `dribble_to`.
fn shoot_misplaced(st: &syntax::Stage, name: &str, r: &mut Reader<'_>) {
    if let Some(span) = st.shoot {
        r.error_help(
            Code::MisplacedShoot,
            format!("`{name}` cannot be followed by `then shoot`"),
            span,
            "only after `dribble_to`",
            "only `dribble_to((x, y)) then shoot` shoots; to shoot from where the player is, dribble to his own point",
        );
    }
}

/// How each behaviour is written, for help.
fn usage(name: &str) -> &'static str {
    match name {
        "follow" => "follow(ball) or follow(PLAYER)",
        "mark" => "mark(PLAYER), PLAYER an opponent",
        "move_to" => "move_to((x, y))",
        "dribble_to" => "dribble_to((x, y)), optionally followed by `then shoot`",
        "pass_to" => "pass_to(PLAYER) or pass_to(PLAYER, short|long|high), PLAYER a team-mate",
        "builtin" => "builtin or builtin(θ), θ in [0, 1]",
        _ => "a behaviour",
    }
}

fn arguments_error(r: &mut Reader<'_>, message: String, span: Span, usage: &str) {
    r.error_help(Code::BehaviourArguments, message, span, "wrong arguments", format!("write `{usage}`"));
}

fn arity(r: &mut Reader<'_>, name: &str, found: usize, span: Span) {
    arguments_error(r, format!("`{name}` cannot take {found} arguments"), span, usage(name));
}

/// `follow`'s and `mark`'s target: the ball (only for `follow`) or a player other than `me`.
fn followed(name: &str, e: &Expr, side: Side, index: usize, s: &Scenario, r: &mut Reader<'_>) -> Option<Target> {
    let is_ball = matches!(&e.kind, ExprKind::Path { head, field: None } if head.value == "ball");
    if is_ball && name == "follow" {
        return Some(Target::Ball);
    }
    let is_player = matches!(&e.kind, ExprKind::Index { .. } | ExprKind::Path { field: Some(_), .. });
    if !is_player {
        let expected = if name == "follow" { "the ball or a player" } else { "a player" };
        arguments_error(r, format!("`{name}` takes {expected}, found {}", e.describe()), e.span, usage(name));
        return None;
    }
    let (other, i) = condition::player(e, s, r)?;
    if (other, i) == (side, index) {
        arguments_error(r, format!("a player cannot {name} himself"), e.span, usage(name));
        return None;
    }
    if name == "mark" && other == side {
        arguments_error(r, "`mark` takes an opponent, not a team-mate".to_owned(), e.span, usage(name));
        return None;
    }
    Some(if other == Side::Left { Target::Left(i) } else { Target::Right(i) })
}

/// A point `(x, y)` (or two coordinates) in the team frame, on the pitch's rim.
fn point(name: &str, args: &[Argument], span: Span, r: &mut Reader<'_>) -> Option<[f32; 2]> {
    let p = match args {
        [one] if matches!(one.value.kind, ExprKind::Tuple(_)) => r.fixed_point(&one.value, Frame::Player)?,
        [x, y] if [x, y].iter().all(|a| matches!(a.value.kind, ExprKind::Quantity { .. })) => {
            let tuple = Expr {
                kind: ExprKind::Tuple(vec![x.clone(), y.clone()]),
                span: Span::join(x.value.span, y.value.span),
            };
            r.fixed_point(&tuple, Frame::Player)?
        }
        [other] => {
            arguments_error(
                r,
                format!("`{name}` takes a point, found {}", other.value.describe()),
                other.value.span,
                usage(name),
            );
            return None;
        }
        _ => {
            arity(r, name, args.len(), span);
            return None;
        }
    };
    if !within_rim(p) {
        r.error_help(
            Code::OutOfRange,
            format!("`{name}` goes off the pitch, to ({}, {})", super::value::short(p[0]), super::value::short(p[1])),
            span,
            "off the pitch",
            format!(
                "points are in the player's team frame: {}",
                super::pitch::units_help(" from his own goal line", "")
            ),
        );
        return None;
    }
    Some(p)
}

/// `pass_to`'s receiver: a team-mate's index.
fn pass_target(e: &Expr, side: Side, index: usize, s: &Scenario, r: &mut Reader<'_>) -> Option<usize> {
    if !matches!(&e.kind, ExprKind::Index { .. } | ExprKind::Path { field: Some(_), .. }) {
        arguments_error(r, format!("`pass_to` takes a player, found {}", e.describe()), e.span, usage("pass_to"));
        return None;
    }
    let (other, i) = condition::player(e, s, r)?;
    let team = if side == Side::Left { "left" } else { "right" };
    if other != side {
        r.error_help(
            Code::PassTarget,
            "`pass_to` a player of the other team",
            e.span,
            "not a team-mate",
            format!("this player plays for {team}: pass to a `{team}` player"),
        );
        return None;
    }
    if i == index {
        r.error_help(
            Code::PassTarget,
            "a player cannot pass to himself",
            e.span,
            "the passer himself",
            format!("pass to another `{team}` player; to keep the ball, `dribble_to` a point"),
        );
        return None;
    }
    Some(i)
}

fn pass_kind(e: &Expr, r: &mut Reader<'_>) -> Option<PassKind> {
    match &e.kind {
        ExprKind::Path { head, field: None } if head.value == "short" => Some(PassKind::Short),
        ExprKind::Path { head, field: None } if head.value == "long" => Some(PassKind::Long),
        ExprKind::Path { head, field: None } if head.value == "high" => Some(PassKind::High),
        _ => {
            let close = match &e.kind {
                ExprKind::Path { head, field: None } => suggest::closest(&head.value, &["short", "long", "high"]),
                _ => Vec::new(),
            };
            r.error_help(
                Code::BehaviourArguments,
                format!("expected `short`, `long` or `high`, found {}", e.describe()),
                e.span,
                "not a kind of pass",
                suggest_help(&close, "a pass is `short` (ground), `long` (driven) or `high` (lofted)"),
            );
            None
        }
    }
}
