"""Delamination and coalescence: damage-driven growth of GAG pools (paper section 2.7, figures 5-7).

The answer is a sequence of converged equilibria, not a trajectory. From a
pressurised passive wall (lumen pressure held), the pools of a *pool set* are
seeded (converted to GAG at c = 0, :class:`sphgag.engine.history.HistoryMaterial`); then
the fixed-charge concentration ``c`` is raised level by level to
``max_concentration_mEq_l`` and held there. At every level a staggered scheme runs:

1. solve the equilibrium with the particles' history (damage ``D``, GAG pools) fixed;
2. **damage pass**: update ``D`` of the candidate particles from that state
   (eq. 2.28, :meth:`sphgag.physics.damage.DamageState.update`); particles with ``D = 1``
   rupture and become GAG particles of the nearest pool (their fixed charge rises to
   the pool's along the same path); solve the transition from the old history to
   the new one (a material path the solver can bisect), and repeat;
3. the level ends when a pass changes no ``D`` by more than ``damage_tolerance`` and
   ruptures nothing.

**Snaps.** A damage pass whose new history cannot be reached along its transition, or a
concentration step with no equilibrium on its path (after bisection), has lost
equilibrium: the wall snaps. The run follows the snap to where the overdamped
pseudo-dynamics come to rest (:mod:`sphgag.engine.snap`), records that state (converged below
the tolerance, ``snap`` in growth.csv) and keeps growing from it at the same
concentration. A run ends where a level arrests at the highest concentration
(``arrested``), where the pools merge (``merged``), where a pool spans ``max_extent_deg``
(``maximum extent``) or comes within the candidate window of a symmetry edge
(``symmetry edge``), after ``max_passes`` (``pass limit``), or where a snap comes to rest at
no equilibrium (``no stable state after a snap``, with the step and load): always at its
last equilibrium.

**Pseudo-time** is the number of damage-and-relax passes. The paper's normalised time
is that of its explicit dynamics, in which every time step is one damage update with
at most one step of relaxation; a pass here is one damage update with complete
relaxation, so pseudo-time counts the same updates, each taken to equilibrium.

**Candidates** (``candidates``, :data:`sphgag.studies.candidates.RULES`): tissue particles of the media in a
pool's radial band (the reference radii of its seeded sector), not on a wall surface, within
``candidate_window_deg`` of the pool's current angular extent (the authors' script, ``window``), and by default
(``contact``, the paper's "radial stress at the tip of the pool") only those with a GAG particle of the pool within
1.5 dx in the reference configuration.

**Delaminated length**: the reference area converted by damage and connected to its pool (through the reference
neighbours within 1.5 dx among the pool's GAG particles, from its seeded ones) over the band's thickness. Converted
particles not connected to their pool are *islands*, counted apart (``islands``, ``island_particles``,
``island_distance_um``); ``converted_particles`` counts both.

**Onset measure** (``criterion``): ``particle``, the particle's own radial Cauchy stress
(current polar frame), as in the paper; or ``averaged``, the volume-weighted mean of the
radial stress of the intact medial particles within a disc of diameter
``averaging_length_um`` (:func:`sphgag.engine.measure.averaging_matrix`), which has a fixed
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
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from ..engine import forces, measure, snap, solver
from ..engine.geometry import Sector
from ..engine.history import DAMAGED, SEEDED, HistoryMaterial, ParticleHistory
from ..engine.loading import MMHG_TO_KPA, Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..physics import damage, fracture, materials
from ..records import state as state_io
from . import artery, protocols
from .candidates import RULES
from .onset import CRITERIA

log = logging.getLogger("sphgag")

#: the contact distance in the reference configuration, in particle spacings: two particles within it touch (pools
#: merge, a candidate touches its pool, a converted particle is connected to its neighbour)
CONTACT_DX = 1.5

GROWTH_COLUMNS = [
    "case",
    "sigma_cr_kPa",
    "criterion",
    "candidates",
    "dx_um",
    "damage_law",
    "fracture_energy_J_m2",
    "step",
    "pseudo_time",
    "concentration_mEq_l",
    "converted_particles",
    "converted_interior",
    "converted_exterior",
    "delaminated_length_um",
    "islands",
    "island_particles",
    "island_distance_um",
    "tip_radial_stress_kPa",
    "residual",
    "snap",
]
SUMMARY_COLUMNS = [
    "case",
    "sigma_cr_kPa",
    "criterion",
    "candidates",
    "dx_um",
    "damage_law",
    "fracture_energy_J_m2",
    "onset_concentration_mEq_l",
    "final_length_um",
    "islands",
    "island_particles",
    "island_distance_um",
    "outcome",
    "stop",
    "snaps",
    "snap_length_um",
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
    damage_law: str = "paper"  # damage.LAWS: eq. (2.28) as printed, or with a fracture energy
    fracture_energy_J_m2: float = np.nan  # G_c of the fracture_energy law
    candidates: str = "contact"  # candidates.RULES: the particles touching the pool (the paper), or the window

    def __post_init__(self):
        if self.criterion not in CRITERIA:
            raise ValueError(f"criterion must be one of {', '.join(CRITERIA)}, got {self.criterion!r}")
        if self.candidates not in RULES:
            raise ValueError(f"candidates must be one of {', '.join(RULES)}, got {self.candidates!r}")
        if self.damage_law not in damage.LAWS:
            raise ValueError(f"damage_law must be one of {', '.join(damage.LAWS)}, got {self.damage_law!r}")

    @classmethod
    def config_keys(cls) -> tuple[str, ...]:
        """The keys of the ``delamination`` configuration section that every run reads (:meth:`from_config`); sigma_cr,
        the onset criterion and the damage law are each run's own."""
        own = ("critical_stress_kPa", "criterion", "damage_law", "fracture_energy_J_m2")
        return tuple(f.name for f in fields(cls) if f.name not in own)

    @classmethod
    def from_config(
        cls, de: dict, critical_stress_kPa: float, criterion: str, fracture_energy_J_m2: float | None = None
    ) -> Settings:
        """The settings of one run from the ``delamination`` configuration section (its :meth:`config_keys`): eq.
        (2.28) as printed, or the fracture-energy law where ``fracture_energy_J_m2`` (G_c) is given."""
        keys = cls.config_keys()
        law = dict(damage_law="paper")
        if fracture_energy_J_m2 is not None:
            law = dict(damage_law="fracture_energy", fracture_energy_J_m2=float(fracture_energy_J_m2))
        return cls(
            critical_stress_kPa=float(critical_stress_kPa), criterion=criterion, **law, **{k: de[k] for k in keys}
        )

    @property
    def law(self) -> damage.DamageLaw | damage.FractureEnergyLaw:
        """The run's damage law, from the registry :data:`sphgag.physics.damage.LAWS`."""
        return damage.LAWS[self.damage_law].of(self)

    @property
    def levels(self) -> np.ndarray:
        """Concentrations [mEq/l] of the ramp, 0 excluded, ``max_concentration_mEq_l`` included."""
        n = int(np.ceil(self.max_concentration_mEq_l / self.concentration_step_mEq_l - 1e-9))
        return np.linspace(0.0, self.max_concentration_mEq_l, n + 1)[1:]


