"""The growth of GAG pools by damage (paper section 2.7, figures 5-7): one run of the staggered protocol
(:class:`GrowthRun`, :func:`grow`), from seeding its pools to where it stops; and one point of the delamination map
(:func:`map_point`), a pool grown over the ramp and what it does at each level.

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

**Snaps and limit points.** A damage pass whose new history cannot be reached along its transition has lost
equilibrium: the wall snaps. The run follows the snap to where the overdamped pseudo-dynamics come to rest
(:mod:`sphgag.engine.snap`), records that state (converged below the tolerance, ``snap`` in growth.csv) and keeps
growing from it at the same concentration. A concentration step with no equilibrium on its path is first followed
by volume control with the damage frozen (:func:`sphgag.engine.pool_volume.continue_path`): if the concentration the
pools hold has a maximum below the step's, the run ends at that ``limit point``; otherwise the state volume control
reaches, or the snap, is the next state. A snap of a damage pass that comes to rest at no equilibrium is told apart
the same way (:meth:`GrowthRun._no_rest`): from the state before the pass, the pass's history is reached with the
pools' volume held (:func:`sphgag.engine.pool_volume.hold_volume`), then the pools' volume is the control under it;
if the concentration they hold has a maximum below the level's, the damaged structure has no equilibrium at that
concentration (a limit of existence) and the run ends at that ``limit point``; otherwise no limit point was found
and the stop stays ``numerical``, saying what volume control found (it reached the level, an equilibrium the snap
missed; it stopped with the concentration still rising; or it could not hold the pools' volume through the pass).

**Stops** (:data:`sphgag.studies.delamination.tables.STOP_KINDS`, ``stop_kind`` in summary.csv): ``arrested`` (every
level up to the ramp's end came to rest), ``merged``, ``unstable`` (growth at a fixed concentration did not arrest
before a pool spanned ``max_extent_deg``, a cap on the run, or had run away before the level lost equilibrium),
``edge`` (the candidate window of a symmetry edge), ``layer`` (another layer or a free surface), ``limit point`` (a
concentration step's or a damage pass's) and ``numerical`` (a snap came to rest at no equilibrium and volume control
found no limit point, or ``max_passes`` ended growth); the run always ends at its last equilibrium. Then the
concentrations of its events, onset, runaway and merge, are bisected between the ramp's levels
(:func:`.events.critical`).

**Pseudo-time** is the number of damage-and-relax passes. The paper's normalised time
is that of its explicit dynamics, in which every time step is one damage update with
at most one step of relaxation; a pass here is one damage update with complete
relaxation, so pseudo-time counts the same updates, each taken to equilibrium.

**Onset measure** (``criterion``): ``particle``, the particle's own radial Cauchy stress
(current polar frame), as in the paper; or ``averaged``, the volume-weighted mean of the
radial stress of the intact medial particles within a disc of diameter
``averaging_length_um`` (:func:`sphgag.engine.measure.averaging_matrix`), which has a fixed
physical size. Damage, once started, grows with the radial stretch beyond its onset
value whatever the stress.
"""

from __future__ import annotations

import dataclasses
import logging
from dataclasses import dataclass, field

import numpy as np

from ...engine import measure, pool_volume, snap, solver
from ...engine.geometry import Sector
from ...engine.history import HistoryMaterial, ParticleHistory, swelling_load
from ...engine.loading import MMHG_TO_KPA, Load
from ...engine.model import Model
from ...engine.numerics import Numerics
from ...engine.solver import Solver
from .. import artery
from .events import RUNAWAY_EXTENT_FACTOR, LimitPoint, critical
from .front import Front, damage_step, onset_measure, with_ruptures
from .settings import Settings
from .tables import Critical, Pass, Result, Stop, growth_table, level_classes, run_summary

log = logging.getLogger("sphgag")


@dataclass(frozen=True)
class DamageUpdate:
    """One damage update (eq. 2.28) from a run's current state (:meth:`GrowthRun.next_history`).

    ``history``: the history it makes (damage, onsets and ruptures), None if it changes no ``D`` by more than
    ``damage_tolerance`` and ruptures nothing; ``released``: the energy raising ``D`` releases at the current
    deformation [kPa um^2 per unit axial length] (0 without ``history``); ``onsets``: without ``history``, the current
    history with the update's new onsets (``D`` unchanged), None if it has none; ``begun``: some particle has begun
    damage (an onset stretch)."""

    history: ParticleHistory | None
    released: float = 0.0
    onsets: ParticleHistory | None = None
    begun: bool = False


