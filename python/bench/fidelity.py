"""touchline's fidelity harness: GRF's measured cases replayed through `touchline.compat.gfootball`.

Every case of GRF's reference figures (`grf_reference.json`, beside this file, with their source) is
run with the same n, the same policies and the same end-of-episode classification (see
`fidelity_cases.py`), and printed side by side with GRF's: value and se of each, z and a flag
(`fidelity_stats.py` gives the rule: |Δ| > 3 combined se, p̃ in proportions, lengths also 10 % off).

  * academy: the 11 Academy drills × random (n = 200) and idle (n = 50): P(goal for), P(goal
    against), episode length, and the four end shares (goal, out of play, possession, time limit),
    each case's episodes split over engine seeds of both parities and compared with GRF's figures
    measured the same way (`grf_seed_mix.json`, `seed_spread.py` says why; `--single-seed` for the
    first, one-seed reference);
  * match: 11 v 11 easy / medium / hard × builtin_ai / idle / random (n = 5, 3001 steps): goals for
    and against per match;
    these 22 + 9 are "the 31 reference cases": a case is flagged when any of its figures is;
  * probe: a few scripted actions then idle (extra cases, not among the 31);
  * texture: what a full match is made of, builtin_ai at easy / medium / hard (n = 6), next to GRF's
    and real football's figures (extra cases, not among the 31).

Usage (from the repository root, with the package installed):
    python3 python/bench/fidelity.py [--cases SUBSTRING] [--n-scale F] [--seed S]
                                     [--workers N] [--json PATH] [--single-seed]
"""

from __future__ import annotations

import argparse
import json
import math
import multiprocessing
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import asdict
from pathlib import Path
from typing import Any

import fidelity_cases as cases
import fidelity_stats as fs

REFERENCE = Path(__file__).with_name("grf_reference.json")
#: GRF's academy figures measured over 8 engine seeds of both parities (`seed_spread.py`).
SEED_MIX = Path(__file__).with_name("grf_seed_mix.json")
TEXTURE_METRICS = (
    "goal_kicks",
    "free_kicks",
    "corners",
    "throw_ins",
    "penalties",
    "yellow_cards",
    "passes",
    "turnovers",
    "possession",
    "width_m",
    "loose_share",
    "owned_spell",
    "loose_spell",
)
#: §4's metrics that are counts per match (the zero-se floor applies); the others are plain means.
TEXTURE_COUNTS = {"goal_kicks", "free_kicks", "corners", "throw_ins", "penalties", "yellow_cards"}
TEXTURE_N = 6


def build_cases(reference: dict[str, Any]) -> list[dict[str, Any]]:
    """Every case of the reference, in the order of its sections."""
    built: list[dict[str, Any]] = []
    for ref in reference["academy"]["cases"]:
        built.append(
            {
                "id": f"academy {ref['scenario']} {ref['policy']}",
                "section": "academy",
                "scenario": ref["scenario"],
                "policy": ref["policy"],
                "n": ref["n"],
                "ref": ref,
            }
        )
    for ref in reference["full_match"]["cases"]:
        built.append(
            {
                "id": f"match {ref['scenario']} {ref['policy']}",
                "section": "match",
                "scenario": ref["scenario"],
                "policy": ref["policy"],
                "n": ref["n"],
                "ref": ref,
            }
        )
    for ref in reference["probes"]["cases"]:
        built.append(
            {
                "id": f"probe {ref['name']} {ref['scenario']}",
                "section": "probe",
                "scenario": ref["scenario"],
                "policy": ref["script"],
                "n": ref["n"],
                "ref": ref,
            }
        )
    texture = reference["match_texture"]
    for difficulty, ref in texture["difficulties"].items():
        built.append(
            {
                "id": f"texture {difficulty} {ref['scenario']} builtin_ai",
                "section": "texture",
                "scenario": ref["scenario"],
                "policy": "builtin_ai",
                "n": TEXTURE_N,
                "ref": ref,
                "real": texture["real_football"],
            }
        )
    return built


def run_case(job: tuple[dict[str, Any], int, int]) -> tuple[list[dict[str, Any]], float]:
    """Runs one case's episodes (in a worker process): the episodes as dicts, and the seconds."""
    case, n, base_seed = job
    seed = cases.case_seed(base_seed, case["id"])
    policy = case["policy"]
    if isinstance(policy, dict):
        script = policy
        policy = (
            (lambda env: cases.Constant(script["every"]))
            if "every" in script
            else (lambda env: cases.Scripted(script["first"]))
        )
    start = time.perf_counter()
    if case.get("mix"):
        # Split over engine seeds as GRF's seed-mixed figures were measured; each episode keeps
        # the index of its seed's sample.
        samples = cases.run_over_seeds(case["scenario"], policy, n, base_seed, case["id"])
        episodes = [
            {**asdict(episode), "sample": k}
            for k, sample in enumerate(samples)
            for episode in sample
        ]
        return episodes, time.perf_counter() - start
    runs = cases.run_episodes(
        case["scenario"], policy, n, seed, with_stats=case["section"] == "texture"
    )
    return [asdict(episode) for episode in runs], time.perf_counter() - start


