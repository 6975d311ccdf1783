//! What the compiler accepts plays (issue 17, item 3): scenarios built by editing the stdlib and
//! example sources are compiled and, when they compile, built into envs and played over several
//! resets. An env either refuses its configuration when built, with an error, or plays: never a
//! panic at a later reset. (engine/tests/playable.rs does the same on random engine scenarios.)
//!
//! The case count is modest for CI; set `PROPTEST_CASES` for a longer run.

use std::path::Path;

use proptest::prelude::*;
use touchline_dsl::{Code, build_env, compile, stdlib};
use touchline_engine::{EnvConfig, StepOutcome};

/// Statements an edit may add to a scenario: what changes who plays where and when.
const EDITS: &[&str] = &[
    "on odd episodes swap teams",
    "on odd episodes ball at (0.5, 0.1)",
    "control_all_players true",
    "team right { GK at (-1, 0) not controllable }",
    "team right { GK at (-1, 0) }",
    "team left { GK at (-1, 0) not controllable CB at (0, 0) }",
    "team left { GK at (-1, 0) not controllable CB at (0, 0) not controllable }",
    "team left { GK at (-1, 0) CF at (0.5, 0) lazy }",
    "team right formation \"4-4-2\"",
    "team left formation \"4-3-3\"",
    "game_duration 30",
    "end when steps >= 12 or score",
    "reward checkpoint(count: 3, value: 0.1)",
    "reward on shot then goal_for 1",
    "end_episode_on_possession_change true",
    "offsides true",
    "deterministic true",
];

fn sources() -> Vec<(String, String)> {
    let names = stdlib::names().iter().copied().chain(stdlib::test_names());
    // A stdlib scenario is extended rather than edited in place: its own `team` statements would
    // make an added one a duplicate (`tl::E110`) and nothing would play.
    let mut all: Vec<(String, String)> =
        names.map(|n| ("edited.tl".to_owned(), format!("scenario edited {{\n  extends {n}\n}}\n"))).collect();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenarios");
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "tl") {
            all.push((path.display().to_string(), std::fs::read_to_string(&path).unwrap()));
        }
    }
    all.sort();
    all
}

/// `source` with `edits` added as statements of its last definition (the scenario).
fn edited(source: &str, edits: &[usize]) -> String {
    let Some(end) = source.rfind('}') else { return source.to_owned() };
    let added: String = edits.iter().map(|&e| format!("  {}\n", EDITS[e])).collect();
    format!("{}{added}{}", &source[..end], &source[end..])
}

/// Compiles `text` (from `origin`) and, when it compiles, plays 3 episodes of up to 40 steps under
/// `config`. Returns whether it played (it may not compile, or refuse `config` when built).
fn compile_and_play(text: &str, origin: &str, config: EnvConfig) -> Result<bool, String> {
    let Ok(compiled) = compile(text, origin) else { return Ok(false) };
    let dir = Path::new(origin).parent().unwrap_or(Path::new("."));
    let Ok(mut env) = build_env(compiled.scenario, dir, config, 1) else { return Ok(false) };
    for _ in 0..3 {
        for step in 0..40u32 {
            let actions: Vec<u32> = (0..env.num_controllers() as u32).map(|i| (step * 5 + i) % 19).collect();
            let out: StepOutcome = env.step_indices(&actions).map_err(|e| e.to_string())?;
            if env.rewards().iter().any(|r| !r.is_finite()) {
                return Err("a reward is not finite".into());
            }
            if out.terminated || out.truncated {
                break;
            }
        }
        env.reset().unwrap();
    }
    Ok(true)
}

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(48)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn edited_scenarios_that_compile_play_through_resets(
        which in any::<prop::sample::Index>(),
        edits in prop::collection::vec(0..EDITS.len(), 1..4),
        agents in (0usize..=2, 0usize..=1),
    ) {
        let all = sources();
        let (origin, source) = &all[which.index(all.len())];
        let text = edited(source, &edits);
        let config = EnvConfig { left_agents: agents.0, right_agents: agents.1, ..EnvConfig::default() };
        let run = std::panic::catch_unwind(|| compile_and_play(&text, origin, config));
        match run {
            Ok(Ok(_)) => {}
            Ok(Err(e)) => return Err(TestCaseError::fail(format!("{e}\n--- source ---\n{text}"))),
            Err(_) => return Err(TestCaseError::fail(format!("panicked\n--- source ---\n{text}"))),
        }
    }
}

/// The case: 5_vs_5 whose right team is one keeper nobody controls. It compiles with the
/// warning `tl::W101` (in odd episodes the left agent would have no player) and the env refuses
/// one left agent when built, instead of panicking at the second reset.
#[test]
fn five_a_side_against_a_lone_keeper_warns_and_refuses_when_built() {
    let text = "scenario lone {\n  extends 5_vs_5\n  team right { GK at (-1, 0) not controllable }\n}\n";
    let compiled = compile(text, "lone.tl").unwrap();
    let w: Vec<_> = compiled.warnings.warnings().collect();
    assert!(
        w.iter().any(|d| d.code == Code::NoControllable && d.message.contains("swap")),
        "{}",
        compiled.warnings.render_plain()
    );
    let Err(err) = build_env(compiled.scenario.clone(), Path::new("."), EnvConfig::default(), 0) else {
        panic!("one left agent cannot play odd episodes");
    };
    assert!(err.to_string().contains("swap"), "{err}");
    let idle = EnvConfig { left_agents: 0, ..EnvConfig::default() };
    assert!(compile_and_play(text, "lone.tl", idle).unwrap());
}

/// The edits give scenarios that play (about half of them; the rest fail to compile or refuse one
/// left agent, by design): each stdlib scenario with each edit alone.
#[test]
fn many_single_edits_compile_and_play() {
    let (mut played, mut total) = (0, 0);
    for (origin, source) in sources().iter().filter(|(o, _)| o == "edited.tl") {
        for e in 0..EDITS.len() {
            total += 1;
            played += usize::from(compile_and_play(&edited(source, &[e]), origin, EnvConfig::default()).unwrap());
        }
    }
    assert!(played * 3 > total, "{played} of {total} played");
}
