"""Rule homeostasis_target: the carried homeostatic pressure against the reference value of Table 2."""

import pandas as pd

from sphgag import jobs

with jobs.run(snakemake) as job:  # noqa: F821
    summary = pd.read_csv(job.input.summary)
    target = float(job.params.target_pressure)
    out = summary[["model", "carried_pressure_mmHg", "semi_analytical_pressure_mmHg"]].assign(
        target_pressure_mmHg=target, relative_to_target=summary.carried_pressure_mmHg / target - 1.0
    )
    out.to_csv(job.output[0], index=False)
    for r in out.itertuples():
        job.log.info(
            "[homeostasis_target] %s: carried %.2f mmHg, target %.0f (%+.1f %%)",
            *(r.model, r.carried_pressure_mmHg, target, 100 * r.relative_to_target),
        )
