"""Rule verify_annulus: the annulus runs in one table, the observed order of each measure and the exact curves."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import annulus, resolution

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    table = pd.concat([pd.read_csv(path) for path in job.input.tables], ignore_index=True)
    table.to_csv(job.output.table, index=False)
    orders = resolution.annulus_orders(table)
    orders.to_csv(job.output.orders, index=False)
    annulus.exact_curves(table, p.radius, p.matrix, p.gag).to_csv(job.output.exact, index=False)
    for r in orders.itertuples():
        job.log.info(
            "%(pool_model)s B/A=%(outer_ratio)g at %(fraction).2f of the limit: %(quantity)s %(pct)+.2f %% at dx = "
            "%(dx_um)g um, observed order %(order_fine).2f (finer pair), %(order_coarse).2f",
            dict(r._asdict(), pct=100 * r.error),
        )
