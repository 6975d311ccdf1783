//! `curriculum { lesson … advance when … }`: each lesson compiled to a complete scenario (the
//! curriculum's own scenario, or the one it extends, with the lesson's parameter values and
//! statements on top), the criteria read and checked, and the lessons checked against each other.

use touchline_engine::Scenario;
use touchline_engine::scenario::{Criterion, Curriculum, EndCondition, Lesson, Metric, RewardKind, Threshold};

use super::params::{self, Params};
use super::statements;
use super::value::{Reader, suggest_help};
use super::{Compiler, check};
use crate::diagnostic::{Code, Diagnostic, Source};
use crate::suggest;
use crate::syntax::{self, Definition, Kind, Span, StatementKind};

impl Compiler {
    /// The curriculum of the main scenario `(unit, def)`, or `None` when it has none or it has errors (reported).
    pub(super) fn curriculum(&mut self, unit: usize, def: usize) -> Option<Box<Curriculum>> {
        let d = self.definition(unit, def).clone();
        let (block, span) = d.statements.iter().find_map(|s| match &s.kind {
            StatementKind::Curriculum(c) => Some((c.clone(), s.span)),
            _ => None,
        })?;
        let source = self.units[unit].source.clone();
        let errors_before = self.diags.errors().count();
        if block.lessons.is_empty() {
            self.diags.push(
                Diagnostic::new(Code::CurriculumShape, "this curriculum has no lessons", &source, span, "no lessons")
                    .with_help("add lessons: `lesson NAME { param_name = VALUE }` or `lesson NAME extends SCENARIO`"),
            );
            return None;
        }
        for extra in block.advance.iter().skip(1) {
            self.diags.push(
                Diagnostic::new(
                    Code::CurriculumShape,
                    "a curriculum has one `advance when`",
                    &source,
                    extra.span,
                    "a second criterion",
                )
                .with_label(block.advance[0].span, "the first")
                .with_help("join the thresholds with `and` in one `advance when`, or give a lesson its own"),
            );
        }
        let global = block.advance.first();
        let mut lessons = Vec::new();
        for (i, l) in block.lessons.iter().enumerate() {
            if let Some(first) = block.lessons[..i].iter().find(|o| o.name.value == l.name.value) {
                self.diags.push(
                    Diagnostic::new(
                        Code::Duplicate,
                        format!("lesson `{}` is given twice", l.name.value),
                        &source,
                        l.name.span,
                        "again here",
                    )
                    .with_label(first.name.span, "first given here")
                    .with_help("give each lesson its own name"),
                );
            }
            if let Some(lesson) = self.lesson(unit, def, l, global, &source) {
                lessons.push((lesson, l.name.span));
            }
        }
        if self.diags.errors().count() > errors_before || lessons.len() != block.lessons.len() {
            return None;
        }
        self.check_lessons(&lessons, &source);
        let last = lessons.len() - 1;
        for (lesson, name_span) in &lessons[..last] {
            if lesson.advance.is_none() {
                self.diags.push(
                    Diagnostic::new(
                        Code::NeverAdvances,
                        format!("lesson `{}` has no `advance when`: the curriculum would never leave it", lesson.name),
                        &source,
                        *name_span,
                        "no criterion",
                    )
                    .with_help(
                        "give the curriculum an `advance when …` for every lesson, or this lesson its own inside its braces",
                    ),
                );
            }
        }
        (self.diags.errors().count() == errors_before)
            .then(|| Box::new(Curriculum { lessons: lessons.into_iter().map(|(l, _)| l).collect() }))
    }

