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

import numpy as np
import pandas as pd

from ..engine import measure, pool_cavity, pool_volume, solver
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..physics import analytic
from ..physics.donnan import CHARGE_LAWS, LAWS
from ..physics.materials import Gag, swelling_pressure
from . import artery

log = logging.getLogger("sphgag")


def pressure_points(calibration: dict) -> np.ndarray:
    """Sorted pressures [mmHg] of the sweep: evenly spaced from 0, plus the transmural pressures."""
    sweep = np.linspace(0.0, calibration["max_pressure_mmHg"], calibration["pressure_points"])
    return np.unique(np.round(np.concatenate([sweep, calibration["transmural_pressures_mmHg"]]), 10))


def log_state(run: str):
    """A ``follow_path`` callback that logs each converged state (progress in the rule log)."""

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
    numerics = Numerics.of(numerics)
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
    states = solver.follow_path(
        model,
        model.layout.X,
        Load(1.0, 0.0),
        loads,
        run=run,
        on_state=log_state(run),
        **numerics.solver_options(),
    )
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
    model: Model, numerics: Numerics, homeo: dict, x0=None, start: Load | None = None, activation: float = 0.0
) -> Homeostasis:
    """Figure 2b: ramp every deposition pre-stretch from 1 to its value, inner radius held.

    Nothing is forced: the pressure the state carries is read back three
    ways (reactions of the held inner surface, mean radial stress of the inner
    ring, and global equilibrium ``int sigma_tt dr / r_in``). With
    ``activation > 0`` the active tone is ramped afterwards, still at the held
    radius (``x0``/``start`` then give the passive homeostatic state).
    """
    numerics = Numerics.of(numerics)
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
    state = solver.follow_path(model, x0, start, loads, run=run, on_state=log_state(run), **numerics.solver_options())[
        -1
    ]
    profile = measure.ring_profile(model, state.evaluation)
    r_in = measure.surface_radius(model, state.x, "inner")
    pressures = dict(
        reactions=measure.carried_pressure(model, state.evaluation),
        inner_radial_stress=-float(profile.radial_stress_kPa.iloc[0]),
        hoop_equilibrium=measure.hoop_force(profile) / r_in,
    )
    return Homeostasis(state, pressures, profile, measure.layer_stats(profile))


def pressurise(
    model: Model, homeostatic: solver.State, pressure_mmHg: float, numerics: Numerics, on_state=None
) -> solver.State:
    """The homeostatic state (held radius) moved to ``pressure_mmHg`` under pressure control: first the same
    equilibrium under pressure control at the carried pressure P_h, then the pressure. Every pressurised state of the
    pipeline takes this path (:func:`bilayer_pressure_diameter`, the resolution studies, the sensitivity samples), so
    that the same pressure gives the same state to the bit."""
    numerics = Numerics.of(numerics)
    P_h = measure.carried_pressure(model, homeostatic.evaluation)
    material = homeostatic.load.material
    here = Load(1.0, P_h, material=material)
    return solver.follow_path(
        model,
        homeostatic.x,
        here,
        [here, Load(1.0, pressure_mmHg * MMHG_TO_KPA, material=material)],
        run=model.name,
        on_state=on_state,
        **numerics.solver_options(),
    )[-1]


def pressurised_wall(bilayer: dict, numerics: Numerics, homeostasis_settings: dict, pressure_mmHg: float, name: str):
    """``(model, state)``: the passive wall of ``bilayer`` at its homeostatic state moved to ``pressure_mmHg``
    (:func:`homeostasis`, :func:`pressurise`), the state without
    its evaluation (a start for a run)."""
    wall = artery.bilayer_model(bilayer, numerics, name=name)
    h = homeostasis(wall, numerics, homeostasis_settings)
    start = pressurise(wall, h.state, pressure_mmHg, numerics)
    return wall, solver.State(start.load, start.x, None, None)


