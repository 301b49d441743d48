"""Rule sensitivity_batch: one batch of samples of a sensitivity design, each a rerun of figure 5's pool at its inputs
(sphgag.studies.pool_response); a sample whose run fails is a row with its inputs and its error."""

import time

import pandas as pd

from sphgag import threads
from sphgag.engine import solver
from sphgag.records import provenance, runlog
from sphgag.studies import pool_response

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
run = f"sensitivity_{w.method}_{w.law}_batch{w.batch}"
with runlog.run(run, sm.log[0]) as log:
    design = pd.read_csv(sm.input.design)
    size = sm.params.batch_size
    rows = design.iloc[int(w.batch) * size : (int(w.batch) + 1) * size]
    names = [c for c in design.columns if c != "sample"]
    scenario = sm.params.scenario
    table = pool_response.sample_rows(
        rows, names, pool_response.evaluate(scenario, run), failure=solver.SimulationError, label=run
    )
    table.insert(1, "charge_law", scenario["gag"]["charge_law"])
    table.to_csv(sm.output.table, index=False)
    failed = int((table.status == "failed").sum())
    log.info("[%s] %d samples, %d failed", run, len(table), failed)
    provenance.write_record(
        sm.output.provenance,
        rule="sensitivity_batch",
        params=dict(scenario=scenario, samples=rows["sample"].tolist()),
        outputs=list(sm.output),
        summary=dict(samples=len(table), failed=failed),
        started=started,
    )