    /// One lesson compiled: its parent resolved with the lesson's parameter values, its
    /// statements applied, the result checked.
    fn lesson(
        &mut self,
        unit: usize,
        def: usize,
        l: &syntax::Lesson,
        global: Option<&syntax::Advance>,
        source: &Source,
    ) -> Option<Lesson> {
        for st in &l.statements {
            let (what, help) = match &st.kind {
                StatementKind::Curriculum(_) => ("a lesson cannot hold a curriculum", "curricula do not nest"),
                StatementKind::Extends(_) => {
                    ("a lesson names what it extends on its first line", "write `lesson NAME extends SCENARIO { … }`")
                }
                _ => continue,
            };
            self.diags.push(Diagnostic::new(Code::CurriculumShape, what, source, st.span, "here").with_help(help));
        }
        let (declared, assigned) = params::of_statements(&l.statements, source);
        self.check_param_duplicates(&declared, source);
        let mut overrides = Params::default();
        for p in declared.iter().chain(&assigned) {
            overrides.set(p.clone());
        }
        let target = match &l.parent {
            None => Some((unit, def)),
            Some(name) => {
                let found = self.lookup(unit, &name.value);
                if found.is_none() {
                    let names = self.visible_names(unit);
                    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
                    let close = suggest::closest(&name.value, &refs);
                    self.diags.push(
                        Diagnostic::new(
                            Code::UnknownLesson,
                            format!("lesson `{}` extends `{}`, which does not exist", l.name.value, name.value),
                            source,
                            name.span,
                            "unknown scenario",
                        )
                        .with_help(suggest_help(
                            &close,
                            "a lesson extends a scenario or preset of this file, an import, or the stdlib",
                        )),
                    );
                }
                found
            }
        };
        let (u, i) = target?;
        let (mut scenario, mut origins, mut env) = self.resolve_with(u, i, &overrides)?;
        for p in &declared {
            env.set(p.clone());
        }
        self.assign_params(&mut env, &assigned, &Params::default(), source, Some(&l.name.value));
        let body = Definition {
            docs: Vec::new(),
            kind: Kind::Scenario,
            name: l.name.clone(),
            statements: l.statements.clone(),
            span: l.span,
        };
        let mut reader = Reader::new(source, &mut self.diags, &env);
        statements::apply(&body, &mut scenario, &mut origins, &mut reader);
        // A lesson's own places can share a draw across axes as a scenario body's can.
        reader.warn_repeated_draws();
        let own = l.statements.iter().find_map(|s| match &s.kind {
            StatementKind::Advance(a) => Some(a),
            _ => None,
        });
        let advance = own.or(global).and_then(|a| criterion(a, &scenario, &mut reader));
        scenario.curriculum = None;
        // A lesson is known by its own name; its scenario carries the curriculum's.
        let main = self.definition(unit, def);
        scenario.name = main.name.value.clone();
        scenario.description = super::description(&main.docs);
        check::check(&scenario, &origins, source, l.name.span, &mut self.diags);
        Some(Lesson { name: l.name.value.clone(), scenario, advance })
    }

    /// `tl::E147` for lessons an env cannot switch between: `control_all_players` set
    /// differently, or set with another number of controllable players a side (an env gets one
    /// agent a controllable player then), or other scripts. (Without `control_all_players` the
    /// agents are the env's choice: the env checks them against every lesson when it is built.)
    fn check_lessons(&mut self, lessons: &[(Lesson, Span)], source: &Source) {
        let Some((first, _)) = lessons.first() else { return };
        let shape = |s: &Scenario| (s.controllable_players(), s.control_all_players);
        for (l, span) in &lessons[1..] {
            let (a, b) = (shape(&first.scenario), shape(&l.scenario));
            if a != b && (a.1 || b.1) {
                self.diags.push(
                    Diagnostic::new(
                        Code::LessonMismatch,
                        format!(
                            "lesson `{}` has {} controllable players left and {} right{}, lesson `{}` {} and {}{}",
                            l.name,
                            b.0[0],
                            b.0[1],
                            if b.1 { " (control_all_players)" } else { "" },
                            first.name,
                            a.0[0],
                            a.0[1],
                            if a.1 { " (control_all_players)" } else { "" }
                        ),
                        source,
                        *span,
                        "other controllable players",
                    )
                    .with_help(
                        "with control_all_players an env has one agent a controllable player and keeps them \
                         across lessons: give every lesson the same controllable players (mark the others \
                         `not controllable`) and the same control_all_players",
                    ),
                );
            }
            if scripts(&first.scenario) != scripts(&l.scenario) {
                self.diags.push(
                    Diagnostic::new(
                        Code::LessonMismatch,
                        format!("lesson `{}` runs other scripts than lesson `{}`", l.name, first.name),
                        source,
                        *span,
                        "other scripts",
                    )
                    .with_help("an env compiles its scripts once: give every lesson the same script terms"),
                );
            }
        }
    }
}

