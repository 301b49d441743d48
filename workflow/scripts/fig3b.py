"""Rule fig3b: transmural stresses of the mean model (figure 3b)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, wall

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("fig3b", sm.log[0]):
    profiles = pd.read_csv(sm.input.profiles)
    style.finite_or_raise(profiles, ["radius_um", "radial_stress_kPa", "circ_stress_kPa"], "fig3b")
    style.save(wall.fig3b(profiles), [sm.output.pdf, sm.output.png], "Figure 3b (mean-behaviour model), sphgag")
