"""Rule verification_pool_figure: SPH against Inglis and Lame, and the errors against resolution."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, verification

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("verification_pool_figure", sm.log[0]):
    table = pd.read_csv(sm.input.table)
    style.finite_or_raise(table, ["tip_stress_kPa", "rel_error", "traction_jump_kPa"], "verification_pool")
    fig = verification.verification_pool(table, pd.read_csv(sm.input.profiles))
    style.save(fig, [sm.output.pdf, sm.output.png], "Verification of the pool stress field, sphgag")
