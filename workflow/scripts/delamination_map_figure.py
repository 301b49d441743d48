"""Rule delamination_map_figure: the delamination map, with the limit concentrations of figure 4's swelling runs."""

import pandas as pd

from sphgag import jobs
from sphgag.views import sensitivity, style

with jobs.run(snakemake) as job:  # noqa: F821
    table = pd.read_csv(job.input.map)
    fig = sensitivity.delamination_map(
        table,
        pd.read_csv(job.input.swelling),
        job.params.cases,
        job.params.pressure,
        list(dict.fromkeys(table.charge_law)),
    )
    style.save(fig, [job.output.pdf, job.output.png], "Delamination map of figure 5's pool, sphgag")
