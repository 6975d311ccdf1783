//! The scripts reference, grammar/scripts.md, is tested (issue 18, item 3): every ` ```tl `
//! scenario in it compiles, and plays with the ` ```rhai ` scripts it names (each script block
//! starts with `// NAME.rhai:`); every ` ```rhai-error ` example fails with the code its
//! `// expect:` line names; the property table is the state scripts see; and every `tl::S…` code
//! the crate defines is in the code tables of scripts.md and grammar/README.md.

mod markdown;

use std::path::PathBuf;

use markdown::{Block, blocks};
use touchline_dsl::script::{STATE_PROPERTIES, ScriptOptions, Scripts};
use touchline_dsl::{build_env, compile};
use touchline_engine::{ActionSet, EnvConfig};

const SCRIPTS: &str = include_str!("../../grammar/scripts.md");
const LANGUAGE: &str = include_str!("../../grammar/README.md");

/// The script blocks by file name (`// progress.rhai: …` on their first line), written into a
/// scratch folder.
fn script_folder() -> (PathBuf, Vec<String>) {
    let dir = std::env::temp_dir().join(format!("touchline-script-reference-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut names = Vec::new();
    for b in blocks(SCRIPTS).into_iter().filter(|b| b.info == "rhai") {
        let first = b.text.lines().next().unwrap_or_default();
        let name = first
            .strip_prefix("// ")
            .and_then(|rest| rest.split_once(':'))
            .map(|(name, _)| name.to_owned())
            .filter(|name| name.ends_with(".rhai"))
            .unwrap_or_else(|| panic!("scripts.md line {}: a script starts with `// NAME.rhai:`", b.line));
        std::fs::write(dir.join(&name), &b.text).unwrap();
        names.push(name);
    }
    (dir, names)
}

/// Every worked example compiles, and plays three episodes of random actions (up to 80 steps each)
/// with its scripts, with one agent and, where the scenario has them, two: no hook fails.
#[test]
fn every_worked_example_compiles_and_plays() {
    let (dir, names) = script_folder();
    let scenarios: Vec<Block> = blocks(SCRIPTS).into_iter().filter(|b| b.info == "tl").collect();
    assert!(scenarios.len() >= 5, "a worked example per hook");
    let mut used = Vec::new();
    let set = ActionSet::Default.actions();
    for b in &scenarios {
        let compiled = compile(&b.text, &format!("scripts.md:{}", b.line)).unwrap_or_else(|d| {
            panic!("scripts.md line {}: the example does not compile\n{}", b.line, d.render_plain())
        });
        assert!(compiled.warnings.items.is_empty(), "scripts.md line {}: {}", b.line, compiled.warnings.render_plain());
        used.extend(names.iter().filter(|n| b.text.contains(&format!("\"{n}\""))).cloned());
        let controllable = compiled.scenario.controllable_every_episode()[0];
        for agents in 1..=controllable.min(2) {
            let config = EnvConfig { left_agents: agents, ..EnvConfig::default() };
            let mut env = build_env(compiled.scenario.clone(), &dir, config, 3)
                .unwrap_or_else(|e| panic!("scripts.md line {}: {}", b.line, touchline_dsl::render_plain(&e)));
            for episode in 0..3_usize {
                if episode > 0 {
                    env.reset().unwrap();
                }
                for step in 0..80_usize {
                    let actions: Vec<_> = (0..agents).map(|a| set[(step * 7 + a * 3 + episode) % set.len()]).collect();
                    let outcome = env.step(&actions).unwrap_or_else(|e| panic!("scripts.md line {}: {e}", b.line));
                    assert!(env.rewards().iter().all(|r| r.is_finite()));
                    if outcome.terminated || outcome.truncated {
                        break;
                    }
                }
            }
        }
    }
    for name in &names {
        assert!(used.contains(name), "scripts.md: no example scenario plays `{name}`");
    }
    let hooks = ["fn reward(s)", "fn end(s)", "fn act(s, me)", "fn reset(s)"];
    for hook in hooks {
        assert!(
            blocks(SCRIPTS).iter().any(|b| b.info == "rhai" && b.text.contains(hook)),
            "no worked example of `{hook}`"
        );
    }
}

#[test]
fn every_error_example_fails_as_it_says() {
    let mut checked = 0;
    for b in blocks(SCRIPTS).into_iter().filter(|b| b.info == "rhai-error") {
        let expected = b.text.lines().find_map(|l| l.strip_prefix("// expect: ")).unwrap_or_else(|| {
            panic!("scripts.md line {}: a rhai-error example names its code", b.line);
        });
        let Err(e) = Scripts::from_text("example.rhai", &b.text, Some(1.0), ScriptOptions::default()) else {
            panic!("scripts.md line {}: the example compiles but should fail", b.line)
        };
        let code = miette::Diagnostic::code(&*e).map(|c| c.to_string()).unwrap_or_default();
        assert_eq!(code, expected.trim(), "scripts.md line {}", b.line);
        checked += 1;
    }
    assert!(checked >= 1);
}

/// The table's first column, in order, is [`STATE_PROPERTIES`], and each one reads.
#[test]
fn the_property_table_is_the_state() {
    let section = SCRIPTS.split("## The state `s`").nth(1).unwrap().split("\n## ").next().unwrap();
    let listed: Vec<&str> = section
        .lines()
        .filter_map(|l| l.strip_prefix("| `"))
        .filter_map(|l| l.split_once('`'))
        .map(|(name, _)| name)
        .collect();
    assert_eq!(listed, STATE_PROPERTIES);
    let reads: Vec<String> = STATE_PROPERTIES.iter().map(|p| format!("let {p} = s.{p};")).collect();
    let text = format!("fn reward(s) {{ {} 0.0 }}", reads.join(" "));
    let scripts = Scripts::from_text("every.rhai", &text, Some(1.0), ScriptOptions::default()).unwrap();
    let scenario = touchline_dsl::load("academy_empty_goal_close").unwrap();
    let mut env =
        touchline_dsl::attach(&scripts, scenario, EnvConfig::default(), 0).expect("every property reads at reset");
    for _ in 0..3 {
        env.step(&[touchline_engine::Action::Right]).expect("every property reads in a step");
    }
}

/// The `tl::S…` codes the crate's sources define (`code(tl::S…)` attributes).
fn script_codes() -> Vec<String> {
    let sources = [
        include_str!("../src/script/error.rs"),
        include_str!("../src/build_env.rs"),
        include_str!("../src/watch.rs"),
        include_str!("../src/script/mod.rs"),
    ];
    let mut codes: Vec<String> =
        sources.iter().flat_map(|s| s.split("code(tl::S").skip(1)).map(|rest| format!("tl::S{}", &rest[..3])).collect();
    codes.sort();
    codes.dedup();
    codes
}

#[test]
fn every_script_code_is_in_both_code_tables() {
    let codes = script_codes();
    assert!(codes.len() >= 11, "{codes:?}");
    for code in &codes {
        let row = format!("| `{code}` |");
        assert!(SCRIPTS.contains(&row), "{code} is missing from scripts.md's table");
        assert!(LANGUAGE.contains(&row), "{code} is missing from grammar/README.md's table");
    }
}
