"""Rule sensitivity_method: the Morris or Sobol indices of every output under every charge law, from the batches of
its design; every sample with its outputs."""

import numpy as np
import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import pool_response, sensitivity

sm = snakemake  # noqa: F821
threads.use(sm.threads)
method = sm.wildcards.method
with runlog.run(f"sensitivity_{method}_indices", sm.log[0]) as log:
    design = pd.read_csv(sm.input.design)
    names = [c for c in design.columns if c != "sample"]
    problem = sensitivity.Problem.from_ranges(sm.params.ranges).subset(names)
    samples = pd.concat([pd.read_csv(p) for p in sm.input.batches], ignore_index=True)
    s = sm.params.settings
    rows = []
    for law, table in samples.groupby("charge_law", sort=False):
        table = design[["sample"]].merge(table, on="sample", how="left")  # every sample of the design, in its order
        failed = (table.status != "ok").to_numpy()
        for output in pool_response.OUTPUTS:
            y = table[output].to_numpy(dtype=float) if output in table else np.full(len(table), np.nan)
            if method == "morris":
                found = sensitivity.morris_indices(
                    problem, design, y, failed, s["levels"], s["resamples"], s["confidence"], s["seed"]
                )
            else:
                found = sensitivity.sobol_indices(problem, y, failed, s["resamples"], s["confidence"], s["seed"])
            rows += [dict(charge_law=law, output=output, **r) for r in found]
            log.info(
                "[sensitivity_%s] %s, %s: %d of %d samples used, %d failed",
                method,
                law,
                output,
                found[0]["samples_used"],
                len(table),
                found[0]["samples_failed"],
            )
    indices = pd.DataFrame(rows)
    columns = ["method", "charge_law", "output", "input"] + sensitivity.INDEX_COLUMNS
    indices[columns].to_csv(sm.output.indices, index=False)
    samples.insert(0, "method", method)
    samples.to_csv(sm.output.samples, index=False)
