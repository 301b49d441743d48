"""Concatenate tidy CSV tables with the same columns (e.g. transmural profiles of several models)."""

import pandas as pd

from sphgag import jobs

with jobs.run(snakemake, name="concat") as job:  # noqa: F821
    tables = [pd.read_csv(path) for path in job.input]
    out = pd.concat(tables, ignore_index=True)
    out.to_csv(job.output[0], index=False)
    job.log.info("%d rows from %d tables -> %s", len(out), len(tables), job.output[0])
