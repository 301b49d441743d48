"""Onset criteria of the damage law (eq. 2.28): the radial Cauchy stress a damage candidate compares with sigma_cr.

A criterion is an :class:`OnsetCriterion` of the registry :data:`CRITERIA`. The configuration's schema
(``delamination.criteria``, :func:`sphgag.config.schema`) and the pipeline's wildcard ``{criterion}`` are built from
the registry, so a new criterion is one function and one entry here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..engine import measure
from ..engine.history import ParticleHistory
from ..engine.model import Evaluation, Model


@dataclass(frozen=True)
class OnsetCriterion:
    """``measure(model, ev, history, candidates, settings)``: the radial Cauchy stress (eq. 2.10, current polar
    frame) at the ``candidates`` that the onset test of eq. (2.28) compares with sigma_cr (``settings``: the run's
    :class:`sphgag.studies.delamination.settings.Settings`). ``averages``: the measure averages over
    ``settings.averaging_length_um`` (the configuration then asks that length to exceed the particle spacing)."""

    name: str
    description: str
    measure: Callable[[Model, Evaluation, ParticleHistory, np.ndarray, object], np.ndarray]
    averages: bool = False


def particle_stress(model: Model, ev: Evaluation, hist: ParticleHistory, cand: np.ndarray, settings) -> np.ndarray:
    """The candidate particle's own radial stress (the paper's measure)."""
    return measure.cauchy_polar(ev)[0][cand]


def averaged_stress(model: Model, ev: Evaluation, hist: ParticleHistory, cand: np.ndarray, settings) -> np.ndarray:
    """The radial stress of the intact pool layers (the media) averaged over a disc of diameter
    ``settings.averaging_length_um`` around the candidate (:func:`sphgag.engine.measure.averaging_matrix`): the same
    length at every resolution."""
    lay = model.layout
    intact = np.flatnonzero(lay.pool_mask & ~hist.gag)
    W = measure.averaging_matrix(lay, settings.averaging_length_um, intact, rows=cand)
    return W @ measure.cauchy_polar(ev)[0]


CRITERIA = {
    c.name: c
    for c in (
        OnsetCriterion("particle", "the candidate particle's own radial stress (the paper's)", particle_stress),
        OnsetCriterion(
            "averaged",
            "the intact media's radial stress averaged over a disc of averaging_length_um",
            averaged_stress,
            averages=True,
        ),
    )
}
