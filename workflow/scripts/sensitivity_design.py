"""Rules sensitivity_design and sobol_design: the samples of one design of the sensitivity study (one row each)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import sensitivity

sm = snakemake  # noqa: F821
threads.use(sm.threads)
method = getattr(sm.wildcards, "method", "sobol")
with runlog.run(f"sensitivity_{method}_design", sm.log[0]) as log:
    problem = sensitivity.Problem.from_ranges(sm.params.ranges)
    if method == "nominal":  # the configuration's own values: the pipeline's runs of figure 5's pool
        design = pd.DataFrame([dict(sample=0, **sm.params.nominal)])
    elif method == "morris":
        m = sm.params.morris
        design = sensitivity.morris_design(problem, m["trajectories"], m["levels"], m["seed"])
    else:
        s = sm.params.sobol
        chosen = sensitivity.most_influential(pd.read_csv(sm.input.morris), s["inputs"])
        log.info("[sobol_design] the %d inputs with the largest Morris mu*: %s", len(chosen), ", ".join(chosen))
        design = sensitivity.sobol_design(problem.subset(chosen), s["base_samples"], s["seed"])
    design.to_csv(sm.output[0], index=False)
    log.info("[sensitivity_%s_design] %d samples of %d inputs", method, len(design), design.shape[1] - 1)
