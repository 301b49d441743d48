"""Rule procedure_summary: the explicit runs in one table, and figure 4's quantities by path at the top of the range."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import paper_procedure

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("procedure_summary", sm.log[0]) as log:
    runs = pd.concat([pd.read_csv(f) for f in sm.input.runs], ignore_index=True)
    runs.to_csv(sm.output.runs, index=False)
    # no damage run where paper_procedure.pool_sets is empty
    damage = pd.concat([pd.read_csv(f) for f in sm.input.damage], ignore_index=True) if sm.input.damage else None
    damage = pd.DataFrame(columns=["pool_set", "sigma_cr_kPa", "step_factor"]) if damage is None else damage
    damage.to_csv(sm.output.damage, index=False)
    equilibrium = pd.concat([pd.read_csv(f) for f in sm.input.equilibrium], ignore_index=True)
    table = paper_procedure.summary(equilibrium, runs, damage, sm.params.concentration)
    table.to_csv(sm.output.table, index=False)
    log.info("[procedure_summary] %d rows at %g mEq/l", len(table), sm.params.concentration)