/// The script terms of a scenario (reward scripts with weights, end scripts), in order.
fn scripts(s: &Scenario) -> Vec<String> {
    let rewards = s.rewards.iter().filter_map(|t| match &t.reward {
        RewardKind::Script { path } => Some(format!("reward {path} {}", t.weight)),
        _ => None,
    });
    let ends = s.end_when.iter().filter_map(|c| match c {
        EndCondition::Script { path } => Some(format!("end {path}")),
        _ => None,
    });
    let mut behaviours: Vec<String> = s.script_behaviours().map(|p| format!("behaviour {p}")).collect();
    behaviours.sort();
    behaviours.dedup();
    rewards.chain(ends).chain(behaviours).collect()
}

/// The most a left agent can earn in one episode of `s`, when that is known: the episode ends on
/// the first goal and every reward term is scoring or checkpoints (an env may add GRF's
/// checkpoints, 1.0 in all, when the scenario has none).
fn max_episode_reward(s: &Scenario) -> Option<f64> {
    if !s.end_episode_on_score {
        return None;
    }
    if s.rewards.is_empty() {
        return Some(2.0);
    }
    let (mut scoring, mut checkpoints) = (0.0f64, None);
    for t in &s.rewards {
        match &t.reward {
            RewardKind::Scoring => scoring += f64::from(t.weight),
            RewardKind::Checkpoints { count, value } => {
                checkpoints = Some((f64::from(*count) * f64::from(*value) * f64::from(t.weight)).max(0.0));
            }
            _ => return None,
        }
    }
    Some(scoring.max(0.0) + checkpoints.unwrap_or(1.0))
}

/// `advance when …` read for the lesson playing `s`.
fn criterion(a: &syntax::Advance, s: &Scenario, r: &mut Reader<'_>) -> Option<Criterion> {
    let help = "write a whole number of episodes, e.g. `over 100 episodes`";
    let window = r.whole(&a.window, "the window", 1, "episodes", help);
    let min = match &a.min {
        Some(m) => r.whole(m, "the minimum", 1, "episodes", help),
        None => window,
    };
    let mut thresholds = Vec::new();
    let mut ok = true;
    for t in &a.thresholds {
        let Some(metric) = Metric::from_name(&t.metric.value) else {
            let close = suggest::closest(&t.metric.value, &Metric::NAMES);
            r.error_help(
                Code::UnknownMetric,
                format!("unknown metric `{}`", t.metric.value),
                t.metric.span,
                "not a metric",
                suggest_help(&close, &format!("the metrics are {}", Metric::NAMES.join(", "))),
            );
            ok = false;
            continue;
        };
        let Some(value) = r.plain_number(&t.value, metric.name()) else {
            ok = false;
            continue;
        };
        let (low, high, why) = match metric {
            Metric::SuccessRate => (Some(0.0), Some(1.0), "a success rate is a fraction in [0, 1]".to_owned()),
            Metric::MeanScore if s.end_episode_on_score => (
                Some(-1.0),
                Some(1.0),
                "the episode ends on the first goal, so the score difference is -1, 0 or 1".to_owned(),
            ),
            Metric::MeanReward => match max_episode_reward(s) {
                Some(max) => (
                    None,
                    Some(max),
                    format!("the episode ends on the first goal and its reward terms pay at most {max} an episode"),
                ),
                None => (None, None, String::new()),
            },
            Metric::MeanScore => (None, None, String::new()),
        };
        let never = if t.at_least { high.is_some_and(|h| value > h) } else { low.is_some_and(|l| value < l) };
        if never {
            r.error_help(
                Code::NeverAdvances,
                format!("`{} {} {value}` can never hold", metric.name(), if t.at_least { ">=" } else { "<=" }),
                t.value.span,
                "out of reach",
                why,
            );
            ok = false;
        }
        thresholds.push(Threshold { metric, at_least: t.at_least, value });
    }
    let (window, min) = (window?, min?);
    if min > window {
        let span = a.min.as_ref().map_or(a.window.span, |m| m.span);
        r.error_help(
            Code::NeverAdvances,
            format!("the criterion waits for {min} episodes, but its window holds only {window}"),
            span,
            "never reached",
            format!("write `min N episodes` with N at most {window}, or widen the window"),
        );
        return None;
    }
    ok.then_some(Criterion { window, min_episodes: min, thresholds })
}
