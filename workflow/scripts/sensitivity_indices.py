"""Rule sensitivity_method: a method's indices of every output under every charge law, from the batches of its design
(sphgag.studies.sensitivity.indices_table); every sample with its outputs."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import pool_response, sensitivity

with jobs.run(snakemake) as job:  # noqa: F821
    method, p = job.w.method, job.params
    design = pd.read_csv(job.input.design)
    samples = pd.concat([pd.read_csv(path) for path in job.input.batches], ignore_index=True)
    indices = sensitivity.indices_table(method, design, samples, p.ranges, pool_response.OUTPUTS, p.settings, job.log)
    indices.to_csv(job.output.indices, index=False)
    samples.insert(0, "method", method)
    samples.to_csv(job.output.samples, index=False)
