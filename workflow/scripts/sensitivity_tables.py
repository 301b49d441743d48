"""Rule sensitivity: the Morris and Sobol indices in one table; every sample (the nominal ones first) in one table;
the samples without an output, by their inputs."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import pool_response

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("sensitivity", sm.log[0]) as log:
    indices = pd.concat([pd.read_csv(p) for p in sm.input.indices], ignore_index=True)
    nominal = pd.concat([pd.read_csv(p) for p in sm.input.nominal], ignore_index=True)
    nominal.insert(0, "method", "nominal")
    samples = pd.concat([nominal] + [pd.read_csv(p) for p in sm.input.samples], ignore_index=True)
    missing = samples[list(pool_response.OUTPUTS)].isna()
    failures = samples[(samples.status != "ok") | missing.any(axis=1)].copy()
    failures.insert(
        failures.columns.get_loc("status") + 1,
        "missing_outputs",
        [" ".join(o for o in pool_response.OUTPUTS if missing.loc[i, o]) for i in failures.index],
    )
    indices.to_csv(sm.output.indices, index=False)
    samples.to_csv(sm.output.samples, index=False)
    failures.to_csv(sm.output.failures, index=False)
    log.info(
        "[sensitivity] %d index rows; %d samples, %d failed runs, %d without every output",
        len(indices),
        len(samples),
        int((samples.status != "ok").sum()),
        len(failures),
    )
