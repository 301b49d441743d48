"""One GAG pool's response to the model's inputs: the sample of the sensitivity study.

A *scenario* is everything one response depends on, as the pipeline's own configuration slices (so that a scenario at
its nominal values reruns exactly the pipeline's runs): ``bilayer``, ``numerics``, ``homeostasis`` (figure 2b),
``gag`` (one charge law, eqs. 2.25-2.27), ``swelling`` (the figure 4 protocol), ``delamination`` (section 2.7: its
``pressure_mmHg`` is the lumen pressure of both protocols, its ``critical_stress_kPa`` sigma_cr of eq. 2.28), the
``pool`` (a medial sector), the onset ``criterion``, the ``concentration_mEq_l`` at which the figure 4 quantities are
read, the ``probe_length_um`` they are measured over, and the ``pool_set`` name that labels the delamination rows.
An *input* is a dotted path into it, e.g.
``gag.shear_modulus_kPa`` or ``pool.angular_extent_deg`` (:func:`perturbed`).

:func:`respond` runs, for one scenario, what the pipeline runs for figure 4 and figure 5 with fresh models at each
stage, as the pipeline's jobs do: the homeostatic state (rule ``homeostasis``), pressure control to the lumen
pressure (rule ``bilayer_pressure_diameter``), the pool converted and swollen up to the stated concentration (rules
``swell`` and ``pool_stresses``: the same concentration steps), and the pool grown by damage (rule ``delaminate``).
:func:`outputs` reads the study's outputs from it.
"""

from __future__ import annotations

import copy
import functools
import logging
import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pandas as pd

from ..engine import solver
from ..engine.numerics import Numerics
from ..options import Options, key_text
from . import artery
from .delamination.growth import grow
from .delamination.settings import Settings
from .delamination.tables import labelled
from .pool_swelling import concentration_steps, pool_table, swell_pool
from .wall_loading import homeostasis, pressurise

log = logging.getLogger("sphgag")

#: the figure 4 quantities at the stated concentration (``pool_table`` columns; eqs. 2.10, 2.27)
SWELLING_OUTPUTS = ("tip_radial_stress_kPa", "top_circ_stress_kPa", "pool_volume_change")
#: the delamination quantities (section 2.7)
DELAMINATION_OUTPUTS = ("onset_concentration_mEq_l", "runaway_concentration_mEq_l", "final_length_um", "propagated")
OUTPUTS = SWELLING_OUTPUTS + DELAMINATION_OUTPUTS


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
    """The ``sensitivity`` configuration section: figure 5's pool rerun (:func:`respond`) with the ``inputs``
    (dotted paths into its scenario, uniform on ``[low, high]``) sampled, figure 4's quantities read at
    ``concentration_mEq_l``, ``batch_size`` samples per job; the ``methods`` run, each by its name with its settings
    (:data:`sphgag.studies.sensitivity.SENSITIVITY_METHODS`, whose checks vouch for them), and the map of figure 5's
    pool (:class:`DelaminationMap`)."""

    SECTION = "sensitivity"

    concentration_mEq_l: float
    batch_size: int
    inputs: Mapping
    methods: Mapping
    map: DelaminationMap

    #: the sections an input may set (``pool``: figure 5's pool)
    INPUT_SECTIONS: ClassVar[tuple] = ("bilayer", "numerics", "homeostasis", "gag", "delamination", "pool")

    @staticmethod
    def config_key(config: Mapping, path: str) -> tuple:
        """The configuration key a sensitivity input (a dotted path into the scenario, :func:`perturbed`) sets:
        ``pool.*`` is figure 5's pool (the first of ``delamination.figures.fig5``'s set), the other sections are the
        configuration's own."""
        section, *rest = path.split(".")
        if section == "pool":
            return ("delamination", "pool_sets", config["delamination"]["figures"]["fig5"], 0, *rest)
        return (section, *rest)

    @classmethod
    def input_problems(cls, config: Mapping, schema_node: Callable[[tuple], Mapping]) -> list[str]:
        """Every input names a number of the configuration that a sample may set (:data:`INPUT_SECTIONS`), and its
        range lies inside that key's own allowed range (its node of the schema, ``schema_node(key)``; for the pool,
        inside the media and away from the symmetry edges); the stated concentration is a step of the swelling ramp;
        (a method's own settings are its check's). The inputs refer to keys the other sections' checks vouch for
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
        de, bil = config["delamination"], artery.Bilayer.of(config["bilayer"])
        pool = de["pool_sets"][de["figures"]["fig5"]][0]
        radius = se["inputs"].get("pool.centre_radius_um", {})
        for end in ("low", "high"):
            if end in radius:
                lo, hi = artery.Pool.of(dict(pool, centre_radius_um=radius[end])).radii()
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
            first, last = artery.Pool.of(dict(pool, angular_extent_deg=w)).angles()
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
        return out


def _node(scenario: dict, path: str):
    *parents, leaf = path.split(".")
    node = scenario
    for part in parents:
        if not isinstance(node, dict) or part not in node:
            raise KeyError(f"input {path!r}: no {part!r} in the scenario")
        node = node[part]
    if not isinstance(node, dict) or leaf not in node or isinstance(node[leaf], (dict, list)):
        raise KeyError(f"input {path!r} is not a number of the scenario")
    return node, leaf


def check_inputs(scenario: dict, paths) -> None:
    """Raise ``KeyError`` naming every path of ``paths`` that is not a number of ``scenario``."""
    bad = []
    for path in paths:
        try:
            _node(scenario, path)
        except KeyError as exc:
            bad.append(exc.args[0])
    if bad:
        raise KeyError("; ".join(bad))


def nominal(scenario: dict, path: str) -> float:
    """The scenario's own value of the input ``path``."""
    node, leaf = _node(scenario, path)
    return float(node[leaf])


