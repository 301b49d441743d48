"""Delamination and coalescence: damage-driven growth of GAG pools (paper section 2.7, figures 5-7).

The answer is a sequence of converged equilibria, not a trajectory. From a
pressurised passive wall (lumen pressure held), the pools of a *pool set* are
seeded (converted to GAG at c = 0, :class:`sphgag.history.HistoryMaterial`); then
the fixed-charge concentration ``c`` is raised level by level to
``max_concentration_mEq_l`` and held there. At every level a staggered scheme runs:

1. solve the equilibrium with the particles' history (damage ``D``, GAG pools) fixed;
2. **damage pass**: update ``D`` of the candidate particles from that state
   (eq. 2.28, :meth:`sphgag.damage.DamageState.update`); particles with ``D = 1``
   rupture and become GAG particles of the nearest pool (their fixed charge rises to
   the pool's along the same path); solve the transition from the old history to
   the new one (a material path the solver can bisect), and repeat;
3. the level ends when a pass changes no ``D`` by more than ``damage_tolerance`` and
   ruptures nothing.

**Pseudo-time** is the number of damage-and-relax passes. The paper's normalised time
is that of its explicit dynamics, in which every time step is one damage update with
at most one step of relaxation; a pass here is one damage update with complete
relaxation, so pseudo-time counts the same updates, each taken to equilibrium.

**Candidates** (the authors' script): tissue particles of the media in a pool's
radial band (the reference radii of its seeded sector), not on a wall surface, within
``candidate_window_deg`` of the pool's current angular extent.

**Onset measure** (``criterion``): ``particle``, the particle's own radial Cauchy stress
(current polar frame), as in the paper; or ``averaged``, the volume-weighted mean of the
radial stress of the intact medial particles within a disc of diameter
``averaging_length_um`` (:func:`sphgag.measure.averaging_matrix`), which has a fixed
physical size. Damage, once started, grows with the radial stretch beyond its onset
value whatever the stress.

**Dissipated energy**: raising ``D`` at fixed deformation releases ``dD W_0 V`` (``W_0``
the intact strain energy density of eq. 2.23, ``V`` the particle's reference area), per
unit axial length; divided by the delaminated length it is an energy per unit
delaminated area (J/m^2).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field, fields

import numpy as np
import pandas as pd
from scipy.spatial import cKDTree

from . import artery, damage, forces, measure, protocols, solver
from . import state as state_io
from .geometry import Sector
from .history import DAMAGED, HistoryMaterial, ParticleHistory
from .loading import MMHG_TO_KPA
from .model import Model

log = logging.getLogger("sphgag")

CRITERIA = ("particle", "averaged")

GROWTH_COLUMNS = [
    "case",
    "sigma_cr_kPa",
    "criterion",
    "dx_um",
    "step",
    "pseudo_time",
    "concentration_mEq_l",
    "converted_particles",
    "converted_interior",
    "converted_exterior",
    "delaminated_length_um",
    "tip_radial_stress_kPa",
    "residual",
]
SUMMARY_COLUMNS = [
    "case",
    "sigma_cr_kPa",
    "criterion",
    "dx_um",
    "onset_concentration_mEq_l",
    "final_length_um",
    "growth_rate_um_per_pseudo_time",
    "growth_rate_um_per_mEq_l",
    "merged",
    "merge_step",
    "dissipated_energy_J_m2",
    "max_residual",
]


@dataclass(frozen=True)
class Settings:
    """The ``delamination`` configuration of one run (see config/schema.yaml)."""

    critical_stress_kPa: float
    rupture_stretch_increment: float
    criterion: str
    averaging_length_um: float
    candidate_window_deg: float
    damage_tolerance: float
    concentration_step_mEq_l: float
    max_concentration_mEq_l: float
    max_passes: int
    max_extent_deg: float
    conversion_steps: int

    def __post_init__(self):
        if self.criterion not in CRITERIA:
            raise ValueError(f"criterion must be one of {CRITERIA}, got {self.criterion!r}")

    @classmethod
    def from_config(cls, de: dict, critical_stress_kPa: float, criterion: str) -> Settings:
        """The settings of one run from the ``delamination`` configuration section."""
        keys = [f.name for f in fields(cls) if f.name not in ("critical_stress_kPa", "criterion")]
        return cls(critical_stress_kPa=float(critical_stress_kPa), criterion=criterion, **{k: de[k] for k in keys})

    @property
    def law(self) -> damage.DamageLaw:
        return damage.DamageLaw(self.critical_stress_kPa, self.rupture_stretch_increment)

    @property
    def levels(self) -> np.ndarray:
        """Concentrations [mEq/l] of the ramp, 0 excluded, ``max_concentration_mEq_l`` included."""
        n = int(np.ceil(self.max_concentration_mEq_l / self.concentration_step_mEq_l - 1e-9))
        return np.linspace(0.0, self.max_concentration_mEq_l, n + 1)[1:]


@dataclass
class Front:
    """The pools' geometry: seeded sectors, candidates and the measures of growth."""

    model: Model
    sectors: list[Sector]
    window_deg: float

    def __post_init__(self):
        lay = self.model.layout
        self.media = lay.layer_mask("media")
        surface = np.zeros(lay.n, dtype=bool)
        surface[lay.inner_surface] = surface[lay.outer_surface] = True
        self.interior = self.media & ~surface
        self.bands = [(lay.radius >= s.r_range[0]) & (lay.radius <= s.r_range[1]) for s in self.sectors]
        self.centres = np.deg2rad([s.centre_angle_deg for s in self.sectors])
        self.thickness = np.array([s.radial_extent for s in self.sectors])
        self._tree = cKDTree(lay.X)

    def candidates(self, hist: ParticleHistory):
        """``(indices, pool)``: tissue particles of the media, off the surfaces, in a pool's radial band and within
        the window of its current angular extent; ``pool`` is the nearest such pool (in angle)."""
        th = self.model.layout.theta
        w = np.deg2rad(self.window_deg)
        best = np.full(hist.n, np.inf)
        pool = np.full(hist.n, -1)
        for k, band in enumerate(self.bands):
            members = hist.members(k)
            lo, hi = th[members].min(), th[members].max()
            dist = np.maximum(lo - th, th - hi)
            ok = band & self.interior & ~hist.gag & (dist <= w) & (dist < best)
            best[ok], pool[ok] = dist[ok], k
        idx = np.flatnonzero(pool >= 0)
        return idx, pool[idx]

    def extent_deg(self, hist: ParticleHistory) -> np.ndarray:
        th = self.model.layout.theta
        return np.array([np.rad2deg(np.ptp(th[hist.members(k)])) for k in range(len(self.sectors))])

    def at_symmetry_edge(self, hist: ParticleHistory) -> bool:
        th = np.rad2deg(self.model.layout.theta[hist.gag])
        return bool(th.min() <= self.window_deg or th.max() >= 90.0 - self.window_deg)

    def converted(self, hist: ParticleHistory):
        """``(total, interior, exterior)`` particles converted by damage; interior: on the side of its pool's
        seeded centre that faces the other pools (two or more pools; NaN for one)."""
        damaged = hist.origin == DAMAGED
        total = int(damaged.sum())
        if len(self.sectors) < 2:
            return total, np.nan, np.nan
        th = self.model.layout.theta
        inner = 0
        for k in range(len(self.sectors)):
            mine = np.flatnonzero(damaged & (hist.pool == k))
            towards = np.sign(np.mean([c for j, c in enumerate(self.centres) if j != k]) - self.centres[k])
            inner += int(np.sum(np.sign(th[mine] - self.centres[k]) == towards))
        return total, inner, total - inner

    def delaminated_length(self, hist: ParticleHistory) -> float:
        """Length [um] of the delaminated arc: the reference area converted by damage over its band's thickness."""
        V = self.model.layout.volume
        damaged = hist.origin == DAMAGED
        return float(sum(V[damaged & (hist.pool == k)].sum() / t for k, t in enumerate(self.thickness)))

    def merged(self, hist: ParticleHistory) -> bool:
        """Two pools touch: a particle of one has a particle of another within 1.5 dx (reference positions)."""
        if len(self.sectors) < 2:
            return False
        lay = self.model.layout
        gag = np.flatnonzero(hist.gag)
        for i, near in zip(gag, self._tree.query_ball_point(lay.X[gag], 1.5 * lay.dx)):
            near = np.asarray(near, dtype=np.int64)
            others = hist.pool[near]
            if np.any((others >= 0) & (others != hist.pool[i])):
                return True
        return False


