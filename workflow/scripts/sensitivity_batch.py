"""Rule sensitivity_batch: one batch of samples of a sensitivity design, each a rerun of figure 5's pool at its inputs
(sphgag.studies.pool_response); a sample whose run fails is a row with its inputs and its error."""

import pandas as pd

from sphgag import jobs
from sphgag.engine import solver
from sphgag.studies import pool_response

with jobs.run(snakemake) as job:  # noqa: F821
    design, size, scenario = pd.read_csv(job.input.design), job.params.batch_size, job.params.scenario
    rows = design.iloc[job.w.batch * size : (job.w.batch + 1) * size]
    names = [c for c in design.columns if c != "sample"]
    evaluate = pool_response.evaluate(scenario, job.name)
    table = pool_response.sample_rows(rows, names, evaluate, failure=solver.SimulationError, label=job.name)
    table.insert(1, "charge_law", scenario["gag"]["charge_law"])
    table.to_csv(job.output.table, index=False)
    failed = int((table.status == "failed").sum())
    job.log.info("[%s] %d samples, %d failed", job.name, len(table), failed)
    job.record(dict(scenario=scenario, samples=rows["sample"].tolist()), dict(samples=len(table), failed=failed))
