//! [`scenario_to_tl`]: a compiled [`Scenario`] written back as `.tl` source, so that any compiled
//! scenario (a JSON file, one built in code) can become a text file to edit. Compiling the output
//! gives the same scenario back (tested on every stdlib scenario).

mod draws;

use std::fmt::Write;

use draws::Draws;

use touchline_engine::scenario::{
    Behaviour, Body, Comparison, Condition, Criterion, EndCondition, EventAtom, EventKind, EventReward, EventStep,
    EventTeam, Facing, Owner, PassKind, Region, Require, RewardKind, Sample, Shared, Spot, Stage, Target,
};
use touchline_engine::{GameMode, PlayerEntry, Scenario, Side};

/// The scenario as a standalone `.tl` file (no `extends`: every key that differs from GRF's
/// default is written out, except that a scenario matching the `academy` preset extends it).
pub fn scenario_to_tl(s: &Scenario) -> String {
    let d = Scenario::default();
    let mut out = String::new();
    for line in s.description.split('\n') {
        if line.is_empty() {
            out.push_str("///\n");
        } else {
            for chunk in wrap(line, 96) {
                let _ = writeln!(out, "/// {chunk}");
            }
        }
    }
    let _ = writeln!(out, "scenario {} {{", s.name);
    let academy = s.game_duration == 400 && !s.offsides;
    let base = if academy {
        out.push_str("  extends academy\n");
        Scenario {
            game_duration: 400,
            offsides: false,
            end_episode_on_score: true,
            end_episode_on_out_of_play: true,
            end_episode_on_possession_change: true,
            ..d
        }
    } else {
        d
    };
    // A shared draw is a param its uses name, declared once for the scenario and its lessons.
    let lessons = s.curriculum.iter().flat_map(|c| c.lessons.iter().map(|l| &l.scenario));
    let draws = Draws::declare(std::iter::once(s).chain(lessons));
    for (name, expr) in draws.params() {
        let _ = writeln!(out, "  param {name} = {expr}");
    }
    statements(&mut out, s, &base, 2, true, &draws.in_lesson(s).0);
    if let Some(c) = &s.curriculum {
        let plain = Scenario { curriculum: None, ..s.clone() };
        out.push_str("  curriculum {\n");
        for l in &c.lessons {
            let _ = writeln!(out, "    lesson {} {{", l.name);
            let (own, assign) = draws.in_lesson(&l.scenario);
            for (name, expr) in assign {
                let _ = writeln!(out, "      {name} = {expr}");
            }
            statements(&mut out, &l.scenario, &plain, 6, false, &own);
            if let Some(a) = &l.advance {
                let _ = writeln!(out, "      {}", advance(a));
            }
            out.push_str("    }\n");
        }
        out.push_str("  }\n");
    }
    out.push_str("}\n");
    out
}

