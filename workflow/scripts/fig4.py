"""Rule fig4: the four pools and the stresses around them against GAG concentration, one figure per charge law
(figure 4), with the resolution study's bands where target `resolution` has run."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, swelling

with jobs.run(snakemake) as job:  # noqa: F821
    tips = pd.read_csv(job.input.tips)
    style.finite_or_raise(tips, ["tip_radial_stress_kPa", "top_circ_stress_kPa", "concentration_mEq_l"], "fig4")
    p = job.params
    # the resolution study, where this run or an earlier one made it (else the figure says it has not run)
    study = {k: pd.read_csv(p[k]["path"]) if p[k]["state"] != "not run" else None for k in ("band", "resolution")}
    for law in p.laws:
        fig = swelling.fig4(
            tips,
            pd.read_csv(job.input.particles),
            p.cases,
            p.probe_length,
            law,
            p.max_concentration,
            p.pressures,
            pool_layers=p.pool_layers,
            **study,
        )
        paths = [job.output[f"pdf_{law}"], job.output[f"png_{law}"]]
        style.save(fig, paths, f"Figure 4 (GAG pool swelling), {law} charge law, sphgag")