@dataclass(frozen=True)
class Islands:
    """Particles converted by damage (eq. 2.28, D = 1; section 2.7) that are not connected to their pool
    (:meth:`Front.islands`): ``count`` connected components of them, ``particles`` in all, and the reference distance
    [um] from the nearest of them to the nearest particle of its connected pool (NaN without islands)."""

    count: int = 0
    particles: int = 0
    distance_um: float = np.nan


@dataclass
class Front:
    """The pools' geometry: seeded sectors, candidates and the measures of growth.

    ``rule``: the candidate rule (:data:`sphgag.studies.candidates.RULES`). ``adjacent``: the reference-neighbour
    graph, particles within :data:`CONTACT_DX` spacings in the reference configuration (a symmetric sparse matrix).
    """

    model: Model
    sectors: list[Sector]
    window_deg: float
    rule: str = "contact"

    def __post_init__(self):
        lay = self.model.layout
        self.media = lay.layer_mask("media")
        surface = np.zeros(lay.n, dtype=bool)
        surface[lay.inner_surface] = surface[lay.outer_surface] = True
        self.interior = self.media & ~surface
        self.bands = [(lay.radius >= s.r_range[0]) & (lay.radius <= s.r_range[1]) for s in self.sectors]
        self.centres = np.deg2rad([s.centre_angle_deg for s in self.sectors])
        self.thickness = np.array([s.radial_extent for s in self.sectors])
        pairs = cKDTree(lay.X).query_pairs(CONTACT_DX * lay.dx, output_type="ndarray")
        i, j = np.concatenate([pairs[:, 0], pairs[:, 1]]), np.concatenate([pairs[:, 1], pairs[:, 0]])
        self.adjacent = csr_matrix((np.ones(i.size, dtype=np.int8), (i, j)), shape=(lay.n, lay.n))

    @classmethod
    def of(cls, model: Model, sectors: list[Sector], settings: Settings) -> Front:
        """The front of a run with ``settings`` (its candidate window and rule)."""
        return cls(model, sectors, settings.candidate_window_deg, settings.candidates)

    def candidates(self, hist: ParticleHistory):
        """``(indices, pool)``: tissue particles of the media, off the surfaces, in a pool's radial band, within the
        window of its current angular extent and admitted by the candidate rule for that pool; ``pool`` is the
        nearest such pool (in angle)."""
        th = self.model.layout.theta
        w = np.deg2rad(self.window_deg)
        admits = RULES[self.rule].admits
        best = np.full(hist.n, np.inf)
        pool = np.full(hist.n, -1)
        for k, band in enumerate(self.bands):
            members = hist.members(k)
            lo, hi = th[members].min(), th[members].max()
            dist = np.maximum(lo - th, th - hi)
            ok = band & self.interior & ~hist.gag & (dist <= w) & (dist < best) & admits(self, hist, k)
            best[ok], pool[ok] = dist[ok], k
        idx = np.flatnonzero(pool >= 0)
        return idx, pool[idx]

    def touching(self, hist: ParticleHistory, pool: int) -> np.ndarray:
        """The particles (a mask) with a GAG particle of ``pool`` (seeded or converted) within the contact distance
        in the reference configuration."""
        return self.adjacent @ (hist.pool == pool).astype(np.int64) > 0

    def extent_deg(self, hist: ParticleHistory) -> np.ndarray:
        th = self.model.layout.theta
        return np.array([np.rad2deg(np.ptp(th[hist.members(k)])) for k in range(len(self.sectors))])

    def at_symmetry_edge(self, hist: ParticleHistory) -> bool:
        th = np.rad2deg(self.model.layout.theta[hist.gag])
        return bool(th.min() <= self.window_deg or th.max() >= 90.0 - self.window_deg)

    def converted(self, hist: ParticleHistory):
        """``(total, interior, exterior)`` particles converted by damage (islands included); interior: on the side
        of its pool's seeded centre that faces the other pools (two or more pools; NaN for one)."""
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

    def parts(self, hist: ParticleHistory, pool: int) -> tuple[np.ndarray, np.ndarray, int]:
        """``(connected, islands, count)`` of ``pool``: its GAG particles connected to its seeded ones through the
        reference-neighbour graph (:attr:`adjacent`) among its GAG particles, those that are not (indices), and the
        number of connected components of the latter."""
        mine = hist.members(pool)
        _, label = connected_components(self.adjacent[mine][:, mine], directed=False)
        attached = np.isin(label, label[hist.origin[mine] == SEEDED])
        return mine[attached], mine[~attached], np.unique(label[~attached]).size

    def delaminated_length(self, hist: ParticleHistory) -> float:
        """Length [um] of the delaminated arc: the reference area converted by damage and connected to its pool
        (:meth:`parts`) over its band's thickness; islands do not count."""
        V, damaged = self.model.layout.volume, hist.origin == DAMAGED
        length = 0.0
        for k, t in enumerate(self.thickness):
            connected = self.parts(hist, k)[0]
            length += V[connected[damaged[connected]]].sum() / t
        return float(length)

    def islands(self, hist: ParticleHistory) -> Islands:
        """The converted particles not connected to their pool (:meth:`parts`), over all pools."""
        X = self.model.layout.X
        count = particles = 0
        distance = np.inf
        for k in range(len(self.sectors)):
            connected, apart, n = self.parts(hist, k)
            if apart.size:
                count, particles = count + n, particles + apart.size
                distance = min(distance, float(cKDTree(X[connected]).query(X[apart])[0].min()))
        return Islands(count, particles, distance if count else np.nan)

    def merged(self, hist: ParticleHistory) -> bool:
        """Two pools touch: a particle of one has a particle of another within the contact distance (reference
        positions)."""
        return any(
            np.any(self.touching(hist, k) & (hist.pool >= 0) & (hist.pool != k)) for k in range(len(self.sectors))
        )


