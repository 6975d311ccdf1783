//! `reward on EVENTS [once | each time] VALUE`: event names, regions, scopes, groups and
//! sequences checked and turned into the engine's [`EventReward`].

use touchline_engine::scenario::{
    EventAtom, EventKind, EventReward, EventStep, EventTeam, MAX_EVENT_GROUP, MAX_EVENT_SEQUENCE, RewardKind,
    RewardTerm,
};

use super::value::{Frame, Reader, suggest_help};
use crate::diagnostic::{Code, Diagnostic};
use crate::suggest;
use crate::syntax::{self, Repeat, RewardOn};

/// The events of the language, each of the controller's own team (or about the ball).
pub(crate) const EVENT_NAMES: [&str; 18] = [
    "goal_for",
    "goal_against",
    "shot",
    "shot_on_target",
    "pass",
    "pass_completed",
    "pass_intercepted",
    "possession_won",
    "possession_lost",
    "out_of_play",
    "foul",
    "card",
    "yellow_card",
    "red_card",
    "offside",
    "save",
    "has_ball",
    "ball",
];

/// The events that have an `opponent_` form (the same event done by the other team). Goals and
/// possession come as pairs (`goal_for`/`goal_against`, `possession_won`/`possession_lost`), and
/// `ball` has no team.
pub(crate) const OPPONENT_FORMS: [&str; 13] = [
    "shot",
    "shot_on_target",
    "pass",
    "pass_completed",
    "pass_intercepted",
    "out_of_play",
    "foul",
    "card",
    "yellow_card",
    "red_card",
    "offside",
    "save",
    "has_ball",
];

/// Names people write for an event that has another name here.
const MEANT: [(&str, &str); 12] = [
    ("goal", "goal_for"),
    ("goal_scored", "goal_for"),
    ("scored", "goal_for"),
    ("goal_conceded", "goal_against"),
    ("conceded", "goal_against"),
    ("opponent_goal_for", "goal_against"),
    ("opponent_goal_against", "goal_for"),
    ("opponent_possession_won", "possession_lost"),
    ("opponent_possession_lost", "possession_won"),
    ("interception", "opponent_pass_intercepted"),
    ("tackle", "possession_won"),
    ("out", "out_of_play"),
];

/// Every event name, `opponent_` forms included (for suggestions and messages).
fn all_names() -> Vec<String> {
    EVENT_NAMES.iter().map(|n| (*n).to_owned()).chain(OPPONENT_FORMS.iter().map(|n| format!("opponent_{n}"))).collect()
}

/// The reward term of a `reward on` statement, or `None` after reporting its problems.
pub(crate) fn reward_on(ro: &RewardOn, r: &mut Reader<'_>) -> Option<RewardTerm> {
    let mut ok = true;
    let mut sequence = Vec::new();
    for step in &ro.sequence {
        match event_step(step, r) {
            Some(s) => sequence.push(s),
            None => ok = false,
        }
    }
    if sequence.len() > MAX_EVENT_SEQUENCE {
        let span = syntax::Span::join(step_span(&ro.sequence[0]), step_span(&ro.sequence[ro.sequence.len() - 1]));
        r.error_help(
            Code::OutOfRange,
            format!("at most {MAX_EVENT_SEQUENCE} steps in a sequence, found {}", ro.sequence.len()),
            span,
            "too long",
            "split the pattern into several `reward on` statements",
        );
        ok = false;
    }
    let once = repeat(&ro.repeats, r);
    let value = super::statements::reward_number(r, &ro.value, "a reward value");
    let (once, value) = (once?, value?);
    ok.then_some(RewardTerm { reward: RewardKind::Event(EventReward { sequence, once }), weight: value })
}

fn step_span(step: &syntax::EventStep) -> syntax::Span {
    match step {
        syntax::EventStep::One(e) => e.span,
        syntax::EventStep::Group { span, .. } => *span,
    }
}

/// `once` (true), `each time` or nothing (false); a contradiction or repetition is `tl::E133`.
fn repeat(repeats: &[syntax::Spanned<Repeat>], r: &mut Reader<'_>) -> Option<bool> {
    let Some(first) = repeats.first() else { return Some(false) };
    let mut ok = true;
    for again in &repeats[1..] {
        let (message, help) = if again.value == first.value {
            (format!("`{}` is given twice", repeat_word(again.value)), "say it once".to_owned())
        } else {
            (
                "`once` and `each time` contradict each other".to_owned(),
                "write `once` to pay the first time in an episode, or `each time` to pay every time".to_owned(),
            )
        };
        r.diags.push(
            Diagnostic::new(Code::EventRepeat, message, r.source, again.span, "here")
                .with_label(first.span, "first given here")
                .with_help(help),
        );
        ok = false;
    }
    ok.then_some(first.value == Repeat::Once)
}

fn repeat_word(r: Repeat) -> &'static str {
    match r {
        Repeat::Once => "once",
        Repeat::EachTime => "each time",
    }
}

fn event_step(step: &syntax::EventStep, r: &mut Reader<'_>) -> Option<EventStep> {
    match step {
        syntax::EventStep::One(e) => event(e, r).map(EventStep::One),
        syntax::EventStep::Group { all, events, span } => {
            let word = if *all { "all of" } else { "any of" };
            if events.is_empty() {
                r.error_help(
                    Code::EmptyEventGroup,
                    format!("`{word}` lists no event"),
                    *span,
                    "empty group",
                    format!("list the events: `{word} (shot_on_target, pass_completed)`"),
                );
                return None;
            }
            if events.len() > MAX_EVENT_GROUP {
                r.error_help(
                    Code::OutOfRange,
                    format!("at most {MAX_EVENT_GROUP} events in a group, found {}", events.len()),
                    *span,
                    "too many",
                    "split the group into several `reward on` statements",
                );
                return None;
            }
            let atoms: Vec<Option<EventAtom>> = events.iter().map(|e| event(e, r)).collect();
            let atoms = atoms.into_iter().collect::<Option<Vec<_>>>()?;
            Some(if *all { EventStep::AllOf(atoms) } else { EventStep::AnyOf(atoms) })
        }
    }
}

