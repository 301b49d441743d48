"""Rule fig7: two pools offset in radius, grown by damage (figure 7)."""

import pandas as pd

from sphgag import plots, runlog

sm = snakemake  # noqa: F821
with runlog.run("fig7", sm.log[0]):
    growth, summary = pd.read_csv(sm.input.growth), pd.read_csv(sm.input.summary)
    plots.finite_or_raise(
        growth[growth.case == sm.params.case],
        ["concentration_mEq_l", "converted_interior", "converted_exterior"],
        "fig7",
    )
    snapshots = {c: plots.read_snapshots(path) for c, path in zip(sm.params.criteria, sm.input.snapshots)}
    fig = plots.fig7(
        growth, summary, snapshots, sm.params.case, sm.params.sigma, sm.params.criteria, sm.params.media_outer
    )
    plots.save(fig, [sm.output.pdf, sm.output.png], "Figure 7 (coalescence of two radially offset GAG pools), sphgag")
