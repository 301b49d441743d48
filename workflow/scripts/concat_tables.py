"""Concatenate tidy CSV tables with the same columns (e.g. transmural profiles of several models)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("concat", sm.log[0]) as log:
    tables = [pd.read_csv(path) for path in sm.input]
    out = pd.concat(tables, ignore_index=True)
    out.to_csv(sm.output[0], index=False)
    log.info("%d rows from %d tables -> %s", len(out), len(tables), sm.output[0])
