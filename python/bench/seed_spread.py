"""The academy reference cases measured over several engine seeds, each case's episodes split evenly
between them: per-seed figures and the pooled ones, with a standard error that counts the spread
between seeds as well as the spread between episodes.

Why: GRF's outcome of a case depends on its engine seed well beyond sampling noise. The seed's
parity sets GRF's `reverse_team_processing` (`gfootball/env/scenario_builder.py`), the order in
which the engine processes the two teams, and a case run with one fixed `game_engine_random_seed`
(as the harness and the first reference measurement ran) plays every episode with one parity. Left
to itself GRF draws a new seed, so a new parity, every episode. Measured here (GRF 2.10.2,
academy_run_to_score, random agent, 200 episodes per seed): ends out of play 0.34 with seed 7 and
0.48 with seed 20, possession 0.58 and 0.37, goal 0.05 and 0.13. Seeds alternate parity here, so
the pooled figure is GRF's behaviour as a user gets it.

Run it in touchline, or in GRF's Python with the measuring folder of `README.md` first on
`PYTHONPATH`, from the repository root:
    PYTHONPATH=python/bench python3 python/bench/seed_spread.py --json /tmp/spread.json
    PYTHONPATH=/tmp/grfshim:python/bench ~/grf-venv/bin/python python/bench/seed_spread.py \
        --cases empty_goal --json /tmp/grf_spread.json
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
from pathlib import Path
from typing import Any

import fidelity_cases as cases
import fidelity_stats as fs

REFERENCE = Path(__file__).with_name("grf_reference.json")
#: GRF's seed-mixed figures, as this script wrote them when run in GRF: the harness compares the
#: academy drills with them (`fidelity.py`).
SEED_MIX = Path(__file__).with_name("grf_seed_mix.json")
#: What `SEED_MIX` holds and how it was measured.
SOURCE = (
    "GRF 2.10.2 (built here from its PyPI sdist), run through this folder's own episode code "
    "(seed_spread.py, gfootball standing in for touchline.compat.gfootball): each academy "
    "reference case's n episodes split evenly over engine seeds, even and odd alternately (the "
    "seed's parity sets the order GRF's engine processes the two teams in; left to itself GRF "
    "draws a new seed every episode): 8 seeds for the random agent, one per episode for the "
    "idle one (with one seed GRF plays every idle episode alike). Each pooled figure's se is the "
    "larger of the pooled sample's and the per-seed values' spread over sqrt(seeds). Full "
    "matches: one engine seed each. Measured 2026-11-25 from base seed 1000; the full-match cases "
    "again 2026-11-29, 20 more matches each from base seed 2000, pooled (`runs`; issue 15)."
)
#: Full matches per match case and sample, one engine seed each (the first reference played 5 with
#: one seed).
MATCHES = 10
#: The base seed of the engine seeds measured (`fidelity_cases.engine_seed`); the harness's runs of
#: touchline start from 0.
BASE_SEED = 1000


def summarise(episodes: list[cases.Episode]) -> dict[str, Any]:
    """One sample's counts and length statistics."""
    lengths = [e.steps for e in episodes]
    return {
        "n": len(episodes),
        "goal_for": sum(e.goals_for > 0 for e in episodes),
        "goal_against": sum(e.goals_against > 0 for e in episodes),
        "ends": {end: sum(e.end == end for e in episodes) for end in cases.ENDS},
        "length_mean": statistics.fmean(lengths),
        "length_sd": statistics.stdev(lengths) if len(lengths) > 1 else 0.0,
    }


