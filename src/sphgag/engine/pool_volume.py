"""The pressure-volume path of a swelling pool, traced with the pool's volume as the control (figure 4 runs).

Under concentration control (the paper's protocol: the fixed-charge
concentration ``c`` of eqs. 2.25-2.27 is raised and the wall follows) a path can
lose equilibrium for two reasons:

* a **limit point** of the pool's pressure-volume path: beyond some ``c_lim`` the
  swelling pressure the wall can hold falls as the pool grows, and a pool held
  at ``c > c_lim`` has no equilibrium near the path (it snaps);
* a **failure of the discretisation**: equilibria exist, but the solver cannot reach
  them (or the particles cannot represent them).

Volume control tells them apart. The pool's volume ``V = sum_i V_i J_i`` (its
particles' reference areas times their J, eq. 2.9; per unit axial length) becomes
the prescribed quantity and ``c`` the unknown that holds it (a bordered Newton
system, the volume constraint's row added to the exact Jacobian of the forces):

    [ K     dr/dc ] [dx]     [ r     ]
    [ dV/dx   0   ] [dc] = - [ V - V*]

A prescribed pool volume cannot snap, so the path passes a limit point of ``c``:
``c`` rises with ``V``, reaches its largest value ``c_lim`` and falls. If instead the
volume-controlled path also stops while ``c`` still rises, there was no limit point
where concentration control failed; the path ends there, and the run says so.

``dr/dc`` is a central difference of the exact residual (the residual is affine in
the prescribed swelling pressure, and smooth in ``c``); ``dV/dx`` is the exact force
of a unit swelling pressure on the pool's particles (the internal force of
eq. 2.11 is the gradient of the discrete energy, and ``-Pi (J - 1)`` is the energy
of eq. 2.27's pressure term).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from ..physics import materials
from . import solver
from .loading import Load
from .model import Model

log = logging.getLogger("sphgag")


@dataclass
class VolumeState:
    """A converged state of the volume-controlled path."""

    x: np.ndarray
    load: Load
    volume: float  # pool volume per unit axial length [um^2]
    convergence: solver.Convergence
    parameter: str = "concentration"  # the load's material value that holds the volume

    @property
    def concentration(self) -> float:
        """The value of the controlling parameter (the concentration, or a prescribed swelling pressure)."""
        return float(self.load.material_value(self.parameter))


@dataclass
class Path:
    """The volume-controlled continuation of a concentration-controlled path that lost equilibrium.

    ``states``: converged states at increasing pool volume; ``end``: ``limit point`` (``c`` passed a largest value,
    ``limit_concentration``) or ``no equilibrium`` (the volume-controlled path stopped with ``c`` still rising;
    ``reason`` says where and why)."""

    states: list
    end: str
    limit_concentration: float
    reason: str


class PoolVolume:
    """The pool's volume ``V = sum V_i J_i`` over ``members`` and its exact gradient ``dV/dx``."""

    @staticmethod
    def of(model: Model, members: np.ndarray):
        """The volume of the pool ``members`` of ``model``: :class:`CavityVolume` where the pool is the model's cavity,
        else :class:`PoolVolume`."""
        return CavityVolume(model) if model.cavities else PoolVolume(model, members)

    def __init__(self, model: Model, members: np.ndarray):
        self.members = np.asarray(members, dtype=np.int64)
        self.V = model.layout.volume[self.members]
        props = materials.empty_props(model.n)
        props[self.members, materials.PI] = 1.0  # energy -(J - 1) per unit volume: its force is dV/dx
        self._unit = Model(f"{model.name}_pool_volume", model.layout, model.nb, props, 0.0)

    def __call__(self, ev) -> float:
        F = ev.F[self.members]
        J = (F[:, 0, 0] * F[:, 1, 1] - F[:, 0, 1] * F[:, 1, 0]) * ev.load.axial_stretch
        return float(np.sum(self.V * J))

    def gradient(self, x: np.ndarray, load: Load) -> np.ndarray:
        return self._unit.evaluate(x, Load(load.axial_stretch, 0.0)).f_int