def activated(
    model: Model, homeostatic: solver.State, numerics: Numerics, cal: dict, active: bool, label: str = ""
) -> solver.State:
    """The wall at the activation pressure ``cal["activation_pressure_mmHg"]`` (:func:`pressurise` from the
    homeostatic state), with its active tone (eq. 2.24) ramped there in ``cal["activation_steps"]`` steps if
    ``active``: the start of the pressure-diameter sweeps and of every pressurised state of the wall."""
    numerics = Numerics.of(numerics)
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
    start = pressurise(model, homeostatic, P_act, numerics, on_state=on_state)
    if not active:
        return start
    steps = cal["activation_steps"]
    activation = [
        Load(1.0, P_act * MMHG_TO_KPA, material=(("activation", a), ("prestretch", 1.0)))
        for a in np.linspace(0.0, 1.0, steps + 1)[1:]
    ]
    return solver.follow_path(
        model, start.x, start.load, activation, run=run, on_state=on_state, **numerics.solver_options()
    )[-1]


def wall_at(
    model: Model, homeostatic: solver.State, numerics: Numerics, cal: dict, active: bool, pressure_mmHg: float
) -> solver.State:
    """The passive or active wall at ``pressure_mmHg`` under pressure control, by the path of the pressure-diameter
    sweep (:func:`activated`, then one step to the pressure): at the activation pressure, the sweep's own state to the
    bit."""
    numerics = Numerics.of(numerics)
    start = activated(model, homeostatic, numerics, cal, active)
    if abs(pressure_mmHg - cal["activation_pressure_mmHg"]) < 1e-12:
        return start
    load = Load(1.0, pressure_mmHg * MMHG_TO_KPA, material=start.load.material)
    return solver.follow_path(model, start.x, start.load, [load], run=model.name, **numerics.solver_options())[-1]


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
    numerics = Numerics.of(numerics)
    opts = dict(run=model.name, on_state=log_state(model.name), **numerics.solver_options())
    start = activated(model, homeostatic, numerics, cal, active, label)
    P_act = cal["activation_pressure_mmHg"]
    sweep = np.linspace(0.0, cal["max_pressure_mmHg"], cal["pressure_points"])
    pressures = np.unique(np.round(np.concatenate([sweep, cal["state_pressures_mmHg"], [P_act]]), 10))
    down = [P for P in pressures[::-1] if P < P_act]
    up = [P for P in pressures if P > P_act]
    states = [start]
    for branch in (down, up):
        loads = [Load(1.0, P * MMHG_TO_KPA, material=start.load.material) for P in branch]
        states += solver.follow_path(model, start.x, start.load, loads, **opts)
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


