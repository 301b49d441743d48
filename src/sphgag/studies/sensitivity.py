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

import functools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pandas as pd
from SALib.analyze import morris as morris_analyze
from SALib.analyze import sobol as sobol_analyze
from SALib.sample import morris as morris_sample
from SALib.sample import sobol as sobol_sample

from ..options import Options, key_text
from .artery import Bilayer, Pool
from .protocols import concentration_steps

#: columns of the index table (results/sensitivity/indices.csv), besides method, charge_law, output, input
INDEX_COLUMNS = ["index", "value", "conf_low", "conf_high", "samples_used", "samples_missing", "samples_failed"]


@dataclass(frozen=True)
class Morris(Options):
    """Morris screening of every input: ``trajectories`` r on a ``levels``-level grid, the bootstrap of the mu*
    interval (``resamples``, ``confidence``)."""

    trajectories: int
    levels: int
    seed: int
    resamples: int
    confidence: float


@dataclass(frozen=True)
class Sobol(Options):
    """Sobol indices of the ``inputs`` inputs Morris ranks highest: ``base_samples`` N, the bootstrap of the S1 and
    ST intervals (``resamples``, ``confidence``)."""

    inputs: int
    base_samples: int
    seed: int
    resamples: int
    confidence: float


@dataclass(frozen=True)
class DelaminationMap(Options):
    """Figure 5's pool at each angular extent and sigma_cr, every level of the ramp classed."""

    angular_extents_deg: tuple
    critical_stresses_kPa: tuple


def _bounds(node: Mapping) -> tuple[list, str]:
    """The range tests of a schema node (``minimum``, ``exclusiveMaximum``, ...) and their text."""
    tests, words = [], []
    for word, sym, ok in (
        ("minimum", ">=", lambda v, b: v >= b),
        ("exclusiveMinimum", ">", lambda v, b: v > b),
        ("maximum", "<=", lambda v, b: v <= b),
        ("exclusiveMaximum", "<", lambda v, b: v < b),
    ):
        if word in node:
            tests.append((ok, node[word]))
            words.append(f"{sym} {node[word]}")
    return tests, " and ".join(words)


@dataclass(frozen=True)
class Sensitivity(Options):
    """The ``sensitivity`` configuration section: figure 5's pool rerun (:mod:`sphgag.studies.pool_response`) with
    the ``inputs`` (dotted paths, uniform on ``[low, high]``) sampled, figure 4's quantities read at
    ``concentration_mEq_l``, ``batch_size`` samples per job; Morris screening (:class:`Morris`), Sobol indices
    (:class:`Sobol`) and the map of figure 5's pool (:class:`DelaminationMap`)."""

    SECTION = "sensitivity"

    concentration_mEq_l: float
    batch_size: int
    inputs: Mapping
    morris: Morris
    sobol: Sobol
    map: DelaminationMap

    #: the sections an input may set (``pool``: figure 5's pool)
    INPUT_SECTIONS: ClassVar[tuple] = ("bilayer", "numerics", "homeostasis", "gag", "delamination", "pool")

    @staticmethod
    def config_key(config: Mapping, path: str) -> tuple:
        """The configuration key a sensitivity input (a dotted path into :mod:`sphgag.studies.pool_response`'s
        scenario) sets: ``pool.*`` is figure 5's pool (the first of ``delamination.figures.fig5``'s set), the other
        sections are the configuration's own."""
        section, *rest = path.split(".")
        if section == "pool":
            return ("delamination", "pool_sets", config["delamination"]["figures"]["fig5"], 0, *rest)
        return (section, *rest)

    @classmethod
    def input_problems(cls, config: Mapping, schema_node: Callable[[tuple], Mapping]) -> list[str]:
        """Every input names a number of the configuration that a sample may set (:data:`INPUT_SECTIONS`), and its
        range lies inside that key's own allowed range (its node of the schema, ``schema_node(key)``; for the pool,
        inside the media and away from the symmetry edges); the stated concentration is a step of the swelling ramp;
        Sobol takes no more inputs than there are. The inputs refer to keys the other sections' checks vouch for
        (e.g. figure 5's pool): check them only for a configuration whose other relations hold."""
        se = config.get("sensitivity")
        if not se:
            return []
        out = []
        sections = cls.INPUT_SECTIONS
        for path, r in se["inputs"].items():
            name = f"sensitivity.inputs.{path}"
            if path.split(".")[0] not in sections or path.startswith("delamination.pool_sets"):
                out.append(
                    f"{name}: an input is a number of one of the sections {', '.join(sections)} (pool: figure 5's pool)"
                )
                continue
            key = cls.config_key(config, path)
            try:
                node = functools.reduce(lambda parent, part: parent[part], key, config)
            except (KeyError, IndexError, TypeError):
                node = None
            if isinstance(node, bool) or not isinstance(node, (int, float)):
                out.append(f"{name}: {key_text(key)} is not a number of the configuration")
                continue
            tests, text = _bounds(schema_node(key))
            for end in ("low", "high"):
                if not all(ok(r[end], b) for ok, b in tests):
                    out.append(f"{name}.{end} = {r[end]} is outside the allowed range of {key_text(key)} ({text})")
            if not r["low"] < r["high"]:
                out.append(f"{name}: low = {r['low']} must be below high = {r['high']}")
        de, bil = config["delamination"], Bilayer.of(config["bilayer"])
        pool = de["pool_sets"][de["figures"]["fig5"]][0]
        radius = se["inputs"].get("pool.centre_radius_um", {})
        for end in ("low", "high"):
            if end in radius:
                lo, hi = Pool.of(dict(pool, centre_radius_um=radius[end])).radii()
                if spans := bil.pool_span_text(lo, hi):
                    out.append(
                        f"sensitivity.inputs.pool.centre_radius_um.{end} = {radius[end]}: the pool ({lo:g}-{hi:g} "
                        f"um) leaves {spans}"
                    )
        widths = [("sensitivity.map.angular_extents_deg", w) for w in se["map"]["angular_extents_deg"]]
        widths += [
            (f"sensitivity.inputs.pool.angular_extent_deg.{e}", se["inputs"].get("pool.angular_extent_deg", {}).get(e))
            for e in ("low", "high")
        ]
        for name, w in widths:
            if w is None:
                continue
            first, last = Pool.of(dict(pool, angular_extent_deg=w)).angles()
            if first <= 0 or last >= 90:
                out.append(
                    f"{name} = {w}: figure 5's pool (centre {pool['centre_angle_deg']:g} deg) would reach a symmetry "
                    "edge"
                )
        steps = concentration_steps(config["swelling"])
        if not any(math.isclose(c, se["concentration_mEq_l"]) for c in steps):
            steps = ", ".join(f"{c:g}" for c in steps)
            out.append(
                f"sensitivity.concentration_mEq_l = {se['concentration_mEq_l']} must be a step of the swelling ramp "
                f"({steps})"
            )
        if se["sobol"]["inputs"] > len(se["inputs"]):
            out.append(
                f"sensitivity.sobol.inputs = {se['sobol']['inputs']} exceeds the number of inputs ({len(se['inputs'])})"
            )
        return out


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