class CavityVolume:
    """The volume of a pool modelled as a cavity (:mod:`sphgag.engine.pool_cavity`): ``V_pool + A - A_0`` (the area its
    lining encloses; per unit axial reference length as :class:`PoolVolume` is, up to the constant ``lz``), and its
    exact gradient, the area's ``dA/dx`` on the lining."""

    def __init__(self, model: Model):
        (self.cavity,) = model.cavities
        self.V = model.layout.volume[self.cavity.members]
        self.n = model.n

    def __call__(self, ev) -> float:
        return self.cavity.pool_area * self.cavity.volume_ratio(ev.x)

    def gradient(self, x: np.ndarray, load: Load) -> np.ndarray:
        g = np.zeros((self.n, 2))
        g[self.cavity.loop] = self.cavity.area_gradient(x)
        return g


LABELS = {"concentration": ("c", "mEq/l"), "swelling_pressure": ("Pi", "kPa")}  # the parameter as the log names it


def _at(load: Load, c: float, parameter: str = "concentration") -> Load:
    return load.with_material(**{parameter: float(c)})


def concentration_slope(
    model: Model, x: np.ndarray, load: Load, h: float = 1e-3, parameter: str = "concentration"
) -> np.ndarray:
    """``dr/dc`` by a central difference (``h`` in the parameter's unit: mEq/l, or kPa for a swelling pressure)."""
    c = float(load.material_value(parameter))
    up = model.evaluate(x, _at(load, c + h, parameter)).residual_vector
    down = model.evaluate(x, _at(load, max(c - h, 0.0), parameter)).residual_vector
    return (up - down) / (c + h - max(c - h, 0.0))


def _admissible(ev) -> bool:
    return bool(ev.min_det > 0.0 and ev.finite)


def _bordered_step(model: Model, pool, ev, target: float, parameter: str, run: str) -> tuple[np.ndarray, float]:
    """The Newton step ``(dx, dc)`` of the bordered system at the evaluation ``ev`` (module docstring)."""
    x, load = ev.x, ev.load
    fac = solver.factorise(model, ev, model.jacobian(ev), 0.0, run)
    a = -fac.step(ev).ravel()  # K^-1 r
    b = fac.solve(concentration_slope(model, x, load, parameter=parameter).ravel())
    g = pool.gradient(x, load).ravel()
    dc = ((pool(ev) - target) - g @ a) / (g @ b)
    return (-a - b * dc).reshape(-1, 2), float(dc)


def solve_at_volume(
    model: Model,
    pool: PoolVolume,
    x0: np.ndarray,
    load0: Load,
    target: float,
    tol: float,
    max_iter: int,
    run: str,
    parameter: str = "concentration",
) -> VolumeState:
    """The equilibrium whose pool volume is ``target``, with the concentration (or the load's material value
    ``parameter``, e.g. a prescribed ``swelling_pressure``) as the unknown (bordered Newton with a backtracking line
    search on the residual and the volume error, and a watchdog step: :func:`_bordered_step`)."""
    x, load = x0.copy(), load0
    ev = model.evaluate(x, load)
    solver.check(model, ev, run)
    n_eval, n_jac = 1, 0

    def merit(ev):
        return np.hypot(np.linalg.norm(ev.residual_vector) / ev.force_scale(model), (pool(ev) - target) / target)

    progress = (merit(ev), 0)  # (merit, iteration) when the merit last halved
    for it in range(max_iter + 1):
        rel = solver.relative_residual(model, ev)
        err = (pool(ev) - target) / target
        if rel < tol and abs(err) < 1e-8:
            return VolumeState(x, load, pool(ev), solver.Convergence(rel, it, n_eval, n_jac, 0.0), parameter)
        if it == max_iter:
            break
        if merit(ev) < 0.5 * progress[0]:
            progress = (merit(ev), it)
        elif it - progress[1] >= solver.STALL_ITERATIONS:
            raise solver.NotConverged(run, load, f"volume control stagnated (residual {rel:.3g})")
        dx, dc = _bordered_step(model, pool, ev, target, parameter, run)
        n_jac, n_eval = n_jac + 1, n_eval + 3
        m0, step = merit(ev), 1.0
        c = float(load.material_value(parameter))
        while step > 1e-4:
            trial_load = _at(load, max(c + step * dc, 0.0), parameter)
            trial = model.evaluate(x + step * dx, trial_load)
            n_eval += 1
            if _admissible(trial) and merit(trial) < (1.0 - 1e-4 * step) * m0:
                break
            if step == 1.0 and _admissible(trial):
                # watchdog (Chamberlain et al. 1982): where the path bends, a full step can raise the merit that the
                # next full step brings below where it started; take both then, else backtrack from here
                dx2, dc2 = _bordered_step(model, pool, trial, target, parameter, run)
                second_load = _at(trial_load, max(float(trial_load.material_value(parameter)) + dc2, 0.0), parameter)
                second = model.evaluate(trial.x + dx2, second_load)
                n_jac, n_eval = n_jac + 1, n_eval + 4
                if _admissible(second) and merit(second) < (1.0 - 1e-4) * m0:
                    trial, trial_load = second, second_load
                    break
            step *= 0.5
        else:
            raise solver.NotConverged(run, load, f"volume control: line search failed (residual {rel:.3g})")
        x, load, ev = trial.x, trial_load, trial
    raise solver.NotConverged(run, load, f"volume control: no convergence in {max_iter} iterations")


