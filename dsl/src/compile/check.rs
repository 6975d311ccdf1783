//! Checks on the merged scenario: team sizes, goalkeepers, positions on the pitch, `require`
//! constraints that can hold, and the engine's own validation as a backstop.

use touchline_engine::geometry::coords::SCENARIO_LINES;
use touchline_engine::scenario::{MAX_PLACEMENT_TRIES, Spot};
use touchline_engine::{MAX_PLAYERS_PER_TEAM, Role, Scenario};

use super::origins::{Loc, Origins};
use super::pitch::RIM;
use super::value::short;
use crate::diagnostic::{Code, Diagnostic, Diagnostics, Source};
use crate::syntax::Span;

/// The lines: |x| ≤ 1, |y| ≤ 0.42.
const LINES: [f32; 2] = SCENARIO_LINES;
/// Placements drawn to estimate how often the `require` constraints hold.
const ACCEPTANCE_SAMPLES: u32 = 4_000;
/// Largest accepted chance that one reset runs out of retries.
const MAX_FAILURE: f64 = 1e-9;

pub(super) fn check(s: &Scenario, o: &Origins, source: &Source, name_span: Span, diags: &mut Diagnostics) {
    let at_name = |code, message: String, label: &str| Diagnostic::new(code, message, source, name_span, label);
    if let (Some(restart), Some(with), Some(ball)) = (&s.start_with, &o.start_with, &o.ball)
        && ball.source.name() == with.source.name()
    {
        let name = super::start::restart_name(restart.mode);
        diags.push(
            Diagnostic::new(
                Code::BallReplaced,
                "the restart places the ball; `ball` is ignored",
                &ball.source,
                ball.span,
                "ignored",
            )
            .with_label(with.span, format!("the {} puts the ball on its spot", name.replace('_', " ")))
            .with_help("remove the `ball` statement"),
        );
    }
    for (i, (side, team)) in [("left", &s.left_team), ("right", &s.right_team)].into_iter().enumerate() {
        let team_loc = o.team[i].clone();
        let at_team = |code, message: String, label: &str| match &team_loc {
            Some(l) => Diagnostic::new(code, message, &l.source, l.span, label),
            None => at_name(code, message, label),
        };
        if o.team_errors[i] {
            // The team statement already has errors and its players are incomplete: counting them
            // would only repeat those errors.
        } else if team.is_empty() {
            diags.push(at_team(Code::PlayerCount, format!("the {side} team has no players"), "no players").with_help(
                format!("add `team {side} {{ GK at (-1, 0) … }}`, a formation, or extend a scenario that has one"),
            ));
            continue;
        }
        if team.len() > MAX_PLAYERS_PER_TEAM && !o.team_errors[i] {
            let d = match o.players[i].get(MAX_PLAYERS_PER_TEAM) {
                Some(l) => Diagnostic::new(
                    Code::PlayerCount,
                    format!("the {side} team has {} players", team.len()),
                    &l.source,
                    l.span,
                    "the 12th player",
                ),
                None => at_team(
                    Code::PlayerCount,
                    format!("the {side} team has {} players", team.len()),
                    "too many players",
                ),
            };
            diags.push(d.with_help("a team fields at most 11 players (Law 3)"));
        }
        let keepers: Vec<usize> = team.iter().enumerate().filter(|(_, p)| p.role == Role::GK).map(|(k, _)| k).collect();
        match keepers.as_slice() {
            _ if o.team_errors[i] => {}
            [_] => {}
            [] => diags.push(
                at_team(Code::Goalkeepers, format!("the {side} team has no goalkeeper"), "no GK")
                    .with_help("every team needs exactly one player with role GK"),
            ),
            [first, second, ..] => {
                let mut d = match o.players[i].get(*second) {
                    Some(l) => Diagnostic::new(
                        Code::Goalkeepers,
                        format!("the {side} team has {} goalkeepers", keepers.len()),
                        &l.source,
                        l.span,
                        "another GK",
                    ),
                    None => at_team(
                        Code::Goalkeepers,
                        format!("the {side} team has {} goalkeepers", keepers.len()),
                        "too many GKs",
                    ),
                };
                if let Some(l) = o.players[i].get(*first).filter(|l| std::sync::Arc::ptr_eq(&l.source, &d.source)) {
                    d = d.with_label(l.span, "first GK");
                }
                diags.push(d.with_help("a team has exactly one goalkeeper; give the others an outfield role"));
            }
        }
        for (k, p) in team.iter().enumerate() {
            let bounds = p.random.as_ref().map_or([[p.x, p.x], [p.y, p.y]], Spot::bounds);
            let loc = o.players[i].get(k).cloned().unwrap_or(Loc { source: source.clone(), span: name_span });
            position(bounds, &format!("{side} player {k} ({})", p.role), &loc, diags);
        }
    }
    let ball_loc = o.ball.clone().unwrap_or(Loc { source: source.clone(), span: name_span });
    let ball = s.ball_random.as_ref().map_or([[s.ball_position[0]; 2], [s.ball_position[1]; 2]], Spot::bounds);
    // A restart's spot is where the laws put the ball (a corner's is on the lines).
    if s.start_with.is_none() {
        position(ball, "the ball", &ball_loc, diags);
    }
    if diags.has_errors() {
        return;
    }
    if let Err(e) = s.validate() {
        diags.push(at_name(Code::OutOfRange, e.to_string(), "this scenario"));
        return;
    }
    if s.start_state.is_some()
        && let Err(e) = touchline_engine::Env::new(s.clone(), 0)
    {
        diags.push(
            at_name(Code::StartState, format!("the saved state cannot start this scenario: {e}"), "this scenario")
                .with_help("save the state from a match of this scenario (or one with the same team sizes)"),
        );
    }
    if !s.requires.is_empty() {
        requires(s, o, &at_name, diags);
    }
    if !s.left_team.iter().any(|p| p.controllable) {
        let d = match &o.team[0] {
            Some(l) => Diagnostic::new(
                Code::NoControllable,
                "no left player is controllable",
                &l.source,
                l.span,
                "agents cannot play this side",
            ),
            None => {
                at_name(Code::NoControllable, "no left player is controllable".into(), "agents cannot play this side")
            }
        };
        diags.push(d.with_help("remove `not controllable` from a left player, unless only the built-in AI plays"));
    } else if s.swap_teams_on_odd_episodes && !s.right_team.iter().any(|p| p.controllable) {
        // The right list plays left in odd episodes: an agent would have no one to drive there.
        let message = "no right player is controllable, and the teams swap on odd episodes";
        let label = "agents cannot play the left side in odd episodes";
        let d = match &o.team[1] {
            Some(r) => Diagnostic::new(Code::NoControllable, message, &r.source, r.span, label),
            None => at_name(Code::NoControllable, message.into(), label),
        };
        diags.push(d.with_help(
            "remove `not controllable` from a right player, or drop `on odd episodes swap teams`, unless only the built-in AI plays",
        ));
    }
}

