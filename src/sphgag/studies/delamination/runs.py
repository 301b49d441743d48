"""The pipeline's delamination runs (figures 5-7 and the delamination map): one pool set seeded in the pressurised
passive wall and grown by damage (eq. 2.28 as printed, or the damage law with a fracture energy G_c), as the tables of
``results/delamination`` label it, and one point of the delamination map (:func:`.tables.level_classes`)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pandas as pd

from ...physics import damage
from .. import artery
from .growth import grow, seeded_only
from .settings import MATCHED, Settings
from .tables import griffith, labelled, level_classes


def fracture_energy(gc: str | None, matched: str | None = None, log=None, run: str = "") -> tuple[float | None, str]:
    """The G_c [J/m^2] of a run and why it has none: ``gc`` is its wildcard (None: eq. 2.28 as printed, no G_c; a
    number; or :data:`.settings.MATCHED`: the energy the paper's law dissipated in the run whose summary table is
    ``matched``, NaN with the reason where that run grew nothing)."""
    if gc != MATCHED:
        return (None if gc is None else float(gc)), ""
    energy = float(pd.read_csv(matched).dissipated_energy_J_m2.iloc[0])
    if not energy > 0.0:  # NaN: the paper's run grew nothing
        return np.nan, f"no G_c to match: the paper's law dissipated no energy in {matched} (no growth)"
    if log is not None:
        log.info("[%s] G_c = %.4g J/m^2: the energy the paper's law dissipates (%s)", run, energy, matched)
    return energy, ""


def crack_modulus(bilayer: dict, sector) -> float:
    """E' = 4 phi_e mu_e [kPa]: the plane-strain modulus of the elastin matrix of the layer the pool ``sector`` lies
    in (the pool as a pressurised crack, :func:`.tables.griffith`)."""
    layer = artery.layer_at(bilayer, sector.centre_radius)
    return 4.0 * bilayer["mass_fractions"][layer]["elastin"] * bilayer["elastin_shear_modulus_kPa"]


def delaminate(model, start, sectors, settings: Settings, state: dict, gag: dict, case: str, unmatched="", run=None):
    """One run of the pool set ``case`` (its ``sectors``) from the pressurised state ``start`` of the wall ``model``
    (made with the configuration slice ``state``): grown by ``settings``, or, where its G_c could not be matched
    (``unmatched``, the reason), seeded only. Returns its labelled growth and summary tables (the charge law first;
    a run with a G_c beside Griffith's closed form) and its :class:`.tables.Result`."""
    numerics, bilayer = state["numerics"], state["bilayer"]
    if unmatched:
        paper = damage.DAMAGE_LAWS.paper.name
        seeding = dataclasses.replace(settings, damage_law=paper, fracture_energy_J_m2=np.nan)
        result = seeded_only(model, start, sectors, seeding, numerics, gag, model.props, unmatched, run=run)
    else:
        result = grow(model, start, sectors, settings, numerics, gag, model.props, run=run)
    growth, summary = labelled(result, case, settings, bilayer["dx_um"])
    if damage.FRACTURE_ENERGY in damage.DAMAGE_LAWS[settings.damage_law].keys:  # a G_c (NaN if unmatched): a crack
        modulus = crack_modulus(bilayer, sectors[0])
        closed = griffith(sectors, settings.fracture_energy_J_m2, modulus, gag, settings.max_concentration_mEq_l)
        summary = summary.assign(plane_strain_modulus_kPa=modulus, **closed)
    growth.insert(0, "charge_law", gag["charge_law"])
    summary.insert(0, "charge_law", gag["charge_law"])
    return growth, summary, result


def map_point(model, start, sector, settings: Settings, numerics: dict, gag: dict, width: float, run=None):
    """One point of the delamination map: the pool ``sector`` (``width`` degrees) grown over the ramp by ``settings``
    from ``start``; what it does at each level, labelled by charge law, angular extent and sigma_cr, with how its run
    ended. Returns the table and the run's summary."""
    result = grow(model, start, [sector], settings, numerics, gag, model.props, run=run)
    table = level_classes(result.growth, result.summary, settings.levels)
    table.insert(0, "charge_law", gag["charge_law"])
    table.insert(1, "angular_extent_deg", width)
    table.insert(2, "sigma_cr_kPa", settings.critical_stress_kPa)
    s = result.summary
    ended = ("onset_concentration_mEq_l", "stop_level_mEq_l", "stop_kind", "stop", "max_residual")
    return table.assign(**{k: s[k] for k in ended}), s
