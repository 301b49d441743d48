"""Rule sensitivity_figure: Morris mu* against sigma and Sobol S1 and ST for every output and charge law."""

import pandas as pd

from sphgag import jobs
from sphgag.views import sensitivity, style

with jobs.run(snakemake) as job:  # noqa: F821
    indices = pd.read_csv(job.input.indices)
    fig = sensitivity.sensitivity(indices, list(dict.fromkeys(indices.charge_law)))
    style.save(fig, [job.output.pdf, job.output.png], "Sensitivity of the figure 4 and delamination results, sphgag")