def perturbed(scenario: dict, inputs: dict) -> dict:
    """A copy of ``scenario`` with every ``{dotted path: value}`` of ``inputs`` set.

    The pool moves with the particle grid: a change of ``pool.centre_radius_um`` shifts the media's
    ``bilayer.aligned_radii_um`` (the cell boundaries the pool's radial edges sit on) by the same amount, so that
    the pool keeps its thickness in particles wherever it is (as the nominal pool does).
    """
    out = copy.deepcopy(scenario)
    for path, value in inputs.items():
        node, leaf = _node(out, path)
        node[leaf] = float(value)
    shift = out["pool"]["centre_radius_um"] - scenario["pool"]["centre_radius_um"]
    if shift:
        out["bilayer"]["aligned_radii_um"] = [r + shift for r in scenario["bilayer"]["aligned_radii_um"]]
    return out


def swelling_settings(scenario: dict) -> dict:
    """The figure 4 settings cut at the stated concentration, on the same concentration steps
    (:func:`sphgag.studies.pool_swelling.concentration_steps`, which it must be one of), so that the path up to it is
    the pipeline's."""
    sw, c = scenario["swelling"], scenario["concentration_mEq_l"]
    steps = concentration_steps(sw)
    at = np.flatnonzero(np.isclose(steps, c, rtol=1e-9, atol=0.0))
    if not at.size:
        raise ValueError(
            f"the stated concentration {c:g} mEq/l is not a step of the swelling ramp (0 to "
            f"{sw['max_concentration_mEq_l']:g} in {sw['concentration_points']} points)"
        )
    return dict(sw, max_concentration_mEq_l=float(steps[at[0]]), concentration_points=int(at[0]) + 2)


@dataclass
class Response:
    """The pool's swelling table (:func:`sphgag.studies.pool_swelling.pool_table`) and its delamination run's
    ``(growth, summary)`` (:func:`sphgag.studies.delamination.tables.labelled`), with its scenario."""

    scenario: dict
    swelling: pd.DataFrame
    growth: pd.DataFrame
    summary: pd.DataFrame


def pressurised(scenario: dict, numerics: Numerics, name: str) -> solver.State:
    """The passive homeostatic state (figure 2b) moved to the lumen pressure under pressure control."""
    s = scenario
    wall = artery.bilayer_model(s["bilayer"], numerics, name=name)
    h = homeostasis(wall, numerics, s["homeostasis"])
    wall = artery.bilayer_model(s["bilayer"], numerics, name=name)  # a fresh model, as the pipeline's next job
    start = solver.State(h.state.load, h.state.x, wall.evaluate(h.state.x, h.state.load), None)
    return pressurise(wall, start, s["delamination"]["pressure_mmHg"], numerics)


