"""Quasi-static equilibrium: Newton's method on the discrete SPH forces, and load paths.

The paper integrates the particles' motion with leapfrog steps (eq. 2.13),
mass scaling and artificial viscosity for a fixed number of steps, and takes
the last state as quasi-static. We solve for the equilibrium itself: at every
load we find ``x`` with ``f_int(x) + f_ext(x) = 0`` by Newton's method with the
exact Jacobian of the same discrete forces (:func:`sphgag.engine.forces.jacobian_blocks`),
a sparse direct solve and a backtracking line search, and accept the state
only when the relative residual is below a tolerance.

**Relative residual** ``||f_int + f_ext||_2 (free particles) / f_ref`` with
``f_ref = max(||f_ext||_2 + ||reactions||_2, 1e-3 ||q||_2)``: the external load
(pressure, or the reactions of a prescribed radius) of the state, or, for an
(almost) unloaded state such as the axial-stretch ramp at zero pressure, a
thousandth of the internal stress-flux scale ``q_i = V_i |P_i| sum_j |V_j
A_i^-1 grad xi_ij|`` (for loaded states ``||q||`` is ~300 times the load, so
the floor never loosens their criterion); a stress-free state is measured
against the force a stress of 1e-9 of the stiffest modulus exerts on a cell.

A load increment that does not converge is bisected (up to ``max_bisections``
times). A state with NaN forces, an inverted particle (``det F <= 0``) or no
convergence stops the run with a :class:`SimulationError` naming the run and
the load.

A :class:`Solver` is Newton's method and the load paths on one model: it holds the model, the
:class:`PathOptions` of its paths and the :class:`FactorisationCache` its chord steps reuse. The paths that follow
one another on a model share its solver; a new model gets a solver of its own.
"""

from __future__ import annotations

import dataclasses
import logging
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import scipy.linalg.lapack as lapack
import scipy.sparse.linalg as spla

from ..options import Options
from .loading import Load
from .model import Evaluation, Model

log = logging.getLogger("sphgag")


class SimulationError(RuntimeError):
    """A simulation that cannot deliver a trustworthy equilibrium state."""

    def __init__(self, run: str, load: Load | None, reason: str, evaluation: Evaluation | None = None):
        # evaluation: the last iterate, where one exists (to diagnose why there was no equilibrium)
        self.run, self.load, self.reason, self.evaluation = run, load, reason, evaluation
        super().__init__(f"[{run}] {reason}" + (f" at {describe(load)}" if load is not None else ""))


class Diverged(SimulationError):
    """NaN or infinite forces."""


class Inverted(SimulationError):
    """A particle's deformation gradient has det F <= 0."""


class NotConverged(SimulationError):
    """No equilibrium within the iteration and bisection budget."""


def describe(load: Load) -> str:
    parts = [f"lambda_z={load.axial_stretch:.4g}"]
    if load.pressure_kPa is not None:
        parts.append(f"P={load.pressure_mmHg:.4g} mmHg")
    else:
        parts.append(f"r_in={load.inner_radius:.5g} um")
    parts += [f"{k}={v:.4g}" for k, v in load.material]
    return ", ".join(parts)


@dataclass
class Convergence:
    """How one equilibrium state was reached."""

    residual: float
    iterations: int
    force_evaluations: int
    jacobians: int
    seconds: float


