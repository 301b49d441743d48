"""Rule verification_annulus_figure: the pressurised annulus against its exact solution and its limit."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, verification

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("verification_annulus_figure", sm.log[0]):
    table, orders, exact = (pd.read_csv(sm.input[k]) for k in ("table", "orders", "exact"))
    fig = verification.verification_annulus(table, orders, exact)
    style.save(fig, [sm.output.pdf, sm.output.png], "Verification of the pressurised annulus and its limit, sphgag")
