"""Loading protocols of the paper (figure 2), run as paths of converged quasi-static states.

* :func:`mean_pressure_diameter` is figure 2a: from the unloaded reference,
  ramp the axial stretch at zero pressure, then pressurise at fixed axial
  stretch, recording the pressure-diameter response, the mean circumferential
  stress and stretch (eqs. 2.16-2.17) and transmural stress profiles, each
  beside the exact thick-walled solution.
* :func:`homeostasis` is figure 2b: deposition pre-stretches ramped at a held
  inner radius; :func:`bilayer_pressure_diameter` then activates (optionally)
  and pressurises the bi-layered model under pressure control, beside the
  semi-analytical bi-layered tube.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np
import pandas as pd

from ..engine import measure, pool_cavity, pool_volume, solver
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import Options, file_name_problems
from ..physics import analytic
from ..physics.donnan import CHARGE_LAWS, LAWS
from ..physics.materials import Gag, swelling_pressure
from ..registry import Registry, Variant
from . import artery

log = logging.getLogger("sphgag")


def _above_sweep(config, section: str, key: str) -> list[str]:
    """The pressures of ``section.key`` (a list, or one pressure) above the top of the section's sweep,
    ``max_pressure_mmHg``."""
    cal = config.get(section, {})
    top = cal.get("max_pressure_mmHg", 0)
    values = cal.get(key, [])
    problems = []
    for k, p in enumerate(values if isinstance(values, list) else [values]):
        if p > top:
            where = f"{section}.{key}" + (f"[{k}]" if isinstance(values, list) else "")
            problems.append(f"{where} = {p} exceeds {section}.max_pressure_mmHg = {top}")
    return problems


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
        return _above_sweep(config, "calibration", "transmural_pressures_mmHg") + file_name_problems(
            "calibration", "transmural_pressures_mmHg", values
        )


def pressure_points(calibration: dict) -> np.ndarray:
    """Sorted pressures [mmHg] of the sweep: evenly spaced from 0, plus the transmural pressures."""
    sweep = np.linspace(0.0, calibration["max_pressure_mmHg"], calibration["pressure_points"])
    return np.unique(np.round(np.concatenate([sweep, calibration["transmural_pressures_mmHg"]]), 10))


def log_state(run: str):
    """An ``on_state`` callback of :meth:`sphgag.engine.solver.Solver.follow_path` that logs each converged state
    (progress in the rule log)."""

    def on_state(state: solver.State):
        c = state.convergence
        log.info(
            "[%s] converged at %s: residual %.2e, %d Newton its, %d force evaluations, %.2f s",
            run,
            solver.describe(state.load),
            c.residual,
            c.iterations,
            c.force_evaluations,
            c.seconds,
        )

    return on_state


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
    path_solver = Numerics.of(numerics).solver(model)
    states = path_solver.follow_path(model.layout.X, Load(1.0, 0.0), loads, run=run, on_state=log_state(run))
    final = [s for s in states if s.load.axial_stretch == lz]
    wanted = set(np.round(calibration["transmural_pressures_mmHg"], 10))
    table = pd.DataFrame([state_row(model, s, tube, R_in, H) for s in final])
    profiles = pd.concat(
        [transmural(model, s, tube, label) for s in final if round(s.load.pressure_mmHg, 10) in wanted],
        ignore_index=True,
    )
    curve = exact_curve(tube, np.linspace(0.0, calibration["max_pressure_mmHg"], 201), R_in, H)
    return PressureDiameter(table, profiles, curve)


# ---------------------------------------------------------------------------
# Bi-layered model: homeostasis (figure 2b), activation and pressure-diameter
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class HomeostasisSettings(Options):
    """The ``homeostasis`` configuration section, figure 2b (:func:`homeostasis`): the deposition pre-stretches ramped
    in ``prestretch_steps`` at the in vivo inner radius, and the pressure Table 2's pre-stretches were chosen to carry
    (for comparison)."""

    SECTION = "homeostasis"

    prestretch_steps: int
    target_pressure_mmHg: float


@dataclass(frozen=True)
class BilayerCalibration(Options):
    """The ``bilayer_calibration`` configuration section (:func:`bilayer_pressure_diameter`): the active tone
    (eq. 2.24) switched on at ``activation_pressure_mmHg`` in ``activation_steps``, the sweep of ``pressure_points``
    pressures up to ``max_pressure_mmHg``, and the pressures whose states are saved (every later stage starts from
    one of them)."""

    SECTION = "bilayer_calibration"

    activation_pressure_mmHg: float
    activation_steps: int
    max_pressure_mmHg: float
    pressure_points: int
    state_pressures_mmHg: tuple

    @classmethod
    def problems(cls, config) -> list[str]:
        """The saved and the activation pressures inside the sweep, each saved pressure giving its own file name."""
        values = config.get("bilayer_calibration", {}).get("state_pressures_mmHg", [])
        return (
            _above_sweep(config, "bilayer_calibration", "state_pressures_mmHg")
            + _above_sweep(config, "bilayer_calibration", "activation_pressure_mmHg")
            + file_name_problems("bilayer_calibration", "state_pressures_mmHg", values)
        )

    @staticmethod
    def unsaved(config, starts) -> list[str]:
        """The start pressures ``starts`` (``(key, pressure)`` pairs) of later stages that have no saved state (one of
        ``bilayer_calibration.state_pressures_mmHg``)."""
        saved = config.get("bilayer_calibration", {}).get("state_pressures_mmHg", [])
        return [
            f"{key} = {p} has no saved state: it must be one of bilayer_calibration.state_pressures_mmHg = {saved}"
            for key, p in starts
            if p not in saved
        ]


def homeostatic_load(inner_radius: float, prestretch: float, activation: float = 0.0) -> Load:
    """Load of the pre-stretch stage: inner radius held, plane strain at the in vivo length (lz = 1)."""
    return Load(1.0, None, inner_radius=inner_radius, material=(("activation", activation), ("prestretch", prestretch)))


@dataclass
class Homeostasis:
    """The converged homeostatic state and what it carries."""

    state: solver.State
    pressures_kPa: dict  # carried pressure: reactions, inner-surface radial stress, hoop equilibrium
    profile: pd.DataFrame  # ring profile
    layers: pd.DataFrame  # per-layer circumferential stress statistics


def homeostasis(
    model: Model,
    numerics: Numerics,
    homeo: dict,
    x0=None,
    start: Load | None = None,
    activation: float = 0.0,
    path_solver: solver.Solver | None = None,
) -> Homeostasis:
    """Figure 2b: ramp every deposition pre-stretch from 1 to its value, inner radius held.

    Nothing is forced: the pressure the state carries is read back three
    ways (reactions of the held inner surface, mean radial stress of the inner
    ring, and global equilibrium ``int sigma_tt dr / r_in``). With
    ``activation > 0`` the active tone is ramped afterwards, still at the held
    radius (``x0``/``start`` then give the passive homeostatic state). ``path_solver``: the
    :class:`sphgag.engine.solver.Solver` of ``model`` whose paths this one continues (its factorisation cache carries
    over: the paths of a chain on one model are solved as one); by default a new one with ``numerics``' options.
    """
    path_solver = path_solver or Numerics.of(numerics).solver(model)
    run = model.name
    R0 = model.layout.inner_radius
    steps = homeo["prestretch_steps"]
    if (start is None) != (x0 is None):
        raise ValueError("give both x0 and start (the passive homeostatic state), or neither")
    if start is None:
        start, x0 = homeostatic_load(R0, 0.0), model.layout.X
        loads = [homeostatic_load(R0, s) for s in np.linspace(0.0, 1.0, steps + 1)[1:]]
    else:
        loads = [start.with_material(activation=float(a)) for a in np.linspace(0.0, activation, steps + 1)[1:]]
    log.info(
        "[%s] %d particles; ramping %s in %d steps at inner radius %.1f um",
        run,
        model.n,
        "the deposition pre-stretches" if activation == 0.0 else "the active tone",
        steps,
        R0,
    )
    state = path_solver.follow_path(x0, start, loads, run=run, on_state=log_state(run))[-1]
    profile = measure.ring_profile(model, state.evaluation)
    r_in = measure.surface_radius(model, state.x, "inner")
    pressures = dict(
        reactions=measure.carried_pressure(model, state.evaluation),
        inner_radial_stress=-float(profile.radial_stress_kPa.iloc[0]),
        hoop_equilibrium=measure.hoop_force(profile) / r_in,
    )
    return Homeostasis(state, pressures, profile, measure.layer_stats(profile))


def pressurise(
    model: Model,
    homeostatic: solver.State,
    pressure_mmHg: float,
    numerics: Numerics,
    on_state=None,
    path_solver: solver.Solver | None = None,
) -> solver.State:
    """The homeostatic state (held radius) moved to ``pressure_mmHg`` under pressure control: first the same
    equilibrium under pressure control at the carried pressure P_h, then the pressure. Every pressurised state of the
    pipeline takes this path (:func:`bilayer_pressure_diameter`, the resolution studies, the sensitivity samples), so
    that the same pressure gives the same state to the bit. ``path_solver``: as :func:`homeostasis`'s."""
    path_solver = path_solver or Numerics.of(numerics).solver(model)
    P_h = measure.carried_pressure(model, homeostatic.evaluation)
    material = homeostatic.load.material
    here = Load(1.0, P_h, material=material)
    loads = [here, Load(1.0, pressure_mmHg * MMHG_TO_KPA, material=material)]
    return path_solver.follow_path(homeostatic.x, here, loads, run=model.name, on_state=on_state)[-1]