@dataclass(frozen=True)
class PathOptions(Options):
    """The options of every kind of load path (the equilibrium path, :meth:`Solver.follow_path`; the volume-controlled
    path, :func:`sphgag.engine.pool_volume.continue_path`; a snap, :func:`sphgag.engine.snap.follow`): ``tol`` (the
    relative residual of a converged state), ``max_iter`` (Newton iterations per load step), ``max_bisections``
    (halvings of a load step), ``reuse`` (chord steps with the cached factorisation) and ``stall`` (fresh iterations
    without halving the residual before Newton gives up), with the solver's defaults. :meth:`of` builds them from a
    mapping and raises ``ValueError`` naming a key it does not know; a run's own come from
    :meth:`sphgag.engine.numerics.Numerics.solver_options`."""

    SECTION = "solver"

    tol: float = 1e-4
    max_iter: int = 30
    max_bisections: int = 10
    reuse: bool = False
    stall: int | None = None

    def newton_budget(self) -> PathOptions:
        """Newton's ``tol`` and ``max_iter`` alone, the defaults for the rest: the options of the load steps a
        volume-controlled path takes (:func:`sphgag.engine.pool_volume.continue_path`)."""
        return PathOptions(tol=self.tol, max_iter=self.max_iter)

    def for_transition(self) -> PathOptions:
        """The options of a path whose fallback is a snap (the transition of a damage pass): at most
        FALLBACK_BISECTIONS bisections, and Newton's method stops where it stagnates (STALL_ITERATIONS)."""
        return dataclasses.replace(
            self, max_bisections=min(self.max_bisections, FALLBACK_BISECTIONS), stall=STALL_ITERATIONS
        )


def relative_residual(model: Model, ev: Evaluation) -> float:
    return float(np.linalg.norm(ev.residual_vector) / ev.force_scale(model))


def check(model: Model, ev: Evaluation, run: str) -> None:
    """Raise :class:`Diverged` (non-finite positions or forces) or :class:`Inverted` (``det F <= 0``) for an evaluation
    no solve may start from or accept."""
    if not np.isfinite(ev.x).all():
        raise Diverged(run, ev.load, "non-finite positions")
    if ev.min_det <= 0.0:
        raise Inverted(run, ev.load, f"particle inversion (min det F = {ev.min_det:.3g})")
    if not ev.finite:
        raise Diverged(run, ev.load, "non-finite forces")


@dataclass
class Factorisation:
    """An LU factorisation of the (possibly damped) Jacobian with its constraint rows, kept for reuse.

    ``solve(rhs)`` applies the inverse; ``constrained`` are the particles whose rows
    were replaced by ``scale (x - target)``, so the factorisation can only serve
    evaluations with the same constrained set.
    """

    solve: Callable[[np.ndarray], np.ndarray]
    scale: float
    constrained: np.ndarray
    damping: float

    def serves(self, ev: Evaluation) -> bool:
        return self.damping == 0.0 and np.array_equal(self.constrained, ev.constrained)

    def step(self, ev: Evaluation) -> np.ndarray:
        """``dx = -K^-1 (f_int + f_ext)`` (constrained particles move to their targets)."""
        rhs = -(ev.f_int + ev.f_ext)
        cons = ev.constrained
        if cons.size:
            rhs[cons] = self.scale * (ev.target - ev.x[cons])
        return self.solve(rhs.ravel()).reshape(-1, 2)


class FactorisationCache:
    """The last undamped :class:`Factorisation` of one model's Jacobian, kept for the chord steps of
    :meth:`Solver.newton` (``reuse``) at this or later states. Every fresh Newton step replaces it (a damped one
    empties it); :meth:`reset` empties it, so that the next solve starts as a solve of a new model does (a run
    continued from a snapshot)."""

    def __init__(self):
        self.factorisation: Factorisation | None = None

    def keep(self, fac: Factorisation) -> None:
        """Keep ``fac`` if it is undamped; a damped factorisation empties the cache."""
        self.factorisation = fac if fac.damping == 0.0 else None

    def reset(self) -> None:
        """Forget the kept factorisation."""
        self.factorisation = None


# The Jacobian is factorised as a band matrix (LAPACK gbtrf, partial pivoting) when the band is well filled and its
# storage stays below BAND_BYTES: the artery's particles are numbered by angle, so its band is narrow and ~40 %
# full, and the banded LU 2-3 times faster than SuperLU's; sparser bands (the inclusion's rings) use SuperLU.
BAND_BYTES = 512 * 2**20
BAND_FILL = 0.2