@dataclass
class Pass:
    """One damage-and-relax pass (a row of growth.csv, before the run's labels)."""

    step: int
    concentration: float
    converted: tuple
    length: float
    tip_stress: float
    residual: float


@dataclass
class Result:
    growth: pd.DataFrame
    summary: dict
    snapshots: list = field(default_factory=list)  # (step, solver.State, ParticleHistory)
    final: tuple | None = None  # (solver.State, ParticleHistory) at the end


def onset_measure(model: Model, ev, hist: ParticleHistory, cand: np.ndarray, settings: Settings) -> np.ndarray:
    """The radial Cauchy stress (eq. 2.10, current polar frame) the onset test of eq. (2.28) compares with sigma_cr,
    at the candidates: the particle's own or its average (module docstring)."""
    srr = measure.cauchy_polar(ev)[0]
    if settings.criterion == "particle":
        return srr[cand]
    lay = model.layout
    intact = np.flatnonzero(lay.layer_mask("media") & ~hist.gag)
    W = measure.averaging_matrix(lay, settings.averaging_length_um, intact, rows=cand)
    return W @ srr


def growth_rates(growth: pd.DataFrame, concentration_step: float) -> tuple[float, float]:
    """Delaminated length per pseudo-time and per mEq/l, over the part of the run in which the pools grew.

    Per pseudo-time: final length / passes from the last pass before the first rupture to the end. Per mEq/l:
    final length / concentration from the level before the first rupture's to the end (so that growth within a
    single level still has a finite rate). Both are 0 without growth.
    """
    grown = growth[growth.delaminated_length_um > 0]
    if not len(grown):
        return 0.0, 0.0
    length = float(growth.delaminated_length_um.iloc[-1])
    first = grown.iloc[0]
    t_span = growth.pseudo_time.iloc[-1] - first.pseudo_time + 1
    c_span = growth.concentration_mEq_l.iloc[-1] - first.concentration_mEq_l + concentration_step
    return length / t_span, length / c_span


