"""Rule verify_crack: every half-length's crack runs in one table, and SPH against Sneddon and Griffith."""

import pandas as pd

from sphgag import plots, runlog

sm = snakemake  # noqa: F821
with runlog.run("verify_crack", sm.log[0]) as log:
    table = pd.concat([pd.read_csv(path) for path in sm.input.tables], ignore_index=True)
    table.to_csv(sm.output.table, index=False)
    plots.finite_or_raise(table, ["opening_area_um2", "sneddon_um2", "griffith_kPa"], "verify_crack")
    first = table.iloc[0]
    fig = plots.verification_crack(
        table, first.plane_strain_modulus_kPa, first.fracture_energy_J_m2, first.critical_stress_kPa
    )
    plots.save(
        fig, [sm.output.pdf, sm.output.png], "The fracture-energy damage law against Sneddon and Griffith, sphgag"
    )
    log.info("%d runs -> %s", len(table), sm.output.table)
