//! The condition language (`until COND` in behaviours, `end when COND`) compiled to the engine's
//! [`Condition`]: distances, region membership, ball owner, game mode, steps, score and `done`,
//! combined with `and`, `or`, `not` and parentheses.
//!
//! Frames (engine/src/scenario/condition.rs): in a behaviour, points and regions are in the frame
//! of the behaving player's team and metres convert as for player positions; in `end when` they
//! are global and convert as for the ball. Players are absolute (`left[1]`, `right.CB`).

use touchline_engine::scenario::{Comparison, Condition, EndCondition, Owner, Target};
use touchline_engine::{GameMode, PlayerEntry, Scenario, Side};

use super::value::{Frame, Reader, short, suggest_help};
use crate::diagnostic::Code;
use crate::suggest;
use crate::syntax::{self, ConditionKind, Expr, ExprKind, Span};

/// Where a condition is used, which decides its frame and what it may name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Context {
    /// In a player's behaviour: his team's frame, `me` and `done` allowed.
    Behaviour,
    /// In `end when`: global frame.
    End,
}

impl Context {
    /// The frame metres convert in.
    pub(crate) fn frame(self) -> Frame {
        match self {
            Context::Behaviour => Frame::Player,
            Context::End => Frame::Ball,
        }
    }
}

/// The names a bare condition may be.
const NAMES: [&str; 7] =
    ["done", "score", "out_of_play", "possession_change", "save", "keeper_holds_ball", "restart_taken"];
/// What a comparison may measure.
const MEASURES: [&str; 3] = ["distance", "steps", "score"];
/// What `X is …` may ask about.
const SUBJECTS: [&str; 2] = ["owner", "game_mode"];
/// Game modes as written in conditions (GRF's `e_GameMode`, docs/grf-compatibility.md#game-modes).
pub(crate) const GAME_MODES: [(&str, GameMode); 7] = [
    ("normal", GameMode::Normal),
    ("kick_off", GameMode::KickOff),
    ("goal_kick", GameMode::GoalKick),
    ("free_kick", GameMode::FreeKick),
    ("corner", GameMode::Corner),
    ("throw_in", GameMode::ThrowIn),
    ("penalty", GameMode::Penalty),
];
const LANGUAGE_HELP: &str = "conditions are distance(a, b) < D m, steps >= N, score(left) >= N, WHAT in REGION, \
owner is …, game_mode is …, done, combined with and, or, not and parentheses";

/// Compiles one condition; `None` (with diagnostics) when any part is wrong.
pub(crate) fn condition(c: &syntax::Condition, ctx: Context, s: &Scenario, r: &mut Reader<'_>) -> Option<Condition> {
    match &c.kind {
        ConditionKind::Any(parts) | ConditionKind::All(parts) => {
            let compiled: Vec<Option<Condition>> = parts.iter().map(|p| condition(p, ctx, s, r)).collect();
            let compiled = compiled.into_iter().collect::<Option<Vec<_>>>()?;
            Some(if matches!(c.kind, ConditionKind::Any(_)) {
                Condition::Any(compiled)
            } else {
                Condition::All(compiled)
            })
        }
        ConditionKind::Not(inner) => condition(inner, ctx, s, r).map(|c| Condition::Not(Box::new(c))),
        ConditionKind::Group(inner) => condition(inner, ctx, s, r),
        ConditionKind::Compare { lhs, op, rhs } => compare(lhs, op, rhs, ctx, s, r),
        ConditionKind::In { what, region } => {
            let what = target(what, ctx, s, r, false);
            let region = r.region(region, ctx.frame());
            Some(Condition::In { what: what?, region: region? })
        }
        ConditionKind::Is { what, value } => is(what, value, ctx, s, r),
        ConditionKind::Script(path) => {
            end_only(r, "script", path.span, "a script ends an episode only as a whole `end when` condition");
            None
        }
        ConditionKind::Name(n) => match n.value.as_str() {
            "done" => match ctx {
                Context::Behaviour => Some(Condition::Done),
                Context::End => {
                    r.error_help(
                        Code::BehaviourOnly,
                        "`done` only means something in a behaviour",
                        n.span,
                        "no behaviour here",
                        "`done` holds when a behaviour stage has finished; an episode ends on steps, score, \
                         the ball's place or owner instead",
                    );
                    None
                }
            },
            name @ ("score" | "out_of_play" | "possession_change" | "save" | "keeper_holds_ball" | "restart_taken") => {
                let help = match (name, ctx) {
                    ("score", _) => {
                        "to compare goals, write `score(left) >= 1`; `score` alone ends an episode on a goal as a whole `end when` condition"
                    }
                    (_, Context::End) => "write it as a whole `end when` condition, joined to the others with `or`",
                    _ => {
                        "it ends an episode as a whole `end when` condition; in a behaviour use distance, owner, game_mode, steps or score(side)"
                    }
                };
                end_only(r, name, n.span, help);
                None
            }
            other => {
                let close = suggest::closest(other, &NAMES);
                r.error_help(
                    Code::UnknownCondition,
                    format!("unknown condition `{other}`"),
                    n.span,
                    "not a condition",
                    suggest_help(&close, LANGUAGE_HELP),
                );
                None
            }
        },
    }
}

