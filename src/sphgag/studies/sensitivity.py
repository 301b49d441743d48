"""Global sensitivity analysis: Morris screening, then Sobol variance indices (SALib), with failed runs accounted for.

The study is model-agnostic here: a *problem* is a list of inputs with uniform ranges; a *design* is a
table of input values, one row per sample (:func:`morris_design`, :func:`sobol_design`); a model evaluated on every
row gives a table of outputs (:func:`sphgag.studies.pool_response.sample_rows`, which records a sample whose run fails
by its inputs and its error instead of dropping it); the indices come back as one tidy table (:func:`morris_indices`,
:func:`sobol_indices`). This module computes no sample: editing it redoes the designs and the indices, not the runs.

* **Morris** (Morris 1991; Campolongo et al. 2007): ``r`` one-at-a-time trajectories of ``k + 1`` samples on a grid
  of ``levels`` levels. The elementary effect of input ``i`` is ``(y(x + Delta e_i) - y(x)) / Delta`` with ``Delta``
  in units of the input's range, so that a linear ``y = sum a_i x_i`` has ``mu* = |a_i| (high_i - low_i)`` and
  ``sigma = 0`` exactly. ``mu*`` (mean of ``|EE|``) ranks influence, ``sigma`` flags non-linearity or interaction.
* **Sobol** (Saltelli 2002, 2010): first-order ``S1`` and total ``ST`` indices from ``N (k + 2)`` samples (no
  second-order terms), with bootstrap confidence intervals.

A sample without an output (its run failed, or the output is undefined there, e.g. no equilibrium at the stated
concentration) breaks the finite differences it takes part in: the indices of that output are computed from the
complete trajectories (Morris) or complete base rows (Sobol) only, and every index row says how many samples it used
and how many were missing or failed, so that nothing leaves the indices silently.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from SALib.analyze import morris as morris_analyze
from SALib.analyze import sobol as sobol_analyze
from SALib.sample import morris as morris_sample
from SALib.sample import sobol as sobol_sample

#: columns of the index table (results/sensitivity/indices.csv), besides method, charge_law, output, input
INDEX_COLUMNS = ["index", "value", "conf_low", "conf_high", "samples_used", "samples_missing", "samples_failed"]


@dataclass(frozen=True)
class Problem:
    """Inputs (names, e.g. dotted config keys) with their uniform ranges ``[low, high]``."""

    names: tuple[str, ...]
    low: tuple[float, ...]
    high: tuple[float, ...]

    @classmethod
    def from_ranges(cls, ranges: dict) -> Problem:
        """From ``{name: {low, high, ...}}`` (the ``sensitivity.inputs`` configuration), in its order."""
        names = tuple(ranges)
        return cls(names, tuple(float(ranges[n]["low"]) for n in names), tuple(float(ranges[n]["high"]) for n in names))

    def __post_init__(self):
        bad = [n for n, lo, hi in zip(self.names, self.low, self.high) if not lo < hi]
        if bad:
            raise ValueError(f"inputs need low < high: {', '.join(bad)}")

    @property
    def salib(self) -> dict:
        return dict(
            num_vars=len(self.names), names=list(self.names), bounds=[[lo, hi] for lo, hi in zip(self.low, self.high)]
        )

    def subset(self, names) -> Problem:
        idx = [self.names.index(n) for n in names]
        return Problem(
            tuple(self.names[i] for i in idx), tuple(self.low[i] for i in idx), tuple(self.high[i] for i in idx)
        )


def _design(problem: Problem, X: np.ndarray) -> pd.DataFrame:
    table = pd.DataFrame(X, columns=list(problem.names))
    table.insert(0, "sample", np.arange(len(table)))
    return table


def morris_design(problem: Problem, trajectories: int, levels: int, seed: int) -> pd.DataFrame:
    """``trajectories (k + 1)`` samples: Morris one-at-a-time trajectories on a ``levels``-level grid."""
    X = morris_sample.sample(problem.salib, trajectories, num_levels=levels, seed=seed)
    return _design(problem, X)


def sobol_design(problem: Problem, base_samples: int, seed: int) -> pd.DataFrame:
    """``base_samples (k + 2)`` samples: Saltelli's scheme for S1 and ST (scrambled Sobol' sequence)."""
    X = sobol_sample.sample(problem.salib, base_samples, calc_second_order=False, seed=seed)
    return _design(problem, X)


def _complete_blocks(y: np.ndarray, block: int) -> np.ndarray:
    """Mask of the samples in blocks (trajectories, base rows) of ``block`` samples without a missing value."""
    ok = np.isfinite(y).reshape(-1, block).all(axis=1)
    return np.repeat(ok, block)


def _counts(y: np.ndarray, used: np.ndarray, failed: np.ndarray) -> dict:
    return dict(
        samples_used=int(used.sum()), samples_missing=int((~np.isfinite(y)).sum()), samples_failed=int(failed.sum())
    )


def _rows(method, problem, indices: dict, counts: dict) -> list[dict]:
    rows = []
    for name, idx in indices.items():
        for i, inp in enumerate(problem.names):
            value, half = idx[i]
            rows.append(
                dict(
                    method=method,
                    input=inp,
                    index=name,
                    value=value,
                    conf_low=value - half,
                    conf_high=value + half,
                    **counts,
                )
            )
    return rows


def morris_indices(
    problem: Problem, design: pd.DataFrame, y, failed, levels: int, resamples: int, confidence: float, seed: int
) -> list[dict]:
    """Index rows (``mu_star`` with its bootstrap interval, ``mu``, ``sigma``) of one output ``y`` over the Morris
    ``design``; ``failed``: samples whose run failed. Trajectories with a missing value are left out and counted;
    an output with fewer than two complete trajectories has no indices (NaN)."""
    y, failed = np.asarray(y, float), np.asarray(failed, bool)
    X = design[list(problem.names)].to_numpy()
    k = len(problem.names)
    used = _complete_blocks(y, k + 1)
    counts = _counts(y, used, failed)
    if used.sum() < 2 * (k + 1):
        nan = {n: [(np.nan, np.nan)] * k for n in ("mu_star", "mu", "sigma")}
        return _rows("morris", problem, nan, counts)
    res = morris_analyze.analyze(
        problem.salib, X[used], y[used], num_resamples=resamples, conf_level=confidence, num_levels=levels, seed=seed
    )
    none = np.full(k, np.nan)  # mu and sigma: no interval
    indices = dict(
        mu_star=list(zip(res["mu_star"], res["mu_star_conf"])),
        mu=list(zip(res["mu"], none)),
        sigma=list(zip(res["sigma"], none)),
    )
    return _rows("morris", problem, indices, counts)


def sobol_indices(problem: Problem, y, failed, resamples: int, confidence: float, seed: int) -> list[dict]:
    """Index rows (``S1``, ``ST`` with bootstrap intervals) of one output ``y`` over a :func:`sobol_design`;
    base rows with a missing value are left out and counted; a constant output has no indices (NaN)."""
    y, failed = np.asarray(y, float), np.asarray(failed, bool)
    k = len(problem.names)
    used = _complete_blocks(y, k + 2)
    counts = _counts(y, used, failed)
    if used.sum() < 2 * (k + 2) or np.ptp(y[used]) == 0.0:
        nan = {n: [(np.nan, np.nan)] * k for n in ("S1", "ST")}
        return _rows("sobol", problem, nan, counts)
    res = sobol_analyze.analyze(
        problem.salib, y[used], calc_second_order=False, num_resamples=resamples, conf_level=confidence, seed=seed
    )
    indices = dict(S1=list(zip(res["S1"], res["S1_conf"])), ST=list(zip(res["ST"], res["ST_conf"])))
    return _rows("sobol", problem, indices, counts)


def most_influential(indices: pd.DataFrame, count: int) -> list[str]:
    """The ``count`` inputs with the largest Morris ``mu*`` relative to the largest of their output: ranked by the
    maximum of that ratio over outputs and charge laws (an input that leads any one output first), ties by its mean
    (the breadth of its influence), then by the inputs' order."""
    m = indices[(indices.method == "morris") & (indices["index"] == "mu_star")].copy()
    top = m.groupby(["charge_law", "output"]).value.transform("max")
    m["relative"] = (m.value / top).where(top > 0)
    order = list(dict.fromkeys(m.input))
    by_input = m.groupby("input", sort=False).relative
    best, breadth = by_input.max().reindex(order).fillna(-1.0), by_input.mean().reindex(order).fillna(-1.0)
    ranked = sorted(order, key=lambda n: (-best[n], -breadth[n], order.index(n)))
    return ranked[:count]


