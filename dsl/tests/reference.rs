//! The language reference, grammar/README.md, is tested: every ` ```tl ` example in it compiles
//! without warnings, every ` ```tl-error ` example fails with the codes its `// expect:` lines name
//! (and its rendered text, when the README shows it, is exactly what the compiler prints), and every
//! ` ```json ` example is a loadable compiled scenario.
//!
//! Examples are compiled as if they were files in `tests/fixtures/reference/`, so that
//! `import "drills.tl"` finds the file the README describes.

mod markdown;

use markdown::{Block, blocks};
use touchline_dsl::{compile, load_json};

const README: &str = include_str!("../../grammar/README.md");

fn expected_codes(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| l.strip_prefix("// expect: "))
        .map(|rest| rest.split(' ').next().unwrap_or_default().to_owned())
        .collect()
}

/// Compiles every ` ```tl ` block of `markdown` (named `name` in messages) without a diagnostic;
/// returns how many there were.
fn compile_examples(markdown: &str, name: &str) -> usize {
    let examples: Vec<Block> = blocks(markdown).into_iter().filter(|b| b.info == "tl").collect();
    for b in &examples {
        let origin = format!("tests/fixtures/reference/{name}:{}", b.line);
        match compile(&b.text, &origin) {
            Ok(c) => {
                assert!(c.warnings.items.is_empty(), "{name} line {}: warnings\n{}", b.line, c.warnings.render_plain())
            }
            Err(d) => panic!("{name} line {}: the example does not compile\n{}", b.line, d.render_plain()),
        }
    }
    examples.len()
}

#[test]
fn every_tl_example_compiles() {
    let n = compile_examples(README, "README.md");
    assert!(n >= 12, "only {n} examples");
}

#[test]
fn the_project_readme_examples_compile() {
    let n = compile_examples(include_str!("../../README.md"), "../README.md");
    assert!(n >= 3, "only {n} examples");
}

#[test]
fn every_tl_error_example_fails_as_it_says() {
    let all = blocks(README);
    let mut checked = 0;
    for (i, b) in all.iter().enumerate().filter(|(_, b)| b.info == "tl-error") {
        let expected = expected_codes(&b.text);
        assert!(!expected.is_empty(), "README.md line {}: a tl-error example names its codes", b.line);
        let Err(diags) = compile(&b.text, "README.md") else {
            panic!("README.md line {}: the example compiles but should fail", b.line)
        };
        let found: Vec<String> = diags.items.iter().map(|d| d.code.as_str().to_owned()).collect();
        assert_eq!(found, expected, "README.md line {}", b.line);
        // "renders as" followed by a text block: the block is the compiler's exact output.
        if let Some(next) = all.get(i + 1).filter(|n| n.info == "text") {
            let between = README.lines().skip(b.line).take(next.line - b.line).collect::<Vec<_>>().join("\n");
            if between.contains("renders as") {
                assert_eq!(next.text.trim_end(), diags.render_plain().trim_end(), "README.md line {}", next.line);
            }
        }
        checked += 1;
    }
    assert!(checked >= 1);
}

#[test]
fn every_json_example_loads() {
    for b in blocks(README).into_iter().filter(|b| b.info == "json") {
        if let Err(e) = load_json(&b.text, "README.md") {
            panic!("README.md line {}: {}", b.line, touchline_dsl::render_plain(&e));
        }
    }
}

#[test]
fn the_prelude_shown_is_the_prelude() {
    let shown = blocks(README)
        .into_iter()
        .find(|b| b.text.starts_with("preset academy"))
        .expect("the README shows the academy preset");
    assert!(touchline_dsl::PRELUDE.contains(shown.text.trim_end()), "the README's academy preset is out of date");
}

#[test]
fn the_imported_file_shown_is_the_fixture() {
    let shown =
        blocks(README).into_iter().find(|b| b.text.contains("preset quick_drill")).expect("the README shows drills.tl");
    let on_disk = std::fs::read_to_string("tests/fixtures/reference/drills.tl").unwrap();
    assert_eq!(shown.text, on_disk);
}

#[test]
fn every_code_is_in_the_table() {
    for code in touchline_dsl::Code::ALL {
        assert!(README.contains(&format!("| `{code}` |")), "{code} is missing from the README's table");
    }
}
