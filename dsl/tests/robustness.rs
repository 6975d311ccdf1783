//! No input panics the compiler: mutated stdlib sources (bytes deleted, inserted or replaced,
//! tokens swapped, duplicated or replaced by keywords, the text truncated) are compiled, and every
//! diagnostic must have its spans inside its source on `char` boundaries and render.
//!
//! The case count is modest for CI (384); set `PROPTEST_CASES` for a longer run, e.g.
//! `PROPTEST_CASES=200000 cargo nextest run -p touchline-dsl --test robustness --release`.

use proptest::prelude::*;
use touchline_dsl::{Diagnostics, compile, stdlib};

/// Every stdlib source and the prelude.
fn sources() -> Vec<&'static str> {
    let mut all: Vec<&str> =
        stdlib::names().iter().copied().chain(stdlib::test_names()).filter_map(stdlib::tl_source).collect();
    all.push(touchline_dsl::PRELUDE);
    all.extend(EXAMPLES);
    all
}

/// The example scenarios with behaviours and conditions.
const EXAMPLES: [&str; 5] = [
    include_str!("../../examples/scenarios/defend_zigzag_dribbler.tl"),
    include_str!("../../examples/scenarios/keep_ball_under_press.tl"),
    include_str!("../../examples/scenarios/keeper_one_on_one.tl"),
    include_str!("../../examples/scenarios/mark_and_intercept.tl"),
    include_str!("../../examples/scenarios/two_vs_two_box_defence.tl"),
];

/// Tokens a mutation may insert: the language's keywords and punctuation, and a few troublemakers
/// (non-ASCII text, huge and odd numbers, an import, names that create cycles).
const TOKENS: &[&str] = &[
    "{",
    "}",
    "(",
    ")",
    "[",
    "]",
    ",",
    ":",
    ".",
    "+",
    ">=",
    "<=",
    "\"",
    "//",
    "///",
    "\n",
    "scenario",
    "preset",
    "import",
    "extends",
    "academy",
    "ball",
    "at",
    "in",
    "team",
    "left",
    "right",
    "formation",
    "\"4-4-2\"",
    "lazy",
    "not",
    "controllable",
    "on",
    "odd",
    "episodes",
    "swap",
    "teams",
    "require",
    "distance",
    "reward",
    "scoring",
    "checkpoint",
    "script",
    "\"x.rhai\"",
    "weight",
    "end",
    "when",
    "or",
    "steps",
    "score",
    "out_of_play",
    "possession_change",
    "start",
    "from",
    "uniform",
    "normal",
    "choice",
    "circle",
    "rect",
    "penalty_area",
    "GK",
    "CB",
    "CF",
    "m",
    "0",
    "-1",
    "1e40",
    "-1e-40",
    "NaN",
    "inf",
    "99999999999999999999",
    "0.5 m",
    "é",
    "€",
    "𝄞",
    "\u{0}",
    "\t",
    "left[0]",
    "right.GK",
    "import \"x.tl\"",
    "extends academy_corner",
    "game_duration",
    "second_half",
    "difficulty",
    "true",
    "false",
    "does",
    "do",
    "then",
    "shoot",
    "until",
    "and",
    "is",
    "behaviour",
    "me",
    "done",
    "owner",
    "game_mode",
    "<",
    "==",
    "!=",
    "press",
    "move_to((0.5, 0))",
    "pass_to(left[1], high)",
    "builtin(2)",
    "does press then idle",
    "until distance(ball, me) < 5 m",
];

