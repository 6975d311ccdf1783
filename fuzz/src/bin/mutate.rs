//! A mutation fuzzer on the stable toolchain, for the targets of `touchline_fuzz` (cargo-fuzz
//! needs nightly). It starts from the stdlib and example scenarios (`.tl` or their compiled JSON),
//! applies 1 to 8 random edits a case — bytes, tokens of the language, long runs that make deep
//! nesting and very long lines, lines joined into one — runs the target under `catch_unwind`, and
//! writes each input that panics to the crash directory.
//!
//! ```text
//! mutate TARGET [--seconds N] [--seed S] [--crashes DIR]
//!   TARGET   compile | json | play
//! ```
//!
//! Prints the cases run and the crashes found every 30 s and at the end (with, for `json` and
//! `play`, how many inputs got as far as a built env and were played); exits 1 when any case
//! crashed. The input under test is kept in `DIR/in-progress` (removed at a clean exit), so that
//! one that kills the process (a stack overflow aborts) is not lost.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Tokens an edit may insert: the language's words and punctuation, JSON's, and troublemakers.
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
    "-",
    "*",
    "/",
    ">=",
    "<=",
    "<",
    "==",
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
    "not controllable",
    "on odd episodes swap teams",
    "on odd episodes ball at (0.5, 0)",
    "require",
    "distance",
    "reward",
    "scoring",
    "checkpoint",
    "weight",
    "end",
    "when",
    "or",
    "and",
    "steps",
    "score",
    "out_of_play",
    "possession_change",
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
    "1e38",
    "NaN",
    "inf",
    "0.5 m",
    "é",
    "𝄞",
    "\u{0}",
    "\t",
    "left[0]",
    "right.GK",
    "extends 5_vs_5",
    "extends academy_corner",
    "game_duration",
    "control_all_players true",
    "does press",
    "then",
    "until",
    "is",
    "behaviour",
    "me",
    "done",
    "owner",
    "game_mode",
    "move_to((0.5, 0))",
    "pass_to(left[1], high)",
    "param gap = 5 m",
    "gap",
    "curriculum",
    "lesson",
    "advance when",
    "team right { GK at (-1, 0) not controllable }",
    "null",
    "true",
    "false",
    "\"left_team\"",
    "\"right_team\"",
    "\"controllable\": false",
    "\"swap_teams_on_odd_episodes\": true",
    "{\"role\": \"GK\", \"x\": -1.0, \"y\": 0.0}",
    "\"game_duration\": ",
    "99999999999999999999",
    "-0",
];

/// xorshift64*: small, seeded, the same everywhere.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        if n == 0 { 0 } else { (self.next() % n as u64) as usize }
    }
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

/// One random edit of `text`.
fn mutate(text: &mut Vec<u8>, rng: &mut Rng) {
    let n = text.len();
    let at = rng.below(n + 1);
    match rng.below(11) {
        0 => {
            let len = 1 + rng.below(16);
            text.drain(at..(at + len).min(n));
        }
        1 => {
            let bytes: Vec<u8> = (0..1 + rng.below(6)).map(|_| rng.next() as u8).collect();
            text.splice(at..at, bytes);
        }
        2 if n > 0 => text[at.min(n - 1)] = rng.next() as u8,
        3 => {
            let t = format!(" {} ", TOKENS[rng.below(TOKENS.len())]);
            text.splice(at..at, t.bytes());
        }
        4 => {
            let toks = tokens(text);
            if let Some(&(s, e)) = toks.get(rng.below(toks.len())) {
                let t = TOKENS[rng.below(TOKENS.len())];
                text.splice(s..e, t.bytes());
            }
        }
        5 => {
            let toks = tokens(text);
            if let Some(&(s, e)) = toks.get(rng.below(toks.len())) {
                let copy: Vec<u8> = std::iter::once(b' ').chain(text[s..e].iter().copied()).collect();
                text.splice(e..e, copy);
            }
        }
        // A long run: deep nesting (`(`, `not `, `-`), a very long line, a huge number.
        6 => {
            let unit: &[u8] = match rng.below(8) {
                0 => b"(",
                1 => b"not ",
                2 => b"- ",
                3 => b" ",
                4 => b"x",
                5 => b"[",
                6 => b"9",
                _ => b"0.5 + ",
            };
            let count = [10, 70, 200, 1_000, 10_000, 70_000][rng.below(6)];
            let run: Vec<u8> = unit.iter().copied().cycle().take(unit.len() * count).collect();
            text.splice(at..at, run);
        }
        // Everything on one line (a minified JSON, a one-line scenario).
        7 => {
            for b in text.iter_mut() {
                if *b == b'\n' {
                    *b = b' ';
                }
            }
        }
        // A stretch copied elsewhere (grows the text, repeats structures).
        8 if n > 0 => {
            let s = rng.below(n);
            let e = (s + 1 + rng.below(400)).min(n);
            let copy = text[s..e].to_vec();
            let to = rng.below(n + 1);
            text.splice(to..to, copy);
        }
        9 => text.truncate(at),
        _ => {
            let toks = tokens(text);
            if toks.len() >= 2 {
                let (i, j) = (rng.below(toks.len()), rng.below(toks.len()));
                let (a, b) = if i <= j { (toks[i], toks[j]) } else { (toks[j], toks[i]) };
                if a != b {
                    let (ta, tb) = (text[a.0..a.1].to_vec(), text[b.0..b.1].to_vec());
                    text.splice(b.0..b.1, ta);
                    text.splice(a.0..a.1, tb);
                }
            }
        }
    }
    // Inputs stay under 1 MiB, as files users write do.
    text.truncate(1 << 20);
}