@dataclass
class Pass:
    """One damage-and-relax pass (a row of growth.csv, before the run's labels)."""

    step: int
    concentration: float
    converted: tuple
    length: float
    islands: Islands
    tip_stress: float
    residual: float
    snap: bool = False  # reached through a snap (sphgag.engine.snap)


@dataclass
class Result:
    growth: pd.DataFrame
    summary: dict
    snapshots: list = field(default_factory=list)  # (step, solver.State, ParticleHistory)
    final: tuple | None = None  # (solver.State, ParticleHistory) at the end


def onset_measure(model: Model, ev, hist: ParticleHistory, cand: np.ndarray, settings: Settings) -> np.ndarray:
    """The radial Cauchy stress (eq. 2.10, current polar frame) the onset test of eq. (2.28) compares with sigma_cr,
    at the candidates, by the run's onset criterion (:data:`sphgag.studies.onset.CRITERIA`)."""
    return CRITERIA[settings.criterion].measure(model, ev, hist, cand, settings)


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


def first_level_growth(growth: pd.DataFrame) -> tuple[float, float]:
    """``(concentration, length)``: the first concentration level at which the pools grew, and the length they grew
    at that level (snaps included); ``(nan, 0)`` without growth."""
    grew = growth.delaminated_length_um.diff() > 0
    if not grew.any():
        return np.nan, 0.0
    c = float(growth.concentration_mEq_l[grew].iloc[0])
    level = growth[np.isclose(growth.concentration_mEq_l, c)].delaminated_length_um
    return c, float(level.iloc[-1] - level.iloc[0])