def indices_table(
    method: str, design: pd.DataFrame, samples: pd.DataFrame, ranges: dict, outputs, settings: dict, log=None
):
    """The ``method`` (``morris`` or ``sobol``) indices of every output of ``outputs`` under every charge law, in one
    tidy table (``method``, ``charge_law``, ``output``, ``input``, :data:`INDEX_COLUMNS`): ``samples`` are the rows
    of the ``design`` with their outputs (a column ``charge_law``, and ``status``, ``ok`` where the run succeeded),
    ``ranges`` the inputs' ranges (:meth:`Problem.from_ranges`) and ``settings`` the method's (``levels`` for Morris,
    ``resamples``, ``confidence``, ``seed``). A missing output (a failed run) is NaN in its samples."""
    names = [c for c in design.columns if c != "sample"]
    problem, s, rows = Problem.from_ranges(ranges).subset(names), settings, []
    for law, table in samples.groupby("charge_law", sort=False):
        table = design[["sample"]].merge(table, on="sample", how="left")  # every sample of the design, in its order
        failed = (table.status != "ok").to_numpy()
        for output in outputs:
            y = table[output].to_numpy(dtype=float) if output in table else np.full(len(table), np.nan)
            if method == "morris":
                found = morris_indices(
                    problem, design, y, failed, s["levels"], s["resamples"], s["confidence"], s["seed"]
                )
            else:
                found = sobol_indices(problem, y, failed, s["resamples"], s["confidence"], s["seed"])
            rows += [dict(charge_law=law, output=output, **r) for r in found]
            if log is not None:
                log.info(
                    "[sensitivity_%s] %s, %s: %d of %d samples used, %d failed",
                    *(method, law, output, found[0]["samples_used"], len(table), found[0]["samples_failed"]),
                )
    return pd.DataFrame(rows)[["method", "charge_law", "output", "input"] + INDEX_COLUMNS]
