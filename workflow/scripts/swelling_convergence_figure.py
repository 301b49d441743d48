"""Rule swelling_convergence_figure: the pool stresses and volume change at every particle spacing."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, swelling

with jobs.run(snakemake) as job:  # noqa: F821
    table = pd.read_csv(job.input.table)
    table = table[table.stage == "converted"]  # the path (the states at a volume ratio are in results/swelling/gci.csv)
    style.finite_or_raise(table, ["tip_radial_stress_kPa", "pool_volume_change"], "swelling_convergence")
    style.save(
        swelling.swelling_convergence(table, job.params.laws),
        [job.output.pdf, job.output.png],
        "Resolution study of the GAG-pool stresses, sphgag",
    )
