"""Rule fig6: two pools at one radius, low and high separation, grown by damage (figure 6)."""

import pandas as pd

from sphgag import plots, runlog

sm = snakemake  # noqa: F821
with runlog.run("fig6", sm.log[0]):
    growth, summary = pd.read_csv(sm.input.growth), pd.read_csv(sm.input.summary)
    plots.finite_or_raise(
        growth[growth.case.isin(sm.params.cases)],
        ["concentration_mEq_l", "converted_interior", "converted_exterior"],
        "fig6",
    )
    keys = [(case, c) for case in sm.params.cases for c in sm.params.criteria]  # the order of the rule's input
    snapshots = {key: plots.read_snapshots(path) for key, path in zip(keys, sm.input.snapshots)}
    fig = plots.fig6(growth, summary, snapshots, sm.params.cases, sm.params.criteria, sm.params.media_outer)
    plots.save(fig, [sm.output.pdf, sm.output.png], "Figure 6 (coalescence of two GAG pools at one radius), sphgag")
