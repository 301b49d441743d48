"""Rule swelling_convergence_figure: the pool stresses and volume change at every particle spacing."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, swelling

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("swelling_convergence_figure", sm.log[0]):
    table = pd.read_csv(sm.input.table)
    table = table[table.stage == "converted"]  # the path (the states at a volume ratio are in results/swelling/gci.csv)
    style.finite_or_raise(table, ["tip_radial_stress_kPa", "pool_volume_change"], "swelling_convergence")
    style.save(
        swelling.swelling_convergence(table, sm.params.laws),
        [sm.output.pdf, sm.output.png],
        "Resolution study of the GAG-pool stresses, sphgag",
    )
