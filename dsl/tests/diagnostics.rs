//! Every compiler diagnostic, one fixture each: `tests/fixtures/errors/NAME.tl` is compiled (from
//! its path, so that imports resolve), the code and primary span of every diagnostic are checked
//! against the fixture's own `// expect: CODE `spanned text`` lines, and the rendered text
//! ([`Diagnostics::render_plain`]) is compared with the insta snapshot `snapshots/diagnostics__NAME.snap`.
//!
//! Fixture name = test name = snapshot name. A fixture file that no test lists fails
//! `every_fixture_has_a_test`.

use std::path::{Path, PathBuf};

use touchline_dsl::{Code, Diagnostics, compile_file};

const DIR: &str = "tests/fixtures/errors";

/// One expected diagnostic: its code and the text its primary label covers (empty for a
/// diagnostic about the whole file).
#[derive(Debug, PartialEq)]
struct Expected {
    code: String,
    text: String,
}

/// The `// expect: CODE `text`` lines at the top of a fixture, in order.
fn expectations(source: &str) -> Vec<Expected> {
    source
        .lines()
        .map_while(|line| line.strip_prefix("// expect: "))
        .map(|rest| {
            let (code, text) = rest.split_once(' ').unwrap_or((rest, ""));
            let text = text.trim().strip_prefix('`').and_then(|t| t.strip_suffix('`')).unwrap_or("");
            Expected { code: code.to_owned(), text: text.to_owned() }
        })
        .collect()
}

/// Every diagnostic of compiling `path` (errors and warnings), whether it compiled or not.
fn diagnostics(path: &Path) -> (Diagnostics, bool) {
    match compile_file(path) {
        Ok(compiled) => (compiled.warnings, true),
        Err(diags) => (diags, false),
    }
}

/// Checks one fixture's expectations and its snapshot.
fn fixture(name: &str) {
    let path = PathBuf::from(format!("{DIR}/{name}.tl"));
    // Lossy: a fixture may hold bytes that are not UTF-8 after its header (unreadable_source).
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let source = String::from_utf8_lossy(&bytes).into_owned();
    let expected = expectations(&source);
    assert!(!expected.is_empty(), "{name}: the fixture must start with `// expect: CODE `text`` lines");
    let (diags, compiled) = diagnostics(&path);
    let found: Vec<Expected> = diags
        .items
        .iter()
        .map(|d| {
            let span = d.span();
            let text = d.source.inner();
            assert!(span.start <= span.end && span.end <= text.len(), "{name}: span {span:?} outside the source");
            assert!(text.is_char_boundary(span.start) && text.is_char_boundary(span.end), "{name}: {span:?}");
            Expected { code: d.code.as_str().to_owned(), text: text[span.start..span.end].to_owned() }
        })
        .collect();
    assert_eq!(found, expected, "{name}: diagnostics differ from the fixture's `// expect:` lines");
    let only_warnings = expected.iter().all(|e| e.code.starts_with("tl::W"));
    assert_eq!(compiled, only_warnings, "{name}: a fixture with only warnings compiles, any error fails");
    for d in &diags.items {
        let help = d.help.as_deref().unwrap_or("");
        assert!(d.code.is_warning() || !help.is_empty() || d.code == Code::Syntax, "{name}: {} has no help", d.code);
    }
    insta::with_settings!({ omit_expression => true, description => source }, {
        insta::assert_snapshot!(name, diags.render_plain());
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
    syntax_missing_brace
    syntax_missing_paren
    syntax_stray_token
    syntax_unterminated_string
    syntax_empty_file
    import_with_error
    import_cycle
    unknown_key
    unknown_role
    role_lower_case
    unknown_region
    unknown_formation
    wrong_type_bool
    wrong_type_region
    wrong_type_weight
    odd_ball_in_a_circle
    team_reordered
    wrong_unit_duration
    wrong_unit_position
    distance_without_unit
    off_the_pitch
    random_off_the_pitch
    difficulty_out_of_range
    zero_duration
    uniform_empty_range
    negative_std
    too_many_checkpoints
    twelve_players
    empty_team
    no_goalkeeper
    two_goalkeepers
    goalkeeper_misspelt
    duplicate_key
    duplicate_team
    extends_cycle
    extends_cycle_three
    extends_self
    missing_import
    unsatisfiable_require
    require_too_rare
    require_contradiction
    unknown_parent
    unknown_player_ref
    ambiguous_role_ref
    unknown_distribution
    unknown_reward
    unknown_constraint
    wrong_arity
    checkpoint_bad_argument
    scoring_with_arguments
    point_with_three_coordinates
    no_scenario
    two_scenarios
    unknown_end_condition
    duplicate_definition
    start_from
    several_errors
    outside_lines
    no_controllable
    unused_import
    no_effect_key
    unknown_behaviour
    behaviour_wrong_arguments
    behaviour_only_in_end_when
    pass_to_opponent
    unknown_game_mode
    unknown_measure
    shoot_without_dribble
    end_only_condition
    condition_unknown_player
    builtin_difficulty_out_of_range
    unreachable_stage
    syntax_does_without_behaviour
    unknown_event
    event_region
    event_scope
    event_repeat
    empty_event_group
    param_unknown
    param_redefined
    param_wrong_unit
    lesson_unknown_param
    lesson_unknown_scenario
    curriculum_no_lessons
    curriculum_never_met
    lesson_without_criterion
    curriculum_unknown_metric
    lessons_mismatch
    too_deep
    reward_weight_too_large
    unreadable_source
    non_ascii_name
    placement_cycle
    unknown_restart
    restart_without_team
    restart_unknown_team
    restart_needs_a_place
    restart_fixed_spot
    corner_not_a_corner
    throw_in_on_the_axis
    start_with_and_from
    facing_nowhere
    ball_replaced_by_restart
    end_only_save
    restart_off_the_pitch
    relative_to_the_ball
    relative_unknown_player
    param_on_both_axes
    lesson_param_on_both_axes
}

#[test]
fn every_fixture_has_a_test() {
    let mut on_disk: Vec<String> = std::fs::read_dir(DIR)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "tl"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    let mut listed: Vec<&str> = FIXTURES.to_vec();
    listed.sort_unstable();
    assert_eq!(on_disk, listed);
}

#[test]
fn every_code_has_a_fixture() {
    let mut covered = Vec::new();
    for name in FIXTURES {
        let source = String::from_utf8_lossy(&std::fs::read(format!("{DIR}/{name}.tl")).unwrap()).into_owned();
        covered.extend(expectations(&source).into_iter().map(|e| e.code));
    }
    for code in Code::ALL {
        assert!(covered.iter().any(|c| c == code.as_str()), "no fixture expects {code}");
    }
}
