"""Figure 4's pools read at a given volume: the states of a swelling path at which a pool holds a volume ratio.

Under the paper's law (eqs. 2.25-2.27, a prescribed Pi(c)) the pools of figure 4 swell many-fold, and near
150 mEq/l ``d ln J / d ln c`` is about 5.5: the volume at a given concentration is ill-conditioned, so a small error of
the discretisation in the pressure the wall holds becomes a large error in J. Read the other way, the concentration
that holds a given volume ratio, and the stresses around the pool there, are well conditioned. This module finds
those states on a path of :func:`sphgag.studies.pool_swelling.swell_pool`: for each requested ``J``, from the last state
of the path below it, the pool's volume ``J V_0`` is prescribed and the concentration is the unknown (the bordered
Newton system of :func:`sphgag.engine.pool_volume.solve_at_volume`; ``V_0`` the pool's reference volume, ``J`` as
``pool_volume_change + 1`` of :func:`sphgag.studies.pool_swelling.pool_measurements`). A ``J`` beyond the last state of
a complete path (one that reached the top of its ramp) is not reached: no state is extrapolated. Where the path lost
equilibrium under concentration control, the pool's volume goes on as the control from its last state (as the path's
own continuation does, :func:`sphgag.engine.pool_volume.continue_path`), so a ``J`` beyond it is reached from there.
One that volume control cannot reach is logged and left out.
"""

from __future__ import annotations

import logging
from dataclasses import replace

import numpy as np

from ..engine import pool_volume, solver
from ..engine.model import Model
from ..engine.numerics import Numerics
from .pool_swelling import PoolState

log = logging.getLogger("sphgag")

STAGE = "at volume"  # the stage of the states this module returns


def volume_of(model: Model, state: PoolState) -> tuple[pool_volume.PoolVolume, float, float]:
    """``(measure, V, V_0)``: the volume measure of the pool in the model ``state`` is in equilibrium with, the
    pool's volume in ``state`` and its reference volume."""
    at = state.model(model)
    pool = pool_volume.PoolVolume.of(at, model.props.converting)
    return pool, pool(at.evaluate(state.x, state.load)), float(np.sum(pool.V))


def at_volume_ratios(model: Model, states: list[PoolState], targets, numerics: Numerics) -> dict[float, PoolState]:
    """``{J: state}``: the state of the swelling path ``states`` (converted stage, in order of concentration) at
    which the pool holds the volume ratio ``J``, for each ``J`` of ``targets`` that the path passes, or beyond the end
    of a path that lost equilibrium. Each is solved from the last state below it (of the path, or one reached beyond
    it), with the concentration as the unknown; its ``control`` is ``volume`` and its stage :data:`STAGE`."""
    opts = numerics.solver_options()
    path = [s for s in states if s.stage == "converted"]
    if not path:
        return {}
    measured = [volume_of(model, s) for s in path]
    ratios = np.array([v / v0 for _, v, v0 in measured])
    # a path that lost equilibrium under concentration control goes on under volume control: its J beyond the last
    # state are reached from there (each from the last one reached); a complete path ends at the top of the ramp
    open_end = path[-1].path_end != "complete"
    out = {}
    for J in sorted(float(t) for t in targets):
        below = np.flatnonzero(ratios <= J)
        beyond = below.size > 0 and below[-1] == len(path) - 1
        if below.size == 0 or (beyond and not open_end):  # not passed by the path: no state is extrapolated
            continue
        k = int(below[-1])
        start, (pool, _, v0) = path[k], measured[k]
        if beyond and out and max(out) > ratios[k]:
            start = out[max(out)]
        at = start.model(model)
        run = f"{model.name}_J{J:g}"
        try:
            vs = pool_volume.reach_volume(
                at, pool, start.x, start.load, J * v0, run=run, tol=opts.tol, max_iter=opts.max_iter
            )
        except solver.SimulationError as exc:
            log.warning("[%s] no state at J = %g: %s", run, J, exc.reason)
            continue
        reached = solver.State(vs.load, vs.x, None, vs.convergence)
        state = PoolState.of(STAGE, vs.concentration, reached, "volume", at, start.pool_model)
        out[J] = replace(state, path_end=path[k].path_end, end_reason=path[k].end_reason)
        log.info("[%s] the pool holds J = %g at c = %.4g mEq/l", run, J, vs.concentration)
    return out