def pool(samples: list[dict[str, Any]]) -> dict[str, Any]:
    """The samples taken together, each figure as [value, se] (`fidelity_stats.seed_proportion`;
    the length's se the larger of the pooled sample's and the per-seed means' spread over
    sqrt(seeds)), with the per-seed values beside."""
    ns = [s["n"] for s in samples]
    n = sum(ns)

    def proportion(count: list[int]) -> dict[str, Any]:
        p, se = fs.seed_proportion(count, ns)
        return {"p": p, "se": se, "per_seed": [c / m for c, m in zip(count, ns, strict=True)]}

    grand = sum(s["n"] * s["length_mean"] for s in samples) / n
    squares = sum(
        (s["n"] - 1) * s["length_sd"] ** 2 + s["n"] * (s["length_mean"] - grand) ** 2
        for s in samples
    )
    one_sample = math.sqrt(squares / max(n - 1, 1) / n)
    means = [s["length_mean"] for s in samples]
    between = statistics.stdev(means) / math.sqrt(len(means)) if len(means) > 1 else 0.0
    return {
        "n": n,
        "seeds": len(samples),
        "goal_for": proportion([s["goal_for"] for s in samples]),
        "goal_against": proportion([s["goal_against"] for s in samples]),
        "ends": {end: proportion([s["ends"][end] for s in samples]) for end in cases.ENDS},
        "length": {"mean": grand, "se": max(one_sample, between), "per_seed": means},
    }


def match_pooled(goals: dict[str, list[int]]) -> dict[str, Any]:
    """A match case's goals per match, for and against, as mean, se and n."""
    return {
        f"goals_{side}": {"mean": statistics.fmean(g), "se": fs.sample_se(g), "n": len(g)}
        for side, g in goals.items()
    }


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", default="", help="only case ids containing this")
    parser.add_argument("--json", type=Path, default=SEED_MIX, help="where to write the figures")
    parser.add_argument(
        "--matches", type=int, default=MATCHES, help="full matches per match case, one seed each"
    )
    parser.add_argument(
        "--base-seed",
        type=int,
        default=BASE_SEED,
        help="base of the engine seeds; a new base gives a new sample of seeds",
    )
    parser.add_argument(
        "--add",
        action="store_true",
        help="add this run's samples and matches to those already in --json and pool them all "
        "(for a second sample, on seeds of another --base-seed)",
    )
    args = parser.parse_args(argv)
    reference = json.loads(REFERENCE.read_text())
    out: dict[str, Any] = {"source": SOURCE, "cases": {}}
    if args.add:
        out = json.loads(args.json.read_text())
    runs_note = f"{args.cases or 'every case'} from base seed {args.base_seed}"
    out.setdefault("runs", []).append(runs_note)
    for ref in reference["academy"]["cases"]:
        case_id = f"academy {ref['scenario']} {ref['policy']}"
        if args.cases not in case_id:
            continue
        runs = cases.run_over_seeds(
            ref["scenario"], ref["policy"], ref["n"], args.base_seed, case_id
        )
        samples = out["cases"].get(case_id, {}).get("samples", []) if args.add else []
        samples = samples + [summarise(episodes) for episodes in runs]
        pooled = pool(samples)
        out["cases"][case_id] = {"samples": samples, "pooled": pooled}
        ends = " ".join(f"{e} {pooled['ends'][e]['p']:.3f}" for e in cases.ENDS)
        print(
            f"{case_id}: length {pooled['length']['mean']:.1f} ± {pooled['length']['se']:.1f}; {ends}"
        )
        sys.stdout.flush()
        args.json.write_text(json.dumps(out, indent=1))
    for ref in reference["full_match"]["cases"]:
        case_id = f"match {ref['scenario']} {ref['policy']}"
        if args.cases not in case_id:
            continue
        # One match per engine seed, so every match is a new draw of GRF's parity and randomness.
        runs = cases.run_over_seeds(
            ref["scenario"], ref["policy"], args.matches, args.base_seed, case_id
        )
        before = out["cases"].get(case_id, {}).get("matches", {}) if args.add else {}
        goals = {
            side: before.get(side, [])
            + [e.goals_for if side == "for" else e.goals_against for r in runs for e in r]
            for side in ("for", "against")
        }
        out["cases"][case_id] = {"matches": goals, "pooled": match_pooled(goals)}
        print(f"{case_id}: goals for {goals['for']}, against {goals['against']}")
        sys.stdout.flush()
        args.json.write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
