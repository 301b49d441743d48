"""Rule sensitivity_figure: Morris mu* against sigma and Sobol S1 and ST for every output and charge law."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import sensitivity, style

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("sensitivity_figure", sm.log[0]):
    indices = pd.read_csv(sm.input.indices)
    fig = sensitivity.sensitivity(indices, list(dict.fromkeys(indices.charge_law)))
    style.save(fig, [sm.output.pdf, sm.output.png], "Sensitivity of the figure 4 and delamination results, sphgag")
