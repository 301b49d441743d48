"""A GAG pool's conversion and Gibbs-Donnan swelling at a held lumen pressure (paper section 2.6, figure 4): the
swelling load (eqs. 2.25-2.27), the pool models (:data:`POOL_MODELS`), :func:`swell_pool` (conversion, then the
fixed-charge concentration ramped, each state converged), and the measurements and tables of its states.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np
import pandas as pd

from ..engine import measure, pool_cavity, pool_volume, solver
from ..engine.history import swelling_load
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..physics.donnan import CHARGE_LAWS, ChargeLaw, swelling_pressure
from ..physics.materials import Gag
from ..registry import Registry, Variant

log = logging.getLogger("sphgag")


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
    wildcard ``{pool}``, column ``pool_model``), ``title`` (the figures' heading of its rows), ``noun`` (what the
    verification's run names call the pool) and whether it is the paper's. Its behaviour: the charge laws it carries
    (:meth:`carries`, :attr:`laws`, read from the registry :data:`sphgag.physics.donnan.CHARGE_LAWS` when asked, so a
    plug-in's law too), the wall of a pool swollen from rest (:meth:`around`, the
    verification), what becomes of the wall once the pool is converted (:meth:`convert`, figure 4), and the wall a
    converted state is in equilibrium with (:meth:`converted_model`, :meth:`converts`)."""

    name: str
    title: str
    noun: str
    paper: bool = False

    keys: ClassVar[tuple[str, ...]] = (
        "swelling.pool_models",
        "swelling.variant_pool_models",
        "verification.circular_pool.pool_models",
    )
    #: its converted states are in a wall of its own (:meth:`converted_model`), not the run's
    rebuilds: ClassVar[bool] = False

    def carries(self, law: ChargeLaw) -> bool:
        """Whether it can hold a pool under the charge law ``law``: the paper's particles hold every law."""
        return True

    @property
    def laws(self) -> tuple[str, ...]:
        """The names of the registered charge laws it carries (:meth:`carries`), in the registry's order."""
        return tuple(name for name, law in CHARGE_LAWS.items() if self.carries(law))

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
    ``hourglass`` (:data:`sphgag.engine.forces.HOURGLASS_FORMS`), whatever ``numerics.hourglass`` says: the form as
    printed loses the path next to the swollen cavity (docs/physics.md). The override is logged where it changes the
    form."""

    hourglass: str | None = None
    rebuilds: ClassVar[bool] = True

    def carries(self, law: ChargeLaw) -> bool:
        """A cavity carries one pressure whatever its J: a law that holds the pressure (:meth:`ChargeLaw.
        holds_pressure`)."""
        return law.holds_pressure()

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
        PoolModel("particles", "the pool's GAG particles (eq. 2.27; the paper's)", "pool", paper=True),
        CavityPool(
            "cavity",
            "the pool as a pressurised cavity (our deviation: its lining carries Pi, its contents swell uniformly)",
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
    path_solver = numerics.solver(model)
    run = model.name
    opts = dict(run=run, on_state=solver.log_states(run))
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
