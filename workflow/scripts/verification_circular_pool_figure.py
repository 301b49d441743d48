"""Rule verification_circular_pool_figure: the circular pool at large strain against its exact solution."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, verification

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("verification_circular_pool_figure", sm.log[0]):
    table = pd.read_csv(sm.input.table)
    reached = table[table.path_end == "complete"]  # a path that ended early has no numbers beyond it (drawn as such)
    style.finite_or_raise(reached, ["volume_error", "lining_error"], "verification_circular_pool")
    fig = verification.verification_circular_pool(table)
    style.save(fig, [sm.output.pdf, sm.output.png], "Verification of a circular pool at large strain, sphgag")
