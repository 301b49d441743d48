"""Saved equilibrium states: positions, load and the parameters and code that made them.

A state file (``.npz``) lets later rules start from a converged state (the
homeostatic artery, the pressurised passive/active arteries) without
recomputing it. It records the *configuration slice* the state depends on;
:func:`load` refuses a file whose slice differs from the one the caller
expects, so a later rule can never silently continue from a state made with
other parameters.
"""

from __future__ import annotations

import json
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..engine.history import ParticleHistory
from ..engine.loading import Load
from . import provenance


class StateMismatch(ValueError):
    """The state file was made with different parameters than the caller expects."""


class CorruptState(ValueError):
    """The state file cannot be read (truncated, not a state file)."""


def canonical(params) -> str:
    """Canonical JSON of a configuration slice (sorted keys, floats as floats)."""
    return json.dumps(params, sort_keys=True, default=float)


@dataclass
class SavedState:
    x: np.ndarray
    load: Load
    params: dict
    code: dict
    info: dict
    history: ParticleHistory | None = None  # the particles' history (damage, GAG pools), if the state has one


def contents(
    x: np.ndarray, load: Load, params: dict, info: dict | None = None, history: ParticleHistory | None = None
) -> dict:
    """The arrays of a state file: positions, metadata (load, configuration slice, code version, extra info) and
    the particle history, if any."""
    meta = {
        "load": {
            "axial_stretch": load.axial_stretch,
            "pressure_kPa": load.pressure_kPa,
            "inner_radius": load.inner_radius,
            "material": list(map(list, load.material)),
        },
        "params": json.loads(canonical(params)),
        "code": provenance.code_version(),
        "info": info or {},
    }
    arrays = {} if history is None else history.arrays()
    return dict(x=np.asarray(x, dtype=float), meta=np.array(json.dumps(meta)), **arrays)


def save(
    path, x: np.ndarray, load: Load, params: dict, info: dict | None = None, history: ParticleHistory | None = None
) -> None:
    """Write a state file (:func:`contents`)."""
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    with open(path, "wb") as fh:
        np.savez(fh, **contents(x, load, params, info, history))


def save_series(path, states, params: dict, arrays: dict | None = None) -> None:
    """Several states of one run in one compressed ``.npz``: state ``k``'s :func:`contents` under the prefix
    ``s{k}_`` (``states`` holds ``(x, load, info, history)`` tuples), ``count``, and shared ``arrays``."""
    out = dict(arrays or {}, count=np.array(len(states)))
    for k, (x, load_, info, history) in enumerate(states):
        out.update({f"s{k}_{name}": value for name, value in contents(x, load_, params, info, history).items()})
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(path, **out)


def load(path, expected_params: dict | None = None) -> SavedState:
    """Read a state file; if ``expected_params`` is given it must equal the stored slice."""
    return _read_file(path, lambda data: read(data, path, expected_params))


def load_series(path, expected_params: dict | None = None) -> list[SavedState]:
    """All states of a :func:`save_series` file, in order."""
    return _read_file(
        path,
        lambda data: [read(_part(data, k), f"{path} (state {k})", expected_params) for k in range(int(data["count"]))],
    )


def load_from_series(path, k: int, expected_params: dict | None = None) -> SavedState:
    """State ``k`` of a :func:`save_series` file."""
    return _read_file(path, lambda data: read(_part(data, k), f"{path} (state {k})", expected_params))


def _part(data: dict, k: int) -> dict:
    prefix = f"s{k}_"
    return {name[len(prefix) :]: value for name, value in data.items() if name.startswith(prefix)}


def _read_file(path, pick):
    """``pick`` applied to the arrays of an ``.npz`` state file; an unreadable file raises :class:`CorruptState`
    naming it and how to regenerate it."""
    try:
        with np.load(path, allow_pickle=False) as npz:
            return pick({name: npz[name] for name in npz.files})
    except StateMismatch:
        raise
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile) as exc:
        raise CorruptState(
            f"{path} is not a readable state file ({type(exc).__name__}: {exc}); delete it and rerun "
            "snakemake, which regenerates it with the rule that wrote it"
        ) from exc


def read(data, source, expected_params: dict | None = None) -> SavedState:
    """The state held by ``data``, a mapping of the arrays of :func:`contents` (``source`` names it in errors)."""
    meta = json.loads(str(data["meta"]))
    history = ParticleHistory.from_arrays(data) if "history_origin" in data else None
    if expected_params is not None and canonical(expected_params) != canonical(meta["params"]):
        diff = _differences(json.loads(canonical(expected_params)), meta["params"])
        raise StateMismatch(f"{source} was made with different parameters: {'; '.join(diff)}")
    ld = meta["load"]
    load_ = Load(
        axial_stretch=ld["axial_stretch"],
        pressure_kPa=ld["pressure_kPa"],
        inner_radius=ld["inner_radius"],
        material=tuple(tuple(kv) for kv in ld["material"]),
    )
    return SavedState(
        x=np.array(data["x"]), load=load_, params=meta["params"], code=meta["code"], info=meta["info"], history=history
    )


def _differences(expected, stored, prefix=""):
    out = []
    for key in sorted(set(expected) | set(stored)):
        a, b = expected.get(key, "<missing>"), stored.get(key, "<missing>")
        name = f"{prefix}{key}"
        if isinstance(a, dict) and isinstance(b, dict):
            out += _differences(a, b, name + ".")
        elif a != b:
            out.append(f"{name}: expected {a!r}, file has {b!r}")
    return out
