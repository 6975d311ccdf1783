//! How episodes start: `start from "file"` (a saved match), `start with RESTART for TEAM [at
//! PLACE]` (a restart the referee sets up) and a player's `facing …` flag.

use touchline_engine::geometry::coords::world_to_obs;
use touchline_engine::scenario::{Facing, StartRestart};
use touchline_engine::{GameMode, Scenario, Side};

use super::value::{Frame, Reader, short, suggest_help};
use crate::diagnostic::{Code, Diagnostic};
use crate::suggest;
use crate::syntax::{self, Expr, ExprKind, Span};

/// The restarts, by the name a `.tl` file gives them, with the game mode each starts in.
const RESTARTS: [(&str, GameMode); 6] = [
    ("kickoff", GameMode::KickOff),
    ("goal_kick", GameMode::GoalKick),
    ("free_kick", GameMode::FreeKick),
    ("corner_kick", GameMode::Corner),
    ("throw_in", GameMode::ThrowIn),
    ("penalty_kick", GameMode::Penalty),
];

/// The `.tl` name of a restart's game mode (`Corner` is `corner_kick`).
pub(crate) fn restart_name(mode: GameMode) -> &'static str {
    RESTARTS.iter().find(|(_, m)| *m == mode).map_or("kickoff", |(n, _)| n)
}

/// `tl::E153`: `start with` and `start from` in one definition.
pub(crate) fn both_starts(with: Span, from: Span, r: &mut Reader<'_>) {
    r.diags.push(
        Diagnostic::new(
            Code::RestartShape,
            "a scenario starts either with a restart or from a saved state, not both",
            r.source,
            with,
            "a restart",
        )
        .with_label(from, "a saved state")
        .with_help("keep one of the two statements"),
    );
}

/// `start from "file"`: the saved state's bytes, read relative to the scenario file.
pub(crate) fn start_from(path: &syntax::Spanned<String>, s: &mut Scenario, r: &mut Reader<'_>) {
    let origin = std::path::Path::new(r.source.name());
    let full = origin.parent().unwrap_or(std::path::Path::new("")).join(&path.value);
    match crate::source_file::read_regular(&full, crate::source_file::MAX_SOURCE_BYTES) {
        Ok(bytes) => s.start_state = Some(bytes),
        Err(e) => r.error_help(
            Code::StartState,
            format!("cannot read the saved state `{}`: {}", path.value, super::io_reason(&e)),
            path.span,
            "not readable",
            format!(
                "the path is relative to this file ({}); save a state with env.unwrapped.get_state() in Python",
                full.display()
            ),
        ),
    }
}

/// Reads a `start with` statement into `s.start_with` (spans for the diagnostics: `span` is the
/// whole statement).
pub(crate) fn start_with(w: &syntax::StartWith, span: Span, s: &mut Scenario, r: &mut Reader<'_>) {
    let name = w.restart.value.as_str();
    let Some(&(_, mode)) = RESTARTS.iter().find(|(n, _)| *n == name) else {
        let names: Vec<&str> = RESTARTS.iter().map(|(n, _)| *n).collect();
        let close = suggest::closest(name, &names);
        r.error_help(
            Code::UnknownRestart,
            format!("unknown restart `{name}`"),
            w.restart.span,
            "not a restart",
            suggest_help(&close, &format!("the restarts are {}", names.join(", "))),
        );
        return;
    };
    let team = match &w.team {
        Some(t) if t.value == "left" => Side::Left,
        Some(t) if t.value == "right" => Side::Right,
        Some(t) => {
            r.error_help(
                Code::RestartShape,
                format!("`{}` is not a team", t.value),
                t.span,
                "not `left` or `right`",
                format!("write `start with {name} for left` or `for right`: the team that takes it"),
            );
            return;
        }
        None => {
            r.error_help(
                Code::RestartShape,
                format!("`start with {name}` does not say which team takes it"),
                w.restart.span,
                "taken by whom?",
                format!("write `start with {name} for left` or `for right`"),
            );
            return;
        }
    };
    let at = match (StartRestart::needs_point(mode), &w.at) {
        (false, None) => None,
        (false, Some(e)) => {
            r.error_help(
                Code::RestartShape,
                format!("a {} is taken from a fixed spot", name.replace('_', " ")),
                e.span,
                "no place here",
                format!("remove `at …`: the laws put the ball for a {name} (grammar/README.md, \"Start with\")"),
            );
            return;
        }
        (true, None) => {
            let example = if mode == GameMode::Corner { "at top` or `at bottom" } else { "at (0.6, 0.1)" };
            r.error_help(
                Code::RestartShape,
                format!("`start with {name}` needs the place it is taken from"),
                span,
                "where?",
                format!("add `{example}` after `for {}`", side_word(team)),
            );
            return;
        }
        (true, Some(e)) if mode == GameMode::Corner => {
            let Some(y) = corner_y(e, r) else { return };
            Some([team.attack_sign(), y])
        }
        (true, Some(e)) => {
            let Some([x, y]) = r.fixed_point(e, Frame::Ball) else { return };
            if !(x.abs() <= 1.0 && y.abs() <= 0.42) {
                r.error_help(
                    Code::OutOfRange,
                    format!("a {} is taken on the pitch, not at ({}, {})", name.replace('_', " "), short(x), short(y)),
                    e.span,
                    "off the pitch",
                    "give a point inside the lines: x in [-1, 1], y in [-0.42, 0.42] (global frame, as `ball at`)",
                );
                return;
            }
            if mode == GameMode::ThrowIn && y == 0.0 {
                r.error_help(
                    Code::RestartShape,
                    "a throw-in point on the pitch's long axis names neither touchline",
                    e.span,
                    "y = 0",
                    "give a point nearer the touchline the throw is taken from: y < 0 for the top one, y > 0 for the bottom one",
                );
                return;
            }
            Some([x, y])
        }
    };
    s.start_with = Some(StartRestart { mode, team, at });
}

