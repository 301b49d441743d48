"""Runs that end at their last equilibrium: an interim wrapper of the pool protocols (issue 15, items 2-3).

Under the prescribed charge law (``gag.charge_laws``) a step of the concentration ramp can have no
equilibrium: the pools swell many-fold, and past some concentration the solver finds no converged state
(a limit point of the pool's pressure-volume path, or a failure of the discretisation; issue 15). Today
:func:`sphgag.protocols.swell_pool` and :func:`sphgag.delamination.grow` raise
:class:`sphgag.solver.NotConverged` there, and the job fails. Until they return their converged states
with an end reason themselves, these wrappers catch that failure at a concentration step, run the
protocol again up to the last concentration below it (the same deterministic path from a fresh
factorisation: the same states), and return the reason, which the workflow scripts record. A run that
fails before its first concentration (seeding, conversion) still fails, and a run that converges is
returned exactly as the protocol returns it (the wrapper calls it once, with the configured settings).

No state beyond the last equilibrium is ever reported: the tables simply end there.
"""

from __future__ import annotations

import dataclasses
import logging

import numpy as np
import pandas as pd

from . import convergence, delamination, protocols, solver

log = logging.getLogger("sphgag")


def failed_concentration(exc: solver.SimulationError) -> float:
    """The GAG concentration [mEq/l] of the load at which ``exc`` found no equilibrium (0 without one)."""
    return float(exc.load.material_value("concentration", 0.0)) if exc.load is not None else 0.0


def reason(c: float) -> str:
    """The end reason of a run whose concentration ramp found no equilibrium at ``c``."""
    return f"no equilibrium at c = {c:.4g} mEq/l"


def _below(levels, c: float) -> np.ndarray:
    """The concentration levels strictly below ``c`` (those the failed run had reached)."""
    levels = np.asarray(levels, dtype=float)
    return levels[levels < c - 1e-9]


def swell_pool(model, start: solver.State, numerics: dict, sw: dict) -> tuple[list[protocols.PoolState], str]:
    """:func:`sphgag.protocols.swell_pool` and its end: ``"max concentration"``, or :func:`reason` with the states up
    to the last converged concentration of the ramp."""
    try:
        return protocols.swell_pool(model, start, numerics, sw), "max concentration"
    except solver.NotConverged as exc:
        c = failed_concentration(exc)
        levels = _below(np.linspace(0.0, sw["max_concentration_mEq_l"], sw["concentration_points"]), c)
        if levels.size < 2:  # not even the first concentration above 0: a failure, not an end
            raise
        log.warning("[%s] %s: the run ends at %g mEq/l, its last converged state", model.name, reason(c), levels[-1])
        model.factorisation = None
        short = dict(sw, max_concentration_mEq_l=float(levels[-1]), concentration_points=int(levels.size))
        return protocols.swell_pool(model, start, numerics, short), reason(c)


def swell_cases(dx, bilayer, numerics, homeostasis, swelling, gag, cases, pressure, name) -> tuple[dict, dict]:
    """:func:`sphgag.convergence.swell_cases` and each case's end (:func:`swell_pool`); after a failure, every case
    runs on its own (from the same pressurised wall, rebuilt)."""
    try:
        states = convergence.swell_cases(dx, bilayer, numerics, homeostasis, swelling, gag, cases, pressure, name=name)
        return states, dict.fromkeys(cases, "max concentration")
    except solver.NotConverged:
        states, ends = {}, {}
        for case, entry in cases.items():
            try:
                one = convergence.swell_cases(
                    dx, bilayer, numerics, homeostasis, swelling, gag, {case: entry}, pressure, name=name
                )
                states[case], ends[case] = one[case], "max concentration"
            except solver.NotConverged as exc:
                c = failed_concentration(exc)
                levels = _below(
                    np.linspace(0.0, swelling["max_concentration_mEq_l"], swelling["concentration_points"]), c
                )
                if levels.size < 2:
                    raise
                short = dict(swelling, max_concentration_mEq_l=float(levels[-1]), concentration_points=int(levels.size))
                log.warning("[%s] case %s: %s: the run ends at %g mEq/l", name, case, reason(c), levels[-1])
                one = convergence.swell_cases(
                    dx, bilayer, numerics, homeostasis, short, gag, {case: entry}, pressure, name=name
                )
                states[case], ends[case] = one[case], reason(c)
        return states, ends


def grow(model, start, sectors, settings: delamination.Settings, numerics, gag, base, **kwargs):
    """:func:`sphgag.delamination.grow`; if a step of its concentration ramp has no equilibrium, the run again up to the
    last level below it, with :func:`reason` as its ``stop``."""
    try:
        return delamination.grow(model, start, sectors, settings, numerics, gag, base, **kwargs)
    except solver.NotConverged as exc:
        c = failed_concentration(exc)
        levels = _below(settings.levels, c)
        if not levels.size:
            raise
        log.warning("[%s] %s: the run ends at %g mEq/l, its last converged level", model.name, reason(c), levels[-1])
        model.factorisation = None
        short = dataclasses.replace(settings, max_concentration_mEq_l=float(levels[-1]))
        result = delamination.grow(model, start, sectors, short, numerics, gag, base, **kwargs)
        result.summary["stop"] = reason(c)
        return result


def convergence_study(dx, bilayer, numerics, homeostasis, de: dict, gag, name) -> pd.DataFrame:
    """:func:`sphgag.delamination.convergence_study`; after a failure, every onset criterion runs on its own and one
    whose concentration ramp has no equilibrium ends at its last level below it (``stop``: :func:`reason`)."""
    try:
        return delamination.convergence_study(dx, bilayer, numerics, homeostasis, de, gag, name=name)
    except solver.NotConverged:
        rows = []
        for criterion in de["criteria"]:
            one = dict(de, criteria=[criterion])
            try:
                rows.append(delamination.convergence_study(dx, bilayer, numerics, homeostasis, one, gag, name=name))
            except solver.NotConverged as exc:
                c = failed_concentration(exc)
                settings = delamination.Settings.from_config(de, de["critical_stress_kPa"], criterion)
                levels = _below(settings.levels, c)
                if not levels.size:
                    raise
                log.warning("[%s] %s onset: %s: the run ends at %g mEq/l", name, criterion, reason(c), levels[-1])
                short = dict(one, max_concentration_mEq_l=float(levels[-1]))
                table = delamination.convergence_study(dx, bilayer, numerics, homeostasis, short, gag, name=name)
                rows.append(table.assign(stop=reason(c)))
        return pd.concat(rows, ignore_index=True)