/// The statements that turn `base` into `s`, at `indent` spaces; `top` writes both teams even
/// when they match `base` (a scenario's own body).
/// `draws` names the shared draws.
fn statements(out: &mut String, s: &Scenario, base: &Scenario, indent: usize, top: bool, draws: &Draws) {
    let pad = " ".repeat(indent);
    if s.game_duration != base.game_duration {
        let _ = writeln!(out, "{pad}game_duration {}", s.game_duration);
    }
    for (key, value, default) in [
        ("deterministic", s.deterministic, base.deterministic),
        ("offsides", s.offsides, base.offsides),
        ("control_all_players", s.control_all_players, base.control_all_players),
    ] {
        if value != default {
            let _ = writeln!(out, "{pad}{key} {value}");
        }
    }
    for (key, value, default) in [
        ("left_team_difficulty", s.left_team_difficulty, base.left_team_difficulty),
        ("right_team_difficulty", s.right_team_difficulty, base.right_team_difficulty),
    ] {
        if value != default {
            let _ = writeln!(out, "{pad}{key} {}", number(value));
        }
    }
    if s.game_engine_random_seed != base.game_engine_random_seed {
        let _ = writeln!(out, "{pad}game_engine_random_seed {}", s.game_engine_random_seed);
    }
    if s.second_half != base.second_half {
        let _ = writeln!(out, "{pad}second_half {}", s.second_half);
    }
    let ends_differ = (s.end_episode_on_score, s.end_episode_on_out_of_play, s.end_episode_on_possession_change)
        != (base.end_episode_on_score, base.end_episode_on_out_of_play, base.end_episode_on_possession_change)
        || s.end_when != base.end_when;
    if ends_differ {
        let mut conditions: Vec<String> = [
            (s.end_episode_on_score, "score"),
            (s.end_episode_on_out_of_play, "out_of_play"),
            (s.end_episode_on_possession_change, "possession_change"),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, n)| (*n).to_owned())
        .collect();
        conditions.extend(s.end_when.iter().map(|c| match c {
            EndCondition::Steps(n) => format!("steps >= {n}"),
            EndCondition::BallIn(r) => format!("ball in {}", region(r)),
            EndCondition::Script { path } => format!("script \"{path}\""),
            EndCondition::When(c) => end_condition(c),
            EndCondition::Save => "save".to_owned(),
            EndCondition::KeeperHoldsBall => "keeper_holds_ball".to_owned(),
            EndCondition::RestartTaken => "restart_taken".to_owned(),
        }));
        if conditions.is_empty() {
            // No condition at all: only the time limit ends the episode.
            let _ = writeln!(out, "{pad}end_episode_on_score false");
            let _ = writeln!(out, "{pad}end_episode_on_out_of_play false");
            let _ = writeln!(out, "{pad}end_episode_on_possession_change false");
        } else {
            let _ = writeln!(out, "{pad}end when {}", conditions.join(" or "));
        }
    }
    if s.swap_teams_on_odd_episodes && !base.swap_teams_on_odd_episodes {
        let _ = writeln!(out, "{pad}on odd episodes swap teams");
    } else if !s.swap_teams_on_odd_episodes && base.swap_teams_on_odd_episodes {
        let _ = writeln!(out, "{pad}swap_teams_on_odd_episodes false");
    }
    if let Some(w) = s.start_with.filter(|_| s.start_with != base.start_with) {
        let side = if w.team == Side::Left { "left" } else { "right" };
        let mut line = format!("start with {} for {side}", crate::compile::restart_name(w.mode));
        match w.at {
            Some([_, y]) if w.mode == GameMode::Corner => line.push_str(if y < 0.0 { " at top" } else { " at bottom" }),
            Some([x, y]) => {
                let _ = write!(line, " at ({}, {})", number(x), number(y));
            }
            None => {}
        }
        let _ = writeln!(out, "{pad}{line}");
    }
    // A restart puts the ball on its spot: the compiler writes the spot as the ball's start.
    if s.start_with.is_none() && (s.ball_position, &s.ball_random) != (base.ball_position, &base.ball_random) {
        let _ = writeln!(out, "{pad}ball {}", place(s.ball_position, s.ball_random.as_ref(), draws));
    }
    let odd_ball = (s.odd_episode_ball_position, &s.odd_episode_ball_random);
    if odd_ball != (base.odd_episode_ball_position, &base.odd_episode_ball_random) && odd_ball != (None, &None) {
        let nominal = s.odd_episode_ball_position.unwrap_or(s.ball_position);
        let _ =
            writeln!(out, "{pad}on odd episodes ball {}", place(nominal, s.odd_episode_ball_random.as_ref(), draws));
    }
    for (side, team, before) in [("left", &s.left_team, &base.left_team), ("right", &s.right_team, &base.right_team)] {
        if !top && team == before {
            continue;
        }
        let _ = writeln!(out, "{pad}team {side} {{");
        let side = if side == "left" { Side::Left } else { Side::Right };
        for p in team {
            let _ = writeln!(out, "{pad}  {}", player(p, side, draws));
        }
        let _ = writeln!(out, "{pad}}}");
    }
    for r in s.requires.iter().filter(|_| s.requires != base.requires) {
        let (a, b, metres, op) = match r {
            Require::MinDistance { a, b, metres } => (a, b, metres, ">="),
            Require::MaxDistance { a, b, metres } => (a, b, metres, "<="),
        };
        let _ = writeln!(out, "{pad}require distance({}, {}) {op} {} m", body(*a), body(*b), number(*metres));
    }
    for t in s.rewards.iter().filter(|_| s.rewards != base.rewards) {
        if let RewardKind::Event(reward) = &t.reward {
            let _ = writeln!(out, "{pad}{}", event_reward(reward, t.weight));
            continue;
        }
        let term = match &t.reward {
            RewardKind::Scoring => "scoring".to_owned(),
            RewardKind::Checkpoints { count, value } => {
                format!("checkpoint(count: {count}, value: {})", number(*value))
            }
            RewardKind::Script { path } => format!("script \"{path}\""),
            RewardKind::Event(_) => unreachable!("printed above"),
        };
        if t.weight == 1.0 {
            let _ = writeln!(out, "{pad}reward {term}");
        } else {
            let _ = writeln!(out, "{pad}reward {term} weight {}", number(t.weight));
        }
    }
}

