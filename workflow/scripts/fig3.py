"""Rule fig3: the complete figure 3 (mean, passive and active models)."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, wall

with jobs.run(snakemake) as job:  # noqa: F821
    tables = {
        k: pd.read_csv(job.input[k])
        for k in ("mean_states", "mean_exact", "bilayer", "passive_exact", "active_exact", "profiles")
    }
    style.finite_or_raise(tables["bilayer"], ["outer_diameter_um", "pressure_mmHg", "mean_circ_stretch"], "fig3")
    style.finite_or_raise(tables["profiles"], ["radius_um", "radial_stress_kPa", "circ_stress_kPa"], "fig3")
    fig = wall.fig3(
        tables["mean_states"],
        tables["mean_exact"],
        tables["bilayer"],
        {"passive": tables["passive_exact"], "active": tables["active_exact"]},
        tables["profiles"],
        job.params.homeostatic_pressure,
    )
    style.save(fig, [job.output.pdf, job.output.png], "Figure 3 (mean, passive and active models), sphgag")