def lu_solver(model: Model, data: np.ndarray) -> Callable[[np.ndarray], np.ndarray]:
    """A solver for the block matrix ``data``: banded LAPACK LU if the band is narrow, SuperLU otherwise.
    Raises ``RuntimeError`` for an exactly singular matrix."""
    kl, ku, index = model.band
    n2 = 2 * model.n
    if (2 * kl + ku + 1) * n2 * 8 <= BAND_BYTES and index.size >= BAND_FILL * n2 * (kl + ku + 1):
        ab = np.zeros((n2, 2 * kl + ku + 1))  # the band storage's transpose: ab.T is the Fortran array LAPACK takes
        np.put(ab, index, data)
        lub, piv, info = lapack.dgbtrf(ab.T, kl, ku, overwrite_ab=True)
        if info > 0:
            raise RuntimeError(f"U({info},{info}) is exactly zero")

        def solve(rhs):
            return lapack.dgbtrs(lub, kl, ku, rhs, piv)[0]

        return solve
    return spla.splu(model.block_matrix(data).tocsc(), permc_spec="NATURAL").solve


# Chord steps (stale factorisation) must cut the relative residual by CHORD_CONTRACTION per step on average: the
# k-th chord step (k = 0, 1, ...) since the last fresh Jacobian is kept if the residual is below
# 2 CHORD_CONTRACTION^k times the residual the sequence started from (the first step may even rise a little: chord
# residuals are not monotone, and the next steps usually contract fast). At most CHORD_STEPS per state
# (a chord step costs one force evaluation and one LU solve, a fresh Newton step 20-30 times more).
CHORD_CONTRACTION = 0.5
CHORD_STEPS = 12
# A step that has a fallback where it finds no equilibrium is bisected at most FALLBACK_BISECTIONS times (increments
# down to 1/16 of it): deeper bisection only delays the fallback (a concentration step of a swelling run, whose fallback
# is the pool's volume as the control, sphgag.engine.pool_volume: the full 10 bisections spent up to 160 s of a
# 220 s run on a step with no equilibrium, and gave the same states). In the transition of a damage pass, whose
# fallback is a snap (sphgag.engine.snap), Newton's method also gives up after STALL_ITERATIONS fresh iterations that
# do not halve the relative residual: near a state with no equilibrium the residual has a positive local minimum
# (PathOptions.for_transition; a snap's own Newton handoffs stop the same way). The swelling steps keep Newton's full
# iteration budget: on the swollen prescribed-law pools a converging step can take 20 damped iterations that each cut
# the residual by only a few per cent, which the stall test would cut short (losing states the path has). Other load
# steps (pressure, conversion, the concentration steps of a growth run) keep the configuration's full budget.
FALLBACK_BISECTIONS = 4
STALL_ITERATIONS = 8


class _Iterate:
    """The state of one :meth:`Solver.newton` solve: the iterate ``x`` and its evaluation ``ev`` and relative residual
    ``rel``, the work done (``n_eval`` force evaluations, ``n_jac`` Jacobians, ``chords`` chord steps), the
    Levenberg-Marquardt ``damping``, the current sequence of chord steps (``run_start``: the residual it started
    from, ``run_length``: its steps) and ``progress``: ``(residual, fresh iterations)`` when the residual last
    halved."""

    def __init__(self, x: np.ndarray, ev: Evaluation, rel: float):
        self.x, self.ev, self.rel = x, ev, rel
        self.n_eval, self.n_jac, self.damping, self.chords = 1, 0, 0.0, 0
        self.run_start, self.run_length = rel, 0
        self.progress = (rel, 0)


def _converged(model: Model, s: _Iterate, tol: float) -> bool:
    """The acceptance test: relative residual below ``tol`` and the prescribed particles at their targets."""
    return s.rel < tol and s.ev.constraint_error < 1e-9 * model.layout.outer_radius


