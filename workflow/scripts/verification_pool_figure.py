"""Rule verification_pool_figure: SPH against Inglis and Lame, and the errors against resolution."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, verification

with jobs.run(snakemake) as job:  # noqa: F821
    table = pd.read_csv(job.input.table)
    style.finite_or_raise(table, ["tip_stress_kPa", "rel_error", "traction_jump_kPa"], "verification_pool")
    fig = verification.verification_pool(table, pd.read_csv(job.input.profiles))
    style.save(fig, [job.output.pdf, job.output.png], "Verification of the pool stress field, sphgag")