def outcome(stop: str, length: float, merged: bool) -> str:
    """What a run did: ``merges``, ``grows`` (it ended growing, for the reason in ``stop``), ``arrests`` (it grew and
    stopped at the highest concentration) or ``no growth``."""
    if merged:
        return "merges"
    if length <= 0.0:
        return "no growth"
    return "arrests" if stop == "arrested" else "grows"


#: what a pool does at one level of the concentration ramp (the delamination map, :func:`level_classes`)
LEVEL_CLASSES = ("no onset", "onset, arrested", "propagation", "no equilibrium")


def level_classes(growth: pd.DataFrame, summary: dict, levels) -> pd.DataFrame:
    """What the pools of one run do at each concentration ``levels`` of its ramp (one of :data:`LEVEL_CLASSES`).

    * below the level the run stopped in (``stop_level_mEq_l``), or in it if the run ended arrested there, the pools
      came to a stable state: ``no onset`` if damage has not begun (sigma_cr of eq. 2.28 not reached) by that level,
      ``onset, arrested`` otherwise (whatever they grew on the way);
    * in and beyond the level the run stopped in without arresting: ``propagation`` if it stopped during that level's
      damage passes (merged, maximum extent, symmetry edge, pass limit, or a damage pass with no stable state after
      it), ``no equilibrium`` if the ramp could not reach the level at all (the swollen wall has no stable state
      there, before any new damage: the limit point of figure 4's swelling, or a failure of the discretisation).

    Rows: ``concentration_mEq_l``, ``state``, ``delaminated_length_um`` (at the level's last equilibrium; NaN beyond
    the run).
    """
    stop_level, stop = float(summary["stop_level_mEq_l"]), str(summary["stop"])
    onset = float(summary["onset_concentration_mEq_l"])
    reached = growth.concentration_mEq_l.to_numpy()
    beyond = "propagation" if np.any(np.abs(reached - stop_level) < 1e-9) else "no equilibrium"
    rows = []
    for c in levels:
        at = growth[np.abs(reached - c) < 1e-9]
        stable = c < stop_level - 1e-9 or (stop == "arrested" and c <= stop_level + 1e-9)
        if stable:
            state = "onset, arrested" if onset <= c + 1e-9 else "no onset"
        else:
            state = beyond
        length = float(at.delaminated_length_um.iloc[-1]) if len(at) else np.nan
        rows.append(dict(concentration_mEq_l=float(c), state=state, delaminated_length_um=length))
    return pd.DataFrame(rows)


def intact_energy(model: Model, ev, base_props: np.ndarray) -> np.ndarray:
    """``W_0`` (eq. 2.23) of every particle with the undamaged material, at the state ``ev``."""
    W = np.empty(model.n)
    forces.energy_densities(ev.F, ev.load.axial_stretch, model.cth, model.sth, base_props, W)
    return W


