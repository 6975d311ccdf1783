"""Behaviours of GRF that must never regress, with wide margins (issue 15).

The full comparison with GRF's figures is `python/bench/fidelity.py` (minutes, outside CI); these
are the few behaviours that, when broken, let an agent learn a shortcut GRF does not allow. Episodes
run through `touchline.compat.gfootball` with the harness's own runner and GRF's end classification
(`python/bench/fidelity_cases.py`). GRF's figures quoted here are gfootball 2.10.2's, run the same
way.
"""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parents[1] / "bench"
sys.path.insert(0, str(BENCH))

import fidelity_cases as cases  # noqa: E402 (found through BENCH)
import fidelity_stats as fs  # noqa: E402 (found through BENCH)

STDLIB = Path(__file__).resolve().parents[2] / "stdlib-scenarios"


def test_idle_agent_loses_the_ball_in_empty_goal_close() -> None:
    # GRF: the opponent's keeper comes, takes the ball and it goes out at step 151 (50 of 50
    # episodes).
    episodes = cases.run_episodes("academy_empty_goal_close", "idle", 10, seed=1)
    ends = [(e.end, e.steps) for e in episodes]
    assert all(end in ("out_of_play", "possession") and steps < 250 for end, steps in ends), ends


def test_no_receiver_long_pass_at_the_centre_spot_does_not_score() -> None:
    # GRF: the pass goes back to our own keeper, the only team-mate (0 goals); the ball stays near
    # x = 0.02.
    episodes = cases.run_episodes(
        "academy_empty_goal", lambda env: cases.OnceOwned(cases.LONG_PASS), 5, seed=2
    )
    goals = [e.goals_for for e in episodes]
    assert sum(goals) == 0, (
        f"goals per episode {goals}, max ball x {[e.max_ball_x for e in episodes]}"
    )


def test_sliding_in_possession_does_not_move_the_ball_forward() -> None:
    # GRF accepts the agent's sliding only when his team is not in possession: pressed by the ball
    # owner it does nothing, so the ball stays at his feet (a carrier drifts < 0.1 units of x).
    env = cases.make_env("academy_empty_goal", seed=3)
    for _ in range(3):
        policy = cases.OnceOwned(cases.SLIDING, times=20)
        trace: list[tuple[int, float]] = []

        def record(
            step: int,
            obs: cases.Observation,
            trace: list[tuple[int, float]] = trace,
            policy: cases.OnceOwned = policy,
        ) -> None:
            trace.append((policy.pressed, float(obs["ball"][0])))

        cases.run_episode(env, policy, on_step=record)
        first = next((i for i, (pressed, _) in enumerate(trace) if pressed > 0), None)
        assert first is not None, "our player never owned the ball"
        # From just before the first of the 20 presses to 10 steps after the last.
        window = [x for _, x in trace[first - 1 : first + 30]]
        advance = max(window) - window[0]
        assert advance < 0.1, f"the ball went {advance:.3f} forward while its owner pressed sliding"


def test_sliding_every_step_does_not_carry_the_ball_to_goal() -> None:
    # The shortcut seen in PPO: sliding held from kick-off knocks the ball on, all the way into the
    # empty goal (every episode). In GRF our player, whose team has the ball, cannot slide.
    episodes = cases.run_episodes(
        "academy_empty_goal", lambda env: cases.Constant(cases.SLIDING), 5, seed=4
    )
    summary = [(e.goals_for, round(e.max_ball_x, 3)) for e in episodes]
    assert all(goals == 0 and x < 0.2 for goals, x in summary), summary


def test_random_agent_seldom_scores_against_the_hard_side() -> None:
    # GRF: a random agent scored in 0 of 15 full matches (easy, medium and hard).
    episodes = cases.run_episodes("11_vs_11_hard_stochastic", "random", 30, seed=5)
    scored = [e.goals_for for e in episodes if e.goals_for > 0]
    assert len(scored) <= 2, f"the random agent scored in {len(scored)} of 30 matches: {scored}"


