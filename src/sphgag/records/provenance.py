"""Provenance: which code and which parameters made an output."""

from __future__ import annotations

import functools
import json
import platform
import subprocess
import time
from pathlib import Path

from .. import CODE_HASH, __version__


@functools.lru_cache
def git_commit(path: Path | str = ".") -> str:
    """The git commit of the working tree (``+dirty`` if it has local changes), or 'unknown'; asked once per
    process (state files of a series each record it)."""
    try:
        top = subprocess.run(
            ["git", "rev-parse", "--show-toplevel"], cwd=path, capture_output=True, text=True, check=True
        ).stdout.strip()
        sha = subprocess.run(["git", "-C", top, "rev-parse", "HEAD"], capture_output=True, text=True, check=True)
        dirty = subprocess.run(
            ["git", "-C", top, "status", "--porcelain", "--", "src"], capture_output=True, text=True, check=True
        )
        return sha.stdout.strip() + ("+dirty" if dirty.stdout.strip() else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def code_version() -> dict:
    """sphgag version, hash of its sources and the git commit."""
    import numba
    import numpy

    return {
        "sphgag": __version__,
        "source_sha256": CODE_HASH,
        "git_commit": git_commit(Path(__file__).parent),
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "numba": numba.__version__,
    }


def write_record(path, *, rule: str, params: dict, outputs, summary: dict | None = None, started: float | None = None):
    """Write a JSON provenance record for one rule's outputs."""
    record = {
        "rule": rule,
        "code": code_version(),
        "params": params,
        "outputs": [str(p) for p in outputs],
        "summary": summary or {},
        "finished": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
    }
    if started is not None:
        record["wall_time_s"] = round(time.time() - started, 3)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text(json.dumps(record, indent=2, default=_jsonable) + "\n")
    return record


def figure_metadata(description: str) -> dict:
    """Metadata embedded in saved figures (PDF and PNG keep it)."""
    return {"Title": description, "Creator": f"sphgag {__version__} (sources {CODE_HASH[:12]})"}


def _jsonable(obj):
    try:
        import numpy as np

        if isinstance(obj, np.generic):
            return obj.item()
        if isinstance(obj, np.ndarray):
            return obj.tolist()
    except ImportError:  # pragma: no cover
        pass
    return str(obj)
