"""Loading protocols of the paper (figure 2), run as paths of converged quasi-static states.

:func:`mean_pressure_diameter` is figure 2a: from the unloaded reference, ramp
the axial stretch at zero pressure, then pressurise at fixed axial stretch,
recording the pressure-diameter response, the mean circumferential stress and
stretch (eqs. 2.16-2.17) and transmural stress profiles, each beside the exact
thick-walled solution.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
import pandas as pd

from . import analytic, measure, solver
from .loading import MMHG_TO_KPA, Load
from .model import Model

log = logging.getLogger("sphgag")


def solver_options(numerics: dict) -> dict:
    return dict(tol=numerics["tolerance"], max_iter=numerics["max_newton_iterations"],
                max_bisections=numerics["max_bisections"])


def pressure_points(calibration: dict) -> np.ndarray:
    """Sorted pressures [mmHg] of the sweep: evenly spaced from 0, plus the transmural pressures."""
    sweep = np.linspace(0.0, calibration["max_pressure_mmHg"], calibration["pressure_points"])
    return np.unique(np.round(np.concatenate([sweep, calibration["transmural_pressures_mmHg"]]), 10))


def log_state(run: str):
    """A ``follow_path`` callback that logs each converged state (progress in the rule log)."""

    def on_state(state: solver.State):
        c = state.convergence
        log.info("[%s] converged at %s: residual %.2e, %d Newton its, %d force evaluations, %.2f s",
                 run, solver.describe(state.load), c.residual, c.iterations, c.force_evaluations, c.seconds)

    return on_state


@dataclass
class PressureDiameter:
    """Results of the figure 2a protocol."""

    states: pd.DataFrame  # one row per converged state at the target axial stretch
    transmural: pd.DataFrame  # SPH ring profiles and exact profiles
    analytic: pd.DataFrame  # dense exact curve

    def max_od_error(self, p_min_mmHg=10.0) -> float:
        s = self.states[self.states.pressure_mmHg >= p_min_mmHg - 1e-9]
        return float(s.od_rel_error.abs().max())


def mean_pressure_diameter(model: Model, tube: analytic.ThickWallTube, p: dict, numerics: dict,
                           calibration: dict, label: str = "mean") -> PressureDiameter:
    """Figure 2a on the mean-behaviour model, compared with the exact tube ``tube``.

    ``label`` is the ``model`` column of the transmural table.
    """
    run = model.name
    lz = p["axial_stretch"]
    R_in, R_out = p["inner_radius_um"], p["outer_radius_um"]
    H = R_out - R_in
    steps = calibration["axial_stretch_steps"]
    axial = [Load(axial_stretch=s, pressure_kPa=0.0) for s in np.linspace(1.0, lz, steps + 1)[1:]]
    pressures = pressure_points(calibration)
    loads = axial + [Load(axial_stretch=lz, pressure_kPa=P * MMHG_TO_KPA) for P in pressures if P > 0.0]
    log.info("[%s] %d particles, %d neighbour entries; axial stretch to %.3g in %d steps, then %d pressures "
             "up to %.0f mmHg", run, model.n, model.nb.n_entries, lz, steps, len(pressures) - 1, pressures.max())
    states = solver.follow_path(model, model.layout.X, Load(1.0, 0.0), loads, run=run, on_state=log_state(run),
                                **solver_options(numerics))
    final = [s for s in states if s.load.axial_stretch == lz]

    rows, profiles = [], []
    wanted = set(np.round(calibration["transmural_pressures_mmHg"], 10))
    for s in final:
        P_mmHg = s.load.pressure_mmHg
        ID, OD = measure.diameters(model, s.x)
        r_in, h = ID / 2.0, (OD - ID) / 2.0
        exact_r_in = tube.inner_radius(s.load.pressure_kPa)
        exact_OD = 2.0 * float(tube.radius(R_out, exact_r_in))
        profile = measure.ring_profile(model, s.evaluation)
        hoop = measure.hoop_force(profile)
        rows.append(dict(
            pressure_mmHg=P_mmHg,
            outer_diameter_um=OD,
            inner_diameter_um=ID,
            wall_thickness_um=h,
            mean_circ_stress_kPa=float(analytic.thin_wall_stress(s.load.pressure_kPa, r_in, h)),
            mean_circ_stretch=float(analytic.thin_wall_stretch(r_in, h, R_in, H)),
            residual=s.convergence.residual,
            newton_iterations=s.convergence.iterations,
            force_evaluations=s.convergence.force_evaluations,
            jacobians=s.convergence.jacobians,
            solve_seconds=s.convergence.seconds,
            exact_outer_diameter_um=exact_OD,
            exact_inner_diameter_um=2.0 * exact_r_in,
            od_rel_error=OD / exact_OD - 1.0,
            hoop_force_kPa_um=hoop,
            equilibrium_error=(hoop / (s.load.pressure_kPa * r_in) - 1.0) if P_mmHg > 0 else np.nan,
            outer_radial_stress_kPa=float(profile.radial_stress_kPa.iloc[-1]),
            min_jacobian=float(profile.jacobian.min()),
        ))
        if round(P_mmHg, 10) in wanted:
            profiles.append(profile.assign(model=label, pressure_mmHg=P_mmHg, source="sph"))
            ex = tube.state(s.load.pressure_kPa)
            profiles.append(pd.DataFrame(dict(
                model=label, pressure_mmHg=P_mmHg, source="exact", radius_um=ex.radius, layer="wall",
                radial_stress_kPa=ex.radial_stress, circ_stress_kPa=ex.circ_stress)))
    table = pd.DataFrame(rows)
    transmural = pd.concat(profiles, ignore_index=True)
    cols = ["model", "pressure_mmHg", "source", "radius_um", "layer", "radial_stress_kPa", "circ_stress_kPa"]
    transmural = transmural[cols + [c for c in transmural.columns if c not in cols]]
    return PressureDiameter(table, transmural, exact_curve(tube, calibration["max_pressure_mmHg"]))


def exact_curve(tube: analytic.ThickWallTube, max_pressure_mmHg: float, n: int = 201) -> pd.DataFrame:
    """Dense exact pressure-diameter and thin-wall mean stress-stretch curves (eqs. 2.16-2.17)."""
    P = np.linspace(0.0, max_pressure_mmHg, n)
    r_in = np.array([tube.inner_radius(p * MMHG_TO_KPA) for p in P])
    r_out = tube.radius(tube.R_out, r_in)
    h = r_out - r_in
    return pd.DataFrame(dict(
        pressure_mmHg=P,
        outer_diameter_um=2.0 * r_out,
        inner_diameter_um=2.0 * r_in,
        mean_circ_stress_kPa=analytic.thin_wall_stress(P * MMHG_TO_KPA, r_in, h),
        mean_circ_stretch=analytic.thin_wall_stretch(r_in, h, tube.R_in, tube.R_out - tube.R_in),
    ))