/// `tl::E113` when the `require` constraints never hold, or too rarely for the retry budget,
/// labelled on the constraints to blame: those that fail on their own, or else all of them.
fn requires(s: &Scenario, o: &Origins, at_name: &dyn Fn(Code, String, &str) -> Diagnostic, diags: &mut Diagnostics) {
    let acceptance = s.require_acceptance(ACCEPTANCE_SAMPLES);
    let failure = (1.0 - f64::from(acceptance)).powi(MAX_PLACEMENT_TRIES as i32);
    if acceptance > 0.0 && failure <= MAX_FAILURE {
        return;
    }
    // How often each constraint holds on its own.
    let alone: Vec<f32> = s
        .requires
        .iter()
        .map(|r| Scenario { requires: vec![r.clone()], ..s.clone() }.require_acceptance(ACCEPTANCE_SAMPLES))
        .collect();
    let percent = |a: f32| format!("{:.2}%", 100.0 * a);
    let (message, label, help) = if acceptance == 0.0 {
        (
            format!("the `require` constraints never held in {ACCEPTANCE_SAMPLES} draws"),
            "never holds",
            "widen the distributions or relax the distances; between fixed positions a constraint either always or never holds",
        )
    } else {
        (
            format!(
                "the `require` constraints hold in only {} of draws: a reset may run out of its {MAX_PLACEMENT_TRIES} tries",
                percent(acceptance)
            ),
            "rarely holds",
            "relax the constraints or narrow the distributions so that at least ~2% of draws meet them",
        )
    };
    // Blame the constraints that fail (or are too rare) on their own; if each is fine alone, they
    // fail together, and all are labelled with how often each holds alone.
    let too_rare = |a: f32| a == 0.0 || (1.0 - f64::from(a)).powi(MAX_PLACEMENT_TRIES as i32) > MAX_FAILURE;
    let failing: Vec<usize> = (0..s.requires.len())
        .filter(|&k| if acceptance == 0.0 { alone[k] == 0.0 } else { too_rare(alone[k]) })
        .collect();
    let together = failing.is_empty();
    let blamed: Vec<usize> = if together { (0..s.requires.len()).collect() } else { failing };
    let locs: Vec<&Loc> = blamed.iter().filter_map(|&k| o.requires.get(k)).collect();
    let Some(first) = locs.first() else {
        diags.push(at_name(Code::Unsatisfiable, message, label).with_help(help));
        return;
    };
    let label_of = |k: usize| {
        if together { format!("holds in {} of draws on its own", percent(alone[k])) } else { label.to_owned() }
    };
    let help = if together && s.requires.len() > 1 {
        "each constraint holds on its own but not together with the others: relax one of them"
    } else {
        help
    };
    let mut d = Diagnostic::new(Code::Unsatisfiable, message, &first.source, first.span, label_of(blamed[0]));
    for (&k, l) in blamed.iter().zip(&locs).skip(1) {
        if std::sync::Arc::ptr_eq(&l.source, &first.source) {
            d = d.with_label(l.span, label_of(k));
        }
    }
    diags.push(d.with_help(help));
}