def pressurised_wall(bilayer: dict, numerics: Numerics, homeostasis_settings: dict, pressure_mmHg: float, name: str):
    """``(model, state)``: the passive wall of ``bilayer`` at its homeostatic state moved to ``pressure_mmHg``
    (:func:`homeostasis`, :func:`pressurise`), the state without
    its evaluation (a start for a run)."""
    wall = artery.bilayer_model(bilayer, numerics, name=name)
    path_solver = Numerics.of(numerics).solver(wall)
    h = homeostasis(wall, numerics, homeostasis_settings, path_solver=path_solver)
    start = pressurise(wall, h.state, pressure_mmHg, numerics, path_solver=path_solver)
    return wall, solver.State(start.load, start.x, None, None)


def activated(
    model: Model,
    homeostatic: solver.State,
    numerics: Numerics,
    cal: dict,
    active: bool,
    label: str = "",
    path_solver: solver.Solver | None = None,
) -> solver.State:
    """The wall at the activation pressure ``cal["activation_pressure_mmHg"]`` (:func:`pressurise` from the
    homeostatic state), with its active tone (eq. 2.24) ramped there in ``cal["activation_steps"]`` steps if
    ``active``: the start of the pressure-diameter sweeps and of every pressurised state of the wall.
    ``path_solver``: as :func:`homeostasis`'s."""
    path_solver = path_solver or Numerics.of(numerics).solver(model)
    run = model.name
    P_act = cal["activation_pressure_mmHg"]
    on_state = log_state(run)
    log.info(
        "[%s] %s model: pressure control from the homeostatic %.1f mmHg to %.1f mmHg%s",
        run,
        label or ("active" if active else "passive"),
        measure.carried_pressure(model, homeostatic.evaluation) / MMHG_TO_KPA,
        P_act,
        f", then activation in {cal['activation_steps']} steps" if active else "",
    )
    start = pressurise(model, homeostatic, P_act, numerics, on_state=on_state, path_solver=path_solver)
    if not active:
        return start
    steps = cal["activation_steps"]
    activation = [
        Load(1.0, P_act * MMHG_TO_KPA, material=(("activation", a), ("prestretch", 1.0)))
        for a in np.linspace(0.0, 1.0, steps + 1)[1:]
    ]
    return path_solver.follow_path(start.x, start.load, activation, run=run, on_state=on_state)[-1]


