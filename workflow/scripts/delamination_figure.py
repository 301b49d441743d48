"""Rules fig5, fig6 and fig7: the delamination runs of a figure's pool sets (delamination.figures) grown by damage,
one figure per charge law; the rule's name says which figure (the rules are one family in
workflow/rules/figures.smk, sphgag.views.delamination.FIGURES)."""

import pandas as pd

from sphgag import jobs
from sphgag.views import delamination as views
from sphgag.views import style

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    # the runs of the configured damage law (delamination.damage_law); the fracture-energy runs have tables of their own
    growth, summary = (pd.read_csv(path) for path in (job.input.growth, job.input.summary))
    for law in p.laws:
        fig = views.figure(
            job.name, growth, summary, job.input.snapshots, p.poolsets, p.sigma, p.criteria, law, p.laws, p.layers
        )
        paths = [job.output[f"pdf_{law}"], job.output[f"png_{law}"]]
        style.save(fig, paths, f"{views.FIGURES[job.name][1]}, {law} charge law, sphgag")
