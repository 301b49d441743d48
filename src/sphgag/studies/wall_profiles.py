"""The transmural profile verification (target ``verification``): the walls' radial and hoop Cauchy stress at every
ring against the exact thick wall, under each lumen load and each stress recovery, at three spacings.

The damage criterion (section 2.7) reads the radial stress; figure 3(c) shows it. The exact references are the
incompressible thick-walled tubes of the same strain energies (:mod:`sphgag.physics.analytic`): the mean-behaviour
model's (eq. 2.18, figure 2a) and the bi-layered model's, passive and active (eqs. 2.19-2.24, figure 3).

* :func:`mean_states` and :func:`bilayer_states`: the converged states of one wall at one spacing (the mean wall by
  figure 2a's path; the bi-layered wall by homeostasis, pressure control and, for the active wall, its tone: the
  path of figure 3).
* :func:`ring_errors`: every ring's radial error [% of the lumen pressure P] and hoop error [% of the exact], at the
  ring's current radius and at its material point (the exact tube's radius of the ring's reference radius).
* :func:`summary` and :func:`orders`: per state, the surfaces' and the interior's largest radial error and the hoop
  rms error; their observed order under refinement.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import measure
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.numerics import Numerics
from ..options import Options
from . import artery
from .inclusion import observed_order
from .pressure_diameter import bilayer_tube, mean_thick_wall
from .wall_loading import activated
from .wall_loading import homeostasis as homeostasis_

log = logging.getLogger("sphgag")


@dataclass(frozen=True)
class ProfileVerification(Options):
    """The ``verification.profiles`` section: the ``walls`` at ``pressures_mmHg`` and ``refinements`` spacings
    (:func:`spacing`), under each of ``lumen_loads`` (one job each) and read by each of ``recoveries``; the figure's
    profiles at ``figure_pressure_mmHg``."""

    walls: tuple
    pressures_mmHg: tuple
    refinements: int
    lumen_loads: tuple
    recoveries: tuple
    figure_pressure_mmHg: float

    @classmethod
    def problems(cls, config) -> list[str]:
        """Pressures inside the calibration's sweep, and the figure's pressure one of them."""
        vp = config.get("verification", {}).get("profiles", {})
        top = config.get("calibration", {}).get("max_pressure_mmHg", np.inf)
        where = "verification.profiles"
        out = [
            f"{where}.pressures_mmHg[{k}] = {p} exceeds calibration.max_pressure_mmHg = {top}"
            for k, p in enumerate(vp.get("pressures_mmHg", []))
            if p > top
        ]
        if vp and vp.get("figure_pressure_mmHg") not in vp.get("pressures_mmHg", []):
            out.append(
                f"{where}.figure_pressure_mmHg = {vp.get('figure_pressure_mmHg')} is not one of "
                f"{where}.pressures_mmHg = {vp.get('pressures_mmHg')}"
            )
        return out


def spacing(base_dx: float, level: int) -> float:
    """The particle spacing of refinement ``level`` (0: the configuration's ``base_dx``; each level divides it by
    sqrt 2), rounded to nm."""
    return round(base_dx / np.sqrt(2.0) ** level, 3)


def _pressure_loads(pressures_mmHg, start_mmHg: float, material=()) -> list[list[Load]]:
    """The pressures as two pressure-controlled branches from ``start_mmHg``: down, then up."""
    down = [P for P in sorted(pressures_mmHg, reverse=True) if P < start_mmHg]
    up = [P for P in sorted(pressures_mmHg) if P > start_mmHg]
    return [[Load(1.0, P * MMHG_TO_KPA, material=material) for P in branch] for branch in (down, up)]


def mean_states(p: dict, numerics: Numerics, calibration: dict, pressures_mmHg) -> list:
    """``[(wall, model, tube, state)]``: the mean-behaviour wall ``p`` at ``pressures_mmHg`` by figure 2a's path (the
    axial stretch in ``calibration["axial_stretch_steps"]``, then the pressure in steps of at most 50 mmHg)."""
    model, tube = artery.mean_model(p, numerics), mean_thick_wall(p)
    lz = p["axial_stretch"]
    steps = calibration["axial_stretch_steps"]
    ramp = np.arange(50.0, max(pressures_mmHg), 50.0)
    loads = [Load(s, 0.0) for s in np.linspace(1.0, lz, steps + 1)[1:]]
    loads += [Load(lz, P * MMHG_TO_KPA) for P in sorted({*ramp, *pressures_mmHg})]
    path = numerics.solver(model).follow_path(model.layout.X, Load(1.0, 0.0), loads, run=model.name)
    wanted = {round(P, 10) for P in pressures_mmHg}
    return [("mean", model, tube, s) for s in path if _pressure(s) in wanted and s.load.axial_stretch == lz]


def bilayer_states(
    p: dict, numerics: Numerics, homeostasis: dict, cal: dict, walls, pressures_mmHg, fitted: bool = False
) -> list:
    """``[(wall, model, tube, state)]``: the bi-layered wall ``p``, passive and/or active (``walls``), at
    ``pressures_mmHg`` by figure 3's path (:func:`sphgag.studies.wall_loading.activated`, then pressure control);
    ``fitted``: on interface-fitted particles (:func:`sphgag.studies.artery.bilayer_model`)."""
    model = artery.bilayer_model(p, numerics, name="bilayer-fitted" if fitted else "bilayer", fitted=fitted)
    path_solver = numerics.solver(model)
    h = homeostasis_(model, numerics, homeostasis, path_solver=path_solver)
    wanted = {round(P, 10) for P in pressures_mmHg}
    out = []
    for wall in walls:
        start = activated(model, h.state, numerics, cal, wall == "active", path_solver=path_solver)
        states = [start]
        for loads in _pressure_loads(pressures_mmHg, start.load.pressure_mmHg, start.load.material):
            states += path_solver.follow_path(start.x, start.load, loads, run=f"{model.name} {wall}")
        tube = bilayer_tube(p, active=wall == "active")
        out += [(wall, model, tube, s) for s in states if _pressure(s) in wanted]
    return out


def _pressure(state) -> float:
    return round(state.load.pressure_mmHg, 10) if state.load.pressure_kPa is not None else np.nan


def exact_at(tube, P_kPa: float, radius: np.ndarray, layer: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The exact radial and hoop stress at current radii ``radius`` inside each ring's layer ``layer``."""
    ex = tube.state(P_kPa, n_per_layer=401)
    srr, stt = np.empty_like(radius), np.empty_like(radius)
    for name in np.unique(layer):
        m, e = layer == name, ex.layer == name
        srr[m] = np.interp(radius[m], ex.radius[e], ex.radial_stress[e])
        stt[m] = np.interp(radius[m], ex.radius[e], ex.circ_stress[e])
    return srr, stt


