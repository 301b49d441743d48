"""Rule verification_circular_pool_figure: the circular pool at large strain against its exact solution."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, verification

with jobs.run(snakemake) as job:  # noqa: F821
    table = pd.read_csv(job.input.table)
    reached = table[table.path_end == "complete"]  # a path that ended early has no numbers beyond it (drawn as such)
    style.finite_or_raise(reached, ["volume_error", "lining_error"], "verification_circular_pool")
    fig = verification.verification_circular_pool(table)
    style.save(fig, [job.output.pdf, job.output.png], "Verification of a circular pool at large strain, sphgag")
