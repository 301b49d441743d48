"""Onset criteria of the damage law (eq. 2.28): the radial Cauchy stress a damage candidate compares with sigma_cr.

A criterion is an :class:`OnsetCriterion` (a :class:`sphgag.registry.Variant`) of the registry :data:`CRITERIA`. The
configuration's schema (``delamination.criteria``, :func:`sphgag.config.schema`) and the pipeline's wildcard
``{criterion}`` are built from the registry, so a new criterion is one function and one entry here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..engine import measure
from ..engine.history import ParticleHistory
from ..engine.model import Evaluation, Model
from ..registry import Registry, Variant


@dataclass(frozen=True)
class OnsetCriterion(Variant):
    """``measure(model, ev, history, candidates, settings)``: the radial Cauchy stress (eq. 2.10, current polar
    frame) at the ``candidates`` that the onset test of eq. (2.28) compares with sigma_cr (``settings``: the run's
    :class:`sphgag.studies.delamination.settings.Settings`). ``title``: what the measure is; ``paper``: the paper's
    measure. ``averages``: the measure averages over ``settings.averaging_length_um``, a key the criterion then owns
    (:meth:`check`: that length at least the coarsest particle spacing it is run at)."""

    name: str
    title: str
    measure: Callable[[Model, Evaluation, ParticleHistory, np.ndarray, object], np.ndarray]
    averages: bool = False
    paper: bool = False

    @property
    def keys(self) -> tuple[str, ...]:
        return ("delamination.averaging_length_um",) if self.averages else ()

    def check(self, config, key: str) -> None:
        """An averaging criterion averages over more than one particle at the coarsest spacing it is run at (the
        wall's ``bilayer.dx_um`` and ``delamination.convergence.dx_um``)."""
        if not self.averages:
            return
        de = config["delamination"]
        coarsest = max([config.get("bilayer", {}).get("dx_um", 0)] + de["convergence"]["dx_um"])
        if de["averaging_length_um"] < coarsest:
            raise ValueError(
                f"delamination.averaging_length_um = {de['averaging_length_um']} is below the coarsest "
                f"particle spacing ({coarsest:g} um): the average of {self.name} would be a single particle's value"
            )


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


#: the registry of onset criteria, by name (``delamination.criteria``, wildcard ``{criterion}``; the paper's first)
CRITERIA: Registry[OnsetCriterion] = Registry(
    "onset criterion",
    (
        OnsetCriterion(
            "particle", "the candidate particle's own radial stress (the paper's)", particle_stress, paper=True
        ),
        OnsetCriterion(
            "averaged",
            "the intact media's radial stress averaged over a disc of averaging_length_um",
            averaged_stress,
            averages=True,
        ),
    ),
)