def ring_errors(model, tube, state, stress_recovery: str) -> pd.DataFrame:
    """Every ring of ``state`` read by ``stress_recovery`` (:data:`sphgag.engine.measure.RECOVERIES`): its radial
    error [% of P] and hoop error [% of the exact] against the exact tube at the ring's current radius and
    (``*_material_*``) at its material point: the exact tube's radius of the ring's reference radius (the SPH wall's
    diameter is off by about 0.1 %, which on the stiff end of the pressure-diameter curve moves the hoop stress at a
    given radius by several %)."""
    ev = state.evaluation
    profile = measure.ring_profile(model, measure.recovered(model, ev, stress_recovery))
    P = state.load.pressure_kPa
    layer = profile.layer.to_numpy()
    srr, stt = exact_at(tube, P, profile.radius_um.to_numpy(), layer)
    r_material = tube.radius(profile.reference_radius_um.to_numpy(), tube.inner_radius(P))
    srr_m, stt_m = exact_at(tube, P, r_material, layer)
    return profile.assign(
        exact_radial_kPa=srr,
        exact_circ_kPa=stt,
        radial_error_pct=100.0 * (profile.radial_stress_kPa - srr) / P,
        circ_error_pct=100.0 * (profile.circ_stress_kPa / stt - 1.0),
        radial_material_error_pct=100.0 * (profile.radial_stress_kPa - srr_m) / P,
        circ_material_error_pct=100.0 * (profile.circ_stress_kPa / stt_m - 1.0),
        residual=state.convergence.residual,
    )


