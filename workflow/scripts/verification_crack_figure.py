"""Rule verification_crack_figure: the crack runs against Sneddon and Griffith, and the errors against resolution."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, verification

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("verification_crack_figure", sm.log[0]):
    table = pd.read_csv(sm.input.table)
    style.finite_or_raise(table, ["opening_area_um2", "sneddon_um2", "griffith_kPa"], "verification_crack_figure")
    first = table.iloc[0]
    fig = verification.verification_crack(
        table, first.plane_strain_modulus_kPa, first.fracture_energy_J_m2, first.critical_stress_kPa
    )
    title = "The fracture-energy damage law against Sneddon and Griffith, sphgag"
    style.save(fig, [sm.output.pdf, sm.output.png], title)