def wall_at(
    model: Model,
    homeostatic: solver.State,
    numerics: Numerics,
    cal: dict,
    active: bool,
    pressure_mmHg: float,
    path_solver: solver.Solver | None = None,
) -> solver.State:
    """The passive or active wall at ``pressure_mmHg`` under pressure control, by the path of the pressure-diameter
    sweep (:func:`activated`, then one step to the pressure): at the activation pressure, the sweep's own state to the
    bit. ``path_solver``: as :func:`homeostasis`'s."""
    path_solver = path_solver or Numerics.of(numerics).solver(model)
    start = activated(model, homeostatic, numerics, cal, active, path_solver=path_solver)
    if abs(pressure_mmHg - cal["activation_pressure_mmHg"]) < 1e-12:
        return start
    load = Load(1.0, pressure_mmHg * MMHG_TO_KPA, material=start.load.material)
    return path_solver.follow_path(start.x, start.load, [load], run=model.name)[-1]


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
    path_solver = Numerics.of(numerics).solver(model)
    start = activated(model, homeostatic, numerics, cal, active, label, path_solver)
    P_act = cal["activation_pressure_mmHg"]
    sweep = np.linspace(0.0, cal["max_pressure_mmHg"], cal["pressure_points"])
    pressures = np.unique(np.round(np.concatenate([sweep, cal["state_pressures_mmHg"], [P_act]]), 10))
    down = [P for P in pressures[::-1] if P < P_act]
    up = [P for P in pressures if P > P_act]
    states = [start]
    for branch in (down, up):
        loads = [Load(1.0, P * MMHG_TO_KPA, material=start.load.material) for P in branch]
        states += path_solver.follow_path(start.x, start.load, loads, run=model.name, on_state=log_state(model.name))
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


# ---------------------------------------------------------------------------
# GAG pool: conversion and Gibbs-Donnan swelling at fixed lumen pressure (section 2.6, figure 4)
# ---------------------------------------------------------------------------


def swelling_load(base: Load, conversion: float, concentration: float) -> Load:
    """``base`` (a pressure-controlled state) with the pool's conversion fraction (the ``transition`` of
    :class:`sphgag.engine.history.HistoryMaterial`) and GAG concentration."""
    return base.with_material(transition=float(conversion), concentration=float(concentration))