@dataclass
class GrowthRun:
    """One delamination run as a record of its state, with one method per step of the protocol.

    :meth:`seed` (or :meth:`resume`) makes the run; :meth:`raise_concentration` moves it to the next level of the
    ramp; :meth:`next_history` is one damage update; :meth:`damage_pass` solves the history it makes;
    :meth:`follow_snap` follows a step that has no equilibrium on its path; :meth:`level` repeats damage passes at
    one concentration until the pools arrest or the run ends; :meth:`run` walks the ramp and returns the
    :class:`Result`. Every state the run holds is converged below the solver tolerance.
    """

    model: Model
    front: Front
    settings: Settings
    opts: dict  # solver options and the run name (Numerics.solver_options)
    material: HistoryMaterial
    state: solver.State
    step: int = 0  # pseudo-time: damage passes so far
    wanted: frozenset = frozenset()  # pseudo-times at which to keep a snapshot
    rows: list = field(default_factory=list)
    snapshots: list = field(default_factory=list)
    dissipated: float = 0.0  # kPa um^2 per unit axial length
    onset_c: float = np.nan
    merge_step: int | None = None
    max_residual: float = 0.0
    snaps: int = 0
    snap_length: float = 0.0  # delaminated length gained through snaps [um]
    tip: float = np.nan  # largest onset measure of the current state (the last row's tip stress)
    _front: tuple = ()  # (candidates, their pools, their onset measures) of the current state

    @property
    def run_name(self) -> str:
        return self.opts["run"]

    @property
    def hist(self) -> ParticleHistory:
        return self.material.history

    # -- making a run ---------------------------------------------------------------------------------------------
    @classmethod
    def seed(cls, model, start, sectors, settings, numerics, gag, base, run=None, snapshot_steps=()) -> GrowthRun:
        """Convert the medial particles of ``sectors`` to GAG pools at c = 0 in the converged pressurised state
        ``start`` (``settings.conversion_steps`` converged increments of the seeding path)."""
        numerics = Numerics.of(numerics)
        opts = dict(run=run or model.name, **numerics.solver_options())
        material = artery.seeding(base, model.layout, sectors, gag)
        model.set_props(material)
        base_load = protocols.swelling_load(start.load, 0.0, 0.0)
        law = settings.law
        log.info(
            "[%s] seeding %d pool(s) (%d particles) in %d steps at %.1f mmHg; sigma_cr %.0f kPa, %s onset, %s",
            opts["run"],
            len(sectors),
            int(material.history.gag.sum()),
            settings.conversion_steps,
            base_load.pressure_mmHg,
            law.critical_stress_kPa,
            settings.criterion,
            law.rupture,
        )
        fractions = np.linspace(0, 1, settings.conversion_steps + 1)[1:]
        state = solver.follow_path(
            model, start.x, base_load, [protocols.swelling_load(base_load, f, 0.0) for f in fractions], **opts
        )[-1]
        run = cls(model, Front.of(model, sectors, settings), settings, opts, material, state)
        run.wanted = frozenset(int(s) for s in snapshot_steps)
        run._settle(material.settled())
        run._accept(state)
        return run

    @classmethod
    def resume(cls, model, snapshot, sectors, settings, numerics, gag, base, run=None, snapshot_steps=()) -> GrowthRun:
        """Continue from ``snapshot = (state, history, pseudo_time)`` of this run (:func:`load_snapshot`)."""
        numerics = Numerics.of(numerics)
        state, hist, step = snapshot
        opts = dict(run=run or model.name, **numerics.solver_options())
        material = HistoryMaterial(base, hist, gag)
        model.set_props(material)
        log.info(
            "[%s] resuming at pass %d, c = %g mEq/l (%d GAG particles)",
            opts["run"],
            step,
            state.load.material_value("concentration"),
            int(hist.gag.sum()),
        )
        if state.evaluation is None:  # a saved snapshot: evaluate it and measure its residual
            ev = model.evaluate(state.x, state.load)
            conv = state.convergence or solver.Convergence(solver.relative_residual(model, ev), 0, 1, 0, 0.0)
            state = solver.State(state.load, state.x, ev, conv)
        run = cls(model, Front.of(model, sectors, settings), settings, opts, material, state, step)
        run.wanted = frozenset(int(s) for s in snapshot_steps)
        run._accept(state)
        return run

    # -- steps of the protocol ------------------------------------------------------------------------------------
    @property
    def concentration(self) -> float:
        return float(self.state.load.material_value("concentration"))

    def raise_concentration(self, c: float) -> None:
        """Move the run to the fixed-charge concentration ``c`` (mEq/l) with its history fixed; a step with no
        equilibrium on its path is followed as a snap."""
        load = protocols.swelling_load(self.state.load, 1.0, float(c))
        if load == self.state.load:
            return
        try:
            state = solver.follow_path(self.model, self.state.x, self.state.load, [load], **self.opts)[-1]
        except solver.NotConverged as exc:
            state = self.follow_snap(load, f"c = {self.concentration:g} -> {c:g} mEq/l", exc)
        self._accept(state)

    def next_history(self) -> tuple[ParticleHistory, float] | None:
        """The history one damage update (eq. 2.28) from the current state makes, and the energy the update releases
        at the current deformation [kPa um^2 per unit axial length]; None if it would change no ``D`` by more than
        ``damage_tolerance`` and rupture nothing (new onsets are then made history, D unchanged)."""
        hist, lay = self.hist, self.model.layout
        cand, pools, sigma = self._front
        ev = self.state.evaluation
        dmg = damage.DamageState(hist.D.copy(), hist.onset_stretch.copy(), hist.onset_energy.copy())
        radial = np.full(lay.n, -np.inf)
        radial[cand] = sigma
        W0 = intact_energy(self.model, ev, self.material.base(ev.load))
        band = np.full(lay.n, np.nan)
        band[cand] = self.front.thickness[pools]  # the band a pool's growth converts: its radial extent
        dmg.update(self.settings.law, cand, radial, damage.radial_stretch(ev.F, lay.theta), W0, band)
        dmg.D[hist.gag] = hist.D[hist.gag]
        ruptured = np.flatnonzero(dmg.ruptured & ~hist.gag)
        if np.isnan(self.onset_c) and np.any(~np.isnan(dmg.onset_stretch)):
            self.onset_c = self.concentration
        if float(np.max(dmg.D - hist.D, initial=0.0)) <= self.settings.damage_tolerance and ruptured.size == 0:
            if not np.array_equal(dmg.onset_stretch, hist.onset_stretch, equal_nan=True):
                # new onsets are history; changes of D below the tolerance are not applied
                onsets = hist.with_damage(hist.D, dmg.onset_stretch, dmg.onset_energy)
                self._settle(HistoryMaterial(self.material.base, onsets, self.material.gag))
            return None
        released = float(np.sum((dmg.D - hist.D) * W0 * lay.volume))
        new = hist.with_damage(dmg.D, dmg.onset_stretch, dmg.onset_energy)
        if ruptured.size:
            owner = np.full(lay.n, -1)
            owner[cand] = pools
            new = new.rupture(ruptured, owner[ruptured], self.step + 1)
        return new, released

    def damage_pass(self) -> bool:
        """One damage pass: the next history (:meth:`next_history`) and the solve of its transition from the current
        state (a snap where the transition has no equilibrium on its path); False if the damage did not change."""
        update = self.next_history()
        if update is None:
            return False
        new, released = update
        hist, step = self.hist, self.step + 1
        ruptured = np.flatnonzero(new.gag & ~hist.gag)
        load = self.state.load
        state, self.material, snapped = snap.transition(
            self.model,
            self.state.x,
            self.material,
            new,
            load,
            self.opts,
            lambda exc: self.follow_snap(load, f"pass {step}", exc),  # NoStableState leaves the run as it was
        )
        self.step = step
        self.dissipated += released
        self._accept(state)
        if snapped:
            self.snap_length += self.front.delaminated_length(new) - self.front.delaminated_length(hist)
        self._record(snapped=snapped)
        if ruptured.size:
            log.info(
                "[%s] pass %d, c = %g mEq/l: %d ruptured (%d converted in all), delaminated %.1f um, "
                "%d islands apart, max onset stress %.1f kPa%s",
                self.run_name,
                self.step,
                self.concentration,
                ruptured.size,
                self.rows[-1].converted[0],
                self.rows[-1].length,
                self.rows[-1].islands.count,
                self.tip,
                " (through a snap)" if snapped else "",
            )
        return True

    def follow_snap(self, load: Load, what: str, exc: solver.SimulationError) -> solver.State:
        """Follow a step with no equilibrium on its path (:mod:`sphgag.engine.snap`) from the current state to the
        equilibrium the overdamped pseudo-dynamics come to rest at, under the model's current material and ``load``;
        raises :class:`sphgag.engine.snap.NoStableState` if there is none."""
        log.info(
            "[%s] %s at c = %g mEq/l has no equilibrium on its path (%s): following the snap",
            self.run_name,
            what,
            load.material_value("concentration"),
            exc.reason,
        )
        state = snap.follow(self.model, self.state.x, load, **self.opts)
        self.snaps += 1
        return state

    def level(self, c: float) -> str:
        """Damage passes at concentration ``c`` until the pools arrest (``arrested``) or the run must end (its
        reason: ``merged``, ``maximum extent``, ``symmetry edge``, ``pass limit``)."""
        self.raise_concentration(c)
        self._record(first_of_level=True)
        while self.damage_pass():
            if self.merge_step is not None:
                return "merged"
            if self.step >= self.settings.max_passes:
                return "pass limit"
            if self.front.extent_deg(self.hist).max() >= self.settings.max_extent_deg:
                return "maximum extent"
            if self.front.at_symmetry_edge(self.hist):
                return "symmetry edge"
        return "arrested"

    def run(self) -> Result:
        """Walk the concentration ramp from the current concentration; the run ends where a level does not arrest,
        or where a snap finds no stable state (``stop`` names the step and the load)."""
        stop, level = "arrested", self.concentration  # the level the run stops in
        for c in self.settings.levels[self.settings.levels >= self.concentration - 1e-9]:
            level = float(c)
            try:
                stop = self.level(float(c))
            except snap.NoStableState as exc:
                stop = f"no stable state after a snap ({exc.reason})"
                log.warning(
                    "[%s] c = %g mEq/l, pass %d: %s; the run ends at its last equilibrium",
                    self.run_name,
                    c,
                    self.step + 1,
                    stop,
                )
                self.model.set_props(self.material)
                break
            log.info(
                "[%s] c = %g mEq/l: %s after %d passes, %d converted",
                self.run_name,
                c,
                stop,
                self.step,
                self.rows[-1].converted[0],
            )
            if stop != "arrested":
                break
        return self.result(stop, level)

    # -- bookkeeping ----------------------------------------------------------------------------------------------
    def _settle(self, material: HistoryMaterial) -> None:
        self.material = material
        self.model.set_props(material)

    def _accept(self, state: solver.State) -> None:
        """Make ``state`` (converged under the current material) the run's state and measure its front."""
        self.state = state
        self.max_residual = max(self.max_residual, state.convergence.residual)
        cand, pools = self.front.candidates(self.hist)
        sigma = (
            onset_measure(self.model, state.evaluation, self.hist, cand, self.settings) if cand.size else np.empty(0)
        )
        self._front = (cand, pools, sigma)
        self.tip = float(sigma.max()) if sigma.size else np.nan
        if self.merge_step is None and self.step and self.front.merged(self.hist):
            self.merge_step = self.step
            log.info("[%s] pools merged at pass %d (c = %g mEq/l)", self.run_name, self.step, self.concentration)

    def _record(self, first_of_level=False, snapped=False) -> None:
        st = self.state
        self.rows.append(
            Pass(
                self.step,
                self.concentration,
                self.front.converted(self.hist),
                self.front.delaminated_length(self.hist),
                self.front.islands(self.hist),
                self.tip,
                st.convergence.residual,
                snapped,
            )
        )
        if (first_of_level or self.step in self.wanted) and not any(
            s[0] == self.step and s[1].load == st.load for s in self.snapshots
        ):
            self.snapshots.append((self.step, st, self.hist))
            # the run continues from a snapshot exactly as a restart from it does: without a stale factorisation
            # (equilibria need not be unique, e.g. a crushed tissue bridge between two GAG regions, so the
            # solver's path must be the same)
            self.model.factorisation = None

    def result(self, stop: str, level: float) -> Result:
        """The run's rows and summary; it stopped (``stop``) in the ramp's level ``level`` [mEq/l]."""
        rows = self.rows
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
                    islands=r.islands.count,
                    island_particles=r.islands.particles,
                    island_distance_um=r.islands.distance_um,
                    tip_radial_stress_kPa=r.tip_stress,
                    residual=r.residual,
                    snap=r.snap,
                )
                for k, r in enumerate(rows)
            ]
        )
        rate_t, rate_c = growth_rates(growth, self.settings.concentration_step_mEq_l)
        length = rows[-1].length
        first_c, first_length = first_level_growth(growth)
        summary = dict(
            onset_concentration_mEq_l=self.onset_c,
            final_length_um=length,
            islands=rows[-1].islands.count,
            island_particles=rows[-1].islands.particles,
            island_distance_um=rows[-1].islands.distance_um,
            outcome=outcome(stop, length, self.merge_step is not None),
            first_growth_concentration_mEq_l=first_c,
            first_level_length_um=first_length,
            max_tip_radial_stress_kPa=float(growth.tip_radial_stress_kPa.max()),
            growth_rate_um_per_pseudo_time=rate_t,
            growth_rate_um_per_mEq_l=rate_c,
            merged=self.merge_step is not None,
            merge_step=self.merge_step if self.merge_step is not None else np.nan,
            dissipated_energy_J_m2=1e-3 * self.dissipated / length if length > 0 else np.nan,
            dissipated_energy_kPa_um2=self.dissipated,
            stop=stop,
            stop_level_mEq_l=level,
            passes=self.step,
            snaps=self.snaps,
            snap_length_um=self.snap_length,
            max_residual=self.max_residual,
            pressure_mmHg=measure.carried_pressure(self.model, self.state.evaluation) / MMHG_TO_KPA,
        )
        state = self.state
        snapshots = list(self.snapshots)
        if not any(s[0] == self.step and s[1].load == state.load for s in snapshots):
            snapshots.append((self.step, state, self.hist))
        return Result(growth, summary, snapshots, (state, self.hist))