/// The seed inputs of `target`: the stdlib's and the examples' `.tl` sources, or the stdlib's
/// compiled JSON.
fn corpus(target: &str) -> Vec<Vec<u8>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let ext = if target == "json" { "json" } else { "tl" };
    let mut files = Vec::new();
    for dir in ["stdlib-scenarios", "stdlib-scenarios/tests", "examples/scenarios"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir)) else { continue };
        files.extend(entries.filter_map(|e| Some(e.ok()?.path())).filter(|p| p.extension().is_some_and(|e| e == ext)));
    }
    files.sort();
    files.iter().filter_map(|p| std::fs::read(p).ok()).collect()
}

fn run_target(target: &str, text: &str) {
    match target {
        "compile" => touchline_fuzz::compile(text),
        "json" => touchline_fuzz::json(text),
        _ => touchline_fuzz::play(text),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let target = args.first().cloned().unwrap_or_default();
    if !["compile", "json", "play"].contains(&target.as_str()) {
        eprintln!("usage: mutate compile|json|play [--seconds N] [--seed S] [--crashes DIR]");
        std::process::exit(2);
    }
    let flag = |name: &str| args.iter().position(|a| a == name).and_then(|i| args.get(i + 1)).cloned();
    let seconds: u64 = flag("--seconds").and_then(|s| s.parse().ok()).unwrap_or(60);
    let seed: u64 = flag("--seed").and_then(|s| s.parse().ok()).unwrap_or(1);
    let crashes = PathBuf::from(flag("--crashes").unwrap_or_else(|| format!("fuzz-crashes/{target}")));
    std::fs::create_dir_all(&crashes).expect("the crash directory");
    let in_progress = crashes.join("in-progress");

    // Panics are counted and their inputs saved; their messages go to the crash files, not the
    // terminal.
    std::panic::set_hook(Box::new(|info| {
        let message = info.to_string();
        LAST_PANIC.with(|p| *p.borrow_mut() = message);
    }));

    let seeds = corpus(&target);
    assert!(!seeds.is_empty(), "no seed inputs found");
    let mut rng = Rng(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1);
    let start = Instant::now();
    let (mut cases, mut crashed, mut slowest) = (0u64, 0u64, Duration::ZERO);
    let mut report = Instant::now();
    while start.elapsed() < Duration::from_secs(seconds) {
        let mut input = seeds[rng.below(seeds.len())].clone();
        for _ in 0..1 + rng.below(8) {
            mutate(&mut input, &mut rng);
        }
        let text = String::from_utf8_lossy(&input).into_owned();
        let _ = std::fs::write(&in_progress, &text);
        let began = Instant::now();
        let outcome = catch_unwind(AssertUnwindSafe(|| run_target(&target, &text)));
        slowest = slowest.max(began.elapsed());
        cases += 1;
        if outcome.is_err() {
            crashed += 1;
            let message = LAST_PANIC.with(|p| p.borrow().clone());
            let name = format!("{target}-{cases}");
            let _ = std::fs::write(crashes.join(format!("{name}.input")), &text);
            let _ = std::fs::write(crashes.join(format!("{name}.panic")), &message);
            eprintln!("crash {crashed} (case {cases}): {}", message.lines().next().unwrap_or(""));
        }
        if report.elapsed() >= Duration::from_secs(30) {
            report = Instant::now();
            eprintln!("{target}: {cases} cases, {crashed} crashes, {:.0} s", start.elapsed().as_secs_f64());
        }
    }
    let _ = std::fs::remove_file(&in_progress);
    println!(
        "{target}: {cases} cases in {:.0} s ({:.0}/s), {crashed} crashes, slowest case {:.2} s, {} played, seed {seed}",
        start.elapsed().as_secs_f64(),
        cases as f64 / start.elapsed().as_secs_f64(),
        slowest.as_secs_f64(),
        touchline_fuzz::PLAYED.load(std::sync::atomic::Ordering::Relaxed)
    );
    std::process::exit(i32::from(crashed > 0));
}

thread_local! {
    static LAST_PANIC: std::cell::RefCell<String> = const { std::cell::RefCell::new(String::new()) };
}