def reach_volume(
    model: Model,
    pool: PoolVolume,
    x0: np.ndarray,
    load0: Load,
    target: float,
    *,
    run: str,
    tol: float,
    max_iter: int,
    growth: float = 0.05,
    min_growth: float = 1e-3,
    parameter: str = "concentration",
) -> VolumeState:
    """The equilibrium whose pool volume is ``target``, reached from the converged state ``(x0, load0)`` through
    volumes that change by at most ``growth`` (relative) per step, halved where a step fails, down to ``min_growth``
    (:func:`solve_at_volume` at each; raises :class:`sphgag.engine.solver.NotConverged` below that)."""
    x, load = x0, load0
    volume = pool(model.evaluate(x, load))
    step = growth
    while True:
        ratio = target / volume
        last = abs(ratio - 1.0) <= step
        goal = target if last else volume * (1.0 + np.sign(ratio - 1.0) * step)
        try:
            s = solve_at_volume(model, pool, x, load, goal, tol, max_iter, run, parameter)
        except solver.SimulationError as exc:
            step *= 0.5
            if step < min_growth:
                raise solver.NotConverged(
                    run, load, f"the pool's volume does not reach its target ({exc.reason})"
                ) from exc
            continue
        if last:
            return s
        x, load, volume = s.x, s.load, s.volume
        step = min(step * 1.5, growth)


def hold_volume(
    path_solver: solver.Solver,
    last: solver.State,
    members: np.ndarray,
    end: Load,
    *,
    run: str | None = None,
    parameter: str = "concentration",
) -> VolumeState:
    """The equilibrium at the end of the load path from the converged state ``last`` to ``end`` (e.g. the
    ``transition`` 0 -> 1 of a change of history, :class:`sphgag.engine.history.HistoryMaterial`) with the volume of
    the pool ``members`` held at ``last``'s and ``parameter`` (the concentration) as the unknown:
    :func:`solve_at_volume` at each increment of the path (the rest of the path at first, halved where a solve fails,
    at most ``solver.FALLBACK_BISECTIONS`` times; raises :class:`sphgag.engine.solver.NotConverged` below that). A
    prescribed pool volume cannot snap, so this path passes where the same path at a fixed ``parameter`` can lose the
    pool's equilibrium: it gives :func:`continue_path` its start under a new history
    (:meth:`sphgag.studies.delamination.growth.GrowthRun.follow_snap`)."""
    model = path_solver.model
    run = run or model.name
    options = path_solver.options.newton_budget()
    pool = PoolVolume.of(model, members)
    target = pool(last.evaluation if last.evaluation is not None else model.evaluate(last.x, last.load))
    x, value, done = last.x, float(last.load.material_value(parameter)), 0.0
    smallest = 0.5**solver.FALLBACK_BISECTIONS
    step = 1.0
    while True:
        at = min(done + step, 1.0)
        load = _at(last.load.lerp(end, at), value, parameter)
        try:
            held = solve_at_volume(model, pool, x, load, target, options.tol, options.max_iter, run, parameter)
        except solver.SimulationError as exc:
            step *= 0.5
            if step < smallest:
                name, unit = LABELS[parameter]
                reason = (
                    f"the path at a fixed pool volume stops {done:.3g} of the way, at {name} = {value:.4g} {unit} "
                    f"({exc.reason})"
                )
                raise solver.NotConverged(run, load, reason) from exc
            continue
        if at == 1.0:
            return held
        x, value, done = held.x, held.concentration, at
        step = min(2.0 * step, 1.0 - done)