def intact_energy(model: Model, ev, base_props: np.ndarray) -> np.ndarray:
    """``W_0`` (eq. 2.23) of every particle with the undamaged material, at the state ``ev``."""
    W = np.empty(model.n)
    forces.energy_densities(ev.F, ev.load.axial_stretch, model.cth, model.sth, base_props, W)
    return W


def grow(
    model: Model,
    start: solver.State,
    sectors: list[Sector],
    settings: Settings,
    numerics: dict,
    gag: dict,
    base,
    snapshot_steps=(),
    run: str | None = None,
    resume: tuple | None = None,
) -> Result:
    """Seed the pools of ``sectors`` in the wall at the converged pressurised state ``start`` and grow them.

    ``base``: the intact wall's material (``load -> props``, e.g. :class:`sphgag.artery.BilayerMaterial`).
    ``snapshot_steps``: pseudo-times at which to keep the state (the first state of every concentration level and
    the last state are always kept). ``resume``: ``(state, history, pseudo_time)`` of a snapshot of this run
    (:func:`load_snapshot`) to continue from instead of seeding; the rows then start there.
    """
    run = run or model.name
    opts = dict(run=run, **protocols.solver_options(numerics))
    lay = model.layout
    front = Front(model, sectors, settings.candidate_window_deg)
    law = settings.law
    if resume is None:
        material = artery.seeding(base, lay, sectors, gag)
        hist = material.history
        model.set_props(material)
        base_load = protocols.swelling_load(start.load, 0.0, 0.0)
        log.info(
            "[%s] seeding %d pool(s) (%d particles) in %d steps at %.1f mmHg; sigma_cr %.0f kPa, %s onset, "
            "rupture at +%.3g radial stretch",
            run,
            len(sectors),
            int(hist.gag.sum()),
            settings.conversion_steps,
            base_load.pressure_mmHg,
            law.critical_stress_kPa,
            settings.criterion,
            law.rupture_stretch_increment,
        )
        state = solver.follow_path(
            model,
            start.x,
            base_load,
            [protocols.swelling_load(base_load, f, 0.0) for f in np.linspace(0, 1, settings.conversion_steps + 1)[1:]],
            **opts,
        )[-1]
        material = material.settled()
        step, c_from = 0, 0.0
    else:
        state, hist, step = resume
        material = HistoryMaterial(base, hist, gag)
        base_load = state.load
        c_from = float(state.load.material_value("concentration"))
        log.info("[%s] resuming at pass %d, c = %g mEq/l (%d GAG particles)", run, step, c_from, int(hist.gag.sum()))
    model.set_props(material)
    if state.evaluation is None:  # a resumed snapshot: evaluate it and measure its residual
        ev = model.evaluate(state.x, state.load)
        conv = state.convergence or solver.Convergence(solver.relative_residual(model, ev), 0, 1, 0, 0.0)
        state = solver.State(state.load, state.x, ev, conv)
    dmg = damage.DamageState(hist.D.copy(), hist.onset_stretch.copy())
    rows, snapshots = [], []
    dissipated = 0.0  # kPa um^2 per unit axial length
    onset_c, merge_step = np.nan, None
    stop = "pass limit"
    max_residual = state.convergence.residual if state.convergence else 0.0
    wanted = set(int(s) for s in snapshot_steps)

    def record(c, tip, st, first_of_level=False):
        rows.append(Pass(step, c, front.converted(hist), front.delaminated_length(hist), tip, st.convergence.residual))
        if (first_of_level or step in wanted) and not any(s[0] == step and s[1].load == st.load for s in snapshots):
            snapshots.append((step, st, hist))
            # the run continues from a snapshot exactly as a restart from it does: without a stale factorisation
            # (equilibria need not be unique, e.g. a crushed tissue bridge between two GAG regions, so the
            # solver's path must be the same)
            model.factorisation = None

    def in_front(state):
        """Candidates, their pools and onset measures, and the largest of these (the row's tip stress)."""
        cand, pools = front.candidates(hist)
        sigma = onset_measure(model, state.evaluation, hist, cand, settings) if cand.size else np.empty(0)
        return cand, pools, sigma, float(sigma.max()) if sigma.size else np.nan

    def level(c, state):
        nonlocal hist, material, dmg, dissipated, onset_c, merge_step, step, max_residual
        cand, pools, sigma, tip = in_front(state)
        record(c, tip, state, first_of_level=True)
        while True:
            ev = state.evaluation
            stretch = damage.radial_stretch(ev.F, lay.theta)
            radial = np.full(lay.n, -np.inf)
            radial[cand] = sigma
            D_old = dmg.D.copy()
            dmg.update(law, cand, radial, stretch)
            dmg.D[hist.gag] = D_old[hist.gag]
            change = float(np.max(dmg.D - D_old, initial=0.0))
            ruptured = np.flatnonzero(dmg.ruptured & ~hist.gag)
            if np.isnan(onset_c) and np.any(~np.isnan(dmg.onset_stretch)):
                onset_c = c
            if change <= settings.damage_tolerance and ruptured.size == 0:
                dmg.D = D_old  # changes below the tolerance are not applied: D stays that of the solved state
                if not np.array_equal(dmg.onset_stretch, hist.onset_stretch, equal_nan=True):
                    hist = hist.with_damage(D_old, dmg.onset_stretch)  # new onsets are history (D unchanged)
                    material = HistoryMaterial(material.base, hist, material.gag)
                    model.set_props(material)
                return state, "arrested"
            W0 = intact_energy(model, ev, material.base(ev.load))
            released = float(np.sum((dmg.D - D_old) * W0 * lay.volume))
            step += 1
            new = hist.with_damage(dmg.D, dmg.onset_stretch)
            if ruptured.size:
                owner = np.full(lay.n, -1)
                owner[cand] = pools
                new = new.rupture(ruptured, owner[ruptured], step)
            path = material.towards(new)
            model.set_props(path)
            load = ev.load
            try:
                state = solver.follow_path(
                    model, state.x, load.with_material(transition=0.0), [load.with_material(transition=1.0)], **opts
                )[-1]
            except solver.NotConverged as exc:
                # no equilibrium along the path to the new history: the growth is unstable (a snap) at this
                # concentration; the run ends at the last converged state, with the reason in the summary
                log.warning(
                    "[%s] pass %d, c = %g mEq/l: %s; growth is unstable here, the run stops at the last "
                    "converged state",
                    run,
                    step,
                    c,
                    exc.reason,
                )
                step -= 1
                dmg.D = D_old
                model.set_props(material)
                return state, "unstable"
            dissipated += released
            material, hist = path.settled(), new
            model.set_props(material)
            state = solver.State(ev.load, state.x, model.evaluate(state.x, ev.load), state.convergence)
            max_residual = max(max_residual, state.convergence.residual)
            if merge_step is None and front.merged(hist):
                merge_step = step
                log.info("[%s] pools merged at pass %d (c = %g mEq/l)", run, step, c)
            cand, pools, sigma, tip = in_front(state)  # also the next pass's onset test
            record(c, tip, state)
            if ruptured.size:
                log.info(
                    "[%s] pass %d, c = %g mEq/l: %d ruptured (%d converted in all), delaminated %.1f um, "
                    "max onset stress %.1f kPa",
                    run,
                    step,
                    c,
                    ruptured.size,
                    rows[-1].converted[0],
                    rows[-1].length,
                    tip,
                )
            if step >= settings.max_passes:
                return state, "pass limit"
            if front.extent_deg(hist).max() >= settings.max_extent_deg:
                return state, "maximum extent"
            if front.at_symmetry_edge(hist):
                return state, "symmetry edge"

    for c in settings.levels[settings.levels >= c_from - 1e-9]:
        load = protocols.swelling_load(base_load, 1.0, float(c))
        if load != state.load:
            state = solver.follow_path(model, state.x, state.load, [load], **opts)[-1]
            max_residual = max(max_residual, state.convergence.residual)
        state, stop = level(float(c), state)
        log.info("[%s] c = %g mEq/l: %s after %d passes, %d converted", run, c, stop, step, rows[-1].converted[0])
        if stop != "arrested":
            break
    length = rows[-1].length
    growth = pd.DataFrame(
        [
            dict(
                step=k,
                pseudo_time=r.step,
                concentration_mEq_l=r.concentration,
                converted_particles=r.converted[0],
                converted_interior=r.converted[1],
                converted_exterior=r.converted[2],
                delaminated_length_um=r.length,
                tip_radial_stress_kPa=r.tip_stress,
                residual=r.residual,
            )
            for k, r in enumerate(rows)
        ]
    )
    rate_t, rate_c = growth_rates(growth, settings.concentration_step_mEq_l)
    summary = dict(
        onset_concentration_mEq_l=onset_c,
        final_length_um=length,
        max_tip_radial_stress_kPa=float(growth.tip_radial_stress_kPa.max()),
        growth_rate_um_per_pseudo_time=rate_t,
        growth_rate_um_per_mEq_l=rate_c,
        merged=merge_step is not None,
        merge_step=merge_step if merge_step is not None else np.nan,
        dissipated_energy_J_m2=1e-3 * dissipated / length if length > 0 else np.nan,
        dissipated_energy_kPa_um2=dissipated,
        stop=stop,
        passes=step,
        max_residual=max_residual,
        pressure_mmHg=measure.carried_pressure(model, state.evaluation) / MMHG_TO_KPA,
    )
    if not any(s[0] == step and s[1].load == state.load for s in snapshots):
        snapshots.append((step, state, hist))
    return Result(growth, summary, snapshots, (state, hist))


