"""Rule verification_crack_figure: the crack runs against Sneddon and Griffith, and the errors against resolution."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, verification

with jobs.run(snakemake) as job:  # noqa: F821
    table = pd.read_csv(job.input.table)
    style.finite_or_raise(table, ["opening_area_um2", "sneddon_um2", "griffith_kPa"], "verification_crack_figure")
    first = table.iloc[0]
    fig = verification.verification_crack(
        table, first.plane_strain_modulus_kPa, first.fracture_energy_J_m2, first.critical_stress_kPa
    )
    title = "The fracture-energy damage law against Sneddon and Griffith, sphgag"
    style.save(fig, [job.output.pdf, job.output.png], title)
