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
from contextlib import nullcontext
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import provenance
from .history import ParticleHistory
from .loading import Load


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


def save(path, x: np.ndarray, load: Load, params: dict, info: dict | None = None,
         history: ParticleHistory | None = None) -> None:
    """Write a state file with its load, configuration slice, code version, extra info and particle history."""
    meta = {
        "load": {"axial_stretch": load.axial_stretch, "pressure_kPa": load.pressure_kPa,
                 "inner_radius": load.inner_radius, "material": list(map(list, load.material))},
        "params": json.loads(canonical(params)),
        "code": provenance.code_version(),
        "info": info or {},
    }
    arrays = {} if history is None else history.arrays()
    if not hasattr(path, "write"):  # a path; file objects (e.g. io.BytesIO) are written as they are
        Path(path).parent.mkdir(parents=True, exist_ok=True)
    with nullcontext(path) if hasattr(path, "write") else open(path, "wb") as fh:
        np.savez(fh, x=np.asarray(x, dtype=float), meta=np.array(json.dumps(meta)), **arrays)


def load(path, expected_params: dict | None = None) -> SavedState:
    """Read a state file; if ``expected_params`` is given it must equal the stored slice."""
    try:
        with np.load(path, allow_pickle=False) as data:
            x = data["x"].copy()
            meta = json.loads(str(data["meta"]))
            history = ParticleHistory.from_arrays(data) if "history_origin" in data.files else None
    except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile) as exc:
        raise CorruptState(f"{path} is not a readable state file ({type(exc).__name__}: {exc}); delete it and rerun "
                           "snakemake, which regenerates it with the rule that wrote it") from exc
    if expected_params is not None and canonical(expected_params) != canonical(meta["params"]):
        diff = _differences(json.loads(canonical(expected_params)), meta["params"])
        raise StateMismatch(f"{path} was made with different parameters: {'; '.join(diff)}")
    ld = meta["load"]
    load_ = Load(axial_stretch=ld["axial_stretch"], pressure_kPa=ld["pressure_kPa"], inner_radius=ld["inner_radius"],
                 material=tuple(tuple(kv) for kv in ld["material"]))
    return SavedState(x=x, load=load_, params=meta["params"], code=meta["code"], info=meta["info"], history=history)


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
