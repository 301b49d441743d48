"""Rule procedure_figure: the explicit procedure's stresses and residuals against the equilibrium path."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import procedure, style

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("procedure_figure", sm.log[0]):
    equilibrium = pd.concat([pd.read_csv(f) for f in sm.input.equilibrium], ignore_index=True)
    runs, damage = pd.read_csv(sm.input.runs), pd.read_csv(sm.input.damage)
    fig = procedure.figure(equilibrium, runs, damage, sm.params.tolerance, sm.params.concentration)
    style.save(fig, [sm.output.pdf, sm.output.png], "The paper's explicit procedure against the equilibria, sphgag")
