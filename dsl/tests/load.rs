//! Loading from names and files, and the diagnostics of every way it can fail.

use std::path::PathBuf;

use miette::Diagnostic;
use touchline_dsl::{LoadError, load, load_file, load_json, render_plain};

fn code(err: &LoadError) -> String {
    err.code().map(|c| c.to_string()).unwrap_or_default()
}

/// A scratch file under the system temp dir, removed on drop.
struct TempFile(PathBuf);

impl TempFile {
    fn new(name: &str, contents: &str) -> TempFile {
        let path = std::env::temp_dir().join(format!("touchline-dsl-test-{}-{name}", std::process::id()));
        std::fs::write(&path, contents).unwrap();
        TempFile(path)
    }

    fn spec(&self) -> &str {
        self.0.to_str().unwrap()
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

const TWO_KEEPERS: &str = r#"{
  "name": "two_keepers",
  "left_team": [
    {"role": "GK", "x": -1.0, "y": 0.0},
    {"role": "GK", "x": 0.5, "y": 0.1}
  ],
  "right_team": [
    {"role": "GK", "x": -1.0, "y": 0.0}
  ]
}
"#;

#[test]
fn json_file_loads() {
    let text = serde_json::to_string_pretty(&touchline_dsl::load("academy_corner").unwrap()).unwrap();
    let file = TempFile::new("corner.json", &text);
    let s = load(file.spec()).unwrap();
    assert_eq!(s, touchline_dsl::stdlib::scenario("academy_corner").unwrap());
    assert_eq!(load_file(&file.0).unwrap(), s);
}

#[test]
fn sparse_json_takes_grf_defaults() {
    let s = load_json(
        r#"{"left_team":[{"role":"GK","x":-1,"y":0}],"right_team":[{"role":"GK","x":-1,"y":0}]}"#,
        "sparse.json",
    )
    .unwrap();
    assert_eq!(s.game_duration, 3000);
    assert_eq!((s.left_team_difficulty, s.right_team_difficulty), (1.0, 0.6));
    assert!(s.left_team[0].controllable && !s.left_team[0].lazy);
}

#[test]
fn missing_file_is_e002() {
    let err = load("no/such/dir/scenario.json").unwrap_err();
    assert_eq!(code(&err), "tl::E002");
    assert!(matches!(&err, LoadError::Unreadable { source, .. } if source.kind() == std::io::ErrorKind::NotFound));
    insta::assert_snapshot!(render_plain(&err));
}

#[test]
fn bad_json_is_e003_with_a_label() {
    let text = "{\n  \"name\": \"broken\",\n  \"game_duration\": 400\n  \"offsides\": false\n}\n";
    let err = load_json(text, "broken.json").unwrap_err();
    assert_eq!(code(&err), "tl::E003");
    let LoadError::Json(details) = &err else { panic!("{err:?}") };
    assert_eq!((details.line, details.column), (4, 3));
    let span = details.span;
    assert_eq!(&text[span.offset()..span.offset() + span.len()], "\"");
    insta::assert_snapshot!(render_plain(&err));
}

#[test]
fn bad_json_file_is_e003() {
    let file = TempFile::new("bad.json", "{ \"name\": ");
    let err = load(file.spec()).unwrap_err();
    assert_eq!(code(&err), "tl::E003");
    assert!(err.to_string().contains(file.spec()));
}

#[test]
fn wrong_shape_is_e003() {
    let text = r#"{
  "left_team": [{"role": "GK", "x": -1.0, "y": 0.0}],
  "right_team": [{"role": "XX", "x": -1.0, "y": 0.0}]
}"#;
    let err = load_json(text, "bad_role.json").unwrap_err();
    assert_eq!(code(&err), "tl::E003");
    insta::assert_snapshot!(render_plain(&err));

    let err = load_json(r#"{"game_durration": 400}"#, "typo.json").unwrap_err();
    assert_eq!(code(&err), "tl::E003");
    insta::assert_snapshot!("unknown_field", render_plain(&err));
}

#[test]
fn truncated_json_is_e003_at_the_end() {
    let text = "{\n  \"name\": \"cut\",\n  \"left_team\": [\n";
    let err = load_json(text, "cut.json").unwrap_err();
    assert_eq!(code(&err), "tl::E003");
    insta::assert_snapshot!(render_plain(&err));
}

#[test]
fn unknown_name_is_e001_with_a_suggestion() {
    let err = load("academy_empty_gaol").unwrap_err();
    assert_eq!(code(&err), "tl::E001");
    assert_eq!(err.help().unwrap().to_string(), "did you mean `academy_empty_goal`?");
    insta::assert_snapshot!(render_plain(&err));
}

#[test]
fn unknown_name_suggestions() {
    let help = |spec: &str| load(spec).unwrap_err().help().unwrap().to_string();
    assert_eq!(help("5_vs_4"), "did you mean `5_vs_5`?");
    assert_eq!(
        help("counterattack"),
        "did you mean one of `academy_counterattack_easy`, `academy_counterattack_hard`?"
    );
    assert!(help("penalty_shootout").starts_with("the stdlib scenarios are: 11_vs_11_competition, "));
    assert_eq!(code(&load("no_extension_file").unwrap_err()), "tl::E001");
}

#[test]
fn nothing_close_is_e001_listing_the_stdlib() {
    let err = load("penalty_shootout").unwrap_err();
    insta::assert_snapshot!(render_plain(&err));
}

#[test]
fn two_goalkeepers_is_e004() {
    let err = load_json(TWO_KEEPERS, "two_keepers.json").unwrap_err();
    assert_eq!(code(&err), "tl::E004");
    insta::assert_snapshot!(render_plain(&err));

    let file = TempFile::new("two_keepers.json", TWO_KEEPERS);
    assert_eq!(code(&load(file.spec()).unwrap_err()), "tl::E004");
}

#[test]
fn missing_tl_source_is_e150() {
    let err = load("drills/my_drill.tl").unwrap_err();
    assert_eq!(code(&err), "tl::E150");
    insta::assert_snapshot!(render_plain(&err));
}

#[test]
fn tl_source_compiles() {
    let file = TempFile::new("drill.tl", "scenario drill {\n  extends academy_empty_goal\n  difficulty 0.2\n}\n");
    let s = load(file.spec()).unwrap();
    assert_eq!((s.name.as_str(), s.right_team_difficulty, s.game_duration), ("drill", 0.2, 400));
}

#[test]
fn codes_are_stable() {
    let errors = [
        load("academy_empty_gaol").unwrap_err(),
        load("no/such/file.json").unwrap_err(),
        load_json("[", "x.json").unwrap_err(),
        load_json(TWO_KEEPERS, "x.json").unwrap_err(),
        load("x.tl").unwrap_err(),
    ];
    let codes: Vec<String> = errors.iter().map(code).collect();
    assert_eq!(codes, ["tl::E001", "tl::E002", "tl::E003", "tl::E004", "tl::E150"]);
    for err in &errors {
        assert_eq!(err.code_str(), code(err));
    }
}

#[test]
fn a_newer_format_version_is_refused_by_name() {
    let err = load_json(r#"{"format_version": 2, "a_field_from_the_future": true}"#, "future.json").unwrap_err();
    assert_eq!(code(&err), "tl::E004");
    let text = render_plain(&err);
    let words: Vec<&str> = text.split_whitespace().filter(|w| *w != "│").collect();
    let flat = words.join(" ");
    assert!(flat.contains("format_version 2") && flat.contains("reads version 1"), "{text}");
}
