"""Plots the `learning_curve.csv` files of `train_sb3_ppo.py` runs, one panel per drill.

    pip install matplotlib
    python examples/python/plot_learning_curves.py runs/ppo_* --out docs/learning_curves.png

Run folders are grouped by drill (the `# scenario` line `train_sb3_ppo.py` writes in `run.txt`, or
the folder name); each run is one line of mean evaluation return (= goal rate with the scoring
reward) against environment steps, with a band of ± 1 standard error of its evaluation episodes.
"""

from __future__ import annotations

import argparse
import csv
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt


def scenario_of(run: Path) -> str:
    info = run / "run.txt"
    if info.is_file():
        for line in info.read_text().splitlines():
            if line.startswith("scenario:"):
                return line.split(":", 1)[1].strip()
    return run.name


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", type=Path, help="folders holding learning_curve.csv")
    parser.add_argument("--out", type=Path, default=Path("learning_curves.png"))
    args = parser.parse_args()

    by_scenario: dict[str, list[Path]] = defaultdict(list)
    for run in args.runs:
        if (run / "learning_curve.csv").is_file():
            by_scenario[scenario_of(run)].append(run)
    if not by_scenario:
        parser.error("no learning_curve.csv in the given folders")
    figure, axes = plt.subplots(
        1, len(by_scenario), figsize=(4.5 * len(by_scenario), 3.6), sharey=True, squeeze=False
    )
    for axis, (scenario, runs) in zip(axes[0], sorted(by_scenario.items())):
        for run in sorted(runs):
            with (run / "learning_curve.csv").open() as f:
                rows = list(csv.DictReader(f))
            steps = [int(r["steps"]) / 1e6 for r in rows]
            mean = [float(r["mean_return"]) for r in rows]
            se = [float(r["se_return"]) for r in rows]
            axis.plot(steps, mean, label=run.name)
            axis.fill_between(
                steps,
                [m - s for m, s in zip(mean, se)],
                [m + s for m, s in zip(mean, se)],
                alpha=0.2,
            )
        axis.set_title(scenario)
        axis.set_xlabel("environment steps (millions)")
        axis.grid(alpha=0.3)
        axis.legend(fontsize=7, loc="lower right")
    axes[0][0].set_ylabel("mean evaluation return (goal rate)")
    axes[0][0].set_ylim(-0.05, 1.05)
    figure.suptitle("SB3 PPO on touchline Academy drills (simple115v2, scoring reward)")
    figure.tight_layout()
    args.out.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