#: how the tip radial stress of figure 4 is measured (``swelling.tip_probe``): over the region ``probe_length_um``
#: beyond each end of the pool (ours), or on the pool layers' particles adjacent to each end (the authors' script: "a
#: few medial particles just beyond the angular ends of the pool at its radius"), one particle spacing wide
TIP_PROBES = {
    "region": "the pool layers' material swelling.probe_length_um beyond each angular end, across the pool's radial "
    "extent (ours)",
    "adjacent": "the pool layers' particles within one particle spacing beyond each angular end, across the pool's "
    "radial extent (the authors' script)",
}


def tip_length(tip_probe: str, probe_length: float, dx: float) -> float:
    """The arc length [um] of the tip regions of :func:`pool_measurements` under ``tip_probe`` (:data:`TIP_PROBES`):
    ``probe_length`` for ``region``, the layout's particle spacing ``dx`` for ``adjacent`` (the column of particles
    next to each end)."""
    if tip_probe not in TIP_PROBES:
        raise ValueError(f"tip probe {tip_probe!r}: one of {', '.join(TIP_PROBES)}")
    return probe_length if tip_probe == "region" else dx


def pool_measurements(
    model: Model, ev, pool, members: np.ndarray, probe_length: float, tip_probe: str = "region"
) -> dict:
    """Tip radial and top/bottom circumferential Cauchy stress around a pool (current polar frame).

    Each stress is the volume-weighted mean over a region of fixed physical size
    (:func:`measure.pool_probes`): the medial material ``probe_length`` beyond
    each angular end of the pool across its radial extent (tips) and just
    outside it at its mid-angle (top = outer side, bottom = inner side); with ``tip_probe = adjacent``
    (:data:`TIP_PROBES`) the tips are the particles within one spacing beyond each end (:func:`tip_length`). Beside
    the tip mean, ``tip_peak_radial_stress_kPa`` is the largest particle value
    in the tip regions (a kernel average next to the pool's corners, which does
    not converge with refinement). ``pool_volume_change`` is the pool's
    ``sum V J / sum V - 1``; for a pool modelled as a cavity (``model.cavities``), the area its lining encloses over
    its reference area, less 1 (:meth:`sphgag.engine.pool_cavity.Cavity.volume_ratio`; the pool's mean and largest J
    are then that ratio too: its contents swell uniformly).
    """
    lay = model.layout
    probes = measure.pool_probes(pool, probe_length)
    ends = [measure.pool_probes(pool, tip_length(tip_probe, probe_length, lay.dx))[k] for k in ("tip_low", "tip_high")]
    tips = [measure.sector_average(ev, lay, end, "rr", lay.pool_layers) for end in ends]
    srr, _, _, J_all = measure.cauchy_polar(ev)
    tip_particles = np.concatenate([end.members(lay, layer=lay.pool_layers) for end in ends])
    J = J_all[members] if members.size else np.array([np.nan])
    V = lay.volume[members] if members.size else np.array([1.0])
    if model.cavities:  # the contents swell uniformly: the lining's area gives the pool's volume (engine.pool_cavity)
        J = np.array([model.cavities[0].volume_ratio(ev.x)])
        V = np.array([1.0])
    return dict(
        tip_radial_stress_kPa=0.5 * (tips[0] + tips[1]),
        tip_low_radial_stress_kPa=tips[0],
        tip_high_radial_stress_kPa=tips[1],
        tip_peak_radial_stress_kPa=float(srr[tip_particles].max()),
        top_circ_stress_kPa=measure.sector_average(ev, lay, probes["top"], "tt", lay.pool_layers),
        bottom_circ_stress_kPa=measure.sector_average(ev, lay, probes["bottom"], "tt", lay.pool_layers),
        pool_particles=int(members.size),
        pool_volume_change=float(np.sum(V * J) / np.sum(V) - 1.0),
        pool_mean_jacobian=float(np.mean(J)),
        pool_max_jacobian=float(np.max(J)),
    )