def save_snapshots(path, model: Model, snapshots, params: dict) -> None:
    """All snapshots of a run in one ``.npz`` (:func:`sphgag.state.save_series`: positions, load, particle history),
    each with its radial Cauchy stress (eq. 2.10, current polar frame) as ``s{k}_radial_stress_kPa``; ``steps`` and
    ``concentrations`` index them. Each snapshot can restart the run (:func:`load_snapshot`)."""
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


def labelled(result: Result, case: str, settings: Settings, dx: float) -> tuple[pd.DataFrame, pd.DataFrame]:
    """``(growth, summary)`` of one run with the labels of ``results/delamination/{growth,summary}.csv``."""
    labels = dict(case=case, sigma_cr_kPa=settings.critical_stress_kPa, criterion=settings.criterion, dx_um=float(dx))
    growth = result.growth.assign(**labels)[GROWTH_COLUMNS]
    summary = pd.DataFrame([dict(labels, **result.summary)])
    return growth, summary[SUMMARY_COLUMNS + [c for c in summary.columns if c not in SUMMARY_COLUMNS]]


def convergence_study(
    dx: float,
    bilayer: dict,
    numerics: dict,
    homeostasis: dict,
    de: dict,
    gag: dict,
    name: str = "delamination_convergence",
) -> pd.DataFrame:
    """Rows of ``results/delamination/convergence.csv`` for one particle spacing: the one pool set of
    ``de["pool_sets"]`` (figure 5's, by any name) at ``critical_stress_kPa``, every onset criterion, from the passive
    wall pressurised at this spacing."""
    if len(de["pool_sets"]) != 1:
        raise ValueError(f"the resolution study runs one pool set, got {', '.join(de['pool_sets'])}")
    [(case, pools)] = de["pool_sets"].items()
    p = dict(bilayer, dx_um=float(dx))
    wall = artery.bilayer_model(p, numerics, name=name)
    h = protocols.homeostasis(wall, numerics, homeostasis)
    start = protocols.pressurise(wall, h.state, de["pressure_mmHg"], numerics)
    sectors = [artery.pool_sector(s) for s in pools]
    rows = []
    for criterion in de["criteria"]:
        settings = Settings.from_config(de, de["critical_stress_kPa"], criterion)
        model = artery.bilayer_model(p, numerics, name=f"{name}_{criterion}")
        result = grow(
            model, solver.State(start.load, start.x, None, None), sectors, settings, numerics, gag, model.props
        )
        rows.append(labelled(result, case, settings, dx)[1].assign(particles=model.n))
    return pd.concat(rows, ignore_index=True)