def grow(
    model: Model,
    start: solver.State,
    sectors: list[Sector],
    settings: Settings,
    numerics: Numerics,
    gag: dict,
    base,
    snapshot_steps=(),
    run: str | None = None,
    resume: tuple | None = None,
) -> Result:
    """Seed the pools of ``sectors`` in the wall at the converged pressurised state ``start`` and grow them
    (:class:`GrowthRun`).

    ``base``: the intact wall's material (``load -> props``, e.g. :class:`sphgag.studies.artery.BilayerMaterial`).
    ``snapshot_steps``: pseudo-times at which to keep the state (the first state of every concentration level and
    the last state are always kept). ``resume``: ``(state, history, pseudo_time)`` of a snapshot of this run
    (:func:`load_snapshot`) to continue from instead of seeding; the rows then start there.
    """
    args = (model, resume if resume is not None else start, sectors, settings, numerics, gag, base, run, snapshot_steps)
    return (GrowthRun.resume(*args) if resume is not None else GrowthRun.seed(*args)).run()


def seeded_only(
    model: Model,
    start: solver.State,
    sectors: list[Sector],
    settings: Settings,
    numerics: Numerics,
    gag: dict,
    base,
    stop: str,
    run: str | None = None,
) -> Result:
    """A run that ends where its pools are seeded, before the ramp, for the reason ``stop`` (e.g. a damage law whose
    G_c is not defined): its one state is the seeded wall at c = 0 (``settings`` seed it; no damage law acts)."""
    log.warning("[%s] %s: the run ends where its pools are seeded", run or model.name, stop)
    seeded = GrowthRun.seed(model, start, sectors, settings, numerics, gag, base, run=run)
    seeded._record(first_of_level=True)  # the seeded wall is the run's one row (and its snapshot)
    return seeded.result(stop, 0.0)


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