/// `advance when …` of a lesson's criterion.
fn advance(c: &Criterion) -> String {
    let thresholds: Vec<String> = c
        .thresholds
        .iter()
        .map(|t| format!("{} {} {}", t.metric.name(), if t.at_least { ">=" } else { "<=" }, t.value))
        .collect();
    let mut line = format!("advance when {} over {} episodes", thresholds.join(" and "), c.window);
    if c.min_episodes != c.window {
        let _ = write!(line, " min {} episodes", c.min_episodes);
    }
    line
}

fn player(p: &PlayerEntry, side: Side, draws: &Draws) -> String {
    let mut line = format!("{} {}", p.role, place([p.x, p.y], p.random.as_ref(), draws));
    if p.lazy {
        line.push_str(" lazy");
    }
    if !p.controllable {
        line.push_str(" not controllable");
    }
    match p.facing {
        Some(Facing::Ball) => line.push_str(" facing ball"),
        Some(Facing::Goal) => line.push_str(" facing goal"),
        Some(Facing::Direction([dx, dy])) => {
            let _ = write!(line, " facing ({}, {})", number(dx), number(dy));
        }
        None => {}
    }
    if !p.behaviour.is_empty() {
        let _ = write!(line, " does {}", stages(&p.behaviour, side));
    }
    line
}

/// A behaviour's stages: `A until C then B …` (points in the player's team frame, as stored).
fn stages(stages: &[Stage], side: Side) -> String {
    let parts: Vec<String> = stages
        .iter()
        .map(|st| {
            let mut text = behaviour(&st.behaviour, side);
            if let Some(c) = &st.until {
                let _ = write!(text, " until {}", condition(c));
            }
            text
        })
        .collect();
    parts.join(" then ")
}

fn behaviour(b: &Behaviour, side: Side) -> String {
    let point = |[x, y]: [f32; 2]| format!("({}, {})", number(x), number(y));
    match b {
        Behaviour::Idle => "idle".into(),
        Behaviour::HoldPosition => "hold_position".into(),
        Behaviour::Follow(t) => format!("follow({})", target(*t)),
        Behaviour::MoveTo { point: p } => format!("move_to({})", point(*p)),
        Behaviour::DribbleTo { point: p, shoot } => {
            format!("dribble_to({}){}", point(*p), if *shoot { " then shoot" } else { "" })
        }
        Behaviour::PassTo { player, kind } => {
            let team = if side == Side::Left { "left" } else { "right" };
            let kind = match kind {
                PassKind::Short => "short",
                PassKind::Long => "long",
                PassKind::High => "high",
            };
            format!("pass_to({team}[{player}], {kind})")
        }
        Behaviour::Mark(t) => format!("mark({})", target(*t)),
        Behaviour::Press => "press".into(),
        Behaviour::Builtin { difficulty: None } => "builtin".into(),
        Behaviour::Builtin { difficulty: Some(d) } => format!("builtin({})", number(*d)),
        Behaviour::Script { path } => format!("script \"{path}\""),
    }
}

/// A whole `end when` condition of the condition language. Parenthesised where it would
/// otherwise read as several conditions (`a or b`) or as one of the forms with their own compiled
/// form (`steps >= N`, `ball in REGION`).
fn end_condition(c: &Condition) -> String {
    let own_form = matches!(
        c,
        Condition::Any(_) | Condition::Steps { op: Comparison::Ge, .. } | Condition::In { what: Target::Ball, .. }
    );
    if own_form { format!("({})", condition(c)) } else { condition(c) }
}

