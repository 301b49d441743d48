"""Rules sensitivity_design and screened_design: the samples of one design of the sensitivity study (one row each): a
method's (sphgag.studies.sensitivity.SENSITIVITY_METHODS), or the nominal one, the configuration's own values."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import sensitivity

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    method = sensitivity.SENSITIVITY_METHODS.get(p.method)
    if method is None:  # nominal: the configuration's own values, the pipeline's runs of figure 5's pool
        design = pd.DataFrame([dict(sample=0, **p.settings)])
    else:  # a screened method's design reads its screening method's indices (Sobol: the Morris mu*)
        screening = pd.read_csv(job.input.screening) if method.screening else None
        design = method.design(sensitivity.Problem.from_ranges(p.ranges), screening=screening, **p.settings)
    design.to_csv(job.output[0], index=False)
    job.log.info("[%s] %d samples of the inputs %s", job.name, len(design), ", ".join(design.columns[1:]))
