"""Following a loss of equilibrium (a snap) to the next equilibrium: implicit damped pseudo-dynamics.

A quasi-static path can reach a point beyond which no equilibrium lies near the
current state: a damage pass whose new history cannot be reached along its
transition, or a load step past a limit point. Physically the wall then moves
dynamically (it snaps) until it comes to rest at another equilibrium. The paper
follows every change this way, with damped explicit pseudo-dynamics (eqs.
2.12-2.13, mass scaling and viscosity, section 2.3). We follow only the snaps
this way, and implicitly: pseudo-transient continuation (Kelley & Keyes 1998),
the backward-Euler integration of the overdamped pseudo-dynamics

    M dx/dtau = f_int(x) + f_ext(x),      M = diag|K| (the stiffness diagonal: mass scaling),

one linearised step at a time, ``(M / dtau + K) dx = f_int + f_ext``, with no line
search (the residual may rise while the wall moves: that is the snap). The
pseudo-time step grows as the residual falls (switched evolution relaxation,
``dtau_k+1 = dtau_k |r_k-1| / |r_k|``), so the iteration turns into Newton's method as
it comes to rest, and the state is then converged by :meth:`sphgag.engine.solver.Solver.newton`
to the same tolerance as every other state. The overdamped motion descends the
energy, so where it comes to rest is a stable equilibrium (a saddle is not an
attractor of it); a state it cannot converge within its budget is no state at all,
and the caller ends its run there (:class:`NoStableState`).

The damping matrix is that of the solver's Levenberg-Marquardt damping
(:func:`sphgag.engine.solver.factorise`, ``K + m diag|K|`` with ``m = 1/dtau``), so a snap
costs one Jacobian and one LU per pseudo-time step.
"""

from __future__ import annotations

import logging
import time

import numpy as np

from . import solver
from .loading import Load

log = logging.getLogger("sphgag")


SPEEDUP = 0.7
# the motion has come to rest at no equilibrium when its lowest residual has not halved in STALL_STEPS steps, or
# when Newton's method, tried each time the residual has fallen tenfold below the last try, has failed HANDOFFS times
STALL_STEPS = 60
HANDOFFS = 3


class NoStableState(solver.SimulationError):
    """The pseudo-dynamics after a snap came to rest at no equilibrium within its budget."""


def follow(
    path_solver: solver.Solver,
    x0: np.ndarray,
    load: Load,
    *,
    run: str | None = None,
    max_steps: int = 300,
    handoff: float = 1e-2,
    damping: float = 1.0,
) -> solver.State:
    """The equilibrium at ``load`` that the overdamped pseudo-dynamics from ``x0`` come to rest at.

    ``path_solver``: the :class:`sphgag.engine.solver.Solver` of the path the snap interrupts (its model, and its
    Newton ``tol`` and ``max_iter``; its factorisation cache is emptied, then keeps the handoffs' factorisations).
    ``damping``: the first ``m = 1/dtau``. Once the relative residual is below ``handoff`` (or
    ``m`` below 1e-3), Newton's method (:meth:`sphgag.engine.solver.Solver.newton`) tries to converge
    the state; if it fails, the pseudo-dynamics resume from the best state so far
    with ten times more damping, and Newton is tried again once the residual is ten
    times lower (at most ``HANDOFFS`` tries). Raises :class:`NoStableState` after ``max_steps``
    pseudo-time steps, or when the lowest residual has not halved in ``STALL_STEPS`` steps.
    """
    run = run or path_solver.model.name
    try:
        return _follow(path_solver, x0, load, run, max_steps, handoff, damping)
    except NoStableState:
        raise
    except solver.SimulationError as exc:  # a singular or inadmissible pseudo-time step
        raise NoStableState(run, load, f"the pseudo-dynamics failed ({exc.reason})") from exc


