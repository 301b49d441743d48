"""Rule swelling_gci: the grid convergence index of figure 4's quantities, and figure 4's bands, from the resolution
study's table."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import convergence

with jobs.run(snakemake, name="swelling_gci") as job:  # noqa: F821
    table = pd.read_csv(job.input.table)
    out = convergence.gci_table(table, job.params.concentrations, job.params.pressure)
    out.to_csv(job.output.table, index=False)
    convergence.band_table(table, job.params.pressure).to_csv(job.output.band, index=False)
    finest = out.sort_values("dx_um").groupby(convergence.GCI_KEYS, sort=False).head(1)
    for r in finest.itertuples():
        job.log.info(
            "%s %s %s %s %s at %g: %.4g at dx = %g um, order %.2f, extrapolated %.4g, GCI %.1f %%%s",
            r.charge_law, r.pool_model, r.model, r.case, r.quantity, r.at, r.value, r.dx_um, r.observed_order,
            r.extrapolated, 100 * r.gci_fine, "" if r.order_in_range else " (order outside 0.5-3: safety factor 3)",
        )  # fmt: skip