/// With a restart to start from, the ball starts on its spot: the compiled form says so, and
/// places written relative to the ball (`CF at ball + (-2 m, 0)`) are taken from there. Called
/// once a body is applied, so that a `ball` statement anywhere in it (`tl::W106`) gives way.
pub(crate) fn ball_on_the_spot(s: &mut Scenario) {
    if let Some(start) = s.start_with {
        s.ball_position = world_to_obs(start.restart().spot);
        s.ball_random = None;
        s.odd_episode_ball_position = None;
        s.odd_episode_ball_random = None;
    }
}

/// `top` (y = −0.42, the top of GRF's screen) or `bottom` (y = +0.42) for a corner.
fn corner_y(e: &Expr, r: &mut Reader<'_>) -> Option<f32> {
    match &e.kind {
        ExprKind::Path { head, field: None } if head.value == "top" => Some(-0.42),
        ExprKind::Path { head, field: None } if head.value == "bottom" => Some(0.42),
        _ => {
            r.error_help(
                Code::RestartShape,
                format!("a corner kick is taken at `top` or `bottom`, not {}", e.describe()),
                e.span,
                "not a corner",
                "write `at top` (y = -0.42) or `at bottom` (y = +0.42): the corner flag at the goal the team attacks",
            );
            None
        }
    }
}

fn side_word(side: Side) -> &'static str {
    match side {
        Side::Left => "left",
        Side::Right => "right",
    }
}

/// The value of a `facing` flag: `ball`, `goal` or a direction `(dx, dy)` in the player's team
/// frame (plain numbers, not both zero), written out or through a param.
pub(crate) fn facing(e: &Expr, r: &mut Reader<'_>) -> Option<Facing> {
    const HELP: &str = "write `facing ball`, `facing goal` (the goal he attacks) or `facing (dx, dy)`, a direction in \
                        his team's frame: `(1, 0)` towards the goal he attacks";
    match &e.kind {
        ExprKind::Path { head, field: None } if head.value == "ball" => return Some(Facing::Ball),
        ExprKind::Path { head, field: None } if head.value == "goal" => return Some(Facing::Goal),
        _ => {}
    }
    // `param look = (0, 1)` … `facing look`.
    if let Some(result) = r.through_param(e, |r, v| facing(v, r)) {
        return result;
    }
    match &e.kind {
        ExprKind::Tuple(args) if args.len() == 2 && args.iter().all(|a| a.name.is_none()) => {
            let dx = r.plain_number(&args[0].value, "a direction's dx")?;
            let dy = r.plain_number(&args[1].value, "a direction's dy")?;
            if dx == 0.0 && dy == 0.0 {
                r.error_help(Code::Facing, "the direction (0, 0) points nowhere", e.span, "no direction", HELP);
                return None;
            }
            Some(Facing::Direction([dx as f32, dy as f32]))
        }
        _ => {
            r.error_help(
                Code::Facing,
                format!("a player faces the ball, the goal or a direction, not {}", e.describe()),
                e.span,
                "not a facing",
                HELP,
            );
            None
        }
    }
}