@dataclass
class GrowthRun:
    """One delamination run as a record of its state, with one method per step of the protocol.

    :meth:`seed` (or :meth:`resume`) makes the run; :meth:`raise_concentration` moves it to the next level of the
    ramp; :meth:`next_history` finds one damage update (a query: the run does not change) and :meth:`take_onsets`
    keeps the onsets it tells of; :meth:`damage_pass` solves the history it makes; :meth:`follow_snap` follows a step
    that has no equilibrium on its path; :meth:`level` repeats damage passes at one concentration until the pools
    arrest or the run ends; :meth:`run` walks the ramp and returns the
    :class:`Result`. Every state the run holds is converged below the solver tolerance.

    Its paths, snaps and volume-controlled steps are solved by its ``solver`` (a
    :class:`sphgag.engine.solver.Solver` of the run's model), which every :meth:`branch` of the run shares: one model
    and one factorisation cache, emptied where the run keeps a snapshot and before each probe of :meth:`critical`.
    ``name`` is the run's name in logs and errors.
    """

    solver: Solver  # of the run's model: its options (Numerics.solver_options) and factorisation cache
    name: str  # the run's name (logs and errors), apart from its solver's options
    front: Front
    settings: Settings
    material: HistoryMaterial
    state: solver.State
    step: int = 0  # pseudo-time: damage passes so far
    wanted: frozenset = frozenset()  # pseudo-times at which to keep a snapshot
    rows: list = field(default_factory=list)
    snapshots: list = field(default_factory=list)
    dissipated: float = 0.0  # kPa um^2 per unit axial length
    onset_c: float = np.nan  # the ramp's level of the first onset
    limit_c: float = np.nan  # the limit point's concentration, where the run ends at one
    merge_step: int | None = None
    max_residual: float = 0.0
    snaps: int = 0
    snap_length: float = 0.0  # delaminated length gained through snaps [um]
    tip: float = np.nan  # largest onset measure of the current state (the last row's tip stress)
    _snapping: str = ""  # the step whose snap is being followed (a concentration step or a damage pass)
    _rest_extent: float = np.nan  # the pools' largest angular extent at rest before the current level [deg]
    _front: tuple = ()  # (candidates, their pools, their onset measures) of the current state

    @property
    def model(self) -> Model:
        return self.solver.model

    @property
    def hist(self) -> ParticleHistory:
        return self.material.history

    # -- making a run ---------------------------------------------------------------------------------------------
    @classmethod
    def seed(
        cls, model, start, sectors, settings, numerics: Numerics, gag, base, *, run=None, snapshot_steps=()
    ) -> GrowthRun:
        """Convert the medial particles of ``sectors`` to GAG pools at c = 0 in the converged pressurised state
        ``start`` (``settings.conversion_steps`` converged increments of the seeding path)."""
        path_solver, run = numerics.solver(model), run or model.name
        material = artery.seeding(base, model.layout, sectors, gag)
        model.set_props(material)
        base_load = swelling_load(start.load, 0.0, 0.0)
        law = settings.law
        log.info(
            "[%s] seeding %d pool(s) (%d particles) in %d steps at %.1f mmHg; sigma_cr %.0f kPa, %s onset, %s",
            run,
            len(sectors),
            int(material.history.gag.sum()),
            settings.conversion_steps,
            base_load.pressure_mmHg,
            law.critical_stress_kPa,
            settings.criterion,
            law.rupture,
        )
        fractions = np.linspace(0, 1, settings.conversion_steps + 1)[1:]
        seeding = [swelling_load(base_load, f, 0.0) for f in fractions]
        state = path_solver.follow_path(start.x, base_load, seeding, run=run)[-1]
        front = Front.of(model, sectors, settings)
        grown = cls(solver=path_solver, name=run, front=front, settings=settings, material=material, state=state)
        grown.wanted = frozenset(int(s) for s in snapshot_steps)
        grown._settle(material.settled())
        grown._accept(state)
        return grown

    @classmethod
    def resume(
        cls, model, snapshot, sectors, settings, numerics: Numerics, gag, base, *, run=None, snapshot_steps=()
    ) -> GrowthRun:
        """Continue from ``snapshot = (state, history, pseudo_time)`` of this run (:func:`.runs.load_snapshot`)."""
        path_solver, run = numerics.solver(model), run or model.name
        state, hist, step = snapshot
        material = HistoryMaterial(base, hist, gag)
        model.set_props(material)
        log.info(
            "[%s] resuming at pass %d, c = %g mEq/l (%d GAG particles)",
            run,
            step,
            state.load.material_value("concentration"),
            int(hist.gag.sum()),
        )
        if state.evaluation is None:  # a saved snapshot: evaluate it and measure its residual
            ev = model.evaluate(state.x, state.load)
            conv = state.convergence or solver.Convergence(solver.relative_residual(model, ev), 0, 1, 0, 0.0)
            state = solver.State(state.load, state.x, ev, conv)
        front = Front.of(model, sectors, settings)
        resumed = cls(
            solver=path_solver, name=run, front=front, settings=settings, material=material, state=state, step=step
        )
        resumed.wanted = frozenset(int(s) for s in snapshot_steps)
        resumed._accept(state)
        resumed._detect_merge()
        return resumed

    # -- steps of the protocol ------------------------------------------------------------------------------------
    @property
    def concentration(self) -> float:
        return float(self.state.load.material_value("concentration"))

    def raise_concentration(self, c: float) -> None:
        """Move the run to the fixed-charge concentration ``c`` (mEq/l) with its history fixed; a step with no
        equilibrium on its path is followed as a snap."""
        load = swelling_load(self.state.load, 1.0, float(c))
        if load == self.state.load:
            return
        try:
            state = self.solver.follow_path(self.state.x, self.state.load, [load], run=self.name)[-1]
        except solver.NotConverged as exc:
            state = self._volume_control(load, exc)
        self._accept(state)

    def _volume_control(self, load: Load, exc: solver.SimulationError) -> solver.State:
        """The concentration step to ``load`` has no equilibrium on its path: trace the pools' path with their volume
        as the control and the damage frozen (:meth:`_frozen_path`). Raises :class:`LimitPoint` where the concentration
        the pools hold has a maximum below the step's; returns the state at the step's concentration where volume
        control reaches it; else follows the step as a snap (:meth:`follow_snap`; a snap that comes to rest at no
        equilibrium raises :class:`sphgag.engine.snap.NoStableState`, its reason saying where volume control
        stopped)."""
        what = f"c = {self.concentration:g} -> {load.material_value('concentration'):g} mEq/l"
        log.info("[%s] %s has no equilibrium on its path (%s): volume control", self.name, what, exc.reason)
        reached, found = self._frozen_path(self.state, np.flatnonzero(self.hist.gag), load, what)
        if reached is not None:
            return reached
        try:
            return self.follow_snap(load, what, exc)
        except snap.NoStableState as lost:
            raise snap.NoStableState(self.name, load, f"{lost.reason}; {found}") from lost

    def _frozen_path(self, start: solver.State, members: np.ndarray, load: Load, what: str):
        """The pools' (``members``) path from the equilibrium ``start`` of the model's current material (the damage
        frozen) with their volume as the control, towards ``load``'s concentration
        (:func:`sphgag.engine.pool_volume.continue_path`). Raises :class:`LimitPoint` where the concentration the
        pools hold passes a maximum below ``load``'s; else returns ``(the state at load's concentration or None, what
        volume control found)``."""
        c = float(load.material_value("concentration"))
        path, reached = pool_volume.continue_path(self.solver, start, members, [c], run=self.name)
        if path.end == "limit point":
            raise LimitPoint(self.name, load, f"{what}: {path.reason}", path.limit_concentration)
        if reached:
            found = f"volume control reaches c = {c:g} mEq/l: an equilibrium the snap did not come to rest at"
        elif path.end == "complete":  # the path starts at no less than c
            found = f"the pools' path starts at c = {start.load.material_value('concentration'):.4g} mEq/l"
        else:
            found = f"no limit point below c = {c:g} mEq/l: {path.reason}"
        log.info("[%s] %s: %s", self.name, what, found)
        return (reached[-1] if reached else None), found

    def next_history(self) -> DamageUpdate:
        """The damage update (eq. 2.28) from the current state (:class:`DamageUpdate`): the history it makes and the
        energy it releases at the current deformation, or, if it changes no ``D`` by more than ``damage_tolerance``
        and ruptures nothing, its new onsets alone. A query: the run does not change (:meth:`take_onsets`)."""
        hist, lay = self.hist, self.model.layout
        cand, pools, _ = self._front
        dmg, W0 = damage_step(self.model, self.front, self.settings, self.material, self.state.evaluation, self._front)
        ruptured = np.flatnonzero(dmg.ruptured & ~hist.gag)
        begun = bool(np.any(~np.isnan(dmg.onset_stretch)))
        if float(np.max(dmg.D - hist.D, initial=0.0)) <= self.settings.damage_tolerance and ruptured.size == 0:
            onsets = None
            if not np.array_equal(dmg.onset_stretch, hist.onset_stretch, equal_nan=True):
                onsets = hist.with_damage(hist.D, dmg.onset_stretch, dmg.onset_energy)
            return DamageUpdate(None, onsets=onsets, begun=begun)
        changed = dmg.D > hist.D  # W_0 of a GAG particle need not be finite (its base material is not its own)
        released = float(np.sum((dmg.D[changed] - hist.D[changed]) * W0[changed] * lay.volume[changed]))
        new = with_ruptures(
            hist.with_damage(dmg.D, dmg.onset_stretch, dmg.onset_energy), ruptured, cand, pools, self.step + 1
        )
        return DamageUpdate(new, released, begun=begun)

    def take_onsets(self, update: DamageUpdate) -> None:
        """Keep what ``update`` tells of damage onsets: the concentration of the run's first onset, and, where the
        update changes no ``D``, its new onsets, made history (changes of ``D`` below the tolerance are not
        applied)."""
        if np.isnan(self.onset_c) and update.begun:
            self.onset_c = self.concentration
        if update.onsets is not None:
            self._settle(HistoryMaterial(self.material.base, update.onsets, self.material.gag))

    def damage_pass(self) -> bool:
        """One damage pass: the next history (:meth:`next_history`, its onsets kept by :meth:`take_onsets`) and the
        solve of its transition from the current state (a snap where the transition has no equilibrium on its path);
        False if the damage did not change."""
        update = self.next_history()
        self.take_onsets(update)
        if update.history is None:
            return False
        new, released = update.history, update.released
        hist, step = self.hist, self.step + 1
        ruptured = np.flatnonzero(new.gag & ~hist.gag)
        load = self.state.load
        state, self.material, snapped = snap.transition(
            self.solver,
            self.state.x,
            self.material,
            new,
            load,
            run=self.name,
            on_snap=lambda exc: self.follow_snap(load, f"pass {step}", exc, new),  # an error leaves the run as it was
        )
        self.step = step
        self.dissipated += released
        self._accept(state)
        self._detect_merge()
        if snapped:
            self.snap_length += self.front.delaminated_length(new) - self.front.delaminated_length(hist)
        self._record(snapped=snapped)
        if ruptured.size:
            log.info(
                "[%s] pass %d, c = %g mEq/l: %d ruptured (%d converted in all), delaminated %.1f um, "
                "%d islands apart, max onset stress %.1f kPa%s",
                self.name,
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

    def follow_snap(
        self, load: Load, what: str, exc: solver.SimulationError, after: ParticleHistory | None = None
    ) -> solver.State:
        """Follow a step with no equilibrium on its path (:mod:`sphgag.engine.snap`) from the current state to the
        equilibrium the overdamped pseudo-dynamics come to rest at, under the model's current material and ``load``.
        If there is none, raises :class:`sphgag.engine.snap.NoStableState`, or, for a damage pass to the history
        ``after``, what :meth:`_no_rest` finds (:class:`LimitPoint` where that history has a limit point below the
        level)."""
        log.info(
            "[%s] %s at c = %g mEq/l has no equilibrium on its path (%s): following the snap",
            self.name,
            what,
            load.material_value("concentration"),
            exc.reason,
        )
        self._snapping = what
        try:
            state = snap.follow(self.solver, self.state.x, load, run=self.name)
        except snap.NoStableState as lost:
            if after is None:
                raise
            self._no_rest(after, load, what, lost)
        self.snaps += 1
        return state

    def _no_rest(self, after: ParticleHistory, load: Load, what: str, lost: snap.NoStableState):
        """The snap of the damage pass ``what`` to the history ``after`` came to rest at no equilibrium (``lost``):
        limit of existence or solver failure? From the last equilibrium, the run's state before the pass, the new
        history is reached along its transition with the pools' volume held and the concentration the unknown
        (:func:`sphgag.engine.pool_volume.hold_volume`; a prescribed volume cannot snap), and the pools' path is then
        traced under it, the damage frozen, with their volume as the control (:meth:`_frozen_path`). Raises
        :class:`LimitPoint` where the concentration they hold passes a maximum below the level's; else
        :class:`sphgag.engine.snap.NoStableState`, its reason saying what volume control found. No state of this
        search becomes the run's: the run stays at its state before the pass."""
        log.info(
            "[%s] %s at c = %g mEq/l: %s; volume control under its history",
            self.name,
            what,
            load.material_value("concentration"),
            lost.reason,
        )
        members = np.flatnonzero(after.gag)
        self.model.set_props(self.material.towards(after))
        before = solver.State(load.with_material(transition=0.0), self.state.x, self.state.evaluation, None)
        try:
            held = pool_volume.hold_volume(
                self.solver, before, members, load.with_material(transition=1.0), run=self.name
            )
        except solver.SimulationError as exc:
            found = f"the new history does not hold the pools' volume before the pass ({exc.reason})"
            log.info("[%s] %s: %s", self.name, what, found)
        else:
            start = solver.State(held.load, held.x, None, held.convergence)
            # raises LimitPoint
            _, found = self._frozen_path(start, members, load, f"{what}, whose snap came to rest at no equilibrium")
        raise snap.NoStableState(self.name, load, f"{lost.reason}; {found}") from lost

    def level(self, c: float) -> tuple[str, str]:
        """Damage passes at concentration ``c`` until the pools arrest or the run must end: ``(kind, what)``, the kind
        of :data:`sphgag.studies.delamination.tables.STOP_KINDS` (``arrested`` where the level ends at rest) and what
        ended it. Raises :class:`LimitPoint` where ``c`` has no equilibrium and
        :class:`sphgag.engine.snap.NoStableState` where a snap comes to rest at none."""
        self._rest_extent = float(self.front.extent_deg(self.hist).max())
        self.raise_concentration(c)
        self._record(first_of_level=True)
        while self.damage_pass():
            if self.merge_step is not None:
                return "merged", "the pools merged"
            if self.step >= self.settings.max_passes:
                return "numerical", f"the pass limit ({self.settings.max_passes}) ended growth that had not arrested"
            if self.front.extent_deg(self.hist).max() >= self.settings.max_extent_deg:
                return "unstable", (
                    f"growth at a fixed concentration did not arrest; stopped at the maximum extent "
                    f"({self.settings.max_extent_deg:g} deg)"
                )
            if self.front.at_symmetry_edge(self.hist):
                return "edge", "the front reached a symmetry edge"
            if self.front.at_layer(self.hist):
                return "layer", "the front reached another layer or a free surface"
        return "arrested", "arrested"

    def settle_level(self, c: float) -> tuple[str, str]:
        """:meth:`level` at ``c``, its loss of equilibrium a kind of its own: ``limit point`` (with :attr:`limit_c`;
        a concentration step's, or a snap's that came to rest at no equilibrium, :meth:`_no_rest`) or ``numerical``
        (no stable state after a snap, and no limit point); ``unstable`` instead where the level's growth had run
        away before (a pool at :data:`RUNAWAY_EXTENT_FACTOR` times its extent at rest). The model is left at the
        run's material."""
        try:
            return self.level(c)
        except LimitPoint as exc:
            self.limit_c = exc.limit
            kind, what = "limit point", f"no equilibrium: {exc.reason}"
        except snap.NoStableState as exc:
            kind, what = "numerical", f"no stable state after the snap of {self._snapping} ({exc.reason})"
        extent = float(self.front.extent_deg(self.hist).max())
        if extent >= RUNAWAY_EXTENT_FACTOR * self._rest_extent:  # the level had run away before it lost equilibrium
            kind, what = (
                "unstable",
                (
                    f"growth at a fixed concentration did not arrest (a pool grew from {self._rest_extent:.3g} to "
                    f"{extent:.3g} deg); then {what}"
                ),
            )
        self.model.set_props(self.material)
        return kind, what

    def run(self) -> Result:
        """Walk the concentration ramp from the current concentration to where a level does not arrest (its
        :class:`Stop`, which names the level and the pass), then find the concentrations of its events between the
        levels (:meth:`critical`)."""
        before, before_onset = self.branch(), None  # the last state at rest; the one before the onset's level
        stop = Stop("arrested", "arrested", self.concentration)
        for c in self.settings.levels[self.settings.levels >= self.concentration - 1e-9]:
            had_onset = not np.isnan(self.onset_c)
            kind, what = self.settle_level(float(c))
            if not had_onset and not np.isnan(self.onset_c):
                before_onset = before
            stop = Stop(kind, what if kind == "arrested" else f"{what}; c = {c:g} mEq/l, {self.step} passes", float(c))
            log.log(
                logging.INFO if kind in ("arrested", "merged", "unstable") else logging.WARNING,
                "[%s] c = %g mEq/l: %s (%d converted)",
                self.name,
                c,
                stop.reason,
                self.rows[-1].converted[0],
            )
            if kind != "arrested":
                break
            before = self.branch()
        return self.result(stop, critical(self, stop, before, before_onset))

    # -- the concentrations of the run's events, between the ramp's levels ------------------------------------------
    def branch(self) -> GrowthRun:
        """A run that continues from this one's current state without changing it (its own rows, no snapshots), on
        the same model and solver."""
        return dataclasses.replace(self, rows=list(self.rows[-1:]), snapshots=[], wanted=frozenset())

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

    def _detect_merge(self) -> None:
        """Note the pass at which the pools first touch (:meth:`Front.merged`). A step of its own where the history is
        new, the only times the pools can come to touch: after every damage pass and on resuming from a snapshot (the
        seeded pools, pass 0, do not count)."""
        if self.merge_step is None and self.step and self.front.merged(self.hist):
            self.merge_step = self.step
            log.info("[%s] pools merged at pass %d (c = %g mEq/l)", self.name, self.step, self.concentration)

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
            self.solver.reset()

    def result(self, stop: Stop, critical: Critical) -> Result:
        """The run's rows and summary (:func:`sphgag.studies.delamination.tables.run_summary`): where it stopped and
        the concentrations of its events."""
        growth = growth_table(self.rows)
        summary = run_summary(
            growth,
            self.rows[-1],
            stop,
            critical,
            onset_level=self.onset_c,
            merge_step=self.merge_step,
            dissipated=self.dissipated,
            passes=self.step,
            snaps=self.snaps,
            snap_length=self.snap_length,
            max_residual=self.max_residual,
            pressure_mmHg=measure.carried_pressure(self.model, self.state.evaluation) / MMHG_TO_KPA,
            concentration_step=self.settings.concentration_step_mEq_l,
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
    (:func:`.runs.load_snapshot`) to continue from instead of seeding; the rows then start there.
    """
    make, begin = (GrowthRun.seed, start) if resume is None else (GrowthRun.resume, resume)
    return make(model, begin, sectors, settings, numerics, gag, base, run=run, snapshot_steps=snapshot_steps).run()


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
    return seeded.result(Stop("not run", stop, 0.0), Critical())


def map_point(model, start, sector, settings: Settings, numerics: Numerics, gag: dict, width: float, run=None):
    """One point of the delamination map: the pool ``sector`` (``width`` degrees) grown over the ramp by ``settings``
    from ``start``; what it does at each level, labelled by charge law, angular extent and sigma_cr, with how its run
    ended. Returns the table and the run's summary."""
    result = grow(model, start, [sector], settings, numerics, gag, model.props, run=run)
    table = level_classes(result.growth, result.summary, settings.levels)
    table.insert(0, "charge_law", gag["charge_law"])
    table.insert(1, "angular_extent_deg", width)
    table.insert(2, "sigma_cr_kPa", settings.critical_stress_kPa)
    s = result.summary
    ended = ("onset_concentration_mEq_l", "stop_level_mEq_l", "stop_kind", "stop", "max_residual")
    return table.assign(**{k: s[k] for k in ended}), s
