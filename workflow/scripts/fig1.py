"""Rule fig1: particle layout of the bi-layered model, kernel and composition (figure 1)."""

import pandas as pd

from sphgag import jobs
from sphgag.views import layout, style

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    fig = layout.fig1(pd.read_csv(job.input.particles), p.mass_fractions, p.support_factor, p.dx, p.layers)
    style.save(fig, [job.output.pdf, job.output.png], "Figure 1 (particle layout), sphgag")
