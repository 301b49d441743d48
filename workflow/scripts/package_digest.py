"""Rule package_digest: the sha256 of each module the simulations depend on, one line per module (its path)."""

import hashlib
from pathlib import Path

from sphgag import threads

sm = snakemake  # noqa: F821
threads.use(sm.threads)
lines = [f"{hashlib.sha256(Path(path).read_bytes()).hexdigest()}  {path}" for path in sm.input]
Path(sm.output[0]).write_text("\n".join(lines) + "\n")
