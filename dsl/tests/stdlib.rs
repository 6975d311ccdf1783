//! The embedded stdlib scenarios against GRF's tables (docs/grf-compatibility.md#scenario-settings, #scenario-players).

use touchline_dsl::{load, stdlib};
use touchline_engine::{PlayerEntry, Role, Scenario};

/// docs/grf-compatibility.md#scenario-settings: name, #left, #right, game_duration, left difficulty, right difficulty,
/// swap by episode parity.
const SUMMARY: &[(&str, usize, usize, u32, f32, f32, bool)] = &[
    ("11_vs_11_competition", 11, 11, 3000, 1.0, 1.0, true),
    ("11_vs_11_easy_stochastic", 11, 11, 3000, 1.0, 0.05, true),
    ("11_vs_11_hard_stochastic", 11, 11, 3000, 1.0, 0.95, true),
    ("11_vs_11_kaggle", 11, 11, 3000, 1.0, 1.0, true),
    ("11_vs_11_stochastic", 11, 11, 3000, 1.0, 0.6, true),
    ("1_vs_1_easy", 1, 1, 500, 0.0, 0.0, true),
    ("5_vs_5", 5, 5, 3000, 0.05, 0.05, true),
    ("academy_3_vs_1_with_keeper", 4, 2, 400, 1.0, 0.6, false),
    ("academy_corner", 11, 11, 400, 1.0, 0.6, false),
    ("academy_counterattack_easy", 11, 11, 400, 1.0, 0.6, false),
    ("academy_counterattack_hard", 11, 11, 400, 1.0, 0.6, false),
    ("academy_empty_goal", 2, 1, 400, 1.0, 0.6, false),
    ("academy_empty_goal_close", 2, 1, 400, 1.0, 0.6, false),
    ("academy_pass_and_shoot_with_keeper", 3, 2, 400, 1.0, 0.6, false),
    ("academy_run_pass_and_shoot_with_keeper", 3, 2, 400, 1.0, 0.6, false),
    ("academy_run_to_score", 2, 6, 400, 1.0, 0.6, false),
    ("academy_run_to_score_with_keeper", 2, 6, 400, 1.0, 0.6, false),
    ("academy_single_goal_versus_lazy", 11, 11, 3000, 1.0, 0.6, false),
    ("test_example_multiagent", 4, 2, 100, 1.0, 0.6, false),
];

fn get(name: &str) -> Scenario {
    load(name).unwrap_or_else(|e| panic!("{name}: {}", touchline_dsl::render_plain(&e)))
}

#[test]
fn names_are_the_19_grf_scenarios_sorted() {
    let expected: Vec<&str> = SUMMARY.iter().map(|row| row.0).collect();
    assert_eq!(stdlib::names(), expected.as_slice());
}

#[test]
fn every_file_in_the_directory_is_embedded() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../stdlib-scenarios");
    let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    assert_eq!(on_disk, stdlib::names());
}

#[test]
fn every_name_loads_validates_and_matches_the_summary_table() {
    for &(name, left, right, duration, left_diff, right_diff, swap) in SUMMARY {
        let s = get(name);
        s.validate().unwrap();
        assert_eq!(stdlib::scenario(name).as_ref(), Some(&s), "{name}");
        assert_eq!(s.name, name);
        assert!(!s.description.is_empty(), "{name}");
        assert_eq!((s.left_team.len(), s.right_team.len()), (left, right), "{name}");
        assert_eq!(s.game_duration, duration, "{name}");
        assert_eq!(s.left_team_difficulty, left_diff, "{name}");
        assert_eq!(s.right_team_difficulty, right_diff, "{name}");
        assert_eq!(s.swap_teams_on_odd_episodes, swap, "{name}");
        assert!(!s.deterministic, "{name}: no top-level scenario is deterministic");
        assert!(!s.control_all_players, "{name}");
        assert_eq!(s.second_half, if name == "11_vs_11_kaggle" { 1500 } else { 999_999_999 });
        for (side, team) in [("left", &s.left_team), ("right", &s.right_team)] {
            let keepers = team.iter().filter(|p| p.role == Role::GK).count();
            assert_eq!(keepers, 1, "{name}: {side} keeper");
            assert_eq!(team[0].role, Role::GK, "{name}: the {side} keeper is player 0");
        }
    }
}

#[test]
fn config_flags_match_the_summary_table() {
    for &(name, ..) in SUMMARY {
        let s = get(name);
        let academy = name.starts_with("academy_") || name == "test_example_multiagent";
        assert_eq!(s.offsides, !academy, "{name}");
        assert_eq!(s.end_episode_on_score, academy, "{name}");
        assert_eq!(s.end_episode_on_out_of_play, academy, "{name}");
        // academy_corner keeps going when the defenders win the ball.
        assert_eq!(s.end_episode_on_possession_change, academy && name != "academy_corner", "{name}");
    }
}

