"""The snapshots of a delamination run on disk: the particle states it keeps (positions, load, particle history) with
their radial stress, in one ``results/delamination/runs/{law}/*_snapshots.npz`` per run; each one can restart the run
(:func:`sphgag.studies.delamination.growth.grow` with ``resume``)."""

from __future__ import annotations

import numpy as np

from ...engine import measure, solver
from ...engine.model import Model
from ...records import state as state_io


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
