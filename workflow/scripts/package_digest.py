"""Rule package_digest: the sha256 of each module a script's job imports, one line per module (its path).

A module touched but not changed (a checkout, a copy) reruns nothing: Snakemake compares the checksum of an input
newer than the outputs with the one it recorded when the job ran, and only a changed module rewrites the digest.
"""

import hashlib
from pathlib import Path

from sphgag import jobs

with jobs.run(snakemake) as job:  # noqa: F821
    lines = [f"{hashlib.sha256(Path(path).read_bytes()).hexdigest()}  {path}" for path in job.input]
    Path(job.output[0]).write_text("\n".join(lines) + "\n")
