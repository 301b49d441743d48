"""Rule swelling_gci: the grid convergence index of figure 4's quantities, and figure 4's bands, from the resolution
study's table."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import resolution

with jobs.run(snakemake) as job:  # noqa: F821
    table = pd.read_csv(job.input.table)
    out = resolution.swelling_gci(table, job.params.concentrations, job.params.pressure)
    out.to_csv(job.output.table, index=False)
    resolution.swelling_band(table, job.params.pressure).to_csv(job.output.band, index=False)
    finest = out.sort_values("dx_um").groupby(resolution.GCI_KEYS, sort=False).head(1)
    for r in finest.itertuples():
        note = "" if r.order_in_range else " (order outside 0.5-3: safety factor 3)"
        job.log.info(
            "%(charge_law)s %(pool_model)s %(model)s %(case)s %(quantity)s at %(at)g: %(value).4g at dx = "
            "%(dx_um)g um, order %(observed_order).2f, extrapolated %(extrapolated).4g, GCI %(gci_pct).1f %%%(note)s",
            dict(r._asdict(), gci_pct=100 * r.gci_fine, note=note),
        )
