//! Input that used to crash the process (issue 17): text nested thousands deep (items 1) and
//! diagnostics far along very long lines (item 2). Each is now a diagnostic that renders.

use std::path::Path;

use touchline_dsl::syntax::MAX_NESTING;
use touchline_dsl::{Code, Diagnostics, compile, compile_file, load_json, render_plain};

/// A scenario around `end when COND`.
fn with_end(cond: &str) -> String {
    format!("scenario deep {{\n  extends academy_empty_goal_close\n  end when {cond}\n}}\n")
}

/// Compiles `text` on a thread with a 1 MiB stack (smaller than any thread touchline runs on), so
/// that recursion past the limit would show here first.
fn compile_small_stack(text: String) -> Result<touchline_dsl::Compiled, Diagnostics> {
    std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(move || {
            let result = compile(&text, "deep.tl");
            let rendered = match &result {
                Ok(c) => c.warnings.render_plain(),
                Err(d) => d.render_plain(),
            };
            assert!(!rendered.contains("panicked"), "{rendered}");
            result
        })
        .unwrap()
        .join()
        .unwrap()
}

/// The one error of a failed compile: its code and the text its label covers.
fn too_deep(text: String) -> (String, usize) {
    let source = text.clone();
    let diags = compile_small_stack(text).expect_err("too deep to compile");
    let errors: Vec<_> = diags.errors().collect();
    assert_eq!(errors.len(), 1, "{}", diags.render_plain());
    assert_eq!(errors[0].code, Code::TooDeep, "{}", diags.render_plain());
    let span = errors[0].span();
    (source[span.start..span.end].to_owned(), span.start)
}

#[test]
fn a_thousand_parentheses_in_end_when() {
    let cond = format!("{}steps >= 5{}", "(".repeat(1000), ")".repeat(1000));
    let (text, at) = too_deep(with_end(&cond));
    assert_eq!(text, "(");
    let prefix = with_end("");
    let opened = prefix.find("end when ").unwrap() + "end when ".len();
    // The scenario's `{` is the first bracket open: the 64th parenthesis opens level 65.
    assert_eq!(at, opened + MAX_NESTING - 1, "the bracket that opens level {}", MAX_NESTING + 1);
}

#[test]
fn a_position_nested_five_thousand_deep() {
    let point = format!("{}(0.5, 0){}", "(".repeat(5000), ")".repeat(5000));
    let text = format!("scenario deep {{\n  extends academy_empty_goal_close\n  ball at {point}\n}}\n");
    assert_eq!(too_deep(text).0, "(");
}

#[test]
fn not_ten_thousand_times() {
    let cond = format!("{}steps >= 5", "not ".repeat(10_000));
    assert_eq!(too_deep(with_end(&cond)).0, "not");
}

#[test]
fn minus_ten_thousand_times() {
    let text = format!(
        "scenario deep {{\n  extends academy_empty_goal_close\n  ball at ({}0.5, 0)\n}}\n",
        "- ".repeat(10_000)
    );
    assert_eq!(too_deep(text).0, "-");
}

#[test]
fn ten_thousand_operators_in_one_expression() {
    let sum = vec!["0.0001"; 10_001].join(" + ");
    let text = format!("scenario deep {{\n  extends academy_empty_goal_close\n  ball at ({sum}, 0)\n}}\n");
    assert_eq!(too_deep(text).0, "+");
}

#[test]
fn brackets_and_operators_add_up() {
    // 40 brackets, each holding a sum of 40 terms: never 64 of one kind, 1,600 levels in all.
    let mut e = "0.001".to_owned();
    for _ in 0..40 {
        e = format!("({e}{})", " + 0.00001".repeat(40));
    }
    let text = format!("scenario deep {{\n  extends academy_empty_goal_close\n  ball at ({e}, 0)\n}}\n");
    too_deep(text);
}

#[test]
fn nesting_up_to_the_limit_compiles() {
    let depth = MAX_NESTING - 2;
    let cond = format!("{}steps >= 5{}", "(".repeat(depth), ")".repeat(depth));
    compile_small_stack(with_end(&cond)).unwrap_or_else(|d| panic!("{}", d.render_plain()));
    let nots = format!("{}steps >= 5", "not not ".repeat(depth / 2 - 1));
    compile_small_stack(with_end(&nots)).unwrap_or_else(|d| panic!("{}", d.render_plain()));
}

#[test]
fn an_extends_chain_of_a_thousand_presets() {
    let mut text = String::from("preset p0 { extends academy_empty_goal_close }\n");
    for i in 1..1000 {
        text.push_str(&format!("preset p{i} {{ extends p{} }}\n", i - 1));
    }
    text.push_str("scenario s { extends p999 }\n");
    let (name, _) = too_deep(text);
    assert!(name.starts_with('p'), "{name}");
}

