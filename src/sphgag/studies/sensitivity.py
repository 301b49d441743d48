"""Global sensitivity analysis: Morris screening, then Sobol variance indices (SALib), with failed runs accounted for.

The study is model-agnostic here: a *problem* is a list of inputs with uniform ranges; a *design* is a table of input
values, one row per sample (:meth:`SensitivityMethod.design`); a model evaluated on every row gives a table of outputs
(:func:`sphgag.studies.pool_response.sample_rows`, which records a sample whose run fails by its inputs and its error
instead of dropping it); the indices come back as one tidy table (:func:`indices_table`). This module computes no
sample: editing it redoes the designs and the indices, not the runs.

A method is a :class:`SensitivityMethod` of the registry :data:`SENSITIVITY_METHODS` (wildcard ``{method}``, column
``method``, settings ``sensitivity.methods.<name>``), which owns its design and its indices:

* **Morris** (Morris 1991; Campolongo et al. 2007): ``r`` one-at-a-time trajectories of ``k + 1`` samples on a grid
  of ``levels`` levels. The elementary effect of input ``i`` is ``(y(x + Delta e_i) - y(x)) / Delta`` with ``Delta``
  in units of the input's range, so that a linear ``y = sum a_i x_i`` has ``mu* = |a_i| (high_i - low_i)`` and
  ``sigma = 0`` exactly. ``mu*`` (mean of ``|EE|``) ranks influence, ``sigma`` flags non-linearity or interaction.
* **Sobol** (Saltelli 2002, 2010): first-order ``S1`` and total ``ST`` indices from ``N (k + 2)`` samples (no
  second-order terms), with bootstrap confidence intervals, over the inputs Morris ranks highest.

A sample without an output (its run failed, or the output is undefined there, e.g. no equilibrium at the stated
concentration) breaks the finite differences it takes part in: the indices of that output are computed from the
complete blocks of samples (Morris trajectories, Sobol base rows) only, and every index row says how many samples it
used and how many were missing or failed, so that nothing leaves the indices silently.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from SALib.analyze import morris as morris_analyze
from SALib.analyze import sobol as sobol_analyze
from SALib.sample import morris as morris_sample
from SALib.sample import sobol as sobol_sample

from ..registry import Registry, Variant

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

    def design(self, X: np.ndarray) -> pd.DataFrame:
        """The design of the samples ``X`` (a row each): a column ``sample``, then a column per input."""
        table = pd.DataFrame(X, columns=list(self.names))
        table.insert(0, "sample", np.arange(len(table)))
        return table


@dataclass(frozen=True)
class SensitivityMethod(Variant):
    """A method of the sensitivity study: ``name``, ``title`` (the figure's panel titles), ``paper``, the settings of
    ``sensitivity.methods.<name>`` its design reads (``design_keys``) and its indices read (``index_keys``), and
    ``screening``: the method whose indices choose its inputs (None: every input). Its behaviour, with its settings
    as keywords: ``size(k, **design)`` samples over ``k`` inputs; ``design(problem, screening=None, **design)``, a
    :meth:`Problem.design`; ``indices(problem, design, y, failed, **indices)``, its :meth:`rows` of one output."""

    name: str
    title: str
    design_keys: tuple[str, ...]
    index_keys: tuple[str, ...]
    screening: str | None = None
    paper: bool = False

    def check(self, config, key: str) -> None:
        """Its settings (``sensitivity.methods.<name>``) hold the keys its design and its indices read, and the method
        it screens its inputs with runs too (ValueError naming the key)."""
        methods = config["sensitivity"]["methods"]
        missing = [k for k in dict.fromkeys(self.design_keys + self.index_keys) if k not in methods[self.name]]
        if missing:
            raise ValueError(f"sensitivity.methods.{self.name} lacks {', '.join(missing)}")
        if self.screening and self.screening not in methods:
            raise ValueError(f"sensitivity.methods.{self.name} screens its inputs with {self.screening}: run it too")

    def rows(self, problem: Problem, indices: dict, counts: dict) -> list[dict]:
        """Index rows (``method``, ``input``, :data:`INDEX_COLUMNS`) of ``indices`` (index name -> ``(value,
        half-width of its interval)`` per input) with the ``counts`` of :func:`sample_counts`."""
        rows = []
        for name, idx in indices.items():
            for i, inp in enumerate(problem.names):
                value, half = idx[i]
                row = dict(method=self.name, input=inp, index=name, value=value)
                rows.append(dict(row, conf_low=value - half, conf_high=value + half, **counts))
        return rows


def complete_blocks(y: np.ndarray, block: int) -> np.ndarray:
    """Mask of the samples in blocks (trajectories, base rows) of ``block`` samples without a missing value."""
    ok = np.isfinite(y).reshape(-1, block).all(axis=1)
    return np.repeat(ok, block)


def sample_counts(y: np.ndarray, used: np.ndarray, failed: np.ndarray) -> dict:
    """The samples an index row used, those without an output and those whose run failed."""
    return dict(
        samples_used=int(used.sum()), samples_missing=int((~np.isfinite(y)).sum()), samples_failed=int(failed.sum())
    )


class Morris(SensitivityMethod):
    """Morris screening (Morris 1991): elementary effects on one-at-a-time trajectories, ranked by ``mu*``, the mean
    of their absolute values (Campolongo et al. 2007). The paper has no sensitivity study (its abstract names one):
    Morris screening, the study's first stage, is the registry's ``paper`` entry."""

    def size(self, k, trajectories, **design):
        """``trajectories (k + 1)`` samples."""
        return trajectories * (k + 1)

    def design(self, problem, trajectories, levels, seed, screening=None):
        """Morris one-at-a-time trajectories on a ``levels``-level grid (SALib)."""
        return problem.design(morris_sample.sample(problem.salib, trajectories, num_levels=levels, seed=seed))

    def indices(self, problem, design, y, failed, levels, resamples, confidence, seed):
        """``mu_star`` with its bootstrap interval, ``mu`` and ``sigma``; trajectories with a missing value are left
        out and counted; an output with fewer than two complete trajectories has no indices (NaN)."""
        y, failed = np.asarray(y, float), np.asarray(failed, bool)
        X = design[list(problem.names)].to_numpy()
        k = len(problem.names)
        used = complete_blocks(y, k + 1)
        counts = sample_counts(y, used, failed)
        if used.sum() < 2 * (k + 1):
            return self.rows(problem, {n: [(np.nan, np.nan)] * k for n in ("mu_star", "mu", "sigma")}, counts)
        res = morris_analyze.analyze(
            problem.salib,
            X[used],
            y[used],
            num_resamples=resamples,
            conf_level=confidence,
            num_levels=levels,
            seed=seed,
        )
        none = np.full(k, np.nan)  # mu and sigma: no interval
        indices = dict(
            mu_star=list(zip(res["mu_star"], res["mu_star_conf"])),
            mu=list(zip(res["mu"], none)),
            sigma=list(zip(res["sigma"], none)),
        )
        return self.rows(problem, indices, counts)

    def influence(self, indices: pd.DataFrame) -> pd.DataFrame:
        """Its ``mu*`` rows of an index table: how it ranks the inputs."""
        return indices[(indices.method == self.name) & (indices["index"] == "mu_star")]

    def most_influential(self, indices: pd.DataFrame, count: int) -> list[str]:
        """The ``count`` inputs with the largest ``mu*`` relative to the largest of their output: ranked by the
        maximum of that ratio over outputs and charge laws (an input that leads any one output first), ties by its
        mean (the breadth of its influence), then by the inputs' order."""
        m = self.influence(indices).copy()
        top = m.groupby(["charge_law", "output"]).value.transform("max")
        m["relative"] = (m.value / top).where(top > 0)
        order = list(dict.fromkeys(m.input))
        by_input = m.groupby("input", sort=False).relative
        best, breadth = by_input.max().reindex(order).fillna(-1.0), by_input.mean().reindex(order).fillna(-1.0)
        ranked = sorted(order, key=lambda n: (-best[n], -breadth[n], order.index(n)))
        return ranked[:count]


class Sobol(SensitivityMethod):
    """Sobol first-order and total indices (Sobol 1993; Saltelli 2002, 2010) of the ``inputs`` inputs its screening
    method ranks highest (:meth:`Morris.most_influential`)."""

    def check(self, config, key: str) -> None:
        """Its settings, and no more ``inputs`` than the study has."""
        super().check(config, key)
        se = config["sensitivity"]
        count = se["methods"][self.name]["inputs"]
        if count > len(se["inputs"]):
            raise ValueError(
                f"sensitivity.methods.{self.name}.inputs = {count} exceeds the number of inputs ({len(se['inputs'])})"
            )

    def size(self, k, inputs, base_samples, **design):
        """``base_samples (inputs + 2)`` samples."""
        return base_samples * (inputs + 2)

    def design(self, problem, inputs, base_samples, seed, screening=None):
        """Saltelli's scheme for S1 and ST (scrambled Sobol' sequence, SALib) over the ``inputs`` inputs that
        ``screening`` ranks highest (every input without it)."""
        if screening is not None:
            problem = problem.subset(SENSITIVITY_METHODS[self.screening].most_influential(screening, inputs))
        return problem.design(sobol_sample.sample(problem.salib, base_samples, calc_second_order=False, seed=seed))

    def indices(self, problem, design, y, failed, resamples, confidence, seed):
        """``S1`` and ``ST`` with bootstrap intervals; base rows with a missing value are left out and counted; a
        constant output has no indices (NaN)."""
        y, failed = np.asarray(y, float), np.asarray(failed, bool)
        k = len(problem.names)
        used = complete_blocks(y, k + 2)
        counts = sample_counts(y, used, failed)
        if used.sum() < 2 * (k + 2) or np.ptp(y[used]) == 0.0:
            return self.rows(problem, {n: [(np.nan, np.nan)] * k for n in ("S1", "ST")}, counts)
        res = sobol_analyze.analyze(
            problem.salib, y[used], calc_second_order=False, num_resamples=resamples, conf_level=confidence, seed=seed
        )
        indices = dict(S1=list(zip(res["S1"], res["S1_conf"])), ST=list(zip(res["ST"], res["ST_conf"])))
        return self.rows(problem, indices, counts)


MORRIS = Morris(
    "morris", "Morris", ("trajectories", "levels", "seed"), ("levels", "resamples", "confidence", "seed"), paper=True
)
SOBOL = Sobol("sobol", "Sobol", ("inputs", "base_samples", "seed"), ("resamples", "confidence", "seed"), MORRIS.name)
#: the registry of sensitivity methods, by name (wildcard ``{method}``; in the order of the figure's columns)
SENSITIVITY_METHODS: Registry[SensitivityMethod] = Registry("sensitivity method", (MORRIS, SOBOL))


def indices_table(
    method: str, design: pd.DataFrame, samples: pd.DataFrame, ranges: dict, outputs, settings: dict, log=None
):
    """The indices of the method ``method`` (a name of :data:`SENSITIVITY_METHODS`) of every output of ``outputs``
    under every charge law, in one tidy table (``method``, ``charge_law``, ``output``, ``input``,
    :data:`INDEX_COLUMNS`): ``samples`` are the rows of the ``design`` with their outputs (a column ``charge_law``,
    and ``status``, ``ok`` where the run succeeded), ``ranges`` the inputs' ranges (:meth:`Problem.from_ranges`) and
    ``settings`` those its indices read. A missing output (a failed run) is NaN in its samples."""
    by = SENSITIVITY_METHODS.lookup(method)
    names = [c for c in design.columns if c != "sample"]
    problem, rows = Problem.from_ranges(ranges).subset(names), []
    for law, table in samples.groupby("charge_law", sort=False):
        table = design[["sample"]].merge(table, on="sample", how="left")  # every sample of the design, in its order
        failed = (table.status != "ok").to_numpy()
        for output in outputs:
            y = table[output].to_numpy(dtype=float) if output in table else np.full(len(table), np.nan)
            found = by.indices(problem, design, y, failed, **settings)
            rows += [dict(charge_law=law, output=output, **r) for r in found]
            if log is not None:
                log.info(
                    "[sensitivity_%s] %s, %s: %d of %d samples used, %d failed",
                    *(method, law, output, found[0]["samples_used"], len(table), found[0]["samples_failed"]),
                )
    return pd.DataFrame(rows)[["method", "charge_law", "output", "input"] + INDEX_COLUMNS]