def compare(case: dict[str, Any], episodes: list[dict[str, Any]]) -> list[fs.Figure]:
    """The case's figures, GRF's next to touchline's."""
    ref, n = case["ref"], len(episodes)
    section = case["section"]
    if section == "academy" and case.get("mix"):
        return compare_seed_mix(case["mix"], episodes)
    if section == "academy":
        figures = [
            fs.proportion(
                "P(goal for)",
                ref["goal_for"],
                ref["n"],
                sum(e["goals_for"] > 0 for e in episodes),
                n,
            ),
            fs.proportion(
                "P(goal against)",
                ref["goal_against"],
                ref["n"],
                sum(e["goals_against"] > 0 for e in episodes),
                n,
            ),
            fs.mean(
                "episode length",
                ref["length"]["mean"],
                ref["length"]["se"],
                [e["steps"] for e in episodes],
                kind="length",
            ),
        ]
        for end in cases.ENDS:
            k = sum(e["end"] == end for e in episodes)
            figures.append(fs.proportion(f"ends {end}", ref["ends"][end], ref["n"], k, n))
        if "keeper_active_share" in ref:
            # Not among the figures: shown, never flagged (GRF hands control to a pass's
            # target, its keeper too; docs/grf-compatibility.md#controlled-players).
            shares = [e["keeper_active_share"] for e in episodes]
            share = fs.info(
                "keeper active share",
                ref["keeper_active_share"][0],
                statistics.fmean(shares),
                fs.sample_se(shares),
            )
            share.note = "not among the issue's figures"
            figures.append(share)
        others = sum(e["end"] == "other" for e in episodes)
        if others:  # done on none of GRF's four conditions: a touchline end GRF does not have
            figures.append(fs.info("ends other", 0.0, others / n))
        return figures
    if section == "match":
        # GRF's matches over one engine seed each when measured so (`seed_spread.py`).
        grf = case.get("mix") or ref
        return [
            fs.mean(
                f"goals {side} / match",
                grf[f"goals_{side}"]["mean"],
                grf[f"goals_{side}"]["se"],
                [e[f"goals_{side}"] for e in episodes],
                kind="count",
                grf_n=grf[f"goals_{side}"].get("n", ref["n"]),
            )
            for side in ("for", "against")
        ]
    if section == "probe":
        scored = [e for e in episodes if e["goals_for"] > 0]
        figures = [fs.proportion("P(goal)", ref["goals"], ref["n"], len(scored), n)]
        if "max_ball_x" in ref:
            figures.append(
                fs.bound("max ball x", ref["max_ball_x"], max(e["max_ball_x"] for e in episodes))
            )
        if "kicked" in ref:
            kicked = [e for e in episodes if e["first_kick_step"] is not None]
            figures.append(fs.proportion("P(kick)", ref["kicked"], ref["n"], len(kicked), n))
            if "kick_speed" in ref and kicked:
                speeds = [e["first_kick_speed"] for e in kicked]
                figures.append(
                    fs.near("kick speed m/s", ref["kick_speed"], speeds, KICK_SPEED_TOLERANCE)
                )
            after = [e["ball_x_after_kick"] for e in kicked if e["ball_x_after_kick"] is not None]
            if "ball_x_after_kick" in ref and after:
                figures.append(
                    fs.near("ball x 25 steps on", ref["ball_x_after_kick"], after, BALL_X_TOLERANCE)
                )
        if "steps_to_goal" in ref:
            steps = [e["first_goal_step"] for e in scored]
            figures.append(
                fs.info(
                    "steps to goal",
                    ref["steps_to_goal"],
                    statistics.fmean(steps) if steps else math.nan,
                    fs.sample_se(steps) if steps else None,
                )
            )
        return figures
    return compare_texture(case, episodes)


