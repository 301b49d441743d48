"""Rule verify_annulus: the annulus runs in one table, the observed order of each measure and the exact curves."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import annulus

with jobs.run(snakemake, name="verify_annulus") as job:  # noqa: F821
    p = job.params
    table = pd.concat([pd.read_csv(path) for path in job.input.tables], ignore_index=True)
    table.to_csv(job.output.table, index=False)
    orders = annulus.orders(table)
    orders.to_csv(job.output.orders, index=False)
    annulus.exact_curves(table, p.radius, p.matrix, p.gag).to_csv(job.output.exact, index=False)
    for r in orders.itertuples():
        job.log.info(
            "%s B/A=%g at %.2f of the limit: %s %+.2f %% at dx = %g um, observed order %.2f (finer pair), %.2f",
            r.pool_model, r.outer_ratio, r.fraction, r.quantity, 100 * r.error, r.dx_um, r.order_fine, r.order_coarse,
        )  # fmt: skip