def _chord_step(model: Model, cache: FactorisationCache, s: _Iterate, run: str, it: int) -> bool:
    """A chord step ``dx = -K_old^-1 r`` with the cached factorisation, if one serves the iterate and the state has
    chord steps left; taken (True) if it cuts the residual enough (``CHORD_CONTRACTION``)."""
    fac = cache.factorisation
    if not (fac is not None and fac.serves(s.ev) and s.chords < CHORD_STEPS):
        return False
    dx = fac.step(s.ev)
    ev_try = trial(model, s.ev, dx, 1.0, bending(model, s.ev.x, dx))
    s.n_eval += 1
    rel_try = relative_residual(model, ev_try) if ev_try is not None else np.inf
    if rel_try < 2.0 * CHORD_CONTRACTION**s.run_length * s.run_start:
        log.debug("[%s] chord %d: residual %.3e", run, it, s.rel)
        s.x, s.ev, s.rel, s.chords, s.run_length = ev_try.x, ev_try, rel_try, s.chords + 1, s.run_length + 1
        return True
    log.debug("[%s] chord %d rejected: residual %.3e -> %.3e", run, it, s.rel, rel_try)
    return False


def _fresh_step(model: Model, cache: FactorisationCache, s: _Iterate, run: str, it: int) -> None:
    """A Newton step with a fresh Jacobian (assembled, factorised and line searched by :func:`_damped_step`), whose
    undamped factorisation the cache keeps; the damping is relaxed after a full step."""
    data = model.jacobian(s.ev)
    s.n_jac += 1
    step, ev_try, fac, dx = _damped_step(model, s, data, run, it)
    cache.keep(fac)
    if ev_try is None:
        reason = f"line search failed at Newton iteration {it} (relative residual {s.rel:.3g})"
        raise NotConverged(run, s.ev.load, reason, s.ev)
    if step == 1.0:
        s.damping = 0.0 if s.damping <= 1e-4 else 0.1 * s.damping
    log.debug(
        "[%s] newton %d: residual %.3e, step %.3g, damping %.0e, |dx|max %.3g",
        run,
        it,
        s.rel,
        step,
        s.damping,
        np.abs(dx).max(),
    )
    s.x, s.ev = ev_try.x, ev_try
    s.rel = relative_residual(model, s.ev)
    s.run_start, s.run_length = s.rel, 0


def _damped_step(model: Model, s: _Iterate, data: np.ndarray, run: str, it: int):
    """Solve with the factorisation of the Jacobian ``data`` at the iterate's damping and line search
    (:func:`_line_search`); while the line search cuts the step hard (below 1/8), raise the damping and solve again.
    Returns ``(step, evaluation, factorisation, dx)``: the evaluation None if no step was accepted."""
    best = None  # (step, evaluation, factorisation, dx) of the best step a lower damping found
    while True:
        fac = factorise(model, s.ev, data.copy(), s.damping, run)
        dx = fac.step(s.ev)
        step, ev_try, evals = _line_search(model, s.ev, dx, fac.scale)
        s.n_eval += evals
        if step >= 0.125 or s.damping >= 1e4:
            break
        if ev_try is not None and (best is None or _merit(ev_try, fac.scale) < _merit(best[1], fac.scale)):
            best = (step, ev_try, fac, dx)
        s.damping = max(10.0 * s.damping, 1e-4)  # steps cut hard: damp the soft modes and solve again
        log.debug("[%s] newton %d: step %.3g, damping raised to %.0e", run, it, step, s.damping)
    if ev_try is None and best is not None:
        # with an indefinite stiffness a damped direction need not descend at all; the undamped Newton direction
        # always does (exact Jacobian), so the short step found before the damping rose is taken
        step, ev_try, fac, dx = best
        s.damping = fac.damping
        log.debug("[%s] newton %d: damped line search failed, step %.3g of damping %.0e kept", run, it, step, s.damping)
    return step, ev_try, fac, dx


