"""Rule sensitivity_tables: the Morris and Sobol indices in one table; every sample (the nominal ones first) in one
table; the samples without an output, by their inputs (sphgag.studies.pool_response.failures)."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import pool_response

with jobs.run(snakemake) as job:  # noqa: F821
    indices = pd.concat([pd.read_csv(p) for p in job.input.indices], ignore_index=True)
    nominal = pd.concat([pd.read_csv(p) for p in job.input.nominal], ignore_index=True)
    nominal.insert(0, "method", "nominal")
    samples = pd.concat([nominal] + [pd.read_csv(p) for p in job.input.samples], ignore_index=True)
    failures = pool_response.failures(samples)
    indices.to_csv(job.output.indices, index=False)
    samples.to_csv(job.output.samples, index=False)
    failures.to_csv(job.output.failures, index=False)
    job.log.info(
        "[sensitivity] %d index rows; %d samples, %d failed runs, %d without every output",
        *(len(indices), len(samples), int((samples.status != "ok").sum()), len(failures)),
    )