def respond(scenario: dict, name: str = "pool_response") -> Response:
    """Figure 4's swelling and figure 5's growth of the scenario's pool, each from the pressurised wall
    (:func:`pressurised`) as a saved state: positions and load only."""
    s = scenario
    bl, numerics, gag, de = s["bilayer"], Numerics.of(s["numerics"]), s["gag"], s["delamination"]
    wall = pressurised(s, numerics, name)
    start = solver.State(wall.load, wall.x, None, None)
    pool = artery.pool_sector(s["pool"])
    model = artery.bilayer_model(bl, numerics, name=f"{name}_swell", pool=pool, gag=gag)
    states = swell_pool(model, start, numerics, swelling_settings(s))
    swelling = pool_table(model, states, pool, s["probe_length_um"], gag)
    settings = Settings.at_section(de, s["criterion"])
    model = artery.bilayer_model(bl, numerics, name=f"{name}_delaminate")
    result = grow(model, start, [pool], settings, numerics, gag, model.props, run=f"{name}_delaminate")
    growth, summary = labelled(result, s["pool_set"], settings, bl["dx_um"])
    return Response(s, swelling, growth, summary)


def outputs(response: Response) -> dict:
    """The study's outputs of one response.

    * the figure 4 quantities at the stated concentration (NaN where the swelling path ended before it: a limit
      point or no equilibrium, named in ``swelling_end``);
    * the onset and runaway concentrations (bisected between levels), each censored at one step above the ramp where
      the event never happened (``onset_censored``, ``runaway_censored``);
    * the delaminated length up to the run's last equilibrium, and ``propagated`` (1: the run ended growing or
      merged, i.e. the pool did not arrest; 0 otherwise).
    """
    s, sw = response.scenario, response.swelling
    de = s["delamination"]
    at = sw[(sw.stage == "converted") & (np.abs(sw.concentration_mEq_l - s["concentration_mEq_l"]) < 1e-9)]
    row = {k: (float(at[k].iloc[0]) if len(at) else np.nan) for k in SWELLING_OUTPUTS}
    summary = response.summary.iloc[0]
    onset, runaway = float(summary.onset_concentration_mEq_l), float(summary.runaway_concentration_mEq_l)
    censored = bool(np.isnan(onset))
    beyond = de["max_concentration_mEq_l"] + de["concentration_step_mEq_l"]
    row.update(
        onset_concentration_mEq_l=beyond if censored else onset,
        runaway_concentration_mEq_l=beyond if np.isnan(runaway) else runaway,
        final_length_um=float(summary.final_length_um),
        propagated=float(summary.outcome in ("grows", "merges")),
        swelling_end=str(sw.path_end.iloc[-1]),
        delamination_stop=str(summary.stop),
        outcome=str(summary.outcome),
        onset_censored=censored,
        runaway_censored=bool(np.isnan(runaway)),
        delamination_stop_kind=str(summary.stop_kind),
        max_residual=float(max(sw.residual.max(), summary.max_residual)),
    )
    return row


def evaluate(scenario: dict, name: str):
    """``inputs -> outputs`` of :func:`sample_rows` for ``scenario``."""

    def run(inputs: dict) -> dict:
        return outputs(respond(perturbed(scenario, inputs), name))

    return run


def sample_rows(design: pd.DataFrame, names, evaluate, failure=Exception, label: str = "") -> pd.DataFrame:
    """Outputs of ``evaluate({name: value}) -> {output: value}`` on every row of ``design``, one row each with
    ``status`` (``ok`` or ``failed``) and ``error``; a row whose evaluation raises ``failure`` keeps its inputs, has
    no outputs and names the error (anything else propagates: a bug is not a failed sample)."""
    rows = []
    for k, row in enumerate(design.to_dict(orient="records")):
        inputs = {n: float(row[n]) for n in names}
        started = time.time()
        try:
            outputs, status, error = evaluate(inputs), "ok", ""
        except failure as exc:
            outputs, status, error = {}, "failed", f"{type(exc).__name__}: {exc}"
            log.warning("[%s] sample %d failed at %s: %s", label, row["sample"], inputs, error)
        rows.append(dict(sample=int(row["sample"]), **inputs, status=status, error=error, **outputs))
        log.info(
            "[%s] sample %d (%d of %d): %s in %.1f s",
            label,
            row["sample"],
            k + 1,
            len(design),
            status,
            time.time() - started,
        )
    return pd.DataFrame(rows)


def failures(samples: pd.DataFrame) -> pd.DataFrame:
    """The samples of ``samples`` (rows of :func:`sample_rows`) without every output of :data:`OUTPUTS`: a failed run,
    or an output undefined there (e.g. no equilibrium at the stated concentration), by their inputs, each naming the
    outputs it misses (``missing_outputs``, beside its ``status``)."""
    missing = samples[list(OUTPUTS)].isna()
    table = samples[(samples.status != "ok") | missing.any(axis=1)].copy()
    named = [" ".join(o for o in OUTPUTS if missing.loc[i, o]) for i in table.index]
    table.insert(table.columns.get_loc("status") + 1, "missing_outputs", named)
    return table