def compare_seed_mix(mix: dict[str, Any], episodes: list[dict[str, Any]]) -> list[fs.Figure]:
    """An academy case against GRF's seed-mixed figures (`seed_spread.py`): touchline's episodes
    pooled over their engine seeds the same way (`fidelity_stats.seed_proportion`, `seed_mean`)."""
    samples: dict[int, list[dict[str, Any]]] = {}
    for episode in episodes:
        samples.setdefault(episode["sample"], []).append(episode)
    groups = list(samples.values())
    ns = [len(g) for g in groups]

    def share(
        name: str, grf: dict[str, float], test: Callable[[dict[str, Any]], bool]
    ) -> fs.Figure:
        p, se = fs.seed_proportion([sum(1 for e in g if test(e)) for g in groups], ns)
        return fs.versus(name, "proportion", grf["p"], grf["se"], p, se)

    length, length_se = fs.seed_mean([[e["steps"] for e in g] for g in groups])
    grf_length = mix["length"]
    figures = [
        share("P(goal for)", mix["goal_for"], lambda e: e["goals_for"] > 0),
        share("P(goal against)", mix["goal_against"], lambda e: e["goals_against"] > 0),
        fs.versus(
            "episode length", "length", grf_length["mean"], grf_length["se"], length, length_se
        ),
    ]
    for end in cases.ENDS:

        def ends_so(e: dict[str, Any], end: str = end) -> bool:
            return bool(e["end"] == end)

        figures.append(share(f"ends {end}", mix["ends"][end], ends_so))
    others = sum(e["end"] == "other" for e in episodes)
    if others:  # done on none of GRF's four conditions: a touchline end GRF does not have
        figures.append(fs.info("ends other", 0.0, others / len(episodes)))
    return figures


def compare_texture(case: dict[str, Any], episodes: list[dict[str, Any]]) -> list[fs.Figure]:
    """§4: per-match statistics against GRF's (samples pooled), real football's in the note."""
    ref, real = case["ref"], case["real"]
    samples = ref["samples"]
    figures = []
    for side, key in (("for", "score_for"), ("against", "score_against")):
        total = sum(s["n"] * s[key] for s in samples) / sum(s["n"] for s in samples)
        values = [e[f"goals_{side}"] for e in episodes]
        figure = fs.info(f"goals {side}", total, statistics.fmean(values), fs.sample_se(values))
        figure.note = f"real (both teams): {real['goals']}" if side == "for" else ""
        figures.append(figure)
    for metric in TEXTURE_METRICS:
        if metric in ref.get("pooled", {}):
            mean_se = ref["pooled"][metric]
            grf_n, grf_mean, grf_se = sum(s["n"] for s in samples), mean_se[0], mean_se[1]
        else:
            grf_n, grf_mean, grf_se = fs.pooled([(s["n"], *s[metric]) for s in samples])
        values = [e["stats"][metric] for e in episodes]
        kind = "count" if metric in TEXTURE_COUNTS else "mean"
        figure = fs.mean(metric, grf_mean, grf_se, values, kind=kind, grf_n=grf_n)
        if metric in real:
            figure.note = f"real: {real[metric]}"
        elif metric == "free_kicks":
            figure.note = f"real: {real['free_kicks']}"
        figures.append(figure)
    return figures


def _number(value: float | None, digits: int) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.{digits}f}"


def _digits(figure: fs.Figure) -> int:
    if figure.kind == "proportion" or figure.name in ("max ball x", "possession"):
        return 3
    if figure.name in ("loose_share", "keeper active share", "ball x 25 steps on"):
        return 3
    return (
        1
        if figure.kind in ("length", "info")
        or figure.name in ("width_m", "owned_spell", "loose_spell")
        else 2
    )


def format_figure(label: str, figure: fs.Figure) -> str:
    d = _digits(figure)
    grf = _number(figure.grf, d)
    if figure.grf_se is not None:
        grf += f" ± {_number(figure.grf_se, d)}"
    tl = _number(figure.touchline, d)
    if figure.touchline_se is not None:
        tl += f" ± {_number(figure.touchline_se, d)}"
    z = "" if figure.z is None else ("inf" if math.isinf(figure.z) else f"{figure.z:+.1f}")
    flag = "FLAG" if figure.flagged else ""
    return f"{label:<62} {figure.name:<20} {grf:>17} {tl:>17} {z:>6} {flag:>4}  {figure.note}"


