"""Rules fig5, fig6 and fig7: the delamination runs of a figure's pool sets (delamination.figures) grown by damage,
every charge law; the rule's name says which figure (the rules are one family in workflow/rules/figures.smk)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.studies import delamination
from sphgag.views import delamination as views
from sphgag.views import style

# rule -> (the columns of its pool sets' growth that must be finite, its title)
FIGURES = {
    "fig5": (
        ["concentration_mEq_l", "converted_particles", "delaminated_length_um"],
        "Figure 5 (delamination by a single GAG pool)",
    ),
    "fig6": (
        ["concentration_mEq_l", "converted_interior", "converted_exterior"],
        "Figure 6 (coalescence of two GAG pools at one radius)",
    ),
    "fig7": (
        ["concentration_mEq_l", "converted_interior", "converted_exterior"],
        "Figure 7 (coalescence of two radially offset GAG pools)",
    ),
}


def draw(figure: str, growth, summary, snapshots: dict, p):
    """The figure ``figure`` from the tables and the snapshots by (law, pool set, criterion)."""
    if figure == "fig6":
        return views.fig6(growth, summary, snapshots, p.poolsets, p.criteria, p.laws, p.layers)
    (poolset,) = p.poolsets
    by_criterion = {(law, c): snapshots[law, poolset, c] for law in p.laws for c in p.criteria}
    fig = views.fig5 if figure == "fig5" else views.fig7
    return fig(growth, summary, by_criterion, poolset, p.sigma, p.criteria, p.laws, p.layers)


sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run(sm.rule, sm.log[0]):
    p = sm.params
    columns, title = FIGURES[sm.rule]
    # the paper's damage law (eq. 2.28 as printed); the fracture-energy runs are rows of the tables, not of the figure
    growth, summary = (delamination.paper_law(pd.read_csv(path)) for path in (sm.input.growth, sm.input.summary))
    style.finite_or_raise(growth[growth.case.isin(p.poolsets)], columns, sm.rule)
    # the order of the rule's input: by law, then pool set, then criterion
    keys = [(law, case, c) for law in p.laws for case in p.poolsets for c in p.criteria]
    snapshots = {key: views.read_snapshots(path) for key, path in zip(keys, sm.input.snapshots)}
    style.save(draw(sm.rule, growth, summary, snapshots, p), [sm.output.pdf, sm.output.png], f"{title}, sphgag")