def continue_path(
    path_solver: solver.Solver,
    last: solver.State,
    members: np.ndarray,
    targets: list[float],
    *,
    run: str | None = None,
    growth: float = 0.05,
    max_ratio: float = 100.0,
    min_growth: float = 1e-3,
    parameter: str = "concentration",
) -> tuple[Path, list[solver.State]]:
    """Trace the pool's path from the converged state ``last`` with its volume as the control.

    The volume grows by ``growth`` (relative) per step, halved when a step fails, down to ``min_growth``. Whenever
    ``c`` passes one of ``targets`` (concentrations the concentration-controlled path could not reach) while it
    rises, the state at exactly that concentration is solved by concentration control from the bracketing state
    and returned too. Stops at a limit point, when the targets are done, when the volume reaches ``max_ratio``
    times the pool's reference volume, or where volume control fails. ``parameter``: the load's material value that
    plays ``c`` (``concentration``, or ``swelling_pressure`` for a prescribed pressure). ``path_solver``: the
    :class:`sphgag.engine.solver.Solver` of the path this one continues (its model, and its Newton ``tol`` and
    ``max_iter``, :meth:`sphgag.engine.solver.PathOptions.newton_budget`; the concentration-controlled steps keep
    their factorisations in its cache).
    """
    model = path_solver.model
    run = run or model.name
    load_control = path_solver.using(path_solver.options.newton_budget())
    tol, max_iter = load_control.options.tol, load_control.options.max_iter
    pool = PoolVolume.of(model, members)
    reference = float(np.sum(pool.V))
    states, reached = [], []
    x, load = last.x, last.load
    name, unit = LABELS[parameter]
    c = float(load.material_value(parameter))
    volume = pool(last.evaluation if last.evaluation is not None else model.evaluate(x, load))
    todo = sorted(t for t in targets if t > c)
    points = [(volume, c)]
    step = growth
    while todo:
        if volume / reference > max_ratio:
            reason = f"the pool reached {max_ratio:g} times its volume, {name} = {c:.4g} {unit} still rising"
            return Path(states, "no equilibrium", np.nan, reason), reached
        try:
            s = solve_at_volume(model, pool, x, load, volume * (1.0 + step), tol, max_iter, run, parameter)
        except solver.SimulationError as exc:
            step *= 0.5
            if step < min_growth:
                reason = (
                    f"volume control stops at {name} = {c:.4g} {unit}, pool volume {volume / reference:.3g} times its "
                    f"reference, {name} still rising ({exc.reason})"
                )
                return Path(states, "no equilibrium", np.nan, reason), reached
            continue
        states.append(s)
        held = f"{name} = {s.concentration:.4g} {unit} (residual {s.convergence.residual:.2e})"
        log.info(
            "[%s] volume control: pool at %.3g times its reference volume holds %s", run, s.volume / reference, held
        )
        points.append((s.volume, s.concentration))
        if s.concentration < c:  # past the largest concentration: a limit point
            c_lim = _limit(points)
            log.info("[%s] limit point of the pool's pressure-volume path at %s = %.4g %s", run, name, c_lim, unit)
            return Path(states, "limit point", c_lim, f"limit point at {name} = {c_lim:.4g} {unit}"), reached
        while todo and s.concentration >= todo[0]:
            target = _at(s.load, todo.pop(0), parameter)
            try:
                reached.append(load_control.follow_path(s.x, s.load, [target], run=run)[-1])
            except solver.SimulationError as exc:
                reason = (
                    f"{name} = {s.concentration:.4g} {unit} was held at volume control, but load control from "
                    f"there does not reach {name} = {target.material_value(parameter):g} {unit} ({exc.reason})"
                )
                return Path(states, "no equilibrium", np.nan, reason), reached
        x, load, c, volume = s.x, s.load, s.concentration, s.volume
        step = min(step * 1.5, growth)
    return Path(states, "complete", np.nan, ""), reached


def _limit(points: list) -> float:
    """The largest concentration of the path: a parabola ``c(V)`` through the point of largest ``c`` and its two
    neighbours (``points``: ``(V, c)`` in order of volume)."""
    k = int(np.argmax([c for _, c in points]))
    near = points[max(k - 1, 0) : k + 2]
    if len(near) < 3:
        return float(points[k][1])
    v0 = near[1][0]
    a, b, c0 = np.polyfit([v / v0 - 1.0 for v, _ in near], [c for _, c in near], 2)
    return float(c0 - b * b / (4.0 * a)) if a < 0.0 else float(points[k][1])
