"""ParaView time series of saved states: one ``.vtu`` file per state and one ``.pvd`` collection per run (meshio).

Every particle is a VTK vertex at its *current* position (z = 0: the model is the arterial cross-section in plane
strain), so ParaView shows the deformed wall as it is; "Point Gaussian" draws the particles as discs. Point data of
each state (:func:`fields`):

* ``reference_position`` X and ``displacement`` x - X [um] (eq. 2.1);
* ``cauchy_rr_kPa``, ``cauchy_tt_kPa``, ``cauchy_rt_kPa``: the Cauchy stress sigma = P F^T / J (eq. 2.10) in the
  particle's current polar frame, radial, hoop (circumferential) and shear (:func:`sphgag.engine.measure.cauchy_polar`);
* ``J``: det F lambda_z;
* ``damage``: D of eq. (2.28) (:class:`sphgag.engine.history.ParticleHistory`);
* ``layer``: the index of the particle's layer (0 media, 1 adventitia: ``Layout.layer_names``);
* ``origin``: 0 tissue, 1 seeded pool, 2 ruptured tissue that became GAG (section 2.7);
* ``pool``: the index of the GAG pool a particle belongs to, -1 for tissue;
* ``concentration_mEq_l``: the fixed-charge concentration c of the GAG particles (eqs. 2.25-2.27), 0 for tissue;
* ``pseudo_time`` (delamination runs): the damage pass of the snapshot (section 2.7), the same at every particle.

The ``.pvd`` file's ``timestep`` is the state's index along the run (ParaView's time slider needs distinct times:
the snapshots of the concentration levels before onset share pseudo-time 0).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from xml.etree import ElementTree

import meshio
import numpy as np

from ..engine import measure
from ..engine.history import HistoryMaterial, ParticleHistory
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..records import state as state_io
from ..studies import artery
from ..studies.pool_swelling import state_model

FIELDS = (
    "reference_position",
    "displacement",
    "cauchy_rr_kPa",
    "cauchy_tt_kPa",
    "cauchy_rt_kPa",
    "J",
    "damage",
    "layer",
    "origin",
    "pool",
    "concentration_mEq_l",
)


@dataclass(frozen=True)
class Frame:
    """One state of a series: its index along the run (the ``.pvd`` file's time), the current positions ``x`` (n, 2)
    and its point data."""

    time: float
    x: np.ndarray
    data: dict


def _plane(a: np.ndarray) -> np.ndarray:
    """(n, 2) in-plane vectors as the (n, 3) vectors VTK reads."""
    return np.column_stack([a, np.zeros(len(a))])


def fields(model: Model, x: np.ndarray, load, history: ParticleHistory) -> dict:
    """The point data of one state (module docstring), from the model evaluated at ``x`` under ``load`` with the
    model's current material (the caller sets it to the state's history)."""
    ev = model.evaluate(x, load)
    srr, stt, srt, J = measure.cauchy_polar(ev)
    X = model.layout.X
    gag = history.gag
    return dict(
        reference_position=_plane(X),
        displacement=_plane(x - X),
        cauchy_rr_kPa=srr,
        cauchy_tt_kPa=stt,
        cauchy_rt_kPa=srt,
        J=J,
        damage=np.asarray(history.D, dtype=float),
        layer=np.asarray(model.layout.layer, dtype=np.int32),
        origin=np.asarray(history.origin, dtype=np.int32),
        pool=np.asarray(history.pool, dtype=np.int32),
        concentration_mEq_l=np.where(gag, float(load.material_value("concentration")), 0.0),
    )


def delamination_frames(wall: Model, snapshots_path, gag: dict, expected_params: dict | None = None) -> list[Frame]:
    """The frames of a delamination run's snapshots (:func:`sphgag.studies.delamination.runs.save_snapshots`), each
    evaluated with its own history on the intact wall's material (as the run grew it): ``wall`` is the run's wall as
    built (:func:`sphgag.studies.artery.bilayer_model`), before any pool."""
    base = wall.props
    frames = []
    for k, saved in enumerate(state_io.load_series(snapshots_path, expected_params)):
        wall.set_props(HistoryMaterial(base, saved.history, gag))
        data = fields(wall, saved.x, saved.load, saved.history)
        data["pseudo_time"] = np.full(len(saved.x), float(saved.info["pseudo_time"]))
        frames.append(Frame(float(k), saved.x, data))
    wall.set_props(base)
    return frames


def swelling_frames(model: Model, states_path, expected_params: dict | None = None) -> list[Frame]:
    """The frames of a swelling run's states (rule swell): ``model`` is the run's wall with its pool
    (:func:`sphgag.studies.artery.bilayer_model` with ``pool`` and ``gag``), intact before conversion."""
    seeding = model.props
    frames, hollow = [], None
    for k, saved in enumerate(state_io.load_series(states_path, expected_params)):
        stage = saved.info["stage"]
        history = seeding.after if stage == "converted" else seeding.before
        at = state_model(model, bool(saved.info.get("cavity", False)), saved.x, hollow, saved.info.get("pool_model"))
        hollow = at if at.cavities else hollow
        frames.append(Frame(float(k), saved.x, fields(at, saved.x, saved.load, history)))
    return frames


def saved_series(path) -> list[Frame]:
    """The frames of a state series of the pipeline, whose kind and model are read from the parameters it records:
    a delamination run's snapshots (rules delaminate, delaminate_fracture_energy) or a swelling run's states (rule
    swell)."""
    p = state_io.load_from_series(path, 0).params
    if {"state", "pool", "gag"} <= set(p):  # rule swell: the wall with its pool
        cfg = p["state"]
        pool = artery.pool_sector(p["pool"])
        wall = artery.bilayer_model(
            cfg["bilayer"], Numerics.of(cfg["numerics"]), pool=pool, gag=p["gag"], graded=p["grading"]
        )
        return swelling_frames(wall, path)
    if {"bilayer", "numerics", "delamination", "gag"} <= set(p):
        return delamination_frames(artery.bilayer_model(p["bilayer"], Numerics.of(p["numerics"])), path, p["gag"])
    raise ValueError(f"{path} is neither a swelling run's states nor a delamination run's snapshots")


def write_series(pvd_path, frames: list[Frame]) -> Path:
    """``{stem}_{k:04d}.vtu`` per frame beside ``pvd_path`` and the ``.pvd`` collection that orders them in time."""
    pvd_path = Path(pvd_path)
    pvd_path.parent.mkdir(parents=True, exist_ok=True)
    root = ElementTree.Element("VTKFile", type="Collection", version="0.1", byte_order="LittleEndian")
    collection = ElementTree.SubElement(root, "Collection")
    for k, frame in enumerate(frames):
        name = f"{pvd_path.stem}_{k:04d}.vtu"
        n = len(frame.x)
        mesh = meshio.Mesh(_plane(frame.x), [("vertex", np.arange(n).reshape(-1, 1))], point_data=frame.data)
        meshio.write(pvd_path.parent / name, mesh, file_format="vtu")
        ElementTree.SubElement(collection, "DataSet", timestep=repr(frame.time), group="", part="0", file=name)
    ElementTree.indent(root)
    ElementTree.ElementTree(root).write(pvd_path, encoding="utf-8", xml_declaration=True)
    return pvd_path


def read_series(pvd_path) -> list[Frame]:
    """The frames of a ``.pvd`` collection (:func:`write_series`), in its order."""
    pvd_path = Path(pvd_path)
    frames = []
    for d in ElementTree.parse(pvd_path).getroot().iter("DataSet"):
        mesh = meshio.read(pvd_path.parent / d.get("file"))
        frames.append(Frame(float(d.get("timestep")), mesh.points[:, :2], dict(mesh.point_data)))
    return frames


if __name__ == "__main__":  # python -m sphgag.views.paraview STATES.npz OUT.pvd [THREADS]
    import sys

    from .. import threads

    if len(sys.argv) not in (3, 4):
        sys.exit("usage: python -m sphgag.views.paraview STATES.npz OUT.pvd [THREADS (default 1)]")
    threads.use(int(sys.argv[3]) if len(sys.argv) == 4 else 1)
    print(write_series(sys.argv[2], saved_series(sys.argv[1])))