def _check_progress(s: _Iterate, stall: int | None, run: str) -> None:
    """Note when the residual halves; with ``stall``, give up once ``stall`` fresh iterations have not halved it."""
    if s.rel < 0.5 * s.progress[0]:
        s.progress = (s.rel, s.n_jac)
    elif stall is not None and s.n_jac - s.progress[1] >= stall:
        raise NotConverged(
            run,
            s.ev.load,
            f"Newton stagnated: {stall} iterations without halving the relative residual ({s.rel:.3g})",
            s.ev,
        )


def factorise(model: Model, ev: Evaluation, data: np.ndarray, damping: float, run: str) -> Factorisation:
    """LU of ``J - damping diag|J|`` with the constrained rows replaced by ``scale (x - target)``.

    ``data``: the Jacobian blocks of ``ev`` (:meth:`sphgag.engine.model.Model.jacobian`), changed in place (pass a
    copy to keep them); the model's rank-one terms are added by Sherman-Morrison. Raises :class:`NotConverged` for an
    exactly singular matrix."""
    d = data[model.block_diagonal]
    scale = 0.5 * (np.abs(d[:, 0, 0]).mean() + np.abs(d[:, 1, 1]).mean())
    if damping:
        for k in range(2):
            data[model.block_diagonal, k, k] -= damping * np.abs(d[:, k, k])
    cons = ev.constrained
    if cons.size:
        # constrained particles: rows become scale * (x - target) = 0
        data[model.row_blocks(cons)] = 0.0
        data[model.block_diagonal[cons]] = scale * np.eye(2)
    try:
        solve = lu_solver(model, data)
    except RuntimeError as exc:  # exactly singular factor
        raise NotConverged(run, ev.load, f"singular Jacobian ({exc})", ev) from exc
    for c, g in model.rank_one_terms(ev):
        solve = _rank_one_update(solve, c, g, cons)
    return Factorisation(solve, scale, cons.copy(), damping)


def _rank_one_update(solve: Callable, c: float, g: np.ndarray, constrained: np.ndarray) -> Callable:
    """The solver of ``K + c g g^T`` from that of ``K`` (Sherman-Morrison; ``g`` vanishes on constrained rows, which
    hold their targets)."""
    if c == 0.0:
        return solve
    g = g.copy()
    g.reshape(-1, 2)[constrained] = 0.0
    z = solve(g)
    denom = 1.0 + c * float(g @ z)

    def updated(rhs):
        y = solve(rhs)
        return y - z * (c * float(g @ y) / denom)

    return updated


def _line_search(model: Model, ev: Evaluation, dx: np.ndarray, scale: float, max_halvings: int = 30):
    """Backtracking (Armijo) on the residual norm along the step bent onto the area-preserving radial map.

    Returns ``(step, evaluation, evaluations used)``; the evaluation is None if no step was accepted.
    """
    bend = bending(model, ev.x, dx)
    merit0 = _merit(ev, scale)
    step = 1.0
    for k in range(1, max_halvings + 1):
        ev_try = trial(model, ev, dx, step, bend)
        if ev_try is not None and _merit(ev_try, scale) <= (1.0 - 1e-4 * step) * merit0:
            return step, ev_try, k
        step *= 0.5
    return 0.0, None, max_halvings


def bending(model: Model, x: np.ndarray, dx: np.ndarray) -> tuple[float, float]:
    """``(r_in, dr_in)``: mean inner radius and the step's mean radial expansion there, the bend of a step
    ``dx`` from ``x`` that :func:`trial` applies (see :func:`_radial_correction`)."""
    inner = model.layout.inner_surface
    if not inner.size:  # no lumen: no radial expansion to correct
        return 0.0, 0.0
    rho_in = np.linalg.norm(x[inner], axis=1)
    return rho_in.mean(), float(np.mean((dx[inner] * x[inner]).sum(axis=1) / rho_in))