/// The end conditions a name may give.
const CONDITIONS: [&str; 6] =
    ["score", "out_of_play", "possession_change", "save", "keeper_holds_ball", "restart_taken"];

/// `end when A or B …`: each top-level condition of the forms GRF knows (`score`, `out_of_play`,
/// `possession_change`, `steps >= N`, `ball in REGION`, `script "…"`) keeps its own compiled form;
/// any other, or one in parentheses, is a condition of the condition language
/// ([`EndCondition::When`]): its place in `end_when` holds a stand-in, and the condition is
/// returned with the place, to be read once the teams are in place.
pub(crate) fn end_when<'d>(
    conditions: &'d [syntax::Condition],
    s: &mut Scenario,
    r: &mut Reader<'_>,
) -> Vec<(usize, &'d syntax::Condition)> {
    let mut deferred = Vec::new();
    s.end_episode_on_score = false;
    s.end_episode_on_out_of_play = false;
    s.end_episode_on_possession_change = false;
    s.end_when.clear();
    for c in conditions {
        match &c.kind {
            ConditionKind::Name(n) if n.value != "done" => match n.value.as_str() {
                "score" => s.end_episode_on_score = true,
                "out_of_play" => s.end_episode_on_out_of_play = true,
                "possession_change" => s.end_episode_on_possession_change = true,
                "save" => s.end_when.push(EndCondition::Save),
                "keeper_holds_ball" => s.end_when.push(EndCondition::KeeperHoldsBall),
                "restart_taken" => s.end_when.push(EndCondition::RestartTaken),
                other => {
                    let close = suggest::closest(other, &CONDITIONS);
                    r.error_help(
                        Code::UnknownCondition,
                        format!("unknown end condition `{other}`"),
                        n.span,
                        "not an end condition",
                        suggest_help(
                            &close,
                            "the conditions are score, out_of_play, possession_change, save, keeper_holds_ball, restart_taken, steps >= N, ball in REGION, script \"file.rhai\"",
                        ),
                    );
                }
            },
            ConditionKind::Compare { lhs: Expr { kind: ExprKind::Path { head, field: None }, .. }, op, rhs }
                if head.value == "steps" && op.value == ">=" =>
            {
                if let Some(n) = r.steps(rhs, "the step limit", 1) {
                    s.end_when.push(EndCondition::Steps(n));
                }
            }
            ConditionKind::In { what: Expr { kind: ExprKind::Path { head, field: None }, .. }, region }
                if head.value == "ball" =>
            {
                if let Some(region) = r.region(region, Frame::Ball) {
                    s.end_when.push(EndCondition::BallIn(region));
                }
            }
            ConditionKind::Script(path) => s.end_when.push(EndCondition::Script { path: path.value.clone() }),
            _ => {
                // A stand-in until the teams are read; replaced, or the compile fails.
                deferred.push((s.end_when.len(), c));
                s.end_when.push(EndCondition::When(Condition::Done));
            }
        }
    }
    deferred
}

/// `tl::E129`: an `end when`-only condition inside the condition language.
fn end_only(r: &mut Reader<'_>, name: &str, span: Span, help: &str) {
    r.error_help(
        Code::EndOnlyCondition,
        format!("`{name}` is not part of the condition language"),
        span,
        "only a whole `end when` condition",
        help,
    );
}

fn comparison(op: &syntax::Spanned<String>) -> Comparison {
    match op.value.as_str() {
        "<" => Comparison::Lt,
        "<=" => Comparison::Le,
        ">" => Comparison::Gt,
        ">=" => Comparison::Ge,
        "==" => Comparison::Eq,
        _ => Comparison::Ne,
    }
}

