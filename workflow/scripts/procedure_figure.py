"""Rule procedure_figure: the explicit procedure's stresses and residuals against the equilibrium path."""

import pandas as pd

from sphgag import jobs
from sphgag.views import procedure, style

with jobs.run(snakemake) as job:  # noqa: F821
    equilibrium = pd.concat([pd.read_csv(f) for f in job.input.equilibrium], ignore_index=True)
    runs, damage = pd.read_csv(job.input.runs), pd.read_csv(job.input.damage)
    fig = procedure.figure(equilibrium, runs, damage, job.params.tolerance, job.params.concentration)
    style.save(fig, [job.output.pdf, job.output.png], "The paper's explicit procedure against the equilibria, sphgag")