def wall_rings(found: list, recoveries, **keys) -> pd.DataFrame:
    """Every ring of every state in ``found`` (:func:`mean_states`, :func:`bilayer_states`) under each of
    ``recoveries``, with the columns ``keys`` (the lumen load, the spacing)."""
    rows = [
        ring_errors(model, tube, s, name).assign(wall=wall, pressure_mmHg=s.load.pressure_mmHg, recovery=name, **keys)
        for wall, model, tube, s in found
        for name in recoveries
    ]
    out = pd.concat(rows, ignore_index=True)
    first = ["wall", "pressure_mmHg", *keys, "recovery", "ring"]
    return out[first + [c for c in out.columns if c not in first]]


KEYS = ["wall", "lumen_load", "recovery", "pressure_mmHg"]


def summary(rings: pd.DataFrame) -> pd.DataFrame:
    """Per wall, lumen load, recovery, pressure and spacing: the inner- and outer-surface radial error, the largest
    interior one and the largest at any ring [% of P], the hoop rms error [%], at the rings' current radii and
    (``material_*``) at their material points; and the state's residual."""

    def one(g):
        out = {}
        for tag, radial, circ in (
            ("", "radial_error_pct", "circ_error_pct"),
            ("material_", "radial_material_error_pct", "circ_material_error_pct"),
        ):
            e = g.sort_values("ring")[radial].to_numpy()
            out[f"{tag}inner_radial_pct"] = e[0]
            out[f"{tag}outer_radial_pct"] = e[-1]
            out[f"{tag}interior_radial_max_pct"] = np.abs(e[1:-1]).max()
            out[f"{tag}radial_max_pct"] = np.abs(e).max()
            out[f"{tag}circ_rms_pct"] = float(np.sqrt(np.mean(g[circ] ** 2)))
        out["residual"] = float(g.residual.max())
        return pd.Series(out)

    return rings.groupby(KEYS + ["dx_um"], sort=False).apply(one, include_groups=False).reset_index()


def orders(table: pd.DataFrame) -> pd.DataFrame:
    """The observed order of each error measure of :func:`summary` (:func:`sphgag.studies.inclusion.observed_order`)
    from the two finest spacings and from all of them; none where the error is round-off (a surface read from its
    traction)."""
    rows = []
    measures = [c for c in table.columns if c.endswith("_pct")]
    for key, g in table.groupby(KEYS, sort=False):
        g = g.sort_values("dx_um", ascending=False)
        if len(g) < 2:
            continue
        row = dict(zip(KEYS, key), dx_um=float(g.dx_um.min()))
        for m in measures:
            e = g[m].to_numpy()
            exact = np.abs(e[-2:]).min() < 1e-6
            row[m] = e[-1]
            row[f"{m}_order"] = np.nan if exact else observed_order(g.dx_um.to_numpy()[-2:], e[-2:])
            row[f"{m}_order_all"] = np.nan if exact else observed_order(g.dx_um.to_numpy(), e)
        rows.append(row)
    return pd.DataFrame(rows)


def log_summary(table: pd.DataFrame) -> None:
    """One line per state of :func:`summary`."""
    for r in table.itertuples():
        log.info(
            "%s %g mmHg, %s load, %s reading, dx = %g um: inner %+.1f, outer %+.1f, interior max %.1f %% of P; hoop "
            "rms %.2f %% (material point %.2f %%); residual %.1e",
            r.wall,
            r.pressure_mmHg,
            r.lumen_load,
            r.recovery,
            r.dx_um,
            r.material_inner_radial_pct,
            r.material_outer_radial_pct,
            r.material_interior_radial_max_pct,
            r.circ_rms_pct,
            r.material_circ_rms_pct,
            r.residual,
        )