/// A condition in the condition language; nested `and`/`or` lists keep their structure with
/// parentheses.
fn condition(c: &Condition) -> String {
    let part = |c: &Condition, group: fn(&Condition) -> bool| {
        if group(c) { format!("({})", condition(c)) } else { condition(c) }
    };
    match c {
        Condition::Any(parts) => {
            parts.iter().map(|p| part(p, |c| matches!(c, Condition::Any(_)))).collect::<Vec<_>>().join(" or ")
        }
        Condition::All(parts) => parts
            .iter()
            .map(|p| part(p, |c| matches!(c, Condition::Any(_) | Condition::All(_))))
            .collect::<Vec<_>>()
            .join(" and "),
        Condition::Not(inner) => format!("not {}", part(inner, |c| matches!(c, Condition::Any(_) | Condition::All(_)))),
        Condition::Distance { a, b, op, metres } => {
            format!("distance({}, {}) {} {} m", target(*a), target(*b), op.symbol(), number(*metres))
        }
        Condition::In { what, region: r } => format!("{} in {}", target(*what), region(r)),
        Condition::Owner(Owner::Nobody) => "owner is nobody".into(),
        Condition::Owner(Owner::Team(side)) => format!("owner is {}", side_name(*side)),
        Condition::Owner(Owner::Player(t)) => format!("owner is {}", target(*t)),
        Condition::Mode(mode) => format!("game_mode is {}", game_mode(*mode)),
        Condition::Steps { op, steps } => format!("steps {} {steps}", op.symbol()),
        Condition::Score { side, op, goals } => format!("score({}) {} {goals}", side_name(*side), op.symbol()),
        Condition::Done => "done".into(),
    }
}

fn target(t: Target) -> String {
    match t {
        Target::Ball => "ball".into(),
        Target::Me => "me".into(),
        Target::Left(i) => format!("left[{i}]"),
        Target::Right(i) => format!("right[{i}]"),
        Target::Point([x, y]) => format!("({}, {})", number(x), number(y)),
    }
}

fn side_name(side: Side) -> &'static str {
    match side {
        Side::Left => "left",
        Side::Right => "right",
    }
}

/// The condition language's name of a game mode (`throw_in`).
fn game_mode(mode: GameMode) -> &'static str {
    match mode {
        GameMode::Normal => "normal",
        GameMode::KickOff => "kick_off",
        GameMode::GoalKick => "goal_kick",
        GameMode::FreeKick => "free_kick",
        GameMode::Corner => "corner",
        GameMode::ThrowIn => "throw_in",
        GameMode::Penalty => "penalty",
    }
}

fn place(nominal: [f32; 2], random: Option<&Spot>, draws: &Draws) -> String {
    match random {
        None => format!("at ({}, {})", number(nominal[0]), number(nominal[1])),
        Some(Spot::Point { x, y }) => format!("at ({}, {})", sample(x, draws), sample(y, draws)),
        Some(Spot::In(r)) => format!("in {}", region(r)),
        Some(Spot::OneOf(points)) => format!(
            "at choice[{}]",
            points.iter().map(|[x, y]| format!("({}, {})", number(*x), number(*y))).collect::<Vec<_>>().join(", ")
        ),
        Some(Spot::Relative(a)) => {
            let of = match a.of {
                Body::Ball => "ball".to_owned(),
                Body::Left(i) => format!("left[{i}]"),
                Body::Right(i) => format!("right[{i}]"),
            };
            let at = if a.offset == [0.0, 0.0] {
                of
            } else {
                format!("{of} + ({} m, {} m)", number(a.offset[0]), number(a.offset[1]))
            };
            if a.radius > 0.0 { format!("at near({at}, {} m)", number(a.radius)) } else { format!("at {at}") }
        }
    }
}

/// A coordinate: a shared draw by its param's name, anything else written out.
fn sample(s: &Sample, draws: &Draws) -> String {
    if let Some(name) = draws.name(s) {
        return name.to_owned();
    }
    match s {
        Sample::Fixed(v) => number(*v),
        // A shared draw no param can express (a hand-written JSON's) is drawn at each use.
        Sample::Random(d) | Sample::Shared(Shared { of: d, .. }) => draws::text(d, number),
    }
}

