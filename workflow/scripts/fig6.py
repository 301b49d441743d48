"""Rule fig6: pools at one radius (e.g. low and high separation) grown by damage, every charge law (figure 6)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import delamination
from sphgag.views import delamination as views
from sphgag.views import style

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("fig6", sm.log[0]):
    p = sm.params
    # the paper's damage law (eq. 2.28 as printed); the fracture-energy runs are rows of the tables, not of the figure
    growth, summary = (delamination.paper_law(pd.read_csv(path)) for path in (sm.input.growth, sm.input.summary))
    style.finite_or_raise(
        growth[growth.case.isin(p.cases)],
        ["concentration_mEq_l", "converted_interior", "converted_exterior"],
        "fig6",
    )
    keys = [(law, case, c) for law in p.laws for case in p.cases for c in p.criteria]  # the order of the rule's input
    snapshots = {key: views.read_snapshots(path) for key, path in zip(keys, sm.input.snapshots)}
    fig = views.fig6(growth, summary, snapshots, p.cases, p.criteria, p.laws, p.layers)
    style.save(fig, [sm.output.pdf, sm.output.png], "Figure 6 (coalescence of two GAG pools at one radius), sphgag")