@dataclass(frozen=True)
class PoolState:
    """One converged state of the figure 4 protocol: its stage (``intact`` or ``converted``), the GAG
    concentration [mEq/l], the positions and load, how the solver reached it (``control``: ``concentration``, or
    ``volume`` where the concentration-controlled path had lost equilibrium, :mod:`sphgag.engine.pool_volume`), the
    run's pool model (``pool_model``: ``particles``, the paper's GAG particles, or ``cavity``; :data:`POOL_MODELS`)
    and whether the state is in equilibrium with the pool model's converted wall (``cavity``, the name the state
    files keep: :meth:`PoolModel.converts`; :meth:`model` rebuilds that wall), and how the run's path ended (the same
    for every state of a run: ``path_end`` ``complete``, ``limit point`` at ``limit_concentration``, or
    ``no equilibrium``, with ``end_reason``)."""

    stage: str
    concentration: float
    x: np.ndarray
    load: Load
    residual: float
    newton_iterations: int
    force_evaluations: int
    control: str = "concentration"
    pool_model: str = "particles"
    cavity: bool = False
    path_end: str = "complete"
    limit_concentration: float = np.nan
    end_reason: str = ""

    @classmethod
    def of(
        cls,
        stage: str,
        concentration: float,
        state: solver.State,
        control="concentration",
        model: Model | None = None,
        pool_model="particles",
    ) -> PoolState:
        """The state ``state`` of a run with pool model ``pool_model``, in equilibrium with ``model`` (the pool model
        says whether that is its converted wall, :meth:`PoolModel.converts`)."""
        c = state.convergence
        return cls(
            stage,
            float(concentration),
            state.x,
            state.load,
            c.residual,
            c.iterations,
            c.force_evaluations,
            control,
            pool_model,
            bool(model is not None and POOL_MODELS.lookup(pool_model).converts(model)),
        )

    def model(self, run_model: Model, converted: Model | None = None) -> Model:
        """The wall this state is in equilibrium with: the run's ``run_model``, or the pool model's converted wall
        (:meth:`PoolModel.converted_model`; ``converted`` if given, the one an earlier state of the run rebuilt)."""
        return state_model(run_model, self.cavity, self.x, converted, self.pool_model)

    def info(self) -> dict:
        """What a state file keeps beside positions and load (:func:`sphgag.records.state.save_series`)."""
        return dict(
            stage=self.stage,
            concentration_mEq_l=self.concentration,
            residual=self.residual,
            newton_iterations=self.newton_iterations,
            force_evaluations=self.force_evaluations,
            control=self.control,
            pool_model=self.pool_model,
            cavity=self.cavity,
            path_end=self.path_end,
            limit_concentration_mEq_l=None if np.isnan(self.limit_concentration) else self.limit_concentration,
            end_reason=self.end_reason,
        )

    @classmethod
    def from_saved(cls, saved) -> PoolState:
        """The state of a :class:`sphgag.records.state.SavedState` written with :meth:`info`."""
        i = saved.info
        limit = i.get("limit_concentration_mEq_l")
        return cls(
            i["stage"],
            i["concentration_mEq_l"],
            saved.x,
            saved.load,
            i["residual"],
            i["newton_iterations"],
            i["force_evaluations"],
            i.get("control", "concentration"),
            i.get("pool_model", "particles"),
            bool(i.get("cavity", False)),
            i.get("path_end", "complete"),
            np.nan if limit is None else float(limit),
            i.get("end_reason", ""),
        )


@dataclass(frozen=True)
class PoolModel(Variant):
    """A model of the pool in the figure 4 runs (a :class:`sphgag.registry.Variant` of :data:`POOL_MODELS`): its
    ``name`` (``swelling.pool_models``, ``swelling.variant_pool_models``, ``verification.circular_pool.pool_models``,
    wildcard ``{pool}``, column ``pool_model``), ``title`` (the figures' heading of its rows), the charge ``laws`` it
    carries (:data:`sphgag.physics.donnan.LAWS`), ``noun`` (what the verification's run names call the pool) and
    whether it is the paper's. Its behaviour: the wall of a pool swollen from rest (:meth:`around`, the
    verification), what becomes of the wall once the pool is converted (:meth:`convert`, figure 4), and the wall a
    converted state is in equilibrium with (:meth:`converted_model`, :meth:`converts`)."""

    name: str
    title: str
    laws: tuple[str, ...]
    noun: str
    paper: bool = False

    keys: ClassVar[tuple[str, ...]] = (
        "swelling.pool_models",
        "swelling.variant_pool_models",
        "verification.circular_pool.pool_models",
    )
    #: its converted states are in a wall of its own (:meth:`converted_model`), not the run's
    rebuilds: ClassVar[bool] = False

    def check(self, config, key: str) -> None:
        """A pool model of the swelling runs carries one of the configured charge laws (it runs under those)."""
        laws = config.get("gag", {}).get("charge_laws", [])
        if not set(self.laws) & set(laws):
            raise ValueError(
                f"{key} = {self.name!r} carries the charge laws {', '.join(self.laws)}, none of "
                f"gag.charge_laws = {laws}"
            )

    def around(self, model: Model, members: np.ndarray, mirrored: bool = False) -> Model:
        """``model`` (whose pool ``members`` are GAG particles) with the pool as this model holds it from rest
        (``mirrored``: a pool about the origin of a quarter layout)."""
        return model

    def convert(
        self, path_solver: solver.Solver, state: solver.State, opts: dict
    ) -> tuple[solver.Solver, solver.State]:
        """``(solver, state)`` once the pool of the wall of ``path_solver`` is converted at ``state`` (c = 0): the
        solver of the wall the swelling runs on (a new wall has a solver of its own, with the same options) and its
        equilibrium (raises :class:`sphgag.engine.solver.NotConverged`, with :meth:`unconverged`'s reason, where it has
        none near ``state``). ``opts``: the path's ``run`` and ``on_state``."""
        return path_solver, state

    def unconverged(self, exc: solver.NotConverged) -> str:
        """Why the path of the run ends at conversion, where :meth:`convert` found no equilibrium."""
        return f"the converted pool has no equilibrium ({exc.reason})"

    def converts(self, model: Model) -> bool:
        """Whether ``model`` is the converted wall of :meth:`convert` rather than the run's own."""
        return False

    def converted_model(self, model: Model, x: np.ndarray, converted: Model | None = None) -> Model:
        """The converted wall of the run's ``model`` a state at positions ``x`` is in equilibrium with (``converted``
        if given: the one an earlier state of the run rebuilt)."""
        return model


