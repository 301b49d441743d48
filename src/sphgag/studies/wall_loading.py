"""The bi-layered wall's loading (figure 2b and figure 3), run as paths of converged quasi-static states:
:func:`homeostasis` ramps the deposition pre-stretches at a held inner radius; :func:`pressurise` and
:func:`pressurised_wall` bring it to a lumen pressure under pressure control; :func:`activated` switches the active
tone on. Figure 3's sweep from the homeostatic state, beside the semi-analytical bi-layered tube, is
:func:`sphgag.studies.pressure_diameter.bilayer_pressure_diameter`.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import measure, solver
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import REFERENCE, Options, file_name_problems, role
from . import artery

log = logging.getLogger("sphgag")


def above_sweep(config, section: str, key: str) -> list[str]:
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
class HomeostasisSettings(Options):
    """The ``homeostasis`` configuration section, figure 2b (:func:`homeostasis`): the deposition pre-stretches ramped
    in ``prestretch_steps`` at the in vivo inner radius, and the pressure Table 2's pre-stretches were chosen to carry
    (for comparison)."""

    SECTION = "homeostasis"

    prestretch_steps: int
    target_pressure_mmHg: float = role(REFERENCE)  # a reference value: not part of the states' slice


@dataclass(frozen=True)
class BilayerCalibration(Options):
    """The ``bilayer_calibration`` configuration section (:func:`.pressure_diameter.bilayer_pressure_diameter`): the
    active tone (eq. 2.24) switched on at ``activation_pressure_mmHg`` in ``activation_steps``, the sweep of
    ``pressure_points`` pressures up to ``max_pressure_mmHg``, and the pressures whose states are saved (every later
    stage starts from one of them)."""

    SECTION = "bilayer_calibration"

    activation_pressure_mmHg: float
    activation_steps: int
    max_pressure_mmHg: float
    pressure_points: int
    state_pressures_mmHg: tuple

    @staticmethod
    def activation(section: Mapping) -> dict:
        """The keys of the section ``section`` that switch the active tone on (eq. 2.24): what a job that activates a
        wall anew reads of it."""
        return {k: section[k] for k in ("activation_pressure_mmHg", "activation_steps")}

    @classmethod
    def problems(cls, config) -> list[str]:
        """The saved and the activation pressures inside the sweep, each saved pressure giving its own file name."""
        values = config.get("bilayer_calibration", {}).get("state_pressures_mmHg", [])
        return (
            above_sweep(config, "bilayer_calibration", "state_pressures_mmHg")
            + above_sweep(config, "bilayer_calibration", "activation_pressure_mmHg")
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
    path_solver = path_solver or numerics.solver(model)
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
    state = path_solver.follow_path(x0, start, loads, run=run, on_state=solver.log_states(run))[-1]
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
    pipeline takes this path (:func:`.pressure_diameter.bilayer_pressure_diameter`, the resolution studies, the
    sensitivity samples), so that the same pressure gives the same state to the bit. ``path_solver``: as
    :func:`homeostasis`'s."""
    path_solver = path_solver or numerics.solver(model)
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
    path_solver = numerics.solver(wall)
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
    path_solver = path_solver or numerics.solver(model)
    run = model.name
    P_act = cal["activation_pressure_mmHg"]
    on_state = solver.log_states(run)
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
    path_solver = path_solver or numerics.solver(model)
    start = activated(model, homeostatic, numerics, cal, active, path_solver=path_solver)
    if abs(pressure_mmHg - cal["activation_pressure_mmHg"]) < 1e-12:
        return start
    load = Load(1.0, pressure_mmHg * MMHG_TO_KPA, material=start.load.material)
    return path_solver.follow_path(start.x, start.load, [load], run=model.name)[-1]