fn region(r: &Region) -> String {
    match r {
        Region::Rect { x, y } => {
            format!("rect(({}, {}), ({}, {}))", number(x[0]), number(y[0]), number(x[1]), number(y[1]))
        }
        Region::Circle { x, y, r } => format!("circle({}, {}, {})", number(*x), number(*y), number(*r)),
    }
}

/// `reward on A then any of (B, C) once 0.5`.
fn event_reward(reward: &EventReward, value: f32) -> String {
    let steps: Vec<String> = reward
        .sequence
        .iter()
        .map(|step| match step {
            EventStep::One(a) => event_atom(a),
            EventStep::AnyOf(atoms) | EventStep::AllOf(atoms) => {
                let kind = if matches!(step, EventStep::AllOf(_)) { "all" } else { "any" };
                format!("{kind} of ({})", atoms.iter().map(event_atom).collect::<Vec<_>>().join(", "))
            }
        })
        .collect();
    let repeat = if reward.once { "once" } else { "each time" };
    format!("reward on {} {repeat} {}", steps.join(" then "), number(value))
}

fn event_atom(a: &EventAtom) -> String {
    let (name, region) = match &a.event {
        EventKind::GoalFor => ("goal_for", None),
        EventKind::GoalAgainst => ("goal_against", None),
        EventKind::Shot => ("shot", None),
        EventKind::ShotOnTarget => ("shot_on_target", None),
        EventKind::Pass => ("pass", None),
        EventKind::PassCompleted => ("pass_completed", None),
        EventKind::PassIntercepted => ("pass_intercepted", None),
        EventKind::PossessionWon => ("possession_won", None),
        EventKind::PossessionLost => ("possession_lost", None),
        EventKind::OutOfPlay => ("out_of_play", None),
        EventKind::Foul => ("foul", None),
        EventKind::Card => ("card", None),
        EventKind::YellowCard => ("yellow_card", None),
        EventKind::RedCard => ("red_card", None),
        EventKind::Offside => ("offside", None),
        EventKind::Save => ("save", None),
        EventKind::BallEnters(r) => ("ball", Some(format!("enters {}", region(r)))),
        EventKind::BallIn(r) => ("ball", Some(format!("in {}", region(r)))),
        EventKind::HasBall => ("has_ball", None),
        EventKind::HasBallIn(r) => ("has_ball", Some(format!("in {}", region(r)))),
    };
    // The language writes the other team's events `opponent_…`; goal_against and
    // possession_lost already are the other side of goal_for and possession_won.
    let mut text = match (a.team, name) {
        (EventTeam::Own, _) => name.to_owned(),
        (EventTeam::Opponent, "goal_for") => "goal_against".to_owned(),
        (EventTeam::Opponent, "goal_against") => "goal_for".to_owned(),
        (EventTeam::Opponent, "possession_won") => "possession_lost".to_owned(),
        (EventTeam::Opponent, "possession_lost") => "possession_won".to_owned(),
        (EventTeam::Opponent, _) => format!("opponent_{name}"),
    };
    if let Some(region) = region {
        text.push(' ');
        text.push_str(&region);
    }
    if a.by_player {
        text.push_str(" by player");
    }
    text
}

fn body(b: touchline_engine::scenario::Body) -> String {
    use touchline_engine::scenario::Body;
    match b {
        Body::Ball => "ball".into(),
        Body::Left(i) => format!("left[{i}]"),
        Body::Right(i) => format!("right[{i}]"),
    }
}

/// The shortest text that reads back as the same `f32` (`-1`, `0.02`, `0.063559`).
fn number(v: f32) -> String {
    let text = format!("{v}");
    if text == "-0" { "0".into() } else { text }
}

/// Splits a doc line at spaces into chunks of at most `width` characters.
fn wrap(line: &str, width: usize) -> Vec<String> {
    let mut chunks: Vec<String> = Vec::new();
    for word in line.split(' ') {
        match chunks.last_mut() {
            Some(last) if last.len() + 1 + word.len() <= width => {
                last.push(' ');
                last.push_str(word);
            }
            _ => chunks.push(word.to_owned()),
        }
    }
    chunks
}