@dataclass(frozen=True)
class CavityPool(PoolModel):
    """The pool as a pressurised cavity (:mod:`sphgag.engine.pool_cavity`; our deviation): its lining carries the
    prescribed Pi(c), its contents swell uniformly, so it carries only the laws that do not conserve the fixed charge
    (a cavity carries one pressure, whatever its J). Once converted, its wall is solved with the hourglass form
    ``hourglass`` (:data:`sphgag.engine.hourglass.FORMS`), whatever ``numerics.hourglass`` says: the form as printed
    loses the path next to the swollen cavity (docs/physics.md). The override is logged where it changes the form."""

    hourglass: str | None = None
    rebuilds: ClassVar[bool] = True

    def around(self, model, members, mirrored=False):
        cavity = pool_cavity.Cavity.around(model.layout, members, model.layout.X, mirrored=mirrored)
        return replace(model, cavities=(cavity,))

    def convert(self, path_solver, state, opts):
        model = path_solver.model
        log.info("[%s] the pool becomes a cavity: its contents swell uniformly, its lining carries Pi", model.name)
        hollow = solver.Solver(self.converted_model(model, state.x), path_solver.options)  # a new model's own cache
        return hollow, hollow.follow_path(state.x, state.load, [state.load], **opts)[-1]

    def unconverged(self, exc):
        return f"the unswollen pool has no equilibrium as a cavity ({exc.reason})"

    def converts(self, model):
        return bool(model.cavities)

    def converted_model(self, model, x, converted=None):
        """``model`` with its pool as the cavity, its particles held at ``x`` (where the pool became a cavity, so
        every converted state of the run rebuilds the same wall), and the cavity's hourglass form."""
        if converted is not None:
            return converted
        form = self.hourglass or model.hourglass
        if form != model.hourglass:
            log.info(
                "[%s] pool model %s: its wall is solved with the %s hourglass form, not numerics.hourglass = %s",
                model.name,
                self.name,
                form,
                model.hourglass,
            )
        return pool_cavity.hollow(replace(model, hourglass=form), model.props.converting, x)


#: the pool models of the figure 4 runs and the pool verifications, by name (the paper's first): ``particles``, the
#: paper's GAG particles (eq. 2.27), every law; ``cavity``, the pool as a pressurised cavity (:class:`CavityPool`)
POOL_MODELS: Registry[PoolModel] = Registry(
    "pool model",
    (
        PoolModel("particles", "the pool's GAG particles (eq. 2.27; the paper's)", CHARGE_LAWS, "pool", paper=True),
        CavityPool(
            "cavity",
            "the pool as a pressurised cavity (our deviation: its lining carries Pi, its contents swell uniformly)",
            tuple(name for name, law in LAWS.items() if not law.conserves_charge),
            "cavity",
            hourglass="energy",
        ),
    ),
)


#: how the lumen is loaded while a pool swells (``swelling.lumen_control``)
LUMEN_CONTROLS = {
    "pressure": "the lumen pressure of the start state held (a follower load on the inner surface; ours)",
    "radius": "the inner radius of the start state held (displacement control; the authors' script): the pressure "
    "the wall then carries is read back from the reactions",
}


def lumen_load(model: Model, start: solver.State, lumen_control: str) -> Load:
    """The load of ``start`` (a pressure-controlled state) with its lumen held as ``lumen_control`` says
    (:data:`LUMEN_CONTROLS`): its pressure, or the mean current radius of its inner-surface particles (each then placed
    at that radius on its reference ray, :func:`sphgag.engine.loading.prescribed_inner_positions`)."""
    if lumen_control not in LUMEN_CONTROLS:
        raise ValueError(f"lumen control {lumen_control!r}: one of {', '.join(LUMEN_CONTROLS)}")
    if lumen_control == "pressure":
        return start.load
    r_in = measure.surface_radius(model, start.x, "inner")
    return replace(start.load, pressure_kPa=None, inner_radius=r_in)


