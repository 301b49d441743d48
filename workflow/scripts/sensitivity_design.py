"""Rules sensitivity_design and sobol_design: the samples of one design of the sensitivity study (one row each)."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import sensitivity

with jobs.run(snakemake) as job:  # noqa: F821
    p, method = job.params, getattr(job.w, "method", "sobol")  # rule sobol_design: no wildcard
    problem = sensitivity.Problem.from_ranges(p.ranges)
    if method == "sobol":  # over the inputs with the largest Morris mu*
        chosen = sensitivity.most_influential(pd.read_csv(job.input.morris), p.sobol["inputs"])
        job.log.info("[sobol_design] the %d inputs with the largest Morris mu*: %s", len(chosen), ", ".join(chosen))
        design = sensitivity.sobol_design(problem.subset(chosen), p.sobol["base_samples"], p.sobol["seed"])
    elif method == "morris":
        design = sensitivity.morris_design(problem, p.morris["trajectories"], p.morris["levels"], p.morris["seed"])
    else:  # nominal: the configuration's own values, the pipeline's runs of figure 5's pool
        design = pd.DataFrame([dict(sample=0, **p.nominal)])
    design.to_csv(job.output[0], index=False)
    job.log.info("[%s] %d samples of %d inputs", job.name, len(design), design.shape[1] - 1)