def header() -> str:
    return (
        f"{'case':<62} {'figure':<20} {'GRF ± se':>17} {'touchline ± se':>17} {'z':>6} {'flag':>4}"
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="", help="run only cases whose id contains this")
    parser.add_argument("--n-scale", type=float, default=1.0, help="scale every n (quick runs)")
    parser.add_argument("--seed", type=int, default=0, help="base seed of every case's seed")
    parser.add_argument("--workers", type=int, default=2, help="processes running cases")
    parser.add_argument("--json", type=Path, help="write every figure and episode here")
    parser.add_argument(
        "--single-seed",
        action="store_true",
        help="academy cases against GRF's first, one-seed figures, one engine seed per case",
    )
    args = parser.parse_args(argv)

    reference = json.loads(REFERENCE.read_text())
    seed_mix = json.loads(SEED_MIX.read_text()) if SEED_MIX.exists() else {"cases": {}}
    selected = [c for c in build_cases(reference) if args.cases in c["id"]]
    for case in selected:
        measured = seed_mix["cases"].get(case["id"])
        case["mix"] = None if args.single_seed or measured is None else measured["pooled"]
        if case["mix"] and case["section"] == "match":
            case["n"] = case["mix"]["goals_for"]["n"]
            goals = measured["matches"]
            case["ref"] = {
                **case["ref"],
                "scores": [f"{a}-{b}" for a, b in zip(goals["for"], goals["against"], strict=True)],
            }
    if not selected:
        print(f"no case matches {args.cases!r}", file=sys.stderr)
        return 2
    jobs = [(c, max(1, round(c["n"] * args.n_scale)), args.seed) for c in selected]
    # Longest first, so that the full matches do not end up last on one worker.
    order = sorted(range(len(jobs)), key=lambda i: -_cost(jobs[i]))
    start = time.perf_counter()
    results: dict[int, tuple[list[dict[str, Any]], float]] = {}
    if args.workers > 1:
        with multiprocessing.Pool(args.workers) as pool:
            for i, result in zip(order, pool.imap(run_case, [jobs[i] for i in order]), strict=True):
                results[i] = result
    else:
        for i in order:
            results[i] = run_case(jobs[i])
    wall = time.perf_counter() - start

    print(f"GRF: {reference['source']}")
    if any(c["mix"] for c in selected):
        print(f"Academy drills (seed-mixed): {seed_mix['source']}")
    print(
        f"touchline: through touchline.compat.gfootball, base seed {args.seed}, "
        f"n × {args.n_scale}\n"
    )
    report: list[dict[str, Any]] = []
    flagged_reference: list[str] = []
    reference_count = 0
    section = None
    for i, case in enumerate(selected):
        episodes, seconds = results[i]
        figures = compare(case, episodes)
        case_flagged = any(f.flagged for f in figures)
        in_31 = case["section"] in ("academy", "match")
        reference_count += in_31
        if in_31 and case_flagged:
            flagged_reference.append(case["id"])
        if case["section"] != section:
            section = case["section"]
            print(f"\n== {SECTION_TITLES[section]}")
            print(header())
        label = f"{case['id']} n={len(episodes)}"
        for k, figure in enumerate(figures):
            print(format_figure(label if k == 0 else "", figure))
        if case["section"] == "match":
            scores = " ".join(f"{e['goals_for']}-{e['goals_against']}" for e in episodes)
            grf_scores = " ".join(case["ref"].get("scores", []))
            print(f"{'':<62} scores: {scores}" + (f"   (GRF: {grf_scores})" if grf_scores else ""))
        report.append(
            {
                "id": case["id"],
                "section": case["section"],
                "reference_case": in_31,
                "n": len(episodes),
                "seconds": seconds,
                "flagged": case_flagged,
                "figures": [f.as_dict() for f in figures],
                "episodes": episodes,
            }
        )
    print(
        f"\nwall time {wall:.1f} s with {args.workers} worker(s); case seconds summed "
        f"{sum(r[1] for r in results.values()):.1f} s"
    )
    if reference_count:
        print(f"flagged: {len(flagged_reference)} of {reference_count} reference cases")
        for case_id in flagged_reference:
            print(f"  {case_id}")
    extra = [r["id"] for r in report if not r["reference_case"] and r["flagged"]]
    if extra:
        print(f"extra cases (probes, match texture) flagged: {len(extra)}: " + "; ".join(extra))
    if args.json:
        args.json.write_text(
            json.dumps(
                _finite(
                    {
                        "seed": args.seed,
                        "n_scale": args.n_scale,
                        "wall_seconds": wall,
                        "flagged_reference_cases": flagged_reference,
                        "reference_cases": reference_count,
                        "cases": report,
                    }
                ),
                indent=1,
            )
        )
    return 0


#: How far touchline's first kick speed (m/s) and ball x (raw units, about 2.75 m) may lie from a
#: probe GRF repeats exactly.
KICK_SPEED_TOLERANCE = 2.0
BALL_X_TOLERANCE = 0.05

SECTION_TITLES = {
    "academy": "Academy drills, random (n = 200) and idle (n = 50) [reference cases]",
    "match": "Full matches, 3001 steps, goals per match [reference cases]",
    "probe": "A few scripted actions, then idle (probes; not among the 31)",
    "texture": "What a full match is made of, builtin_ai, per match, both teams (not among the 31)",
}


def _cost(job: tuple[dict[str, Any], int, int]) -> float:
    case, n, _ = job
    if case["section"] in ("match", "texture") or "lazy" in case["scenario"]:
        return n * 3001 * 2.5
    return n * 200


def _finite(value: Any) -> Any:
    """`value` with NaN and infinities as null (JSON has neither)."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite(v) for v in value]
    return value


if __name__ == "__main__":
    sys.exit(main())