def with_hourglass_factor(model: Model, factor: float) -> Model:
    """``model`` with the modulus E of every particle's hourglass penalty (eq. 2.14) times ``factor``: the
    authors' script scales E by a factor per stage (0.1 while swelling). Every form's penalty is linear in
    ``alpha E`` (:func:`sphgag.engine.forces.hourglass_coefficients`), so this is alpha times ``factor``."""
    if factor == 1.0:
        return model
    return replace(model, hourglass_alpha=model.hourglass_alpha * float(factor))


def concentration_steps(sw: dict) -> np.ndarray:
    """The fixed-charge concentrations [mEq/l] of the figure 4 ramp after c = 0: ``concentration_points`` evenly
    spaced from 0 to ``max_concentration_mEq_l``."""
    return np.linspace(0.0, sw["max_concentration_mEq_l"], sw["concentration_points"])[1:]


def swell_pool(model: Model, start: solver.State, numerics: Numerics, sw: dict) -> list[PoolState]:
    """Figure 4 protocol for one pool, from a converged pressurised state (lumen pressure held).

    1. ``intact``: the wall before conversion (the filled markers of figure 4);
    2. convert the pool's medial particles to GAG at c = 0 (``conversion_steps``
       converged increments of the material homotopy of
       :func:`materials.convert_to_gag`) and relax;
    3. the pool model ``pool_model`` of ``sw`` (:data:`POOL_MODELS`; default the paper's, ``particles``) converts
       the wall (:meth:`PoolModel.convert`): with ``cavity`` the converted pool becomes a pressurised cavity
       (:mod:`sphgag.engine.pool_cavity`; our deviation) and the wall is relaxed again at c = 0 (where it finds no
       equilibrium, e.g. a long pool squeezed shut, whose lining's faces no contact keeps apart, the path ends there:
       ``no equilibrium``, with the reason);
    4. raise the fixed-charge concentration from 0 to ``max_concentration_mEq_l``
       (``concentration_points`` converged states, c = 0 included).
    The lumen pressure stays constant throughout: it is a follower pressure load
    on the inner surface (pressure control), not a prescribed radius; with ``lumen_control = radius`` in ``sw``
    (:data:`LUMEN_CONTROLS`, the authors' script) the inner radius of ``start`` is held instead. With
    ``hourglass_factor`` in ``sw`` the hourglass modulus E of eq. (2.14) is that factor times its value for the whole
    protocol, the intact wall re-solved first (:func:`with_hourglass_factor`; the script: 0.1 while swelling). The
    states are measured by :func:`pool_table`.

    Where a concentration step finds no equilibrium on its path, the pool's own volume becomes the control
    (:func:`sphgag.engine.pool_volume.continue_path`): the path either passes a limit point (the states end at the last
    equilibrium before it, and every state records the limit concentration), or reaches the remaining
    concentrations (``control = volume``), or stops with the concentration still rising (``no equilibrium``: no
    limit point there, the discretisation fails; the reason is recorded). No state beyond the last equilibrium is
    returned.
    """
    model = with_hourglass_factor(model, sw.get("hourglass_factor", 1.0))
    path_solver = Numerics.of(numerics).solver(model)
    run = model.name
    opts = dict(run=run, on_state=log_state(run))
    held = lumen_load(model, start, sw.get("lumen_control", "pressure"))
    base = swelling_load(held, 0.0, 0.0)
    intact = path_solver.follow_path(start.x, base, [base], **opts)[-1]
    steps = sw["conversion_steps"]
    held_at = (
        f"{base.pressure_mmHg:.1f} mmHg"
        if base.pressure_kPa is not None
        else f"inner radius {base.inner_radius:.1f} um"
    )
    log.info(
        "[%s] converting %d medial particles to GAG in %d steps at %s", run, model.props.converting.size, steps, held_at
    )
    conversion = [swelling_load(base, f, 0.0) for f in np.linspace(0, 1, steps + 1)[1:]]
    conv = path_solver.follow_path(intact.x, base, conversion, **opts)[-1]
    pool = POOL_MODELS.lookup(sw.get("pool_model", POOL_MODELS.paper.name))
    pool_model = pool.name
    states = [PoolState.of("intact", 0.0, intact, pool_model=pool_model)]
    try:
        path_solver, conv = pool.convert(path_solver, conv, opts)
        model = path_solver.model
    except solver.NotConverged as exc:
        reason = pool.unconverged(exc)
        log.warning("[%s] the path ends at c = 0 mEq/l: %s", run, reason)
        ended = PoolState.of("converted", 0.0, conv, pool_model=pool_model)
        return [replace(s, path_end="no equilibrium", end_reason=reason) for s in states + [ended]]
    cs = concentration_steps(sw)
    log.info("[%s] swelling: c = %s mEq/l", run, ", ".join(f"{c:g}" for c in cs))
    states.append(PoolState.of("converted", 0.0, conv, model=model, pool_model=pool_model))
    last = conv
    for k, c in enumerate(cs):
        try:  # a step with a fallback: where it finds no equilibrium on its path, the pool's volume takes over
            target = [swelling_load(base, 1.0, c)]
            budget = path_solver.using(max_bisections=solver.FALLBACK_BISECTIONS)  # Newton keeps its iterations
            last = budget.follow_path(last.x, last.load, target, **opts)[-1]
        except solver.NotConverged as exc:
            log.info("[%s] c = %g mEq/l: %s; the pool's volume becomes the control", run, c, exc.reason)
            path, reached = pool_volume.continue_path(path_solver, last, model.props.converting, list(cs[k:]), run=run)
            states += [
                PoolState.of("converted", s.load.material_value("concentration"), s, "volume", model, pool_model)
                for s in reached
            ]
            end = dict(path_end=path.end, limit_concentration=path.limit_concentration, end_reason=path.reason)
            if path.end != "complete":
                log.warning("[%s] the path ends at c = %g mEq/l: %s", run, states[-1].concentration, path.reason)
            return [replace(s, **end) for s in states]
        states.append(PoolState.of("converted", c, last, model=model, pool_model=pool_model))
    return states


