//! The shipped scenarios (`stdlib-scenarios/*.tl`), embedded at compile time.
//!
//! One scenario per scenario of Google Research Football (docs/grf-compatibility.md#scenario-list,
//! its tables: #scenario-settings, #scenario-players): the 19 top-level ones and the 16 `tests/…` ones, as `.tl` sources compiled on
//! load. Each compiles, without warnings, to exactly the golden compiled JSON checked in beside it
//! (`dsl/tests/golden.rs`).

use touchline_engine::Scenario;

/// `.tl` sources of the stdlib, by name (sorted in byte order); `tests/…` are GRF's test scenarios.
const TL_SOURCES: &[(&str, &str)] = &[
    ("11_vs_11_competition", include_str!("../../stdlib-scenarios/11_vs_11_competition.tl")),
    ("11_vs_11_easy_stochastic", include_str!("../../stdlib-scenarios/11_vs_11_easy_stochastic.tl")),
    ("11_vs_11_hard_stochastic", include_str!("../../stdlib-scenarios/11_vs_11_hard_stochastic.tl")),
    ("11_vs_11_kaggle", include_str!("../../stdlib-scenarios/11_vs_11_kaggle.tl")),
    ("11_vs_11_stochastic", include_str!("../../stdlib-scenarios/11_vs_11_stochastic.tl")),
    ("1_vs_1_easy", include_str!("../../stdlib-scenarios/1_vs_1_easy.tl")),
    ("5_vs_5", include_str!("../../stdlib-scenarios/5_vs_5.tl")),
    ("academy_3_vs_1_with_keeper", include_str!("../../stdlib-scenarios/academy_3_vs_1_with_keeper.tl")),
    ("academy_corner", include_str!("../../stdlib-scenarios/academy_corner.tl")),
    ("academy_counterattack_easy", include_str!("../../stdlib-scenarios/academy_counterattack_easy.tl")),
    ("academy_counterattack_hard", include_str!("../../stdlib-scenarios/academy_counterattack_hard.tl")),
    ("academy_empty_goal", include_str!("../../stdlib-scenarios/academy_empty_goal.tl")),
    ("academy_empty_goal_close", include_str!("../../stdlib-scenarios/academy_empty_goal_close.tl")),
    (
        "academy_pass_and_shoot_with_keeper",
        include_str!("../../stdlib-scenarios/academy_pass_and_shoot_with_keeper.tl"),
    ),
    (
        "academy_run_pass_and_shoot_with_keeper",
        include_str!("../../stdlib-scenarios/academy_run_pass_and_shoot_with_keeper.tl"),
    ),
    ("academy_run_to_score", include_str!("../../stdlib-scenarios/academy_run_to_score.tl")),
    ("academy_run_to_score_with_keeper", include_str!("../../stdlib-scenarios/academy_run_to_score_with_keeper.tl")),
    ("academy_single_goal_versus_lazy", include_str!("../../stdlib-scenarios/academy_single_goal_versus_lazy.tl")),
    ("test_example_multiagent", include_str!("../../stdlib-scenarios/test_example_multiagent.tl")),
    ("tests/11_vs_11_deterministic", include_str!("../../stdlib-scenarios/tests/11_vs_11_deterministic.tl")),
    ("tests/11_vs_11_easy_deterministic", include_str!("../../stdlib-scenarios/tests/11_vs_11_easy_deterministic.tl")),
    ("tests/11_vs_11_hard_deterministic", include_str!("../../stdlib-scenarios/tests/11_vs_11_hard_deterministic.tl")),
    (
        "tests/11_vs_11_single_goal_deterministic",
        include_str!("../../stdlib-scenarios/tests/11_vs_11_single_goal_deterministic.tl"),
    ),
    (
        "tests/11_vs_11_single_goal_stochastic",
        include_str!("../../stdlib-scenarios/tests/11_vs_11_single_goal_stochastic.tl"),
    ),
    (
        "tests/11_vs_4_offence_deterministic",
        include_str!("../../stdlib-scenarios/tests/11_vs_4_offence_deterministic.tl"),
    ),
    ("tests/11_vs_4_offence_stochastic", include_str!("../../stdlib-scenarios/tests/11_vs_4_offence_stochastic.tl")),
    ("tests/corner_test", include_str!("../../stdlib-scenarios/tests/corner_test.tl")),
    ("tests/goal_test", include_str!("../../stdlib-scenarios/tests/goal_test.tl")),
    ("tests/keeper_test", include_str!("../../stdlib-scenarios/tests/keeper_test.tl")),
    (
        "tests/kickoff_for_goal_loosing_team_test",
        include_str!("../../stdlib-scenarios/tests/kickoff_for_goal_loosing_team_test.tl"),
    ),
    ("tests/multiagent_wrapper", include_str!("../../stdlib-scenarios/tests/multiagent_wrapper.tl")),
    ("tests/offside_test", include_str!("../../stdlib-scenarios/tests/offside_test.tl")),
    ("tests/penalty", include_str!("../../stdlib-scenarios/tests/penalty.tl")),
    ("tests/second_half", include_str!("../../stdlib-scenarios/tests/second_half.tl")),
    ("tests/symmetric", include_str!("../../stdlib-scenarios/tests/symmetric.tl")),
];