fn event(e: &syntax::Event, r: &mut Reader<'_>) -> Option<EventAtom> {
    let name = e.name.value.as_str();
    let (base, team) = match name.strip_prefix("opponent_") {
        Some(rest) if OPPONENT_FORMS.contains(&rest) => (rest, EventTeam::Opponent),
        _ if EVENT_NAMES.contains(&name) => (name, EventTeam::Own),
        _ => {
            let names = all_names();
            let refs: Vec<&str> = names.iter().map(String::as_str).collect();
            let close = match MEANT.iter().find(|(said, _)| *said == name) {
                Some((_, meant)) => vec![*meant],
                None => suggest::closest(name, &refs),
            };
            r.error_help(
                Code::UnknownEvent,
                format!("unknown event `{name}`"),
                e.name.span,
                "not an event",
                suggest_help(
                    &close,
                    &format!(
                        "the events are {}, and opponent_ before shot, pass, foul, card, … (see grammar/README.md)",
                        EVENT_NAMES.join(", ")
                    ),
                ),
            );
            return None;
        }
    };
    let kind = event_kind(base, e, r)?;
    let by_player = scope(e, &kind, team, r)?;
    Some(EventAtom { event: kind, team, by_player })
}

/// The event's kind, reading its region (`ball enters R`, `ball in R`, `has_ball [in R]`).
fn event_kind(base: &str, e: &syntax::Event, r: &mut Reader<'_>) -> Option<EventKind> {
    let name = &e.name.value;
    match (base, &e.region) {
        ("ball", Some((word, region))) => {
            let region = r.region(region, Frame::Ball)?;
            Some(if word.value == "enters" { EventKind::BallEnters(region) } else { EventKind::BallIn(region) })
        }
        ("ball", None) => {
            r.error_help(
                Code::EventRegion,
                "`ball` needs a region",
                e.span,
                "which region?",
                "write `ball enters REGION` (the ball comes into it) or `ball in REGION` (at every step it is there)",
            );
            None
        }
        ("has_ball", Some((word, _))) if word.value == "enters" => {
            r.error_help(
                Code::EventRegion,
                format!("`{name}` takes `in REGION`, not `enters`"),
                word.span,
                "not `in`",
                format!("write `{name} in REGION`; for the ball coming into a region write `ball enters REGION`"),
            );
            None
        }
        ("has_ball", Some((_, region))) => r.region(region, Frame::Ball).map(EventKind::HasBallIn),
        ("has_ball", None) => Some(EventKind::HasBall),
        (_, Some((word, region))) => {
            let span = syntax::Span::join(word.span, region.span);
            r.error_help(
                Code::EventRegion,
                format!("`{name}` takes no region"),
                span,
                "no region here",
                "only `ball enters REGION`, `ball in REGION` and `has_ball in REGION` name a region; combine \
                 with `all of (…)` to ask for both",
            );
            None
        }
        (_, None) => Some(match base {
            "goal_for" => EventKind::GoalFor,
            "goal_against" => EventKind::GoalAgainst,
            "shot" => EventKind::Shot,
            "shot_on_target" => EventKind::ShotOnTarget,
            "pass" => EventKind::Pass,
            "pass_completed" => EventKind::PassCompleted,
            "pass_intercepted" => EventKind::PassIntercepted,
            "possession_won" => EventKind::PossessionWon,
            "possession_lost" => EventKind::PossessionLost,
            "out_of_play" => EventKind::OutOfPlay,
            "foul" => EventKind::Foul,
            "card" => EventKind::Card,
            "yellow_card" => EventKind::YellowCard,
            "red_card" => EventKind::RedCard,
            "save" => EventKind::Save,
            _ => EventKind::Offside,
        }),
    }
}

/// `by player` (true), `for team` or nothing (false).
fn scope(e: &syntax::Event, kind: &EventKind, team: EventTeam, r: &mut Reader<'_>) -> Option<bool> {
    let Some((word, target)) = &e.scope else { return Some(false) };
    let span = syntax::Span::join(word.span, target.span);
    let name = &e.name.value;
    match (word.value.as_str(), target.value.as_str()) {
        ("for", "team") => Some(false),
        ("by", "player") if team == EventTeam::Opponent => {
            r.error_help(
                Code::EventScope,
                format!("`{name}` is done by the other team, never by the controlled player"),
                span,
                "cannot apply",
                "`by player` is for the controller's own events; remove it",
            );
            None
        }
        ("by", "player") if !kind.has_player() => {
            let help = if matches!(kind, EventKind::GoalAgainst) {
                "a goal conceded is no player's doing; remove `by player`".to_owned()
            } else {
                "the ball's place names no player: remove `by player`, or write `has_ball in REGION by player`"
                    .to_owned()
            };
            r.error_help(Code::EventScope, format!("`{name}` has no player to match"), span, "cannot apply", help);
            None
        }
        ("by", "player") => Some(true),
        (w, t) => {
            let close = suggest::closest(&format!("{w} {t}"), &["by player", "for team"]);
            r.error_help(
                Code::EventScope,
                format!("unknown scope `{w} {t}`"),
                span,
                "not a scope",
                suggest_help(&close, "the scopes are `by player` (the controlled player did it) and `for team` (anyone of the team, the default)"),
            );
            None
        }
    }
}