def state_model(
    model: Model, cavity: bool, x: np.ndarray, hollow: Model | None = None, pool_model: str | None = None
) -> Model:
    """The model a state of :func:`swell_pool` is in equilibrium with: ``model`` (the run's wall with its pool), or,
    for a state in the converted wall (``cavity``, :attr:`PoolState.cavity`), the pool model's converted wall
    (:meth:`PoolModel.converted_model`; ``hollow`` if given: the one an earlier state of the run rebuilt).
    ``pool_model``: the run's pool model (by default the first that converts its wall, the cavity)."""
    if not cavity:
        return model
    if pool_model is None:
        pool_model = next(name for name, p in POOL_MODELS.items() if p.rebuilds)
    return POOL_MODELS.lookup(pool_model).converted_model(model, x, hollow)


def pool_table(
    model: Model, states: list[PoolState], pool, probe_length: float, gag: Gag | dict, tip_probe: str = "region"
) -> pd.DataFrame:
    """One row per state of :func:`swell_pool`: the Donnan swelling pressure (eq. 2.26), the carried lumen pressure
    and the stresses around the pool (:func:`pool_measurements`, its tips by ``tip_probe``), with the residual of the
    state."""
    gag = Gag.of(gag)
    members = model.props.converting  # the seeded pool (history.HistoryMaterial)
    rows, hollow = [], None
    for st in states:
        at = st.model(model, hollow)
        hollow = at if st.cavity else hollow
        ev = at.evaluate(st.x, st.load)
        row = dict(
            stage=st.stage,
            concentration_mEq_l=st.concentration,
            swelling_pressure_kPa=float(
                swelling_pressure(st.concentration, gag.bath_concentration_mEq_l, gag.temperature_K)
            ),
            pressure_mmHg=measure.carried_pressure(model, ev) / MMHG_TO_KPA,
        )
        row.update(pool_measurements(at, ev, pool, members, probe_length, tip_probe))
        # how the state was reached and how its path ended (what its state file keeps)
        row.update({k: v for k, v in st.info().items() if k not in row and k != "stage"})
        row.update(limit_concentration_mEq_l=st.limit_concentration)  # NaN, not None, without a limit point
        rows.append(row)
    return pd.DataFrame(rows)


def run_table(
    model: Model, saved, pool, probe_length: float, gag: dict, wall: str, case: str, run: str, tip_probe="region"
) -> pd.DataFrame:
    """The rows of one swelling run of figure 4 (rule ``pool_stresses``) from its saved states ``saved``:
    :func:`pool_table` (its tips by ``tip_probe``), first its charge law, pool model, wall model ``wall`` and pool
    ``case``; its tip radial and top hoop stresses intact, converted and at the end logged."""
    table = pool_table(model, [PoolState.from_saved(s) for s in saved], pool, probe_length, gag, tip_probe)
    table.insert(0, "charge_law", gag["charge_law"])
    table.insert(1, "pool_model", table.pop("pool_model"))
    table.insert(2, "model", wall)
    table.insert(3, "case", case)
    first, last = table[table.stage == "converted"].iloc[0], table.iloc[-1]
    log.info(
        "[%s] %d pool particles; tip radial stress %.1f kPa intact, %.1f converted, %.1f at %g mEq/l; "
        "top hoop stress %.1f -> %.1f -> %.1f kPa",
        run,
        int(last.pool_particles),
        table.tip_radial_stress_kPa.iloc[0],
        first.tip_radial_stress_kPa,
        last.tip_radial_stress_kPa,
        last.concentration_mEq_l,
        table.top_circ_stress_kPa.iloc[0],
        first.top_circ_stress_kPa,
        last.top_circ_stress_kPa,
    )
    return table