#[test]
fn golden_files_are_canonical() {
    // Each golden compiled file is byte-identical to re-serialising its value: serde's field
    // order, 2-space indent, trailing newline.
    for name in stdlib::names().iter().copied().chain(stdlib::test_names()) {
        let path = format!("{}/../stdlib-scenarios/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let text = &std::fs::read_to_string(path).unwrap();
        let s: Scenario = serde_json::from_str(text).unwrap();
        let canonical = serde_json::to_string_pretty(&s).unwrap() + "\n";
        assert_eq!(*text, canonical, "{name} is not in canonical form");
    }
}

#[test]
fn ball_starts() {
    let expected: &[(&str, [f32; 2])] = &[
        ("11_vs_11_stochastic", [0.0, 0.0]),
        ("academy_3_vs_1_with_keeper", [0.62, 0.0]),
        ("academy_corner", [0.99, 0.41]),
        ("academy_counterattack_easy", [0.26, -0.11]),
        ("academy_counterattack_hard", [0.26, -0.11]),
        ("academy_empty_goal", [0.02, 0.0]),
        ("academy_empty_goal_close", [0.77, 0.0]),
        ("academy_pass_and_shoot_with_keeper", [0.7, -0.28]),
        ("academy_run_pass_and_shoot_with_keeper", [0.7, -0.28]),
        ("academy_run_to_score", [0.02, 0.0]),
        ("academy_run_to_score_with_keeper", [0.02, 0.0]),
        ("academy_single_goal_versus_lazy", [-0.48, -0.06356]),
        ("test_example_multiagent", [0.62, 0.0]),
    ];
    for &(name, ball) in expected {
        assert_eq!(get(name).ball_position, ball, "{name}");
    }
}

fn p(role: Role, x: f32, y: f32) -> PlayerEntry {
    PlayerEntry::new(role, x, y)
}

#[test]
fn academy_empty_goal_close_players() {
    let s = get("academy_empty_goal_close");
    assert_eq!(s.left_team, [p(Role::GK, -1.0, 0.0), p(Role::CB, 0.75, 0.0)]);
    // The right keeper is placed at x = +1 in its own frame: the left goal, leaving the right goal empty.
    assert_eq!(s.right_team, [p(Role::GK, 1.0, 0.0)]);
}

#[test]
fn academy_run_to_score_with_keeper_players() {
    let s = get("academy_run_to_score_with_keeper");
    assert_eq!(s.left_team, [p(Role::GK, -1.0, 0.0), p(Role::CB, 0.0, 0.0)]);
    assert_eq!(
        s.right_team,
        [
            p(Role::GK, -1.0, 0.0),
            p(Role::LB, 0.12, 0.2),
            p(Role::CB, 0.12, 0.1),
            p(Role::CM, 0.12, 0.0),
            p(Role::CB, 0.12, -0.1),
            p(Role::RB, 0.12, -0.2),
        ]
    );
    // Without keeper, the only difference is the right keeper standing in the other goal.
    let mut without = get("academy_run_to_score");
    without.right_team[0].x = -1.0;
    assert_eq!(without.right_team, s.right_team);
}

#[test]
fn five_vs_five_keepers_are_not_controllable() {
    let s = get("5_vs_5");
    for team in [&s.left_team, &s.right_team] {
        assert!(!team[0].controllable);
        assert!(team[1..].iter().all(|p| p.controllable && !p.lazy));
    }
    assert_eq!(s.controllable_players(), [4, 4]);
}

#[test]
fn single_goal_versus_lazy_opponents_are_lazy_but_their_keeper() {
    let s = get("academy_single_goal_versus_lazy");
    assert!(!s.right_team[0].lazy);
    assert!(s.right_team[1..].iter().all(|p| p.lazy));
    assert!(s.left_team.iter().all(|p| !p.lazy));
    // "our centre back starts with the ball": the ball is just ahead of left player 4.
    assert_eq!(s.left_team[4], p(Role::CB, -0.5, -0.06356));
}

#[test]
fn eleven_a_side_set_a_kicks_off() {
    // Set A (left in even 0-based episodes) has two players either side of the centre spot.
    for name in ["11_vs_11_competition", "11_vs_11_easy_stochastic", "11_vs_11_hard_stochastic", "11_vs_11_stochastic"]
    {
        let s = get(name);
        assert_eq!(&s.left_team[1..3], [p(Role::RM, 0.0, 0.02), p(Role::CF, 0.0, -0.02)], "{name}");
        assert_eq!(&s.right_team[1..3], [p(Role::RM, -0.05, 0.0), p(Role::CF, -0.01, 0.216102)], "{name}");
        let (left, right) = s.teams_for_episode(1);
        assert_eq!((left, right), (s.right_team.as_slice(), s.left_team.as_slice()));
    }
    let kaggle = get("11_vs_11_kaggle");
    let roles: Vec<Role> = kaggle.left_team.iter().map(|p| p.role).collect();
    use Role::*;
    assert_eq!(roles, [GK, LB, CB, CB, RB, CM, CM, CM, LM, CF, RM]);
    assert_eq!(&kaggle.left_team[9..], [p(CF, 0.0, 0.02), p(RM, 0.0, -0.02)]);
    assert_eq!(&kaggle.right_team[9..], [p(CF, -0.05, 0.0), p(RM, -0.01, 0.216102)]);
}

#[test]
fn counterattacks_differ_in_one_defender() {
    let easy = get("academy_counterattack_easy");
    let hard = get("academy_counterattack_hard");
    assert_eq!(easy.left_team, hard.left_team);
    assert_eq!(easy.right_team[2], p(Role::CB, 0.4, -0.06356));
    assert_eq!(hard.right_team[2], p(Role::CB, -0.4, -0.06356));
    let differing: Vec<usize> = (0..11).filter(|&i| easy.right_team[i] != hard.right_team[i]).collect();
    assert_eq!(differing, [2]);
}

#[test]
fn corner_taker_stands_at_the_corner() {
    let s = get("academy_corner");
    assert_eq!(s.left_team[1], p(Role::LB, 1.0, 0.42));
    assert_eq!(s.right_team[4], p(Role::RB, -1.0, -0.1));
}
