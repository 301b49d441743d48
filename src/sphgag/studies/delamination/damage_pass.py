"""One damage pass of eq. (2.28) on a converged state (section 2.7): the onset measure at the candidates, the intact
energy density, the damage state it makes, and the ruptured candidates become GAG particles of their pools. The
quasi-static growth (:mod:`.growth`) and the authors' explicit procedure (:mod:`sphgag.studies.paper_procedure`)
take their passes with it."""

from __future__ import annotations

import numpy as np

from ...engine import forces
from ...engine.history import HistoryMaterial, ParticleHistory
from ...engine.model import Model
from ...physics import damage
from ..onset import CRITERIA
from .front import Front
from .settings import Settings


def onset_measure(model: Model, ev, hist: ParticleHistory, cand: np.ndarray, settings: Settings) -> np.ndarray:
    """The radial Cauchy stress (eq. 2.10, current polar frame) the onset test of eq. (2.28) compares with sigma_cr,
    at the candidates, by the run's onset criterion (:data:`sphgag.studies.onset.CRITERIA`)."""
    return CRITERIA[settings.criterion].measure(model, ev, hist, cand, settings)


def intact_energy(model: Model, ev, base_props: np.ndarray) -> np.ndarray:
    """``W_0`` (eq. 2.23) of every particle with the undamaged material, at the state ``ev``."""
    W = np.empty(model.n)
    forces.energy_densities(ev.F, ev.load.axial_stretch, model.cth, model.sth, base_props, W)
    return W


def damage_step(model: Model, front: Front, settings: Settings, material: HistoryMaterial, ev, found):
    """The damage state (eq. 2.28) that the state ``ev`` makes from the history of ``material``, and the intact energy
    density ``W_0`` (eq. 2.23) of every particle there. ``found``: ``(candidates, their pools, their onset
    measures)``. Only candidates start to damage; GAG particles keep their ``D``."""
    hist, lay = material.history, model.layout
    cand, pools, sigma = found
    dmg = damage.DamageState(hist.D.copy(), hist.onset_stretch.copy(), hist.onset_energy.copy())
    radial = np.full(lay.n, -np.inf)
    radial[cand] = sigma
    W0 = intact_energy(model, ev, material.base(ev.load))
    band = np.full(lay.n, np.nan)
    band[cand] = front.thickness[pools]  # the band a pool's growth converts: its radial extent
    dmg.update(settings.law, cand, radial, damage.radial_stretch(ev.F, lay.theta), W0, band)
    dmg.D[hist.gag] = hist.D[hist.gag]
    return dmg, W0


def with_ruptures(hist: ParticleHistory, ruptured: np.ndarray, cand: np.ndarray, pools: np.ndarray, step: int):
    """``hist`` with the candidates ``ruptured`` become GAG particles of their pools (``pools``, per candidate) at
    damage pass ``step`` (section 2.7)."""
    if not ruptured.size:
        return hist
    owner = np.full(hist.n, -1)
    owner[cand] = pools
    return hist.rupture(ruptured, owner[ruptured], step)
