"""Rule verification_profiles_figure: the walls' transmural stress against the exact thick wall, raw and treated."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, verification

with jobs.run(snakemake) as job:  # noqa: F821
    rings, table = pd.read_csv(job.input.rings), pd.read_csv(job.input.table)
    fig = verification.verification_profiles(rings, table, job.params.pressure)
    style.save(fig, [job.output.pdf, job.output.png], "Verification of the walls' transmural stress, sphgag")