fn compare(
    lhs: &Expr,
    op: &syntax::Spanned<String>,
    rhs: &Expr,
    ctx: Context,
    s: &Scenario,
    r: &mut Reader<'_>,
) -> Option<Condition> {
    let op = comparison(op);
    match &lhs.kind {
        ExprKind::Call { name, args } if name.value == "distance" => {
            let [a, b] = args.as_slice() else {
                r.error_help(
                    Code::Arguments,
                    format!("`distance` takes 2 arguments, found {}", args.len()),
                    lhs.span,
                    "wrong number of arguments",
                    "write `distance(a, b)` with a and b the ball, me, a player or a point (x, y)",
                );
                return None;
            };
            let a = target(&a.value, ctx, s, r, true);
            let b = target(&b.value, ctx, s, r, true);
            let metres = r.metres(rhs);
            Some(Condition::Distance { a: a?, b: b?, op, metres: metres? })
        }
        ExprKind::Path { head, field: None } if head.value == "steps" => {
            let steps = r.steps(rhs, "a step count", 0)?;
            Some(Condition::Steps { op, steps })
        }
        ExprKind::Call { name, args } if name.value == "score" => {
            let side = match args.as_slice() {
                [a] => side_name(&a.value),
                _ => None,
            };
            let goals = whole(rhs, r);
            let Some(side) = side else {
                r.error_help(
                    Code::Arguments,
                    "`score` takes one team, `left` or `right`",
                    lhs.span,
                    "not one team",
                    "write `score(left) >= 1` or `score(right) >= 1`",
                );
                return None;
            };
            Some(Condition::Score { side, op, goals: goals? })
        }
        _ => {
            let (word, span) = match &lhs.kind {
                ExprKind::Call { name, .. } | ExprKind::Index { name, .. } => (name.value.clone(), name.span),
                ExprKind::Path { head, .. } => (head.value.clone(), head.span),
                _ => (String::new(), lhs.span),
            };
            let close = suggest::closest(&word, &MEASURES);
            r.error_help(
                Code::UnknownMeasure,
                format!("cannot compare {}", lhs.describe()),
                span,
                "not a measure",
                suggest_help(&close, "comparisons measure distance(a, b) (in m), steps or score(left|right)"),
            );
            None
        }
    }
}

/// A goal count: a whole number >= 0 without a unit.
fn whole(e: &Expr, r: &mut Reader<'_>) -> Option<u32> {
    let v = r.plain_number(e, "a goal count")?;
    if v.fract() != 0.0 || !(0.0..=f64::from(u32::MAX)).contains(&v) {
        r.error_help(
            Code::OutOfRange,
            format!("a goal count is a whole number >= 0, found {v}"),
            e.span,
            "out of range",
            "write a whole number of goals, e.g. `score(left) >= 1`",
        );
        return None;
    }
    Some(v as u32)
}

fn side_name(e: &Expr) -> Option<Side> {
    match &e.kind {
        ExprKind::Path { head, field: None } if head.value == "left" => Some(Side::Left),
        ExprKind::Path { head, field: None } if head.value == "right" => Some(Side::Right),
        _ => None,
    }
}

fn is(what: &Expr, value: &Expr, ctx: Context, s: &Scenario, r: &mut Reader<'_>) -> Option<Condition> {
    let subject = match &what.kind {
        ExprKind::Path { head, field: None } => head.value.as_str(),
        _ => "",
    };
    match subject {
        "owner" => {
            if let ExprKind::Path { head, field: None } = &value.kind
                && head.value == "nobody"
            {
                return Some(Condition::Owner(Owner::Nobody));
            }
            if let Some(side) = side_name(value) {
                return Some(Condition::Owner(Owner::Team(side)));
            }
            target(value, ctx, s, r, false).and_then(|t| match t {
                Target::Ball => {
                    r.error_help(
                        Code::WrongType,
                        "the ball does not own itself",
                        value.span,
                        "not an owner",
                        "write `owner is nobody`, `left`, `right`, `me` or a player",
                    );
                    None
                }
                t => Some(Condition::Owner(Owner::Player(t))),
            })
        }
        "game_mode" => {
            let name = match &value.kind {
                ExprKind::Path { head, field: None } => Some(head),
                _ => None,
            };
            let names: Vec<&str> = GAME_MODES.iter().map(|(n, _)| *n).collect();
            if let Some(&(_, mode)) = name.and_then(|n| GAME_MODES.iter().find(|(m, _)| *m == n.value)) {
                return Some(Condition::Mode(mode));
            }
            let (word, span) = name.map_or((String::new(), value.span), |n| (n.value.clone(), n.span));
            let close = suggest::closest(&word, &names);
            r.error_help(
                Code::UnknownGameMode,
                format!("unknown game mode {}", if word.is_empty() { value.describe() } else { format!("`{word}`") }),
                span,
                "not a game mode",
                suggest_help(&close, &format!("the game modes are {}", names.join(", "))),
            );
            None
        }
        _ => {
            let span = match &what.kind {
                ExprKind::Path { head, .. } => head.span,
                _ => what.span,
            };
            let close = suggest::closest(subject, &SUBJECTS);
            r.error_help(
                Code::UnknownMeasure,
                format!("cannot ask what {} is", what.describe()),
                span,
                "not `owner` or `game_mode`",
                suggest_help(&close, "write `owner is nobody|left|right|me|PLAYER` or `game_mode is corner|…`"),
            );
            None
        }
    }
}

