"""Rule verify_annulus: the annulus runs in one table, the observed order of each measure and the exact curves."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import annulus

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("verify_annulus", sm.log[0]) as log:
    table = pd.concat([pd.read_csv(path) for path in sm.input.tables], ignore_index=True)
    table.to_csv(sm.output.table, index=False)
    orders = annulus.orders(table)
    orders.to_csv(sm.output.orders, index=False)
    annulus.exact_curves(table, sm.params.radius, sm.params.matrix, sm.params.gag).to_csv(sm.output.exact, index=False)
    for r in orders.itertuples():
        log.info(
            "%s B/A=%g at %.2f of the limit: %s %+.2f %% at dx = %g um, observed order %.2f (finer pair), %.2f",
            r.pool_model, r.outer_ratio, r.fraction, r.quantity, 100 * r.error, r.dx_um, r.order_fine, r.order_coarse,
        )  # fmt: skip