def pool_measurements(model: Model, ev, pool, members: np.ndarray, probe_length: float) -> dict:
    """Tip radial and top/bottom circumferential Cauchy stress around a pool (current polar frame).

    Each stress is the volume-weighted mean over a region of fixed physical size
    (:func:`measure.pool_probes`): the medial material ``probe_length`` beyond
    each angular end of the pool across its radial extent (tips) and just
    outside it at its mid-angle (top = outer side, bottom = inner side). Beside
    the tip mean, ``tip_peak_radial_stress_kPa`` is the largest particle value
    in the tip regions (a kernel average next to the pool's corners, which does
    not converge with refinement). ``pool_volume_change`` is the pool's
    ``sum V J / sum V - 1``; for a pool modelled as a cavity (``model.cavities``), the area its lining encloses over
    its reference area, less 1 (:meth:`sphgag.engine.pool_cavity.Cavity.volume_ratio`; the pool's mean and largest J
    are then that ratio too: its contents swell uniformly).
    """
    lay = model.layout
    probes = measure.pool_probes(pool, probe_length)
    tips = [measure.sector_average(ev, lay, probes[k], "rr", lay.pool_layers) for k in ("tip_low", "tip_high")]
    srr, _, _, J_all = measure.cauchy_polar(ev)
    tip_particles = np.concatenate([probes[k].members(lay, layer=lay.pool_layers) for k in ("tip_low", "tip_high")])
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
    and whether the pool was a cavity in this state (``cavity``), and how the run's path ended (the same for every
    state of a run: ``path_end`` ``complete``, ``limit point`` at ``limit_concentration``, or ``no equilibrium``,
    with ``end_reason``)."""

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
        """The state ``state`` of a run with pool model ``pool_model``, in equilibrium with ``model`` (whose
        cavities say whether the pool was a cavity in it)."""
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
            bool(model is not None and model.cavities),
        )

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
class PoolModel:
    """A model of the pool in the figure 4 runs: the charge ``laws`` it carries and the hourglass form
    (:data:`sphgag.engine.hourglass.FORMS`) its wall is solved with once the pool is converted (None: the
    configuration's ``numerics.hourglass``)."""

    laws: tuple[str, ...]
    hourglass: str | None = None


#: the pool models of the figure 4 runs (``swelling.pool_models``, wildcard ``{pool}``, column ``pool_model``):
#: ``particles``, the paper's GAG particles (eq. 2.27), every law; ``cavity``, the pool as a pressurised cavity whose
#: lining carries the prescribed Pi(c) (:mod:`sphgag.engine.pool_cavity`; our deviation), so only the laws that do
#: not conserve the fixed charge (``prescribed``: a cavity carries one pressure, whatever its J), its wall with the
#: energy form of eq. (2.14) (the form as printed loses the path next to the swollen cavity: docs/physics.md)
POOL_MODELS = {
    "particles": PoolModel(CHARGE_LAWS),
    "cavity": PoolModel(tuple(name for name, law in LAWS.items() if not law.conserves_charge), "energy"),
}


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
    3. with ``pool_model: cavity`` in ``sw`` (default ``particles``, the paper's), the converted pool becomes a
       pressurised cavity (:mod:`sphgag.engine.pool_cavity`; our deviation) and the wall is relaxed again at c = 0
       (where it finds no equilibrium, e.g. a long pool squeezed shut, whose lining's faces no contact keeps apart,
       the path ends there: ``no equilibrium``, with the reason);
    4. raise the fixed-charge concentration from 0 to ``max_concentration_mEq_l``
       (``concentration_points`` converged states, c = 0 included).
    The lumen pressure stays constant throughout: it is a follower pressure load
    on the inner surface (pressure control), not a prescribed radius. The states
    are measured by :func:`pool_table`.

    Where a concentration step finds no equilibrium on its path, the pool's own volume becomes the control
    (:func:`sphgag.engine.pool_volume.continue_path`): the path either passes a limit point (the states end at the last
    equilibrium before it, and every state records the limit concentration), or reaches the remaining
    concentrations (``control = volume``), or stops with the concentration still rising (``no equilibrium``: no
    limit point there, the discretisation fails; the reason is recorded). No state beyond the last equilibrium is
    returned.
    """
    numerics = Numerics.of(numerics)
    run = model.name
    opts = dict(run=run, on_state=log_state(run), **numerics.solver_options())
    base = swelling_load(start.load, 0.0, 0.0)
    intact = solver.follow_path(model, start.x, base, [base], **opts)[-1]
    steps = sw["conversion_steps"]
    log.info(
        "[%s] converting %d medial particles to GAG in %d steps at %.1f mmHg",
        run,
        model.props.converting.size,
        steps,
        base.pressure_mmHg,
    )
    conv = solver.follow_path(
        model, intact.x, base, [swelling_load(base, f, 0.0) for f in np.linspace(0, 1, steps + 1)[1:]], **opts
    )[-1]
    pool_model = sw.get("pool_model", "particles")
    if pool_model not in POOL_MODELS:
        raise ValueError(f"unknown pool model {pool_model!r}: one of {', '.join(POOL_MODELS)}")
    states = [PoolState.of("intact", 0.0, intact, pool_model=pool_model)]
    if pool_model == "cavity":
        try:
            model, conv = _hollowed(model, conv, opts)
        except solver.NotConverged as exc:
            reason = f"the unswollen pool has no equilibrium as a cavity ({exc.reason})"
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
            budget = dict(opts, max_bisections=solver.FALLBACK_BISECTIONS)  # Newton keeps its iterations: see solver
            last = solver.follow_path(model, last.x, last.load, target, **budget)[-1]
        except solver.NotConverged as exc:
            log.info("[%s] c = %g mEq/l: %s; the pool's volume becomes the control", run, c, exc.reason)
            path, reached = pool_volume.continue_path(
                model, last, model.props.converting, list(cs[k:]), run=run, **numerics.solver_options()
            )
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


def _hollowed(model: Model, state: solver.State, opts: dict) -> tuple[Model, solver.State]:
    """The model with the pool as the cavity (:func:`state_model`) and its equilibrium at the load of ``state``
    (raises :class:`sphgag.engine.solver.NotConverged` if it has none near ``state``)."""
    log.info("[%s] the pool becomes a cavity: its contents swell uniformly, its lining carries Pi", model.name)
    hollow = state_model(model, True, state.x)
    return hollow, solver.follow_path(hollow, state.x, state.load, [state.load], **opts)[-1]


def state_model(model: Model, cavity: bool, x: np.ndarray, hollow: Model | None = None) -> Model:
    """The model a state of :func:`swell_pool` is in equilibrium with: ``model`` (the run's wall with its pool), or,
    for a state whose pool is a ``cavity``, ``model`` with its pool as the cavity and the cavity's hourglass form
    (:data:`POOL_MODELS`; ``hollow`` if given: the pool's particles are held where the pool became a cavity, so any
    such state of the run rebuilds the same model)."""
    if not cavity:
        return model
    if hollow is not None:
        return hollow
    form = POOL_MODELS["cavity"].hourglass or model.hourglass
    return pool_cavity.hollow(replace(model, hourglass=form, _cache={}), model.props.converting, x)


def pool_table(model: Model, states: list[PoolState], pool, probe_length: float, gag: Gag | dict) -> pd.DataFrame:
    """One row per state of :func:`swell_pool`: the Donnan swelling pressure (eq. 2.26), the carried lumen pressure
    and the stresses around the pool (:func:`pool_measurements`), with the residual of the state."""
    gag = Gag.of(gag)
    members = model.props.converting  # the seeded pool (history.HistoryMaterial)
    rows, hollow = [], None
    for st in states:
        at = state_model(model, st.cavity, st.x, hollow)
        hollow = at if at.cavities else hollow
        ev = at.evaluate(st.x, st.load)
        row = dict(
            stage=st.stage,
            concentration_mEq_l=st.concentration,
            swelling_pressure_kPa=float(
                swelling_pressure(st.concentration, gag.bath_concentration_mEq_l, gag.temperature_K)
            ),
            pressure_mmHg=measure.carried_pressure(model, ev) / MMHG_TO_KPA,
        )
        row.update(pool_measurements(at, ev, pool, members, probe_length))
        # how the state was reached and how its path ended (what its state file keeps)
        row.update({k: v for k, v in st.info().items() if k not in row and k != "stage"})
        row.update(limit_concentration_mEq_l=st.limit_concentration)  # NaN, not None, without a limit point
        rows.append(row)
    return pd.DataFrame(rows)


def run_table(
    model: Model, saved, pool, probe_length: float, gag: dict, wall: str, case: str, run: str
) -> pd.DataFrame:
    """The rows of one swelling run of figure 4 (rule ``pool_stresses``) from its saved states ``saved``:
    :func:`pool_table`, first its charge law, pool model, wall model ``wall`` and pool ``case``; its tip radial and
    top hoop stresses intact, converted and at the end logged."""
    table = pool_table(model, [PoolState.from_saved(s) for s in saved], pool, probe_length, gag)
    table.insert(0, "charge_law", gag["charge_law"])
    table.insert(1, "pool_model", table.pop("pool_model"))
    table.insert(2, "model", wall)
    table.insert(3, "case", case)
    first, last = table[table.stage == "converted"].iloc[0], table.iloc[-1]
    log.info(
        "[%s] %d pool particles; tip radial stress %.1f kPa intact, %.1f converted, %.1f at %g mEq/l; "
        "top hoop stress %.1f -> %.1f -> %.1f kPa",
        run, int(last.pool_particles), table.tip_radial_stress_kPa.iloc[0], first.tip_radial_stress_kPa,
        last.tip_radial_stress_kPa, last.concentration_mEq_l, table.top_circ_stress_kPa.iloc[0],
        first.top_circ_stress_kPa, last.top_circ_stress_kPa,
    )  # fmt: skip
    return table
