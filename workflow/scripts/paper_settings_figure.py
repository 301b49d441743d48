"""Rule paper_settings_figure: each setting's step in the tip radial stress, from the authors' value to ours."""

import pandas as pd

from sphgag import jobs
from sphgag.views import paper_settings, style

with jobs.run(snakemake) as job:  # noqa: F821
    fig = paper_settings.figure(pd.read_csv(job.input.steps))
    style.save(fig, [job.output.pdf, job.output.png], "Figure 4 under the authors' settings, one at a time, sphgag")
