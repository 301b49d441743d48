"""Pseudo-dynamic relaxation as in the paper: leapfrog steps with artificial viscosity (eqs. 2.12-2.13).

The production solver is Newton's method (:mod:`sphgag.engine.solver`); this module
keeps the paper's explicit scheme as an independent route to the same
equilibrium (the tests check that both agree) and as a reference for the
benchmark. Masses are scaled (``m_i = density * V_i``); the viscous first
Piola-Kirchhoff stress of section 2.3, ``P_visc = 2 eta J d F^-T`` with
``d = sym(F_dot F^-1)`` and ``F_dot = (F^t - F^(t-1)) / dt``, is added to P.
(The paper writes ``2 eta d F^-T``; the factor J is the Piola transform of the
Cauchy stress ``2 eta d`` and is ~1 here.) Optionally the velocities are reset
whenever the kinetic energy peaks (kinetic damping), which reaches the
quasi-static state much faster than viscosity alone.
"""

from __future__ import annotations

import time

import numpy as np
from numba import njit

from .loading import Load
from .model import Model
from .solver import Convergence, Diverged, Inverted, NotConverged, relative_residual


@njit(cache=True, error_model="numpy")
def viscous_stress(F, F_old, dt, eta, out):
    """``P_visc = 2 eta J d F^-T`` per particle (section 2.3), into ``out`` (N, 4)."""
    for i in range(F.shape[0]):
        f00, f01, f10, f11 = F[i, 0, 0], F[i, 0, 1], F[i, 1, 0], F[i, 1, 1]
        det = f00 * f11 - f01 * f10
        # F^-1
        g00, g01, g10, g11 = f11 / det, -f01 / det, -f10 / det, f00 / det
        d00 = (F[i, 0, 0] - F_old[i, 0, 0]) / dt
        d01 = (F[i, 0, 1] - F_old[i, 0, 1]) / dt
        d10 = (F[i, 1, 0] - F_old[i, 1, 0]) / dt
        d11 = (F[i, 1, 1] - F_old[i, 1, 1]) / dt
        # l = F_dot F^-1, d = sym(l)
        l00 = d00 * g00 + d01 * g10
        l01 = d00 * g01 + d01 * g11
        l10 = d10 * g00 + d11 * g10
        l11 = d10 * g01 + d11 * g11
        s00, s11, s01 = l00, l11, 0.5 * (l01 + l10)
        c = 2.0 * eta * det
        # (2 eta J d) F^-T
        out[i, 0] = c * (s00 * g00 + s01 * g01)
        out[i, 1] = c * (s00 * g10 + s01 * g11)
        out[i, 2] = c * (s01 * g00 + s11 * g01)
        out[i, 3] = c * (s01 * g10 + s11 * g11)


def relax(
    model: Model,
    x0: np.ndarray,
    load: Load,
    *,
    density: float,
    dt: float = 1.0,
    eta: float = 0.0,
    kinetic_damping: bool = True,
    tol: float = 1e-4,
    max_steps: int = 200_000,
    check_every: int = 50,
    run: str | None = None,
):
    """Leapfrog relaxation (eq. 2.13) to the equilibrium at ``load``; returns ``(x, evaluation, convergence)``."""
    run = run or model.name
    t0 = time.perf_counter()
    x = x0.copy()
    m = (density * model.layout.volume)[:, None]
    v = np.zeros_like(x)
    cons, target = model.constraints(load)
    x[cons] = target
    extra = np.zeros((model.n, 4))
    ev = model.evaluate(x, load)
    F_old = ev.F.copy()
    kinetic_prev = 0.0
    for step in range(1, max_steps + 1):
        if eta:
            viscous_stress(ev.F, F_old, dt, eta, extra)
            F_old = ev.F.copy()
            ev = model.evaluate(x, load, extra)
        acc = (ev.f_int + ev.f_ext) / m
        acc[cons] = 0.0
        v += acc * dt  # v^(t+1/2) = v^(t-1/2) + a^t dt
        kinetic = float((m * v * v).sum())
        if kinetic_damping and kinetic < kinetic_prev:
            v[:] = 0.0
            kinetic = 0.0
        kinetic_prev = kinetic
        x += v * dt  # x^(t+1) = x^t + v^(t+1/2) dt
        ev = model.evaluate(x, load)
        if ev.min_det <= 0.0:
            raise Inverted(run, load, f"particle inversion during relaxation step {step}")
        if not ev.finite:
            raise Diverged(run, load, f"non-finite forces at relaxation step {step}")
        if step % check_every == 0:
            rel = relative_residual(model, ev)
            if rel < tol:
                return x, ev, Convergence(rel, step, step + 1, 0, time.perf_counter() - t0)
    raise NotConverged(
        run,
        load,
        f"relaxation did not converge in {max_steps} steps (relative residual {relative_residual(model, ev):.3g})",
    )
