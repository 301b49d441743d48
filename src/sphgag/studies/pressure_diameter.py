"""The walls' pressure-diameter protocols, each beside the exact thick-walled solution, and the rows and profiles every
wall's states are recorded as.

* The mean-behaviour model (figure 2a, :func:`mean_pressure_diameter`): from the unloaded reference, ramp the axial
  stretch at zero pressure, then pressurise at fixed axial stretch, recording the pressure-diameter response, the
  mean circumferential stress and stretch (eqs. 2.16-2.17) and transmural stress profiles.
* The bi-layered model (figure 3, :func:`bilayer_pressure_diameter`): from the homeostatic state
  (:mod:`sphgag.studies.wall_loading`), passive or with the active tone, the pressure swept below and above the
  activation pressure under pressure control.

The exact tubes the walls are compared with (:mod:`sphgag.physics.analytic`): the mean wall's
(:func:`mean_thick_wall`) and the bi-layered wall's (:func:`bilayer_tube`), with the same constituents and
pre-stretches, incompressible. The SPH models (:mod:`sphgag.studies.artery`) and their loading paths
(:mod:`sphgag.studies.wall_loading`) do not import them, so an edit of the closed forms reruns no simulation but these
sweeps.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import measure, solver
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import Options, file_name_problems
from ..physics import analytic
from . import artery
from .wall_loading import above_sweep, activated

log = logging.getLogger("sphgag")


@dataclass(frozen=True)
class Calibration(Options):
    """The ``calibration`` configuration section, figure 2a's protocol (:func:`mean_pressure_diameter`): the axial
    stretch ramped in ``axial_stretch_steps`` at zero pressure, then ``pressure_points`` pressures evenly spaced from 0
    to ``max_pressure_mmHg``, and the pressures of the transmural profiles."""

    SECTION = "calibration"

    axial_stretch_steps: int
    max_pressure_mmHg: float
    pressure_points: int
    transmural_pressures_mmHg: tuple

    @classmethod
    def problems(cls, config) -> list[str]:
        """The transmural pressures inside the sweep, each giving its own file name."""
        values = config.get("calibration", {}).get("transmural_pressures_mmHg", [])
        return above_sweep(config, "calibration", "transmural_pressures_mmHg") + file_name_problems(
            "calibration", "transmural_pressures_mmHg", values
        )


def pressure_points(calibration: dict) -> np.ndarray:
    """Sorted pressures [mmHg] of the sweep: evenly spaced from 0, plus the transmural pressures."""
    sweep = np.linspace(0.0, calibration["max_pressure_mmHg"], calibration["pressure_points"])
    return np.unique(np.round(np.concatenate([sweep, calibration["transmural_pressures_mmHg"]]), 10))


@dataclass
class PressureDiameter:
    """Results of a pressure-diameter protocol."""

    states: pd.DataFrame  # one row per converged state of the sweep
    transmural: pd.DataFrame  # SPH ring profiles and exact profiles
    analytic: pd.DataFrame  # dense exact curve
    saved: dict = None  # pressure [mmHg] -> solver.State, for the state pressures

    def max_od_error(self, p_min_mmHg=10.0, p_max_mmHg=np.inf) -> float:
        s = self.states[(self.states.pressure_mmHg >= p_min_mmHg - 1e-9) & (self.states.pressure_mmHg <= p_max_mmHg)]
        return float(s.od_rel_error.abs().max())


def state_row(model: Model, s: solver.State, tube: analytic.ThickWallTube, R_ref: float, H_ref: float) -> dict:
    """One pressure-diameter row: diameters, eqs. (2.16)-(2.17), convergence, exact diameter, equilibrium.

    ``R_ref, H_ref``: inner radius and thickness of the configuration the mean
    circumferential stretch is normalised by (eq. 2.17).
    """
    P_kPa = measure.carried_pressure(model, s.evaluation)
    ID, OD = measure.diameters(model, s.x)
    r_in, h = ID / 2.0, (OD - ID) / 2.0
    exact_r_in = tube.inner_radius(P_kPa)
    exact_OD = 2.0 * float(tube.radius(tube.R_out, exact_r_in))
    profile = measure.ring_profile(model, s.evaluation)
    hoop = measure.hoop_force(profile)
    return dict(
        pressure_mmHg=P_kPa / MMHG_TO_KPA,
        outer_diameter_um=OD,
        inner_diameter_um=ID,
        wall_thickness_um=h,
        mean_circ_stress_kPa=float(analytic.thin_wall_stress(P_kPa, r_in, h)),
        mean_circ_stretch=float(analytic.thin_wall_stretch(r_in, h, R_ref, H_ref)),
        residual=s.convergence.residual,
        newton_iterations=s.convergence.iterations,
        force_evaluations=s.convergence.force_evaluations,
        jacobians=s.convergence.jacobians,
        exact_outer_diameter_um=exact_OD,
        exact_inner_diameter_um=2.0 * exact_r_in,
        od_rel_error=OD / exact_OD - 1.0,
        hoop_force_kPa_um=hoop,
        equilibrium_error=(hoop / (P_kPa * r_in) - 1.0) if P_kPa > 0 else np.nan,
        outer_radial_stress_kPa=float(profile.radial_stress_kPa.iloc[-1]),
        min_jacobian=float(profile.jacobian.min()),
        max_jacobian=float(profile.jacobian.max()),
    )


TRANSMURAL_COLUMNS = ["model", "pressure_mmHg", "source", "radius_um", "layer", "radial_stress_kPa", "circ_stress_kPa"]


def transmural(model: Model, s: solver.State, tube: analytic.ThickWallTube, label: str) -> pd.DataFrame:
    """SPH ring profile (``source = sph``) and exact profile (``source = exact``) of one state."""
    P_mmHg = s.load.pressure_mmHg
    sph = measure.ring_profile(model, s.evaluation).assign(model=label, pressure_mmHg=P_mmHg, source="sph")
    ex = tube.state(s.load.pressure_kPa)
    exact = pd.DataFrame(
        dict(
            model=label,
            pressure_mmHg=P_mmHg,
            source="exact",
            radius_um=ex.radius,
            layer=ex.layer,
            radial_stress_kPa=ex.radial_stress,
            circ_stress_kPa=ex.circ_stress,
        )
    )
    out = pd.concat([sph, exact], ignore_index=True)
    return out[TRANSMURAL_COLUMNS + [c for c in out.columns if c not in TRANSMURAL_COLUMNS]]


def exact_curve(tube: analytic.ThickWallTube, pressures_mmHg, R_ref: float, H_ref: float) -> pd.DataFrame:
    """Exact pressure-diameter and thin-wall mean stress-stretch curves (eqs. 2.16-2.17)."""
    P = np.asarray(pressures_mmHg, dtype=float)
    r_in = np.array([tube.inner_radius(p * MMHG_TO_KPA) for p in P])
    r_out = tube.radius(tube.R_out, r_in)
    h = r_out - r_in
    return pd.DataFrame(
        dict(
            pressure_mmHg=P,
            outer_diameter_um=2.0 * r_out,
            inner_diameter_um=2.0 * r_in,
            mean_circ_stress_kPa=analytic.thin_wall_stress(P * MMHG_TO_KPA, r_in, h),
            mean_circ_stretch=analytic.thin_wall_stretch(r_in, h, R_ref, H_ref),
        )
    )


def mean_pressure_diameter(
    model: Model, tube: analytic.ThickWallTube, p: dict, numerics: Numerics, calibration: dict, label: str = "mean"
) -> PressureDiameter:
    """Figure 2a on the mean-behaviour model, compared with the exact tube ``tube``.

    ``label`` is the ``model`` column of the transmural table. The mean
    circumferential stretch is normalised by the unloaded geometry (eq. 2.17).
    """
    run = model.name
    lz = p["axial_stretch"]
    R_in, H = p["inner_radius_um"], p["outer_radius_um"] - p["inner_radius_um"]
    steps = calibration["axial_stretch_steps"]
    axial = [Load(axial_stretch=s, pressure_kPa=0.0) for s in np.linspace(1.0, lz, steps + 1)[1:]]
    pressures = pressure_points(calibration)
    loads = axial + [Load(axial_stretch=lz, pressure_kPa=P * MMHG_TO_KPA) for P in pressures if P > 0.0]
    log.info(
        "[%s] %d particles, %d neighbour entries; axial stretch to %.3g in %d steps, then %d pressures up to %.0f mmHg",
        run,
        model.n,
        model.nb.n_entries,
        lz,
        steps,
        len(pressures) - 1,
        pressures.max(),
    )
    path_solver = numerics.solver(model)
    states = path_solver.follow_path(model.layout.X, Load(1.0, 0.0), loads, run=run, on_state=solver.log_states(run))
    final = [s for s in states if s.load.axial_stretch == lz]
    wanted = set(np.round(calibration["transmural_pressures_mmHg"], 10))
    table = pd.DataFrame([state_row(model, s, tube, R_in, H) for s in final])
    profiles = pd.concat(
        [transmural(model, s, tube, label) for s in final if round(s.load.pressure_mmHg, 10) in wanted],
        ignore_index=True,
    )
    curve = exact_curve(tube, np.linspace(0.0, calibration["max_pressure_mmHg"], 201), R_in, H)
    return PressureDiameter(table, profiles, curve)


def mean_thick_wall(p: dict) -> analytic.ThickWallTube:
    """Exact incompressible thick-walled tube for the same strain energy (eq. 2.18)."""
    families = tuple(analytic.Family(1.0, a, c1, c2) for a, c1, c2 in artery.mean_fibre_families(p))
    law = analytic.Mixture(p["shear_modulus_kPa"], families)
    return analytic.ThickWallTube.single(law, p["inner_radius_um"], p["outer_radius_um"], p["axial_stretch"])


def bilayer_law(p: artery.Bilayer | dict, layer: str, active: bool) -> analytic.Mixture:
    """Incompressible constituents of one layer at full pre-stretch, for the semi-analytical tube."""
    p = artery.Bilayer.of(p)
    gr, gt, _ = artery.elastin_prestretch(p)
    act = p.active
    return analytic.Mixture(
        mu=p.mass_fractions[layer]["elastin"] * p.elastin_shear_modulus_kPa,
        families=tuple(analytic.Family(*f) for f in artery.bilayer_families(p, layer)),
        Gr=gr,
        Gt=gt,
        tmax=act.max_stress_kPa if (active and artery.has_smc(p, layer)) else 0.0,
        lmax=act.stretch_max,
        lmin=act.stretch_min,
    )


def bilayer_tube(p: artery.Bilayer | dict, active: bool) -> analytic.ThickWallTube:
    """Semi-analytical incompressible layered tube (same layers, constituents and pre-stretches)."""
    p = artery.Bilayer.of(p)
    return analytic.ThickWallTube([(a, b, bilayer_law(p, name, active), name) for name, a, b in p.bands()], lz=1.0)


def bilayer_pressure_diameter(
    model: Model,
    tube: analytic.ThickWallTube,
    homeostatic: solver.State,
    numerics: Numerics,
    cal: dict,
    active: bool,
    label: str,
) -> PressureDiameter:
    """Pressure-diameter sweep of the passive or active bi-layered model under pressure control.

    From the homeostatic state (inner radius held, carried pressure P_h) the
    load switches to pressure control at P_h (the same equilibrium), moves to
    the activation pressure, ramps the active tone there if ``active``, and then
    sweeps the pressures below and above it in two branches. The mean
    circumferential stretch is normalised by the traction-free (zero-pressure)
    geometry, as in figure 3a (that of the semi-analytical tube, so that SPH
    points and exact curve share the normalisation).
    """
    path_solver = numerics.solver(model)
    start = activated(model, homeostatic, numerics, cal, active, label, path_solver)
    P_act = cal["activation_pressure_mmHg"]
    sweep = np.linspace(0.0, cal["max_pressure_mmHg"], cal["pressure_points"])
    pressures = np.unique(np.round(np.concatenate([sweep, cal["state_pressures_mmHg"], [P_act]]), 10))
    down = [P for P in pressures[::-1] if P < P_act]
    up = [P for P in pressures if P > P_act]
    states = [start]
    for branch in (down, up):
        loads = [Load(1.0, P * MMHG_TO_KPA, material=start.load.material) for P in branch]
        states += path_solver.follow_path(
            start.x, start.load, loads, run=model.name, on_state=solver.log_states(model.name)
        )
    states.sort(key=lambda s: s.load.pressure_kPa)
    # eq. (2.17) normalised by the traction-free (zero-pressure) geometry of the semi-analytical tube, the
    # same constant for the SPH points and the exact curve
    r0 = tube.inner_radius(0.0)
    h0 = float(tube.radius(tube.R_out, r0)) - r0
    table = pd.DataFrame([state_row(model, s, tube, r0, h0) for s in states]).assign(model=label)
    table = table[["model"] + [c for c in table.columns if c != "model"]]
    wanted = {round(P, 10) for P in cal["state_pressures_mmHg"]}
    saved = {round(s.load.pressure_mmHg, 10): s for s in states if round(s.load.pressure_mmHg, 10) in wanted}
    profiles = pd.concat([transmural(model, s, tube, label) for s in saved.values()], ignore_index=True)
    curve = exact_curve(tube, np.linspace(0.0, cal["max_pressure_mmHg"], 201), r0, h0).assign(model=label)
    return PressureDiameter(table, profiles, curve, saved)
