"""Rule procedure_summary: the explicit runs in one table, and figure 4's quantities by path at the top of the range."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import paper_procedure

with jobs.run(snakemake) as job:  # noqa: F821
    runs = pd.concat([pd.read_csv(f) for f in job.input.runs], ignore_index=True)
    runs.to_csv(job.output.runs, index=False)
    # no damage run where paper_procedure.pool_sets is empty
    damage = pd.concat([pd.read_csv(f) for f in job.input.damage], ignore_index=True) if job.input.damage else None
    damage = pd.DataFrame(columns=["pool_set", "sigma_cr_kPa", "step_factor"]) if damage is None else damage
    damage.to_csv(job.output.damage, index=False)
    equilibrium = pd.concat([pd.read_csv(f) for f in job.input.equilibrium], ignore_index=True)
    table = paper_procedure.summary(equilibrium, runs, damage, job.params.concentration)
    table.to_csv(job.output.table, index=False)
    job.log.info("[procedure_summary] %d rows at %g mEq/l", len(table), job.params.concentration)
