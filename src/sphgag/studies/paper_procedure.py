"""The authors' fixed-step explicit procedure, run beside our equilibria (target ``paper_procedure``).

The paper's states come from leapfrog pseudo-dynamics (eqs. 2.12-2.13) with stage-dependent mass scaling and
fixed step counts; nothing checks that a state is in equilibrium (the reference implementation,
``../shared/notes/reference-implementation.md``). This module runs that procedure over our forces
(:func:`sphgag.engine.dynamics.advance`: the same particles, materials, hourglass form, lumen control and hourglass
factor as the quasi-static path, :func:`controlled`), so that a difference between our figures and the paper's can
be traced to the physics or to the procedure.

Figure 4's procedure (:func:`swell`), from the pressurised wall at equilibrium, in the script's three stages:

1. ``relax``: the wall as it is, with the script's relaxation density and viscosity;
2. ``convert``: the pool's particles turned into GAG (eq. 2.27) along a linear ramp of the conversion fraction
   (:class:`sphgag.engine.history.HistoryMaterial`'s ``transition``);
3. ``swell``: the fixed-charge concentration ramped linearly from 0 to ``max_concentration_mEq_l`` under the paper's
   prescribed law (eqs. 2.25-2.27).

Each stage's step count is the script's times the run's ``factor``: the ramps are slower, the pseudo-time step and
masses unchanged. The loads of a ramp change every ``load_update_steps`` steps (a staircase; the script changes them
every step). Every recorded state carries its equilibrium residual (the quasi-static solver's norm,
:func:`sphgag.engine.solver.relative_residual`) and kinetic energy: none is an equilibrium unless its residual says
so.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import dynamics, solver
from ..engine.history import SEEDED, HistoryMaterial, swelling_load
from ..engine.loading import Load
from ..engine.model import Model
from ..options import Options, file_name_problems
from ..physics import donnan, materials
from . import artery
from .delamination.front import Front, damage_step, onset_measure, with_ruptures
from .delamination.settings import Settings
from .pool_swelling import lumen_load, pool_measurements, with_hourglass_factor

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Stage(Options):
    """One stage of the script: its step count, pseudo-density (mass scaling) and viscosity."""

    steps: int
    density: float
    viscosity: float


@dataclass(frozen=True)
class SwellingStages(Options):
    """Figure 4's stages (the script's ``GAG2`` run) and the top of its concentration ramp [mEq/l]."""

    relax: Stage
    convert: Stage
    swell: Stage
    max_concentration_mEq_l: float
    stop_concentration_mEq_l: float
    record_every_mEq_l: float


@dataclass(frozen=True)
class DamageStage(Options):
    """Figure 5's stage (the script's ``Damage`` run): the pool converted at c = 0, every GAG particle's concentration
    rising by ``max_concentration_mEq_l / concentration_steps`` per step up to ``max_concentration_mEq_l``, and
    damage (eq. 2.28) grown at every update of the loads. A particle that ruptures carries no swelling pressure for
    ``relax_steps`` steps; while one does, the viscosity acts and no concentration rises. ``saved_states`` states
    are saved, evenly spaced."""

    steps: int
    density: float
    viscosity: float
    relax_steps: int
    concentration_steps: int
    max_concentration_mEq_l: float
    saved_states: int


@dataclass(frozen=True)
class Timing(Options):
    """How the procedure steps (the ``paper_procedure`` section's ``time_step`` and ``load_update_steps``): the
    pseudo-time step, and the number of steps between two updates of a ramped load (or of the damage)."""

    time_step: float
    load_update_steps: int


@dataclass(frozen=True)
class PaperProcedure(Options):
    """The ``paper_procedure`` configuration section: the spacing ``dx_um`` and lumen pressure of the procedure (and
    of this target's equilibria), figure 4's ``cases`` and ``models``, each stage's step count times the
    ``step_factors``, its stepping (:class:`Timing`: ``time_step``, ``load_update_steps``), the temperature of the
    Donnan pressure (eq. 2.26), figure 4's stages (:class:`SwellingStages`), figure 5's stage (:class:`DamageStage`)
    and the delamination pool sets grown, each at its sigma_cr [kPa]."""

    SECTION = "paper_procedure"

    dx_um: float
    pressure_mmHg: float
    cases: tuple
    models: tuple
    step_factors: tuple
    time_step: float
    load_update_steps: int
    temperature_K: float
    swelling: SwellingStages
    damage: DamageStage
    pool_sets: Mapping

    @classmethod
    def problems(cls, config) -> list[str]:
        """The cases are pools of ``swelling.cases``, the pool sets sets of ``delamination.pool_sets``, the ramp stops
        below its top, and the step factors give distinct file names."""
        sw, pp, problems = config.get("swelling", {}), config.get("paper_procedure", {}), []
        for k, name in enumerate(pp.get("cases", [])):
            if name not in sw.get("cases", {}):
                pools = ", ".join(sw.get("cases", {}))
                problems.append(f"paper_procedure.cases[{k}] = {name!r} is not a pool of swelling.cases ({pools})")
        for name in pp.get("pool_sets", {}):
            if name not in config.get("delamination", {}).get("pool_sets", {}):
                problems.append(f"paper_procedure.pool_sets.{name} is not a set of delamination.pool_sets")
        ramp = pp.get("swelling", {})
        if ramp.get("stop_concentration_mEq_l", 0.0) > ramp.get("max_concentration_mEq_l", float("inf")):
            problems.append(
                f"paper_procedure.swelling.stop_concentration_mEq_l = {ramp['stop_concentration_mEq_l']:g} is above "
                f"the ramp's top, paper_procedure.swelling.max_concentration_mEq_l = "
                f"{ramp['max_concentration_mEq_l']:g}"
            )
        return problems + file_name_problems("paper_procedure", "step_factors", pp.get("step_factors", []))


@dataclass(frozen=True)
class Record:
    """One recorded state of the explicit procedure: where it is on the schedule and how far from equilibrium."""

    stage: str
    step: int
    concentration: float
    x: np.ndarray
    load: Load
    residual: float
    kinetic_energy: float

    def info(self, time_step: float) -> dict:
        return dict(
            stage=self.stage,
            step=self.step,
            pseudo_time=self.step * time_step,
            concentration_mEq_l=self.concentration,
            residual=self.residual,
            kinetic_energy=self.kinetic_energy,
        )


def _record(model: Model, motion: dynamics.Motion, load: Load, stage: str, kinetic: float) -> Record:
    ev = model.evaluate(motion.x, load)
    c = float(load.material_value("concentration", 0.0))
    return Record(stage, motion.step, c, motion.x.copy(), load, solver.relative_residual(model, ev), kinetic)


def ramp(
    model: Model,
    motion: dynamics.Motion,
    start: Load,
    end: Load,
    steps: int,
    stepping: dynamics.Stepping,
    every: int,
    record_at: int,
    name: str,
    run: str,
    until: int | None = None,
    records: list[Record] | None = None,
) -> list[Record]:
    """Leapfrog steps while the load goes linearly from ``start`` to ``end`` in ``steps`` steps, changing every
    ``every`` steps (the load of each block of steps is the one at its end), up to step ``until`` (default: the
    ramp's end); a record every ``record_at`` steps and at the last, appended to ``records`` (returned; a new list
    by default) as they are made, so that a run that fails keeps the records before it."""
    out, done = ([] if records is None else records), 0
    until = steps if until is None else until
    while done < until:
        block = min(every, until - done, record_at - done % record_at)
        done += block
        load = start.lerp(end, done / steps)
        kinetic = dynamics.advance(model, motion, load, block, stepping, run)
        if done % record_at == 0 or done == until:
            out.append(_record(model, motion, load, name, kinetic))
            log.info(
                "[%s] %s: step %d of %d, c = %.4g mEq/l, residual %.3g, kinetic energy %.3g",
                run,
                name,
                done,
                until,
                out[-1].concentration,
                out[-1].residual,
                kinetic,
            )
    return out


def swell(
    model: Model,
    x0: np.ndarray,
    base: Load,
    timing: Timing | dict,
    stages: SwellingStages | dict,
    factor: int,
    run: str,
) -> tuple[list[Record], str]:
    """Figure 4's explicit procedure (module docstring) for the pool seeded in ``model`` from the pressurised wall
    ``x0`` at ``base`` (its lumen held as ``base`` says), every stage's steps times ``factor``: the records at the end
    of the relaxation and of the conversion, then one at every ``record_every_mEq_l`` of the concentration ramp up to
    ``stop_concentration_mEq_l`` (the ramp's rate is that of the whole stage, 0 to ``max_concentration_mEq_l``); and
    how the run ended: ``complete``, or ``stopped: <why>`` where the pseudo-dynamics failed (a particle inverted),
    with the records before it."""
    p, s = Timing.of(timing), SwellingStages.of(stages)
    motion = dynamics.Motion.at_rest(x0)
    intact = swelling_load(base, 0.0, 0.0)
    converted = swelling_load(base, 1.0, 0.0)
    swollen = swelling_load(base, 1.0, s.max_concentration_mEq_l)
    every = p.load_update_steps * factor
    out = []
    try:
        for name, stage, a, b in (("relax", s.relax, intact, intact), ("convert", s.convert, intact, converted)):
            stepping = dynamics.Stepping(p.time_step, stage.density, stage.viscosity)
            steps = stage.steps * factor
            out += ramp(model, motion, a, b, steps, stepping, every, steps, name, run, records=[])[-1:]
        steps = s.swell.steps * factor
        per_mEq = steps / s.max_concentration_mEq_l
        stepping = dynamics.Stepping(p.time_step, s.swell.density, s.swell.viscosity)
        record_at, until = round(s.record_every_mEq_l * per_mEq), round(s.stop_concentration_mEq_l * per_mEq)
        ramp(model, motion, converted, swollen, steps, stepping, every, record_at, "swell", run, until, records=out)
    except solver.SimulationError as exc:
        log.warning("[%s] stopped: %s", run, exc)
        at = exc.load.material_value("concentration", 0.0) if exc.load is not None else np.nan
        return out, f"stopped: {exc.reason} (c = {at:.4g} mEq/l)"
    return out, "complete"


def controlled(model: Model, x0: np.ndarray, base: Load, lumen_control: str, hourglass_factor: float):
    """``(model, load)`` of the swelling stage as the equilibria have them (:func:`.protocols.swell_pool`): the
    lumen of the pressurised state ``x0`` at ``base`` held by ``lumen_control`` (its pressure, or its inner radius:
    the authors' script) and the hourglass modulus E of eq. (2.14) times ``hourglass_factor`` (the script: 0.1)"""
    model = with_hourglass_factor(model, hourglass_factor)
    return model, lumen_load(model, solver.State(base, x0, None, None), lumen_control)


def table(
    model: Model, records: list[Record], pool, probe_length: float, time_step: float, tip_probe: str = "region"
) -> pd.DataFrame:
    """One row per record of :func:`swell`: where it is on the schedule, its residual and kinetic energy, and the
    stresses around the pool (:func:`sphgag.studies.pool_swelling.pool_measurements`, its tips by ``tip_probe``)."""
    rows = []
    for r in records:
        ev = model.evaluate(r.x, r.load)
        at = pool_measurements(model, ev, pool, model.props.converting, probe_length, tip_probe)
        rows.append(dict(r.info(time_step), **at))
    return pd.DataFrame(rows)


FIG4 = ("tip_radial_stress_kPa", "top_circ_stress_kPa", "pool_volume_change")
#: what figures 5 and 6 read from a damage run (:func:`growth`), each with the residual it is read at
GROWTH = {
    "onset_time": "onset_residual",
    "onset_concentration_mEq_l": "onset_residual",
    "growth_rate_um_per_time": "median_residual",
    "teeth": "median_residual",
    "final_length_um": "max_residual",
    "interior_particles": "max_residual",
    "exterior_particles": "max_residual",
}


def summary(equilibrium: pd.DataFrame, swelling: pd.DataFrame, damage: pd.DataFrame, concentration: float):
    """The procedure against the equilibria, one row per quantity and path (long form), each with the residual of
    the state it is read at: figure 4's quantities at ``concentration`` [mEq/l] on the equilibrium path
    (:func:`sphgag.studies.convergence.measure`) and on the explicit runs (:func:`table`, with ``step_factor``), and
    what figures 5 and 6 read from each damage run (:func:`growth`; ``damage``: :func:`delaminate`'s rows with
    ``pool_set``, ``sigma_cr_kPa`` and ``step_factor``)."""
    rows = []

    def add(figure, model, pool, sigma, path, factor, values: dict, residual, end=""):
        for quantity, value in values.items():
            res = residual[quantity] if isinstance(residual, dict) else residual
            rows.append(
                dict(
                    figure=figure,
                    model=model,
                    pool=pool,
                    sigma_cr_kPa=sigma,
                    path=path,
                    step_factor=factor,
                    quantity=quantity,
                    value=value,
                    residual=res,
                    end=end,
                )
            )

    eq = equilibrium[(equilibrium.stage == "converted") & np.isclose(equilibrium.concentration_mEq_l, concentration)]
    for _, r in eq.iterrows():
        add("4", r.model, r.case, np.nan, "equilibrium", np.nan, {k: r[k] for k in FIG4}, r.residual, "converged")
    for (model, case, factor), run in swelling.groupby(["model", "case", "step_factor"], sort=False):
        at = run[(run.stage == "swell") & np.isclose(run.concentration_mEq_l, concentration)]
        if len(at):  # a state at the concentration, whatever its residual
            r = at.iloc[0]
            add("4", model, case, np.nan, "explicit", factor, {k: r[k] for k in FIG4}, r.residual, "fixed steps")
        else:  # the run stopped below it (its end says why): no number
            end = str(run.end.iloc[0]) if "end" in run else "no state"
            add("4", model, case, np.nan, "explicit", factor, {k: np.nan for k in FIG4}, np.nan, end)
    for (pool_set, sigma, factor), g in damage.groupby(["pool_set", "sigma_cr_kPa", "step_factor"], sort=False):
        found = growth(g.reset_index(drop=True), sigma)
        residual = {k: found[v] for k, v in GROWTH.items()}
        add(
            "5" if np.isnan(found["interior_particles"]) else "6",
            "passive",
            pool_set,
            sigma,
            "explicit",
            factor,
            {k: found[k] for k in GROWTH},
            residual,
            found["end"],
        )
    return pd.DataFrame(rows)


@dataclass
class Delamination:
    """Figure 5's explicit stage in progress (:func:`delaminate`): the pools' history and material (on the wall's
    intact material, ``material.base``), each particle's fixed-charge concentration and the step until which it
    relaxes (a rupture)."""

    model: Model
    front: Front
    settings: Settings
    gag: materials.Gag
    material: HistoryMaterial
    load: Load
    concentration: np.ndarray
    relax_until: np.ndarray

    @classmethod
    def seed(cls, model: Model, sectors, settings: Settings, gag, base_load: Load) -> Delamination:
        """The wall ``model`` (its intact material) with the pools of ``sectors`` converted at c = 0."""
        gag = materials.Gag.of(gag)
        if not gag.law.holds_pressure():
            raise ValueError("the explicit damage stage carries a law whose Pi is each particle's c's (the paper's)")
        material = artery.seeding(model.props, model.layout, sectors, gag).settled()
        n = model.n
        load = swelling_load(base_load, 1.0, 0.0)
        return cls(
            model, Front.of(model, sectors, settings), settings, gag, material, load, np.zeros(n), np.full(n, -1)
        )

    @property
    def hist(self):
        return self.material.history

    def table(self, step: int) -> np.ndarray:
        """The property table at ``step``: the pools' material with each GAG particle's swelling pressure Pi(c_i)
        (eqs. 2.25-2.26), none while it relaxes."""
        props = self.material(self.load).copy()
        gag = self.hist.gag & (self.relax_until <= step)
        g = self.gag
        props[self.hist.gag, materials.PI] = 0.0
        props[gag, materials.PI] = donnan.swelling_pressure(
            self.concentration[gag], g.bath_concentration_mEq_l, g.temperature_K
        )
        return props

    def update(self, ev, step: int, stage: DamageStage, factor: int) -> tuple[float, int]:
        """One damage update (eq. 2.28) at the state ``ev`` of step ``step``, as the quasi-static passes do
        (:class:`sphgag.studies.delamination.growth.GrowthRun`): returns the tip stress (the largest onset measure
        of the candidates) and the number of particles that ruptured, which relax from now."""
        hist = self.hist
        cand, pools = self.front.candidates(hist)
        if not cand.size:
            return np.nan, 0
        sigma = onset_measure(self.model, ev, hist, cand, self.settings)
        dmg, _ = damage_step(self.model, self.front, self.settings, self.material, ev, (cand, pools, sigma))
        ruptured = np.flatnonzero(dmg.ruptured & ~hist.gag)
        if np.array_equal(dmg.D, hist.D) and np.array_equal(dmg.onset_stretch, hist.onset_stretch, equal_nan=True):
            return float(sigma.max()), 0
        new = with_ruptures(hist.with_damage(dmg.D, dmg.onset_stretch, dmg.onset_energy), ruptured, cand, pools, step)
        self.concentration[ruptured] = 0.0
        self.relax_until[ruptured] = step + stage.relax_steps * factor
        self.material = HistoryMaterial(self.material.base, new, self.gag)
        return float(sigma.max()), int(ruptured.size)


def delaminate(
    model: Model,
    x0: np.ndarray,
    base_load: Load,
    sectors,
    settings: Settings,
    gag,
    timing: Timing | dict,
    stage: DamageStage | dict,
    factor: int,
    run: str,
) -> tuple[pd.DataFrame, list[Record]]:
    """Figure 5's explicit stage (:class:`DamageStage`) for the pools of ``sectors`` in the wall ``model`` from its
    pressurised state ``x0`` at ``base_load``, every count of steps times ``factor``: one row per update of the
    loads (pseudo-time, the seeded pool's concentration, the tip stress, ruptures, the delaminated length, the
    residual and kinetic energy of the state, and how the run ended, ``end``: ``complete``, or the inversion or
    divergence that stopped it) and ``saved_states`` recorded states."""
    p, d = Timing.of(timing), DamageStage.of(stage)
    run_ = Delamination.seed(model, sectors, settings, gag, base_load)
    motion = dynamics.Motion.at_rest(x0)
    total, block = d.steps * factor, p.load_update_steps * factor
    save_at = {round(total * k / (d.saved_states - 1)) for k in range(1, d.saved_states)}
    rise = d.max_concentration_mEq_l / (d.concentration_steps * factor)
    rows, saved = [], []
    seeded = run_.hist.origin == SEEDED
    while motion.step < total:
        relaxing = bool(np.any(run_.relax_until > motion.step))
        model.set_props(run_.table(motion.step))
        stepping = dynamics.Stepping(p.time_step, d.density, d.viscosity if relaxing else 0.0)
        steps = min(block, total - motion.step)
        try:
            kinetic = dynamics.advance(model, motion, run_.load, steps, stepping, run)
        except solver.SimulationError as exc:  # the run ends there, as the script's would (it would stop with NaNs)
            end = f"{exc.reason} (seeded pool at {run_.concentration[seeded].mean():.4g} mEq/l)"
            log.warning("[%s] the explicit run ends: %s", run, end)
            return pd.DataFrame(rows).assign(end=end), saved
        ev = model.evaluate(motion.x, run_.load)
        residual = solver.relative_residual(model, ev)
        if not relaxing:  # the script: no concentration rises while a ruptured particle relaxes
            rising = run_.hist.gag
            run_.concentration[rising] = np.minimum(
                run_.concentration[rising] + rise * steps, d.max_concentration_mEq_l
            )
        tip, ruptured = run_.update(ev, motion.step, d, factor)
        total_converted, interior, exterior = run_.front.converted(run_.hist)
        rows.append(
            dict(
                step=motion.step,
                pseudo_time=motion.step * p.time_step,
                pool_concentration_mEq_l=float(run_.concentration[seeded].mean()),
                tip_radial_stress_kPa=tip,
                ruptured=ruptured,
                converted_particles=total_converted,
                interior_particles=interior,
                exterior_particles=exterior,
                delaminated_length_um=run_.front.delaminated_length(run_.hist),
                relaxing=relaxing,
                residual=residual,
                kinetic_energy=kinetic,
            )
        )
        capped = float(run_.front.extent_deg(run_.hist).max()) >= settings.max_extent_deg
        if motion.step in save_at or capped:
            c = rows[-1]["pool_concentration_mEq_l"]
            saved.append(Record("damage", motion.step, c, motion.x.copy(), run_.load, residual, kinetic))
            log.info(
                "[%s] damage: step %d of %d, pool c = %.4g mEq/l, %d converted, residual %.3g, kinetic energy %.3g",
                run,
                motion.step,
                total,
                c,
                total_converted,
                residual,
                kinetic,
            )
        if capped:  # the quasi-static runs' growth limit ends the explicit runs too
            end = f"a pool reached the runs' cap, delamination.max_extent_deg = {settings.max_extent_deg:g} deg"
            log.info("[%s] the explicit run ends: %s", run, end)
            return pd.DataFrame(rows).assign(end=end), saved
    return pd.DataFrame(rows).assign(end="complete"), saved


def growth(rows: pd.DataFrame, sigma_cr: float) -> dict:
    """What figure 5 reads from one explicit damage run (:func:`delaminate`'s rows): the pseudo-time and the
    seeded pool's concentration at the first rupture, the mean rate of growth of the delaminated length from then to
    the run's end [um per unit pseudo-time], the number of teeth of the tip stress (ruptures after which the tip
    stress falls by more than 10 % of ``sigma_cr`` before the next rupture), the converted particles on each side
    (two pools), and the residuals: at the first rupture, the median over the run and the largest."""
    rup = rows.index[rows.ruptured > 0]
    last = rows.iloc[-1]
    out = dict(
        end=last.end,
        final_pseudo_time=last.pseudo_time,
        final_length_um=last.delaminated_length_um,
        interior_particles=last.interior_particles,
        exterior_particles=last.exterior_particles,
        median_residual=float(rows.residual.median()),
        max_residual=float(rows.residual.max()),
    )
    if not len(rup):
        return dict(
            out,
            onset_time=np.nan,
            onset_concentration_mEq_l=np.nan,
            onset_residual=np.nan,
            growth_rate_um_per_time=0.0,
            teeth=0,
        )
    first = rows.loc[rup[0]]
    tip = rows.tip_radial_stress_kPa.to_numpy()
    teeth = 0
    for a, b in zip(rup, list(rup[1:]) + [len(rows)]):
        after = tip[a + 1 : b]
        teeth += bool(after.size and np.nanmin(after) < tip[a] - 0.1 * sigma_cr)
    span = last.pseudo_time - first.pseudo_time
    rate = last.delaminated_length_um / span if span > 0 else np.nan
    return dict(
        out,
        onset_time=first.pseudo_time,
        onset_concentration_mEq_l=first.pool_concentration_mEq_l,
        onset_residual=first.residual,
        growth_rate_um_per_time=rate,
        teeth=teeth,
    )
