"""sphgag: total-Lagrangian SPH of pre-stressed, fibre-reinforced arterial walls with GAG swelling.

A re-implementation of Ahmadzadeh, Rausch & Humphrey (2018), "Particle-based
computational modelling of arterial disease", J. R. Soc. Interface.

Importing the package points Numba's on-disk cache at a directory named
after a hash of this package's sources (:data:`CODE_HASH`). Numba only
invalidates a cached kernel when *its own* file changes, not when a function
it calls (e.g. a material law) changes; keying the cache directory by the
whole package's sources makes every physics edit recompile what it affects.
A ``NUMBA_CACHE_DIR`` of your own is used as the parent of that directory.
"""

from __future__ import annotations

import hashlib
import os
import sys
from pathlib import Path

__version__ = "0.1.0"

_PACKAGE_DIR = Path(__file__).resolve().parent


def _source_hash(package: Path = _PACKAGE_DIR) -> str:
    """SHA-256 of every module of the package, subpackages included (path relative to the package, then bytes)."""
    h = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        h.update(path.relative_to(package).as_posix().encode())
        h.update(path.read_bytes())
    return h.hexdigest()


CODE_HASH = _source_hash()

_KEY = f"sphgag-numba-{CODE_HASH[:16]}"
_base = os.environ.get("NUMBA_CACHE_DIR") or str(Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")))
if not _base.rstrip("/").endswith(_KEY):
    os.environ["NUMBA_CACHE_DIR"] = str(Path(_base) / _KEY)
    if "numba" in sys.modules:  # numba read its configuration already
        from numba.core import config as _numba_config

        _numba_config.reload_config()