def _follow(path_solver, x0, load, run, max_steps, handoff, damping) -> solver.State:
    model = path_solver.model
    # Newton's handoffs: the path's tolerance and iterations, stopping where they stagnate, without chord steps
    handoffs = path_solver.using(path_solver.options.newton_budget(), stall=solver.STALL_ITERATIONS)
    t0 = time.perf_counter()
    ev = model.evaluate(x0, load)
    solver.check(model, ev, run)
    rel = solver.relative_residual(model, ev)
    best = (rel, ev)
    halved = (rel, 0)  # (residual, step) when the best residual last halved
    m, n_eval, n_jac, attempts = damping, 1, 0, 0
    path_solver.reset()
    for k in range(max_steps):
        if rel < handoff or (m < 1e-3 and attempts == 0):
            attempts += 1
            try:
                x, ev_n, conv = handoffs.newton(ev.x, load, run=run)
            except solver.SimulationError as exc:
                log.debug("[%s] snap: Newton from pseudo-time step %d failed (%s)", run, k, exc.reason)
                if attempts == HANDOFFS:
                    raise NoStableState(
                        run, load, f"Newton failed {HANDOFFS} times near rest (lowest residual {best[0]:.3g})"
                    ) from exc
                # resume from the best state with more damping; try Newton again only 10 times closer to rest
                handoff = 0.1 * min(rel, handoff)
                rel, ev = best
                m = max(m, damping) * 10.0**attempts
            else:
                counts = (k + conv.iterations, n_eval + conv.force_evaluations, n_jac + conv.jacobians)
                conv = solver.Convergence(conv.residual, *counts, time.perf_counter() - t0)
                moved = f"moved {float(np.abs(x - x0).max()):.3g} um at most, residual {conv.residual:.2e}"
                log.info(
                    "[%s] snap at %s: at rest after %d pseudo-time steps, %s", run, solver.describe(load), k, moved
                )
                return solver.State(load, x, ev_n, conv)
        data = model.jacobian(ev)
        n_jac += 1
        while True:
            fac = solver.factorise(model, ev, data.copy(), m, run)
            dx = fac.step(ev)
            trial = solver.trial(model, ev, dx, 1.0, solver.bending(model, ev.x, dx))
            n_eval += 1
            if trial is not None:
                break
            m *= 10.0  # an inadmissible state (inverted particle): a shorter pseudo-time step
            if m > 1e8:
                raise NoStableState(run, load, f"no admissible pseudo-time step at step {k} (residual {rel:.3g})")
        rel_new = solver.relative_residual(model, trial)
        # switched evolution relaxation, bounded: the damping follows the residual, and falls by at least
        # SPEEDUP per step while the residual falls
        m *= min(max(rel_new / rel, 0.25), SPEEDUP) if rel_new < rel else min(rel_new / rel, 4.0)
        rel, ev = rel_new, trial
        if rel < best[0]:
            best = (rel, ev)
        if best[0] < 0.5 * halved[0]:
            halved = (best[0], k)
        elif k - halved[1] >= STALL_STEPS:
            raise NoStableState(
                run, load, f"the pseudo-dynamics came to rest at no equilibrium (lowest residual {best[0]:.3g})"
            )
        moved = float(np.abs(ev.x - x0).max())
        log.debug("[%s] snap step %d: residual %.3e, damping %.2e, moved %.3g um at most", run, k, rel, m, moved)
    raise NoStableState(
        run,
        load,
        f"the pseudo-dynamics came to rest at no equilibrium in {max_steps} steps (lowest residual {best[0]:.3g})",
    )


def transition(
    path_solver: solver.Solver, x0: np.ndarray, material, after, load: Load, *, run: str | None = None, on_snap=None
):
    """Solve the change of history from ``material``'s (a :class:`sphgag.engine.history.HistoryMaterial`) to ``after``
    at ``load`` along its transition path (the load's ``transition`` 0 -> 1, with the options of
    :meth:`sphgag.engine.solver.PathOptions.for_transition`), on the model of ``path_solver``; where that path has no
    equilibrium, ``on_snap(exc)`` follows the snap under the new history in full (by default :func:`follow` from
    ``x0``; it may raise :class:`NoStableState`). Returns ``(state, settled material, snapped)``, the model set to the
    settled material and the state evaluated under it."""
    model = path_solver.model
    path = material.towards(after)
    model.set_props(path)
    try:
        end = load.with_material(transition=1.0)
        transition_path = path_solver.using(path_solver.options.for_transition())
        state = transition_path.follow_path(x0, load.with_material(transition=0.0), [end], run=run)[-1]
        snapped = False
    except solver.NotConverged as exc:
        model.set_props(path.settled())
        state = on_snap(exc) if on_snap is not None else follow(path_solver, x0, load, run=run)
        snapped = True
    settled = path.settled()
    model.set_props(settled)
    return solver.State(load, state.x, model.evaluate(state.x, load), state.convergence), settled, snapped
