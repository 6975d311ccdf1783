//! Every script diagnostic, one fixture each (issue 18, item 3): `tests/fixtures/scripts/NAME.rhai`
//! is attached to academy_empty_goal_close as a reward term (or, with a `// hook: end` line, an
//! end condition; `// weight: W` sets the term's weight) and the env is built and stepped until
//! the script fails, when it loads, at the first reset or in a step. The code and the text at the
//! primary label are checked against the fixture's `// expect: CODE `text`` line, and the rendered
//! text is compared with the insta snapshot `snapshots/script_diagnostics__NAME.snap`.
//!
//! Fixture name = test name = snapshot name; a fixture no test lists fails `every_fixture_has_a_test`.

use std::path::PathBuf;

use miette::Diagnostic;
use touchline_dsl::script::{ErrorPolicy, ScriptOptions};
use touchline_dsl::{BuildError, build_env_with, load, render_plain};
use touchline_engine::scenario::{EndCondition, RewardKind, RewardTerm};
use touchline_engine::{Action, EngineError};

const DIR: &str = "tests/fixtures/scripts";

/// A fixture's header line `// NAME: value`.
fn header<'a>(source: &'a str, name: &str) -> Option<&'a str> {
    source.lines().take_while(|l| l.starts_with("//")).find_map(|l| l.strip_prefix(&format!("// {name}: ")))
}

/// The expected code and the text its label covers (empty: no label).
fn expectation(source: &str) -> (String, String) {
    let rest = header(source, "expect").expect("the fixture starts with `// expect: CODE `text``");
    let (code, text) = rest.split_once(' ').unwrap_or((rest, ""));
    (code.to_owned(), text.trim().trim_matches('`').to_owned())
}

/// 1-based line and column (in characters) of `text`'s first occurrence after the header lines.
fn line_column(source: &str, text: &str) -> (usize, usize) {
    let header_end: usize = source.lines().take_while(|l| l.starts_with("//")).map(|l| l.len() + 1).sum();
    let at = header_end + source[header_end..].find(text).expect("the expected text is in the script");
    let line = source[..at].matches('\n').count() + 1;
    let line_start = source[..at].rfind('\n').map_or(0, |i| i + 1);
    (line, source[line_start..at].chars().count() + 1)
}

/// What went wrong: the code, the labelled text (from the diagnostic, or from the rendered
/// header's line and column for a diagnostic that reached us as text) and the rendered text.
struct Failure {
    code: String,
    at: Option<(usize, usize)>,
    labelled: Option<String>,
    rendered: String,
}

fn fail(name: &str, source: &str) -> Failure {
    let file = format!("{name}.rhai");
    let mut scenario = load("academy_empty_goal_close").unwrap();
    if header(source, "hook") == Some("end") {
        scenario.end_when.push(EndCondition::Script { path: file.clone() });
    } else {
        let weight = header(source, "weight").map_or(1.0, |w| w.parse().unwrap());
        scenario.rewards.push(RewardTerm { reward: RewardKind::Script { path: file.clone() }, weight });
    }
    let options = ScriptOptions { on_error: ErrorPolicy::Raise, ..ScriptOptions::default() };
    let from_text = |message: String| {
        let code = message.lines().next().unwrap_or_default().trim().to_owned();
        let at = message.split(&format!("[{file}:")).nth(1).and_then(|rest| {
            let (line, rest) = rest.split_once(':')?;
            let (column, _) = rest.split_once(']')?;
            Some((line.parse().ok()?, column.parse().ok()?))
        });
        Failure { code, at, labelled: None, rendered: message }
    };
    match build_env_with(scenario, &PathBuf::from(DIR), Default::default(), 0, options) {
        Err(BuildError::Scripts(mut errors)) => {
            let e = errors.errors.remove(0);
            let labelled = e.labels().and_then(|mut l| l.next()).map(|l| {
                let (start, len) = (l.offset(), l.len());
                source[start..start + len].to_owned()
            });
            let code = e.code().map(|c| c.to_string()).unwrap_or_default();
            Failure { code, at: None, labelled: Some(labelled.unwrap_or_default()), rendered: render_plain(&e) }
        }
        Err(BuildError::Engine(EngineError::Script { message, .. })) => from_text(message),
        Err(other) => panic!("{name}: {other:?}"),
        Ok(mut env) => {
            for _ in 0..50 {
                match env.step(&[Action::Right]) {
                    Ok(_) => {}
                    Err(EngineError::Script { message, .. }) => return from_text(message),
                    Err(other) => panic!("{name}: {other:?}"),
                }
            }
            panic!("{name}: the script did not fail in 50 steps")
        }
    }
}

fn fixture(name: &str) {
    let path = PathBuf::from(format!("{DIR}/{name}.rhai"));
    let source = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let (code, text) = expectation(&source);
    let failure = fail(name, &source);
    assert_eq!(failure.code, code, "{name}: the code\n{}", failure.rendered);
    match (&failure.labelled, failure.at) {
        (Some(labelled), _) => assert_eq!(labelled, &text, "{name}: the labelled text\n{}", failure.rendered),
        (None, Some(at)) => assert_eq!(at, line_column(&source, &text), "{name}: the label\n{}", failure.rendered),
        (None, None) => assert!(text.is_empty(), "{name}: no label\n{}", failure.rendered),
    }
    assert!(
        failure.rendered.contains("help:") || code == "tl::S002",
        "{name}: {code} has no help\n{}",
        failure.rendered
    );
    insta::with_settings!({ omit_expression => true, description => source }, {
        insta::assert_snapshot!(name, failure.rendered);
    });
}

macro_rules! fixtures {
    ($($name:ident)*) => {
        $(
            #[test]
            fn $name() {
                fixture(stringify!($name));
            }
        )*

        /// The fixtures with a test, by name.
        const FIXTURES: &[&str] = &[$(stringify!($name)),*];
    };
}

fixtures! {
    syntax_error
    undeclared_variable
    missing_hook
    top_level_let
    thrown_error
    endless_loop_in_reset
    endless_loop_in_reward
    unknown_property_in_a_helper
    assigns_to_the_state
    wrong_return_type
    refused_sleep
    reward_overflow
    unknown_property
    unknown_property_of_prev
}

#[test]
fn every_fixture_has_a_test() {
    let mut on_disk: Vec<String> = std::fs::read_dir(DIR)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rhai"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    let mut listed: Vec<&str> = FIXTURES.to_vec();
    listed.sort_unstable();
    assert_eq!(on_disk, listed);
}