/// `ball`, `me`, `left[i]`, `right[i]`, `left.ROLE`, or (when `point` is allowed) `(x, y)` in the
/// frame of use.
pub(crate) fn target(e: &Expr, ctx: Context, s: &Scenario, r: &mut Reader<'_>, point: bool) -> Option<Target> {
    match &e.kind {
        ExprKind::Path { head, field: None } if head.value == "ball" => Some(Target::Ball),
        ExprKind::Path { head, field: None } if head.value == "me" => match ctx {
            Context::Behaviour => Some(Target::Me),
            Context::End => {
                r.error_help(
                    Code::BehaviourOnly,
                    "`me` only means something in a behaviour",
                    head.span,
                    "no behaviour here",
                    "`me` is the player whose behaviour it is; in `end when` name the player: `left[1]`, `right.CB`",
                );
                None
            }
        },
        ExprKind::Tuple(_) if point => {
            let p = r.fixed_point(e, ctx.frame())?;
            if !super::pitch::within_rim(p) {
                r.error_help(
                    Code::OutOfRange,
                    format!("the point ({}, {}) is off the pitch", short(p[0]), short(p[1])),
                    e.span,
                    "off the pitch",
                    super::pitch::units_help(" between the goal lines", ""),
                );
                return None;
            }
            Some(Target::Point(p))
        }
        _ => player(e, s, r).map(|(side, i)| match side {
            Side::Left => Target::Left(i),
            Side::Right => Target::Right(i),
        }),
    }
}

/// A player of the scenario: `left[i]`, `right[i]`, `left.ROLE`, `right.ROLE`.
pub(crate) fn player(e: &Expr, s: &Scenario, r: &mut Reader<'_>) -> Option<(Side, usize)> {
    let team_of = |name: &str| match name {
        "left" => Some((Side::Left, &s.left_team)),
        "right" => Some((Side::Right, &s.right_team)),
        _ => None,
    };
    match &e.kind {
        ExprKind::Index { name, args } if team_of(&name.value).is_some() => {
            let (side, team) = team_of(&name.value)?;
            let [arg] = args.as_slice() else {
                r.error_help(
                    Code::Arguments,
                    "a player index is one number",
                    e.span,
                    "not one index",
                    format!("write `{}[i]`, i counting from 0 in the team's order", name.value),
                );
                return None;
            };
            let i = r.steps(&arg.value, "a player index", 0)? as usize;
            if i >= team.len() {
                r.error_help(
                    Code::UnknownPlayer,
                    format!("{} has {} players; there is no {}[{i}]", name.value, team.len(), name.value),
                    e.span,
                    "no such player",
                    roster(&name.value, team),
                );
                return None;
            }
            Some((side, i))
        }
        ExprKind::Path { head, field: Some(role) } if team_of(&head.value).is_some() => {
            let (side, team) = team_of(&head.value)?;
            let matching: Vec<usize> =
                team.iter().enumerate().filter(|(_, p)| p.role.name() == role.value).map(|(i, _)| i).collect();
            match matching.as_slice() {
                [i] => Some((side, *i)),
                [] => {
                    r.error_help(
                        Code::UnknownPlayer,
                        format!("{} has no {}", head.value, role.value),
                        e.span,
                        "no such player",
                        roster(&head.value, team),
                    );
                    None
                }
                several => {
                    r.error_help(
                        Code::UnknownPlayer,
                        format!("{} has {} players with role {}", head.value, several.len(), role.value),
                        e.span,
                        "ambiguous",
                        format!(
                            "name one by index: {}",
                            several.iter().map(|i| format!("{}[{i}]", head.value)).collect::<Vec<_>>().join(", ")
                        ),
                    );
                    None
                }
            }
        }
        _ => {
            r.error_help(
                Code::UnknownPlayer,
                format!("expected a player, found {}", e.describe()),
                e.span,
                "not a player",
                "name a player as `left[i]`, `right[i]` (0-based, in the team's order), `left.ROLE` or `right.ROLE`",
            );
            None
        }
    }
}

/// "the team's players are …" help listing a team's roles by index.
fn roster(side: &str, team: &[PlayerEntry]) -> String {
    if team.is_empty() {
        return format!("{side} has no players yet: give its `team {side} {{ … }}` block first");
    }
    let list: Vec<String> = team.iter().enumerate().map(|(i, p)| format!("{side}[{i}] {}", p.role)).collect();
    format!("{side}'s players are {}", list.join(", "))
}
