"""The pipeline's delamination runs (figures 5-7): one pool set seeded in the pressurised passive wall and grown by
damage (eq. 2.28 as printed, or the damage law with a fracture energy G_c), as the tables of ``results/delamination``
label it (:func:`delaminate`), and its snapshots on disk (:func:`save_snapshots`): the particle states it keeps
(positions, load, particle history) with their radial stress, in one ``results/delamination/runs/{law}/*_snapshots.npz``
per run; each one can restart the run (:func:`sphgag.studies.delamination.growth.grow` with ``resume``)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pandas as pd

from ...engine import measure, solver
from ...engine.model import Model
from ...engine.numerics import Numerics
from ...physics import damage
from ...records import state as state_io
from .. import artery
from .growth import grow, seeded_only
from .settings import MATCHED, Settings
from .tables import griffith, labelled


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


def delaminate(
    model, start, sectors, settings: Settings, numerics: Numerics, bilayer: dict, gag, case, unmatched="", run=None
):
    """One run of the pool set ``case`` (its ``sectors``) from the pressurised state ``start`` of the wall ``model``
    (made with the sections ``bilayer`` and ``numerics``): grown by ``settings``, or, where its G_c could not be matched
    (``unmatched``, the reason), seeded only. Returns its labelled growth and summary tables (the charge law first;
    a run with a G_c beside Griffith's closed form) and its :class:`.tables.Result`."""
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


def save_snapshots(path, model: Model, snapshots, params: dict) -> None:
    """All snapshots of a run in one ``.npz`` (:func:`sphgag.records.state.save_series`: positions, load, particle
    history), each with its radial Cauchy stress (eq. 2.10, current polar frame) as ``s{k}_radial_stress_kPa``;
    ``steps`` and ``concentrations`` index them. Each snapshot can restart the run (:func:`load_snapshot`)."""
    arrays = dict(
        steps=np.array([s[0] for s in snapshots]),
        concentrations=np.array([s[1].load.material_value("concentration") for s in snapshots]),
        X=model.layout.X,
        volume=model.layout.volume,
        theta=model.layout.theta,
    )
    arrays.update(
        {f"s{k}_radial_stress_kPa": measure.cauchy_polar(st.evaluation)[0] for k, (_, st, _) in enumerate(snapshots)}
    )
    state_io.save_series(
        path, [(st.x, st.load, dict(pseudo_time=int(step)), hist) for step, st, hist in snapshots], params, arrays
    )


def load_snapshot(path, k: int, expected_params: dict | None = None):
    """``(solver.State, ParticleHistory, pseudo_time)`` of snapshot ``k`` of a :func:`save_snapshots` file."""
    saved = state_io.load_from_series(path, k, expected_params)
    return solver.State(saved.load, saved.x, None, None), saved.history, int(saved.info["pseudo_time"])