def trial(model: Model, ev: Evaluation, dx: np.ndarray, step: float, bend) -> Evaluation | None:
    """The evaluation at ``x + step dx`` (bent onto the area-preserving radial map by ``bend``, :func:`bending` of
    ``ev.x`` and ``dx``), or None if it is inadmissible (non-finite, or an inverted particle)."""
    r_in, dr_in = bend
    with np.errstate(invalid="ignore", over="ignore"):  # a trial step may be absurd; it is rejected
        x_try = ev.x + step * dx + (_radial_correction(ev.x, r_in, step * dr_in) if dr_in else 0.0)
        ev_try = model.evaluate(x_try, ev.load)
    return ev_try if ev_try.min_det > 0.0 and ev_try.finite else None


def _radial_correction(x, r_in, dr):
    """Second-order correction that makes the axisymmetric part of a step area preserving.

    Near-incompressibility makes the linearised step ``u_r = r_in dr / rho``
    (the Newton step's mean radial expansion) change the particles' area at
    second order, which the bulk penalty punishes hard: the first Newton steps
    of a pressure increment on the compliant low-pressure branch would need tiny
    line-search factors. The exact area-preserving map ``rho -> sqrt(rho^2 +
    (r_in + dr)^2 - r_in^2)`` differs from the linearised one by this
    correction, which vanishes as ``dr -> 0`` (so Newton's quadratic
    convergence is untouched).
    """
    rho = np.sqrt((x * x).sum(axis=1))
    exact = np.sqrt(rho * rho + 2.0 * r_in * dr + dr * dr) - rho
    linear = r_in * dr / rho
    return ((exact - linear) / rho)[:, None] * x


def _merit(ev: Evaluation, k: float) -> float:
    r = ev.residual_vector
    c = k * (ev.x[ev.constrained] - ev.target)
    return float(np.sqrt((r * r).sum() + (c * c).sum()))


@dataclass
class State:
    """A converged equilibrium state on a load path."""

    load: Load
    x: np.ndarray
    evaluation: Evaluation
    convergence: Convergence