def test_builtin_against_builtin_at_equal_strength_is_level(tmp_path: Path) -> None:
    # Our player handed to the built-in AI (action 19), both teams at the same θ: neither side may
    # dominate. Wide margin: the mean goal difference of 30 matches within one goal of 0.
    scenario = json.loads((STDLIB / "11_vs_11_stochastic.json").read_text())
    scenario["left_team_difficulty"] = scenario["right_team_difficulty"] = 0.6
    medium = tmp_path / "medium_vs_medium.json"
    medium.write_text(json.dumps(scenario))
    for name in ("11_vs_11_competition", str(medium)):  # θ = 1 on both sides, then 0.6
        episodes = cases.run_episodes(name, "builtin_ai", 30, seed=6)
        difference = statistics.fmean(e.goals_for - e.goals_against for e in episodes)
        scores = [f"{e.goals_for}-{e.goals_against}" for e in episodes]
        assert abs(difference) <= 1.0, f"{name}: mean goal difference {difference:+.2f} ({scores})"


def test_the_flow_of_play_counts_spells_of_one_owner_and_of_a_loose_ball() -> None:
    # The harness's flow figures (GRF: the ball is nobody's on about 41 % of normal-play steps, a
    # player keeps it a median 8-11 steps): spells end when the owner changes or play stops.
    import numpy as np

    def obs(mode: int, team: int, player: int) -> cases.Observation:
        roles = np.array([0, 1])
        return {
            "game_mode": mode,
            "ball_owned_team": team,
            "ball_owned_player": player,
            "left_team": np.zeros((2, 2)),
            "right_team": np.zeros((2, 2)),
            "left_team_roles": roles,
            "right_team_roles": roles,
            "left_team_active": np.array([True, True]),
            "right_team_active": np.array([True, True]),
            "left_team_yellow_card": np.zeros(2),
            "right_team_yellow_card": np.zeros(2),
        }

    # Normal play: player (0, 1) for 3 steps, loose for 2, (1, 0) for 1, a throw-in, then loose.
    owners = [(0, 1)] * 3 + [(-1, -1)] * 2 + [(1, 0)]
    stats = cases.MatchStats()
    stats.start(obs(0, -1, -1))
    for team, player in owners:
        stats.update(obs(0, team, player))
    stats.update(obs(cases.THROW_IN, 1, 0))
    stats.update(obs(0, -1, -1))
    summary = stats.summary()
    assert stats.owned_spells == [3, 1]
    assert stats.loose_spells == [2, 1]
    assert summary["loose_share"] == 3 / 7
    assert summary["owned_spell"] == 2.0 and summary["loose_spell"] == 1.5


def test_figures_pooled_over_engine_seeds_count_the_spread_between_seeds() -> None:
    # GRF's figures depend on its engine seed (its parity orders the teams' processing), so the
    # harness splits a case over seeds of both parities and widens the se by their spread.
    assert [cases.engine_seed(0, "academy x random", k) % 2 for k in range(4)] == [0, 1, 0, 1]
    assert cases.split(50, 8) == [7, 7, 6, 6, 6, 6, 6, 6]
    same, same_se = fs.seed_proportion([5, 5], [10, 10])
    assert same == 0.5 and same_se == fs.proportion_se(10, 20)
    apart, apart_se = fs.seed_proportion([0, 10], [10, 10])
    assert apart == 0.5 and abs(apart_se - 0.5) < 1e-9
    mean, mean_se = fs.seed_mean([[1.0, 1.0], [3.0, 3.0]])
    assert mean == 2.0 and abs(mean_se - 1.0) < 1e-9


def test_the_seed_mixed_reference_covers_the_reference_cases() -> None:
    # Every academy case but the idle single_goal_versus_lazy one (50 × 3,001 steps in GRF, left to
    # the first reference) and every full-match case has GRF's seed-mixed figures.
    reference = json.loads((BENCH / "grf_reference.json").read_text())
    mixed = json.loads((BENCH / "grf_seed_mix.json").read_text())["cases"]
    wanted = [f"academy {c['scenario']} {c['policy']}" for c in reference["academy"]["cases"]]
    wanted += [f"match {c['scenario']} {c['policy']}" for c in reference["full_match"]["cases"]]
    missing = [case for case in wanted if case not in mixed]
    assert missing == ["academy academy_single_goal_versus_lazy idle"], missing
    for case in wanted[:-9]:
        if case in mixed:
            pooled = mixed[case]["pooled"]
            assert pooled["n"] >= 50 and 0 < pooled["length"]["mean"] <= 3001, case
