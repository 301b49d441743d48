"""Rule fig5: the single pool grown by damage, its tip radial stress for every sigma_cr (figure 5)."""

import pandas as pd

from sphgag import plots, runlog

sm = snakemake  # noqa: F821
with runlog.run("fig5", sm.log[0]):
    growth, summary = pd.read_csv(sm.input.growth), pd.read_csv(sm.input.summary)
    plots.finite_or_raise(growth, ["concentration_mEq_l", "converted_particles", "delaminated_length_um"], "fig5")
    snapshots = {c: plots.read_snapshots(path) for c, path in zip(sm.params.criteria, sm.input.snapshots)}
    fig = plots.fig5(growth, summary, snapshots, sm.params.sigma, sm.params.criteria, sm.params.media_outer)
    plots.save(fig, [sm.output.pdf, sm.output.png], "Figure 5 (delamination by a single GAG pool), sphgag")