def labelled(result: Result, case: str, settings: Settings, dx: float) -> tuple[pd.DataFrame, pd.DataFrame]:
    """``(growth, summary)`` of one run with the labels of ``results/delamination/{growth,summary}.csv``."""
    labels = dict(
        case=case,
        sigma_cr_kPa=settings.critical_stress_kPa,
        criterion=settings.criterion,
        candidates=settings.candidates,
        dx_um=float(dx),
        damage_law=settings.damage_law,
        fracture_energy_J_m2=settings.fracture_energy_J_m2,
    )
    growth = result.growth.assign(**labels)[GROWTH_COLUMNS]
    summary = pd.DataFrame([dict(labels, **result.summary)])
    return growth, summary[SUMMARY_COLUMNS + [c for c in summary.columns if c not in SUMMARY_COLUMNS]]


def paper_law(table: pd.DataFrame) -> pd.DataFrame:
    """The rows of a delamination table grown by eq. (2.28) as printed (the paper's figures and claims)."""
    return table[table.damage_law == "paper"] if "damage_law" in table else table


def griffith(sectors: list[Sector], fracture_energy_J_m2: float, modulus: float, gag: dict, concentration: float):
    """The closed form of a pool as a pressurised straight crack (:func:`sphgag.physics.fracture.griffith_pool`), in
    the media's plane-strain modulus ``E'`` [kPa], as summary columns: the concentration at which Griffith's criterion
    makes the longest seeded pool (half-length half its arc) propagate, and the half-length it needs at
    ``concentration``, both under Pi(c) of eqs. (2.25-2.26) (the prescribed law; the conserved law's Pi is lower where
    the pool has swollen)."""
    a = max(0.5 * np.deg2rad(s.angular_extent_deg) * s.centre_radius for s in sectors)
    gag = materials.Gag.of(gag)
    pool = fracture.griffith_pool(
        a,
        fracture_energy_J_m2 * fracture.J_M2,
        modulus,
        concentration,
        gag.bath_concentration_mEq_l,
        gag.temperature_K,
    )
    return dict(
        griffith_pool_half_length_um=float(a),
        griffith_pressure_kPa=float(pool.pressure),
        griffith_concentration_mEq_l=float(pool.concentration),
        griffith_half_length_um=float(pool.half_length),
    )


def convergence_study(
    dx: float,
    bilayer: dict,
    numerics: Numerics,
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
        model = artery.bilayer_model(p, numerics, name=name if len(de["criteria"]) == 1 else f"{name}_{criterion}")
        result = grow(
            model, solver.State(start.load, start.x, None, None), sectors, settings, numerics, gag, model.props
        )
        rows.append(labelled(result, case, settings, dx)[1].assign(particles=model.n))
    return pd.concat(rows, ignore_index=True)