/// One edit of the text.
#[derive(Clone, Debug)]
enum Mutation {
    /// Delete `len` bytes at `at` (a fraction of the length).
    Delete { at: f64, len: usize },
    /// Insert raw bytes (the text is then repaired to UTF-8 lossily).
    InsertBytes { at: f64, bytes: Vec<u8> },
    /// Replace one byte.
    Replace { at: f64, byte: u8 },
    /// Insert a known token.
    InsertToken { at: f64, token: usize },
    /// Swap two whitespace-separated tokens.
    Swap { a: f64, b: f64 },
    /// Duplicate a token in place.
    Duplicate { at: f64 },
    /// Replace a token by a known one.
    ReplaceToken { at: f64, token: usize },
    /// Keep only a prefix.
    Truncate { at: f64 },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let at = 0.0..1.0f64;
    prop_oneof![
        (at.clone(), 1..12usize).prop_map(|(at, len)| Mutation::Delete { at, len }),
        (at.clone(), proptest::collection::vec(any::<u8>(), 1..6))
            .prop_map(|(at, bytes)| Mutation::InsertBytes { at, bytes }),
        (at.clone(), any::<u8>()).prop_map(|(at, byte)| Mutation::Replace { at, byte }),
        (at.clone(), 0..TOKENS.len()).prop_map(|(at, token)| Mutation::InsertToken { at, token }),
        (at.clone(), at.clone()).prop_map(|(a, b)| Mutation::Swap { a, b }),
        at.clone().prop_map(|at| Mutation::Duplicate { at }),
        (at.clone(), 0..TOKENS.len()).prop_map(|(at, token)| Mutation::ReplaceToken { at, token }),
        at.prop_map(|at| Mutation::Truncate { at }),
    ]
}

fn index(at: f64, len: usize) -> usize {
    ((at * len as f64) as usize).min(len)
}

/// Byte ranges of the whitespace-separated tokens of `text`.
fn tokens(text: &[u8]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, b) in text.iter().enumerate() {
        match (start, b.is_ascii_whitespace()) {
            (None, false) => start = Some(i),
            (Some(s), true) => {
                out.push((s, i));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, text.len()));
    }
    out
}

fn apply(text: &mut Vec<u8>, m: &Mutation) {
    let n = text.len();
    match m {
        Mutation::Delete { at, len } => {
            let i = index(*at, n);
            text.drain(i..(i + len).min(n));
        }
        Mutation::InsertBytes { at, bytes } => {
            let i = index(*at, n);
            text.splice(i..i, bytes.iter().copied());
        }
        Mutation::Replace { at, byte } => {
            if n > 0 {
                text[index(*at, n - 1)] = *byte;
            }
        }
        Mutation::InsertToken { at, token } => {
            let i = index(*at, n);
            let t = format!(" {} ", TOKENS[*token]);
            text.splice(i..i, t.bytes());
        }
        Mutation::Swap { a, b } => {
            let toks = tokens(text);
            if toks.len() >= 2 {
                let (i, j) = (index(*a, toks.len() - 1), index(*b, toks.len() - 1));
                let (first, second) = if i <= j { (toks[i], toks[j]) } else { (toks[j], toks[i]) };
                if first != second {
                    let a_text = text[first.0..first.1].to_vec();
                    let b_text = text[second.0..second.1].to_vec();
                    text.splice(second.0..second.1, a_text);
                    text.splice(first.0..first.1, b_text);
                }
            }
        }
        Mutation::Duplicate { at } => {
            let toks = tokens(text);
            if let Some(&(s, e)) = toks.get(index(*at, toks.len().saturating_sub(1))) {
                let copy: Vec<u8> = std::iter::once(b' ').chain(text[s..e].iter().copied()).collect();
                text.splice(e..e, copy);
            }
        }
        Mutation::ReplaceToken { at, token } => {
            let toks = tokens(text);
            if let Some(&(s, e)) = toks.get(index(*at, toks.len().saturating_sub(1))) {
                text.splice(s..e, TOKENS[*token].bytes());
            }
        }
        Mutation::Truncate { at } => text.truncate(index(*at, n)),
    }
}

