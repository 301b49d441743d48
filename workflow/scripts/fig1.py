"""Rule fig1: particle layout of the bi-layered model, kernel and composition (figure 1)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import layout, style

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("fig1", sm.log[0]):
    particles = pd.read_csv(sm.input.particles)
    fig = layout.fig1(particles, sm.params.mass_fractions, sm.params.support_factor, sm.params.dx, sm.params.layers)
    style.save(fig, [sm.output.pdf, sm.output.png], "Figure 1 (particle layout), sphgag")
