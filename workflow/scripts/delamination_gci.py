"""Rule delamination_gci: the grid convergence index of the delamination resolution study's event concentrations."""

import pandas as pd

from sphgag import jobs
from sphgag.studies.resolution import delamination_gci

with jobs.run(snakemake) as job:  # noqa: F821
    table = delamination_gci(pd.read_csv(job.input.convergence))
    table.to_csv(job.output[0], index=False)
    for r in table.drop_duplicates(["charge_law", "criterion", "case", "quantity"]).itertuples():
        job.log.info(
            "[delamination_gci] %s %s %s %s: order %.3g, extrapolated %.4g, GCI %.3g",
            *(r.charge_law, r.criterion, r.case, r.quantity, r.observed_order, r.extrapolated, r.gci_fine),
        )
