"""Rule package_digest: the sha256 of each module the simulations depend on, one line per module (its path)."""

import hashlib
from pathlib import Path

from sphgag import jobs

with jobs.run(snakemake, name="package_digest") as job:  # noqa: F821
    lines = [f"{hashlib.sha256(Path(path).read_bytes()).hexdigest()}  {path}" for path in job.input]
    Path(job.output[0]).write_text("\n".join(lines) + "\n")