/// Errors for a position box outside the rim, a warning outside the lines.
fn position(bounds: [[f32; 2]; 2], what: &str, loc: &Loc, diags: &mut Diagnostics) {
    let [[x0, x1], [y0, y1]] = bounds;
    let beyond = |limit: [f32; 2]| {
        ![x0, x1, y0, y1].iter().all(|v| v.is_finite())
            || x0.abs().max(x1.abs()) > limit[0]
            || y0.abs().max(y1.abs()) > limit[1]
    };
    // A random start is judged by the whole range its draws can reach. Written out only for a
    // diagnostic: formatting numbers for every player would cost more than the check itself.
    let describe = || {
        let [x0s, x1s, y0s, y1s] = [x0, x1, y0, y1].map(short);
        if x0 == x1 && y0 == y1 {
            ("starts", format!("at ({x0s}, {y0s})"))
        } else {
            ("can start", format!("(its draws reach {x0s}..{x1s}, {y0s}..{y1s})"))
        }
    };
    if beyond(RIM) {
        let (starts, place) = describe();
        diags.push(
            Diagnostic::new(
                Code::OutOfRange,
                format!("{what} {starts} off the pitch {place}"),
                &loc.source,
                loc.span,
                "off the pitch",
            )
            .with_help(format!(
                "positions are in scenario units: {}",
                super::pitch::units_help(" (goal lines)", " (touchlines)")
            )),
        );
    } else if beyond(LINES) {
        let (starts, place) = describe();
        diags.push(Diagnostic::new(
            Code::OutsideLines,
            format!("{what} {starts} outside the lines {place}"),
            &loc.source,
            loc.span,
            "outside the lines",
        ));
    }
}