class Solver:
    """Newton's method and load paths on one model: the model, the :class:`PathOptions` of its paths and the
    :class:`FactorisationCache` its Newton steps keep.

    A solver is bound to one model object, and its cache lives as long as the paths on that model that follow one
    another: with ``reuse`` the chord steps of a path reuse the last factorisation of the path before it, so a caller
    that continues on the same model passes its solver on (a changed model, such as the pool made a cavity, gets a
    solver of its own, with an empty cache). :meth:`using` gives a solver of the same model and cache with other
    options (a snap's Newton handoffs, the transition of a damage pass, a step with a fallback); :meth:`reset` empties
    the cache, so that the next solve starts as one on a new model does (a run continued from a snapshot).
    """

    def __init__(
        self, model: Model, options: PathOptions | dict | None = None, cache: FactorisationCache | None = None
    ):
        self.model = model
        self.options = PathOptions() if options is None else PathOptions.of(options)
        self.cache = FactorisationCache() if cache is None else cache

    def using(self, options: PathOptions | None = None, **changes) -> Solver:
        """A solver of the same model and factorisation cache with ``options`` (by default this solver's), changed by
        ``changes`` (names of :class:`PathOptions`)."""
        return Solver(self.model, dataclasses.replace(options or self.options, **changes), self.cache)

    def reset(self) -> None:
        """Forget the kept factorisation (:meth:`FactorisationCache.reset`)."""
        self.cache.reset()

    def newton(
        self, x0: np.ndarray, load: Load, *, run: str | None = None
    ) -> tuple[np.ndarray, Evaluation, Convergence]:
        """Equilibrium at ``load`` starting from ``x0`` (``run``: the name errors and logs give, the model's by
        default).

        Newton's method with the exact Jacobian, a backtracking line search on
        the residual norm and, when the line search has to cut the step hard
        (soft, nearly singular modes such as a GAG pool), Levenberg-Marquardt
        damping of the linear system (``J - m diag|J|``), relaxed again as soon as
        full steps succeed. Damping only shapes the steps; a state is accepted on
        the undamped residual alone (``tol``).

        With ``reuse``, the last undamped factorisation kept in the solver's cache (from this or an earlier state)
        is tried first: a chord step ``dx = -K_old^-1 r`` on the exact residual, kept while the chord steps cut the
        relative residual by ``CHORD_CONTRACTION`` per step on average (at most ``CHORD_STEPS`` per state).
        Otherwise (and whenever no factorisation fits) the iteration is an ordinary Newton step with a fresh
        Jacobian, whose factorisation is then kept. The acceptance test is the same in both cases.

        With ``stall``, the iteration gives up once ``stall`` fresh iterations have not halved the relative residual.

        Each iteration is a sequence of named steps: the convergence test (:func:`_converged`), a chord step with the
        cached factorisation (:func:`_chord_step`), else a fresh step (:func:`_fresh_step`: assemble, factorise and
        line search, :func:`_damped_step`), and the progress test (:func:`_check_progress`).
        """
        model, opts, cache = self.model, self.options, self.cache
        run = run or model.name
        t0 = time.perf_counter()
        x = x0.copy()
        ev = model.evaluate(x, load)
        check(model, ev, run)
        s = _Iterate(x, ev, relative_residual(model, ev))
        for it in range(opts.max_iter + CHORD_STEPS + 1):
            if _converged(model, s, opts.tol):
                return s.x, s.ev, Convergence(s.rel, it, s.n_eval, s.n_jac, time.perf_counter() - t0)
            if it - s.chords == opts.max_iter:
                break
            if opts.reuse and _chord_step(model, cache, s, run, it):
                continue
            _fresh_step(model, cache, s, run, it)
            _check_progress(s, opts.stall, run)
        reason = (
            f"no convergence in {opts.max_iter} Newton iterations (and {s.chords} chord steps; relative residual "
            f"{s.rel:.3g})"
        )
        raise NotConverged(run, load, reason, s.ev)

    def follow_path(
        self,
        x0: np.ndarray,
        start: Load,
        targets: Sequence[Load],
        *,
        run: str | None = None,
        on_state: Callable[[State], None] | None = None,
    ) -> list[State]:
        """Converged states at every load of ``targets``, moving from ``start`` (state ``x0``).

        Each increment is solved with :meth:`newton`; an increment that fails is split in two (recursively, up to
        ``max_bisections`` levels). Only the requested loads are returned (and passed to ``on_state``).
        """
        run = run or self.model.name
        x, current = x0.copy(), start
        states = []
        for target in targets:
            x, ev, conv = self._reach(x, current, target, self.options.max_bisections, run)
            current = target
            state = State(target, x.copy(), ev, conv)
            states.append(state)
            if on_state is not None:
                on_state(state)
        return states

    def _reach(self, x, current, target, depth, run):
        try:
            return self.newton(x, target, run=run)
        except (NotConverged, Inverted, Diverged) as exc:
            if depth == 0:
                raise NotConverged(
                    run, target, f"no convergence after bisecting the load increment ({exc.reason})"
                ) from exc
            log.debug("[%s] bisecting increment to %s (%s)", run, describe(target), exc.reason)
        middle = current.lerp(target, 0.5)
        xm, evm, cm = self._reach(x, current, middle, depth - 1, run)
        x2, ev2, c2 = self._reach(xm, middle, target, depth - 1, run)
        total = Convergence(
            c2.residual,
            cm.iterations + c2.iterations,
            cm.force_evaluations + c2.force_evaluations,
            cm.jacobians + c2.jacobians,
            cm.seconds + c2.seconds,
        )
        return x2, ev2, total


def log_states(run: str):
    """An ``on_state`` callback of :meth:`Solver.follow_path` that logs each converged state
    (progress in the rule log)."""

    def on_state(state: State):
        c = state.convergence
        log.info(
            "[%s] converged at %s: residual %.2e, %d Newton its, %d force evaluations, %.2f s",
            run,
            describe(state.load),
            c.residual,
            c.iterations,
            c.force_evaluations,
            c.seconds,
        )

    return on_state
