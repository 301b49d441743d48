"""Rule delamination_gci: the grid convergence index of the delamination resolution study's event concentrations."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import delamination

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("delamination_gci", sm.log[0]) as log:
    table = delamination.gci_table(pd.read_csv(sm.input.convergence))
    table.to_csv(sm.output[0], index=False)
    for r in table.drop_duplicates(["charge_law", "criterion", "case", "quantity"]).itertuples():
        log.info(
            "[delamination_gci] %s %s %s %s: order %.3g, extrapolated %.4g, GCI %.3g",
            r.charge_law,
            r.criterion,
            r.case,
            r.quantity,
            r.observed_order,
            r.extrapolated,
            r.gci_fine,
        )