/// Names of all stdlib scenarios, sorted (byte order), e.g. `"academy_empty_goal_close"`.
const NAMES: &[&str] = &[
    "11_vs_11_competition",
    "11_vs_11_easy_stochastic",
    "11_vs_11_hard_stochastic",
    "11_vs_11_kaggle",
    "11_vs_11_stochastic",
    "1_vs_1_easy",
    "5_vs_5",
    "academy_3_vs_1_with_keeper",
    "academy_corner",
    "academy_counterattack_easy",
    "academy_counterattack_hard",
    "academy_empty_goal",
    "academy_empty_goal_close",
    "academy_pass_and_shoot_with_keeper",
    "academy_run_pass_and_shoot_with_keeper",
    "academy_run_to_score",
    "academy_run_to_score_with_keeper",
    "academy_single_goal_versus_lazy",
    "test_example_multiagent",
];

/// Names of the stdlib's playable scenarios (GRF's top-level ones), sorted in byte order.
pub fn names() -> &'static [&'static str] {
    NAMES
}

/// Names of GRF's test scenarios in the stdlib (`tests/corner_test`, …), sorted.
pub fn test_names() -> impl Iterator<Item = &'static str> {
    TL_SOURCES.iter().map(|(n, _)| *n).filter(|n| n.starts_with("tests/"))
}

/// The `.tl` source of the stdlib scenario `name`, or `None` if there is no such scenario.
pub fn tl_source(name: &str) -> Option<&'static str> {
    TL_SOURCES.binary_search_by(|(n, _)| (*n).cmp(name)).ok().map(|i| TL_SOURCES[i].1)
}

/// The stdlib scenario `name` (a top-level or a `tests/…` name), compiled; `None` if there is no
/// such scenario.
///
/// The embedded sources are tested to compile without warnings, so a known name always gives
/// `Some`. Use [`crate::load`] to get a [`crate::LoadError`] for unknown names.
pub fn scenario(name: &str) -> Option<Scenario> {
    let text = tl_source(name)?;
    crate::compile(text, &format!("stdlib/{name}.tl")).ok().map(|c| c.scenario)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_sorted_and_agree() {
        assert!(NAMES.windows(2).all(|w| w[0] < w[1]));
        let from_table: Vec<&str> = TL_SOURCES.iter().map(|(n, _)| *n).filter(|n| !n.starts_with("tests/")).collect();
        assert_eq!(from_table, NAMES);
        assert!(TL_SOURCES.windows(2).all(|w| w[0].0 < w[1].0));
    }

    #[test]
    fn lookup() {
        assert!(tl_source("academy_corner").is_some());
        assert!(tl_source("tests/penalty").is_some());
        assert!(tl_source("academy_cornerr").is_none());
        assert_eq!(scenario("5_vs_5").map(|s| s.left_team.len()), Some(5));
        assert!(scenario("").is_none());
    }
}
