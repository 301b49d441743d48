"""Rule fig3b: transmural stresses of the mean model (figure 3b)."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, wall

with jobs.run(snakemake) as job:  # noqa: F821
    profiles = pd.read_csv(job.input.profiles)
    style.finite_or_raise(profiles, ["radius_um", "radial_stress_kPa", "circ_stress_kPa"], "fig3b")
    style.save(wall.fig3b(profiles), [job.output.pdf, job.output.png], "Figure 3b (mean-behaviour model), sphgag")
