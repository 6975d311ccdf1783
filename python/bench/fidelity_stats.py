"""One figure of a fidelity case, GRF's next to touchline's, and issue 15's rule for "differs".

A figure differs from GRF's (is flagged) when |Δ| > 3·sqrt(se_GRF² + se_touchline²), where
  * a proportion k/n has se = sqrt(p̃(1 − p̃)/n) with p̃ = (k + 1)/(n + 2), on both sides, so that 0/50
    is not infinitely sure;
  * a mean has se = sample std / sqrt(n) (GRF's as measured);
  * a count per match (goals, restarts, cards) whose sample se is 0 (every match the same, usually
    all 0) gets the se of a Poisson count with one more event, sqrt(total + 1)/n: the count analogue
    of p̃, so that "0 in 5 matches" is not infinitely sure either;
  * an episode length is flagged only if it is ALSO more than 10 % off GRF's mean, since some GRF
    lengths have almost no spread (151.3 ± 0.1).
Cases run over several engine seeds (the academy drills: GRF's outcome depends on the seed well
beyond sampling noise, see `seed_spread.py`) pool their samples, and each pooled figure's se is the
larger of the one-sample se above and the spread of the per-seed values over sqrt(seeds)
(`seed_proportion`, `seed_mean`), on both sides.
A bound (GRF's probes gave a range, not an se) is flagged when touchline's value is beyond it; a
`near` figure (a probe GRF repeats exactly) when touchline's mean is further from GRF's than its
tolerance; an `info` figure is shown and never flagged.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

#: Combined standard errors beyond which a figure differs.
Z_LIMIT = 3.0
#: An episode length must also be this far off (relative to GRF's mean) to differ.
LENGTH_TOLERANCE = 0.10


@dataclass
class Figure:
    """GRF's value and touchline's, their standard errors, z and whether it is flagged."""

    name: str
    kind: str  # proportion | mean | count | length | bound | near | info
    grf: float | None
    grf_se: float | None
    touchline: float
    touchline_se: float | None
    z: float | None
    flagged: bool
    note: str = ""

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


def proportion_se(k: int, n: int) -> float:
    """se of a proportion k/n with p̃ = (k + 1)/(n + 2)."""
    p = (k + 1) / (n + 2)
    return math.sqrt(p * (1 - p) / n)


def sample_se(values: Sequence[float]) -> float:
    """Sample std / sqrt(n); 0 for fewer than two values."""
    return statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else 0.0


def count_se(mean: float, se: float, n: int) -> float:
    """A count per match's se, floored at the Poisson se of one more event when it is 0."""
    return se if se > 0 else math.sqrt(mean * n + 1) / n


def _z(delta: float, se_a: float, se_b: float) -> float:
    combined = math.hypot(se_a, se_b)
    if combined == 0:
        return 0.0 if delta == 0 else math.copysign(math.inf, delta)
    return delta / combined


def proportion(name: str, grf_p: float, grf_n: int, k: int, n: int) -> Figure:
    """A proportion: GRF's p of grf_n (k derived as round(p·n)), touchline's k of n."""
    grf_k = round(grf_p * grf_n)
    grf_se, tl_se = proportion_se(grf_k, grf_n), proportion_se(k, n)
    z = _z(k / n - grf_p, grf_se, tl_se)
    return Figure(name, "proportion", grf_p, grf_se, k / n, tl_se, z, abs(z) > Z_LIMIT)


def mean(
    name: str,
    grf_mean: float,
    grf_se: float,
    values: Sequence[float],
    kind: str = "mean",
    grf_n: int | None = None,
) -> Figure:
    """A mean over episodes or matches; `kind` is mean, count (se floor) or length (10 % rule)."""
    value = statistics.fmean(values)
    tl_se = sample_se(values)
    if kind == "count":
        grf_se = count_se(grf_mean, grf_se, grf_n or len(values))
        tl_se = count_se(value, tl_se, len(values))
    return versus(name, kind, grf_mean, grf_se, value, tl_se)


def bound(name: str, grf_bound: float, value: float) -> Figure:
    """A value GRF never exceeded in its episodes (no se given): flagged when touchline does."""
    return Figure(name, "bound", grf_bound, None, value, None, None, value > grf_bound, "GRF's max")


def near(name: str, grf: float, values: Sequence[float], tolerance: float) -> Figure:
    """A figure GRF gave without spread (a scripted probe that repeats exactly): flagged when
    touchline's mean is further than `tolerance` from it."""
    value = statistics.fmean(values)
    flagged = abs(value - grf) > tolerance
    return Figure(
        name,
        "near",
        grf,
        None,
        value,
        sample_se(values),
        None,
        flagged,
        f"tolerance ±{tolerance:g}",
    )


def info(name: str, grf: float | None, value: float, tl_se: float | None = None) -> Figure:
    """Shown side by side, never flagged (GRF gave an approximate figure only)."""
    return Figure(name, "info", grf, None, value, tl_se, None, False, "approximate")


def pooled(samples: Sequence[tuple[int, float, float]]) -> tuple[int, float, float]:
    """(n, mean, se) of samples (n_i, mean_i, se_i) taken together, as one sample would give."""
    total = sum(n for n, _, _ in samples)
    grand = sum(n * m for n, m, _ in samples) / total
    squares = sum((n - 1) * (se * math.sqrt(n)) ** 2 + n * (m - grand) ** 2 for n, m, se in samples)
    return total, grand, math.sqrt(squares / (total - 1)) / math.sqrt(total)


def seed_proportion(counts: Sequence[int], ns: Sequence[int]) -> tuple[float, float]:
    """A proportion pooled over per-seed samples (count k_i of n_i each): p and its se, the larger
    of the p̃ se of the pooled sample and the spread of the per-seed proportions over sqrt(seeds)."""
    n = sum(ns)
    p = sum(counts) / n
    spread = [k / m for k, m in zip(counts, ns, strict=True)]
    between = statistics.stdev(spread) / math.sqrt(len(spread)) if len(spread) > 1 else 0.0
    return p, max(proportion_se(sum(counts), n), between)


def seed_mean(samples: Sequence[Sequence[float]]) -> tuple[float, float]:
    """A mean pooled over per-seed samples: the grand mean and its se, the larger of the pooled
    sample's se and the spread of the per-seed means over sqrt(seeds)."""
    values = [v for sample in samples for v in sample]
    means = [statistics.fmean(sample) for sample in samples]
    between = statistics.stdev(means) / math.sqrt(len(means)) if len(means) > 1 else 0.0
    return statistics.fmean(values), max(sample_se(values), between)


def versus(name: str, kind: str, grf: float, grf_se: float, value: float, se: float) -> Figure:
    """GRF's figure and touchline's, each with its se as given; `kind` length adds the 10 % rule."""
    z = _z(value - grf, grf_se, se)
    flagged = abs(z) > Z_LIMIT
    note = ""
    if kind == "length" and flagged and abs(value - grf) <= LENGTH_TOLERANCE * grf:
        flagged = False
        note = "within 10 %"
    return Figure(name, kind, grf, grf_se, value, se, z, flagged, note)
