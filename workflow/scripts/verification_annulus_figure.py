"""Rule verification_annulus_figure: the pressurised annulus against its exact solution and its limit."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, verification

with jobs.run(snakemake) as job:  # noqa: F821
    table, orders, exact = (pd.read_csv(job.input[k]) for k in ("table", "orders", "exact"))
    fig = verification.verification_annulus(table, orders, exact)
    style.save(fig, [job.output.pdf, job.output.png], "Verification of the pressurised annulus and its limit, sphgag")