#[test]
fn a_param_chain_of_a_thousand_params() {
    let mut text = String::from("scenario s {\n  extends academy_empty_goal_close\n  param a0 = 0.5\n");
    for i in 1..1000 {
        text.push_str(&format!("  param a{i} = a{}\n", i - 1));
    }
    text.push_str("  ball at (a999, 0)\n}\n");
    let diags = compile_small_stack(text).expect_err("too deep");
    assert!(diags.errors().any(|d| d.code == Code::TooDeep), "{}", diags.render_plain());
}

#[test]
fn an_import_chain_of_a_hundred_files() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("import_chain");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for i in 0..100 {
        let body = if i == 99 { String::new() } else { format!("import \"f{}.tl\"\n", i + 1) };
        std::fs::write(dir.join(format!("f{i}.tl")), format!("{body}preset q{i} {{ extends academy }}\n")).unwrap();
    }
    std::fs::write(dir.join("main.tl"), "import \"f0.tl\"\nscenario s { extends q0 }\n").unwrap();
    let path = dir.join("main.tl");
    let diags = std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(move || compile_file(&path).map(|_| ()).unwrap_err())
        .unwrap()
        .join()
        .unwrap();
    assert!(diags.errors().any(|d| d.code == Code::TooDeep), "{}", diags.render_plain());
}

/// Item 2: a diagnostic far along a line of 100,000 characters renders (miette's padding used to
/// panic past column 65,535), with the label's real line and column, and a short excerpt.
#[test]
fn a_label_past_column_65535_renders() {
    let text = format!("scenario s {{ extends academy_empty_goal_close {} game_duraton 400 }}\n", " ".repeat(100_000));
    let diags = compile(&text, "long.tl").unwrap_err();
    let rendered = diags.render_plain();
    assert!(rendered.contains("tl::E101"), "{rendered}");
    let column = text.find("game_duraton").unwrap() + 1;
    assert!(rendered.contains(&format!("long.tl:1:{column}]")), "{rendered}");
    assert!(rendered.contains("game_duraton"), "{rendered}");
    assert!(rendered.len() < 2_000, "{} bytes", rendered.len());
}

/// Item 2: a syntax error at the end of one very long line, and labels at both ends of it.
#[test]
fn syntax_errors_and_several_labels_on_long_lines_render() {
    let text = format!("scenario s {{ extends academy_empty_goal_close ball at (0.5, 0{} }}", " ".repeat(70_000));
    let rendered = compile(&text, "long.tl").unwrap_err().render_plain();
    assert!(rendered.contains("tl::E100"), "{rendered}");
    let text =
        format!("scenario s {{ team left {{ GK at (-1, 0) }}{} team left {{ GK at (-1, 0) }} }}", " ".repeat(70_000));
    let rendered = compile(&text, "long.tl").unwrap_err().render_plain();
    assert!(rendered.contains("tl::E110"), "{rendered}");
}

/// Item 2: a compiled scenario written on one line over 64 KiB, with an error at its end.
#[test]
fn a_one_line_json_over_64_kib_renders() {
    let json = format!("{{\"name\": \"{}\", \"game_duration\": \"long\"}}", "n".repeat(70_000));
    let err = load_json(&json, "long.json").unwrap_err();
    let rendered = render_plain(&err);
    assert!(rendered.contains("tl::E003"), "{rendered}");
    assert!(rendered.contains("long.json:1:"), "{rendered}");
    assert!(rendered.len() < 2_000, "{} bytes", rendered.len());
    // A string token 70,000 bytes long is the label itself: it is cut.
    let json =
        format!("{{\"description\": \"{}\", \"game_duration\": \"{}\"}}", "d".repeat(70_000), "9".repeat(70_000));
    let rendered = render_plain(&load_json(&json, "long.json").unwrap_err());
    assert!(rendered.contains("tl::E003") && rendered.len() < 4_000, "{rendered}");
}

/// Issue 18, item 5: a 400,000-byte token quoted in a message (`found the name `xxx…``) is cut
/// in the middle: the whole message was 439 KB.
#[test]
fn a_huge_token_is_not_echoed_whole() {
    for text in [
        format!("scenario s {{\n  extends academy\n  game_duration {}\n}}", "x".repeat(400_000)),
        format!("scenario s {{\n  extends academy\n  ball at (0, 0) {}\n}}", "x.".repeat(200_000)),
        format!("scenario s {{\n  extends academy\n  ball at (0, 0){}\n}}", "}".repeat(400_000)),
    ] {
        let rendered = compile(&text, "long.tl").unwrap_err().render_plain();
        assert!(rendered.contains("tl::E1"), "{rendered}");
        assert!(rendered.len() < 4_000, "{} bytes", rendered.len());
    }
}
