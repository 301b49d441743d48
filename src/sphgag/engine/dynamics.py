"""Pseudo-dynamics as in the paper: leapfrog steps with mass scaling and artificial viscosity (eqs. 2.12-2.13).

The production solver is Newton's method (:mod:`sphgag.engine.solver`). This module is the paper's explicit scheme:
an independent route to the same equilibrium (:func:`relax`, the tests check that both agree) and the step loop of
the authors' fixed-step procedure (:mod:`sphgag.studies.paper_procedure`). The steps run in one Numba loop
(:func:`leapfrog`) over the same forces as the quasi-static solver: the elastic and hourglass forces of
:func:`sphgag.engine.forces.forces_and_stresses`, the energy hourglass form's ``-K (x - X)``
(:mod:`sphgag.engine.forces`) and the lumen pressure (:func:`sphgag.engine.loading.pressure_forces`).

Masses are scaled (``m_i = density * V_i``, a pseudo-density, not physical inertia); the viscous first
Piola-Kirchhoff stress of section 2.3, ``P_visc = 2 eta J d F^-T`` with ``d = sym(F_dot F^-1)`` and
``F_dot = (F^t - F^(t-1)) / dt``, is added to P. (The paper writes ``2 eta d F^-T``; the factor J is the Piola
transform of the Cauchy stress ``2 eta d``, as in the authors' script.) Optionally the velocities are reset whenever
the kinetic energy peaks (kinetic damping), which reaches the quasi-static state much faster than viscosity alone.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
from numba import njit

from . import forces
from .loading import Load, lumen_area_gradient
from .model import Model
from .solver import Convergence, Diverged, Inverted, NotConverged, relative_residual


@njit(cache=True, error_model="numpy")
def viscous_stress(F, F_old, dt, eta, out):
    """``P_visc = 2 eta J d F^-T`` per particle (section 2.3) from (N, 4) rows of F, into ``out`` (N, 4)."""
    for i in range(F.shape[0]):
        f00, f01, f10, f11 = F[i, 0], F[i, 1], F[i, 2], F[i, 3]
        det = f00 * f11 - f01 * f10
        g00, g01, g10, g11 = f11 / det, -f01 / det, -f10 / det, f00 / det  # F^-1
        d00 = (f00 - F_old[i, 0]) / dt
        d01 = (f01 - F_old[i, 1]) / dt
        d10 = (f10 - F_old[i, 2]) / dt
        d11 = (f11 - F_old[i, 3]) / dt
        l00 = d00 * g00 + d01 * g10  # l = F_dot F^-1, d = sym(l)
        l01 = d00 * g01 + d01 * g11
        l10 = d10 * g00 + d11 * g10
        l11 = d10 * g01 + d11 * g11
        s00, s11, s01 = l00, l11, 0.5 * (l01 + l10)
        c = 2.0 * eta * det
        out[i, 0] = c * (s00 * g00 + s01 * g01)  # (2 eta J d) F^-T
        out[i, 1] = c * (s00 * g10 + s01 * g11)
        out[i, 2] = c * (s01 * g00 + s11 * g01)
        out[i, 3] = c * (s01 * g10 + s11 * g11)


@njit(cache=True, error_model="numpy")
def _deformation_gradient_rows(x, pd, xe, FP, out):
    """``F`` of every particle (eq. 2.9) as (N, 4) rows into ``out`` (the first pass of the force kernel; ``pd``: the
    packed pair data, :attr:`sphgag.engine.forces.PairData.arrays`)."""
    n = x.shape[0]
    forces.extend(x, pd[11], pd[12], xe)
    forces._deformation_gradients(xe, pd[0], pd[1], pd[3], pd[5], pd[6], pd[8], False, FP, n)
    for i in range(n):
        for k in range(4):
            out[i, k] = FP[i, k]


@njit(cache=True, error_model="numpy")
def _net_forces(x, pd, material, extra, hg, lumen, work):
    """``f_int + f_ext`` at ``x`` into ``f`` (of ``work = (xe, fe, FP, f, g)``): elastic and eq. (2.14) forces
    (``material = (lz, cth, sth, props)``), ``-K (x - X)`` of the energy hourglass form (``hg = (CSR of K, X)``,
    empty under eq. 2.14) and the lumen pressure ``p lz dA/dx`` (``lumen = (inner surface, p)``); returns the
    smallest det F."""
    lz = material[0]
    hg_ptr, hg_idx, hg_val, X = hg
    inner, pressure = lumen
    xe, fe, FP, f, g = work
    dmin = forces.forces_and_stresses(x, pd, *material, extra, xe, fe, FP, f)
    if hg_ptr.shape[0] > 1:
        u, ff = (x - X).reshape(-1), f.reshape(-1)
        for row in range(hg_ptr.shape[0] - 1):
            acc = 0.0
            for k in range(hg_ptr[row], hg_ptr[row + 1]):
                acc += hg_val[k] * u[hg_idx[k]]
            ff[row] -= acc
    if pressure != 0.0:
        lumen_area_gradient(x, inner, g)
        for k in range(inner.shape[0]):
            f[inner[k], 0] += pressure * lz * g[k, 0]
            f[inner[k], 1] += pressure * lz * g[k, 1]
    return dmin


@njit(cache=True, error_model="numpy")
def leapfrog(x, v, inv_m, held, held_x, pd, material, hg, lumen, stepping, steps, F_old, extra, work):
    """``steps`` leapfrog steps (eq. 2.13) in place: ``v^(t+1/2) = v^(t-1/2) + dt f(x^t) / m``,
    ``x^(t+1) = x^t + dt v^(t+1/2)``, the ``held`` particles at ``held_x``; the forces of :func:`_net_forces` (``pd,
    material, hg, lumen, work``), ``stepping = (dt, eta, damping)``. With ``eta > 0`` the viscous stress of
    :func:`viscous_stress` (``F_old``: the previous step's F rows, updated) is added to P; with ``damping`` the
    velocities are zeroed whenever the kinetic energy falls (kinetic damping). Returns ``(kinetic energy
    1/2 sum m v^2 of the last half step, smallest det F, steps done)``; it stops early at an inversion or a
    non-finite force."""
    n = x.shape[0]
    dt, eta, damping = stepping
    xe, FP, f = work[0], work[2], work[3]
    kinetic_prev = 0.0
    kinetic = 0.0
    dmin = np.inf
    for step in range(steps):
        if eta > 0.0:
            _deformation_gradient_rows(x, pd, xe, FP, extra)
            for i in range(n):
                for k in range(4):
                    F_new = extra[i, k]
                    extra[i, k] = F_old[i, k]
                    F_old[i, k] = F_new
            # extra holds F^(t-1) and F_old holds F^t: P_visc from them, into extra
            viscous_stress(F_old, extra, dt, eta, extra)
        dmin = _net_forces(x, pd, material, extra, hg, lumen, work)
        if not dmin > 0.0:
            return kinetic, dmin, step
        kinetic = 0.0
        for i in range(n):
            for d in range(2):
                v[i, d] += dt * f[i, d] * inv_m[i]
        for k in range(held.shape[0]):
            v[held[k], 0] = v[held[k], 1] = 0.0
        for i in range(n):
            kinetic += 0.5 * (v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1]) / inv_m[i]
        if not np.isfinite(kinetic):
            return kinetic, dmin, step
        if damping and kinetic < kinetic_prev:
            v[:, :] = 0.0
            kinetic = 0.0
        kinetic_prev = kinetic
        for i in range(n):
            x[i, 0] += dt * v[i, 0]
            x[i, 1] += dt * v[i, 1]
        for k in range(held.shape[0]):
            x[held[k], 0], x[held[k], 1] = held_x[k, 0], held_x[k, 1]
    return kinetic, dmin, steps


@dataclass
class Motion:
    """The state of the pseudo-dynamics: positions ``x`` at step ``step`` and velocities ``v`` at the half step
    before it, with ``F_old`` (the deformation gradients of the last step, for the viscous stress)."""

    x: np.ndarray
    v: np.ndarray
    step: int = 0
    F_old: np.ndarray | None = None

    @classmethod
    def at_rest(cls, x: np.ndarray) -> Motion:
        return cls(np.array(x, dtype=float), np.zeros_like(x, dtype=float))


@dataclass(frozen=True)
class Stepping:
    """How the pseudo-dynamics step: pseudo-time step ``dt``, mass scaling ``density`` (``m_i = density V_i``),
    viscosity ``eta`` of the viscous stress (0: none) and kinetic ``damping``."""

    dt: float
    density: float
    eta: float = 0.0
    damping: bool = False


def advance(model: Model, motion: Motion, load: Load, steps: int, stepping: Stepping, run: str | None = None) -> float:
    """``steps`` leapfrog steps of ``motion`` under ``load`` (held fixed), in place (:func:`leapfrog`); returns the
    kinetic energy of the last half step. Raises :class:`~sphgag.engine.solver.Inverted` or
    :class:`~sphgag.engine.solver.Diverged` naming the run, the load and the step."""
    run = run or model.name
    props, _, pairs = model.material(load)
    K = model.hourglass_matrix(load)
    hg = (np.zeros(1, np.int32), np.zeros(0, np.int32), np.zeros(0)) if K is None else (K.indptr, K.indices, K.data)
    held, held_x = model.constraints(load)
    n, pd = model.n, pairs.arrays
    if motion.F_old is None:
        motion.F_old = np.empty((n, 4))
        _deformation_gradient_rows(motion.x, pd, model._xe, np.empty((n, 12)), motion.F_old)
    inner = model.layout.inner_surface
    extra = np.zeros((n, 4)) if stepping.eta > 0.0 else forces.NO_EXTRA_STRESS
    fixed = (np.asarray(held, np.int64), np.ascontiguousarray(held_x, dtype=float).reshape(-1, 2))
    inv_m = 1.0 / (stepping.density * model.layout.volume)
    material = (load.axial_stretch, model.cth, model.sth, props)
    loads = (material, (*hg, model.layout.X), (inner, load.pressure_kPa or 0.0))
    work = (model._xe, model._fe, np.empty((n, 12)), np.empty((n, 2)), np.empty((inner.size, 2)))
    steps_of = (stepping.dt, stepping.eta, stepping.damping)
    kinetic, dmin, done = leapfrog(
        motion.x, motion.v, inv_m, *fixed, pd, *loads, steps_of, steps, motion.F_old, extra, work
    )
    motion.step += done
    if done < steps:
        what = "particle inversion" if not dmin > 0.0 else "non-finite velocities"
        error = Inverted if not dmin > 0.0 else Diverged
        raise error(run, load, f"{what} at pseudo-dynamic step {motion.step}")
    return float(kinetic)


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
    """Leapfrog relaxation (eq. 2.13) to the equilibrium at ``load``; returns ``(x, evaluation, convergence)``: the
    relative residual (:func:`~sphgag.engine.solver.relative_residual`) is checked every ``check_every`` steps."""
    run = run or model.name
    t0 = time.perf_counter()
    cons, target = model.constraints(load)
    motion = Motion.at_rest(x0)
    motion.x[cons] = target
    stepping = Stepping(dt, density, eta, kinetic_damping)
    while motion.step < max_steps:
        advance(model, motion, load, min(check_every, max_steps - motion.step), stepping, run)
        ev = model.evaluate(motion.x, load)
        rel = relative_residual(model, ev)
        if rel < tol:
            return motion.x, ev, Convergence(rel, motion.step, motion.step + 1, 0, time.perf_counter() - t0)
    raise NotConverged(run, load, f"relaxation did not converge in {max_steps} steps (relative residual {rel:.3g})")
