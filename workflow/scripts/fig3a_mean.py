"""Rule fig3a_mean: pressure-diameter and mean stress-stretch of the mean model (figure 3a)."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, wall

with jobs.run(snakemake) as job:  # noqa: F821
    states = pd.read_csv(job.input.states)
    exact = pd.read_csv(job.input.exact)
    style.finite_or_raise(states, ["outer_diameter_um", "pressure_mmHg", "mean_circ_stretch"], "fig3a_mean")
    err = states.loc[states.pressure_mmHg >= 10, "od_rel_error"].abs().max()
    fig = wall.fig3a_mean(states, exact, err, job.params.homeostatic_pressure)
    style.save(fig, [job.output.pdf, job.output.png], "Figure 3a (mean-behaviour model), sphgag")