/// Compiles `text` and checks every diagnostic: spans inside their source, on `char` boundaries,
/// and rendering works.
fn compile_and_check(text: &str) -> Result<(), String> {
    let diags: Diagnostics = match compile(text, "mutated.tl") {
        Ok(c) => c.warnings,
        Err(d) => {
            if !d.has_errors() {
                return Err("compile failed without an error".into());
            }
            d
        }
    };
    for d in &diags.items {
        let source = d.source.inner();
        for (span, _) in &d.labels {
            if span.start > span.end || span.end > source.len() {
                return Err(format!("{}: span {span:?} outside a source of {} bytes", d.code, source.len()));
            }
            if !source.is_char_boundary(span.start) || !source.is_char_boundary(span.end) {
                return Err(format!("{}: span {span:?} not on char boundaries", d.code));
            }
        }
        if touchline_dsl::render_plain(d).is_empty() {
            return Err(format!("{}: renders empty", d.code));
        }
    }
    let _ = diags.render_plain();
    Ok(())
}

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(384)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn mutated_stdlib_sources_never_panic(
        which in any::<prop::sample::Index>(),
        mutations in proptest::collection::vec(mutation(), 1..8),
    ) {
        let all = sources();
        let mut bytes = all[which.index(all.len())].as_bytes().to_vec();
        for m in &mutations {
            apply(&mut bytes, m);
        }
        let text = String::from_utf8_lossy(&bytes);
        if let Err(e) = compile_and_check(&text) {
            return Err(TestCaseError::fail(format!("{e}\n--- source ---\n{text}")));
        }
    }
}

#[test]
fn every_prefix_of_a_scenario_compiles_or_fails_cleanly() {
    let text = stdlib::tl_source("academy_3_vs_1_with_keeper").unwrap();
    for end in (0..=text.len()).filter(|&i| text.is_char_boundary(i)) {
        if let Err(e) = compile_and_check(&text[..end]) {
            panic!("prefix of {end} bytes: {e}");
        }
    }
}

#[test]
fn deleting_any_one_token_compiles_or_fails_cleanly() {
    let text = stdlib::tl_source("academy_pass_and_shoot_with_keeper").unwrap();
    for (s, e) in tokens(text.as_bytes()) {
        let mutated = format!("{}{}", &text[..s], &text[e..]);
        if let Err(err) = compile_and_check(&mutated) {
            panic!("without `{}`: {err}", &text[s..e]);
        }
    }
}

/// Found by a run of 1,000,000 cases (after 617,223 passed): a `//` and then a byte that is not
/// UTF-8 (repaired to U+FFFD) before a word the parser read as a role, which sliced the text
/// inside the replacement character while looking for a missing `}`.
#[test]
fn regression_comment_then_replacement_character() {
    let mut bytes = stdlib::tl_source("tests/corner_test").unwrap().as_bytes().to_vec();
    apply(&mut bytes, &Mutation::InsertToken { at: 0.867_285_025_485_725_3, token: 13 });
    apply(&mut bytes, &Mutation::InsertBytes { at: 0.900_534_000_256_155_7, bytes: vec![128] });
    let text = String::from_utf8_lossy(&bytes);
    compile_and_check(&text).unwrap();
    for text in ["scenario s { team left { GK at (-1, 0) \u{FFFD}team", "scenario s { team left { €team right } }"] {
        compile_and_check(text).unwrap();
    }
}

#[test]
fn hand_picked_troublemakers() {
    let cases = [
        "",
        "scenario",
        "scenario s {",
        "scenario s { team left { GK at (1e40, -1e40) } team right { GK at (-1, 0) } }",
        "scenario s { ball at (uniform(1e38, 1e39), 0) team left { GK at (-1, 0) } team right { GK at (-1, 0) } }",
        "scenario s { game_duration 99999999999999999999 }",
        "scenario s { extends s }",
        "scenario é { team left { GK at (-1, 0) 𝄞 at (0, 0) } }",
        "scenario s { require distance(left[99999999999999999999], ball) >= 1 m }",
        "scenario s { reward checkpoint(count: -1) weight 1e40 }",
        "scenario s { end when steps >= -1 or ball in circle(0, 0, -1) }",
        "scenario s { team left { GK in circle(0, 0, 1e-45) } team right { GK at (-1, 0) } }",
        "import \"\" scenario s { extends academy }",
        "import \"/\" scenario s { extends academy }",
        "scenario s { team left formation \"\" }",
        "/// é\n///\u{0}\nscenario s { extends academy_corner }",
    ];
    for text in cases {
        if let Err(e) = compile_and_check(text) {
            panic!("{text:?}: {e}");
        }
    }
}
