"""Rule fig7: two pools offset in radius, grown by damage, every charge law (figure 7)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import delamination
from sphgag.views import delamination as views
from sphgag.views import style

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("fig7", sm.log[0]):
    p = sm.params
    # the paper's damage law (eq. 2.28 as printed); the fracture-energy runs are rows of the tables, not of the figure
    growth, summary = (delamination.paper_law(pd.read_csv(path)) for path in (sm.input.growth, sm.input.summary))
    style.finite_or_raise(
        growth[growth.case == p.case],
        ["concentration_mEq_l", "converted_interior", "converted_exterior"],
        "fig7",
    )
    keys = [(law, c) for law in p.laws for c in p.criteria]  # the order of the rule's input
    snapshots = {key: views.read_snapshots(path) for key, path in zip(keys, sm.input.snapshots)}
    fig = views.fig7(growth, summary, snapshots, p.case, p.sigma, p.criteria, p.laws, p.layers)
    style.save(fig, [sm.output.pdf, sm.output.png], "Figure 7 (coalescence of two radially offset GAG pools), sphgag")
