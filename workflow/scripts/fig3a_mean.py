"""Rule fig3a_mean: pressure-diameter and mean stress-stretch of the mean model (figure 3a)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, wall

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("fig3a_mean", sm.log[0]):
    states = pd.read_csv(sm.input.states)
    exact = pd.read_csv(sm.input.exact)
    style.finite_or_raise(states, ["outer_diameter_um", "pressure_mmHg", "mean_circ_stretch"], "fig3a_mean")
    err = states.loc[states.pressure_mmHg >= 10, "od_rel_error"].abs().max()
    fig = wall.fig3a_mean(states, exact, err, sm.params.homeostatic_pressure)
    style.save(fig, [sm.output.pdf, sm.output.png], "Figure 3a (mean-behaviour model), sphgag")
