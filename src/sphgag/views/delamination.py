"""Figures 5-7 of the paper, delamination by damage: one pool grown (figure 5), pools at one radius (figure 6)
and pools offset in radius (figure 7), with their snapshots read from the runs' ``*_snapshots.npz``."""

from __future__ import annotations

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import seaborn as sns

from . import snapshots
from .style import (
    GAG_CONCENTRATION,
    _style,
    distinct_colours,
    finite_or_raise,
    law_title,
    palette,
    style_legend,
)

SIDE_COLOURS = {"interior": "#1b9e77", "exterior": "#7570b3"}
PSEUDO_TIME = "pseudo-time\n(concentration levels + damage passes)"


def criterion_dashes(criteria) -> dict:
    """A line style per onset criterion, in the order of ``criteria``: the default (the first) solid, the second
    dashed, then dotted, dash-dot, and dashes with ever more dots between them (distinct for any number)."""
    patterns = ["", (3.7, 1.6), (1.0, 1.65), (5.0, 1.5, 1.0, 1.5)]
    patterns += [(5.0, 1.5) + (1.0, 1.5) * k for k in range(2, len(criteria))]
    return dict(zip(criteria, patterns))


def criterion_colours(criteria) -> dict:
    """A colour per onset criterion, in the order of ``criteria``: the default (the first) black, the second orange,
    then Dark2's other colours and evenly spaced hues (distinct for any number)."""
    return dict(zip(criteria, distinct_colours(len(criteria), lead=("k", "#d95f02"))))


def criterion_lines(ax, data, criteria, **spec):
    """One line per run of ``data`` (seaborn's ``spec``: x, y, hue, palette), styled by its onset criterion
    (:func:`criterion_dashes`: the default solid, the second dashed, ...)."""
    sns.lineplot(
        data,
        style="criterion",
        style_order=list(criteria),
        dashes=criterion_dashes(criteria),
        estimator=None,
        sort=False,
        lw=1.0,
        ax=ax,
        **spec,
    )


def run_note(summary: pd.DataFrame, **labels) -> str:
    """How the run with these labels (summary.csv) ended, in a few words: its stop (``stop_kind``), the concentrations
    of its onset and runaway (bisected between levels) and what it delaminated."""
    sel = np.logical_and.reduce([summary[k] == v for k, v in labels.items()])
    if not sel.any():
        return "not run"
    s = summary[sel].iloc[0]
    if not np.isfinite(s.onset_concentration_mEq_l):
        note = "no damage onset"
    else:
        note = f"onset {s.onset_concentration_mEq_l:.1f} mEq/l"
        if np.isfinite(s.runaway_concentration_mEq_l):
            note += f", runaway {s.runaway_concentration_mEq_l:.1f}"
        note += f", {s.final_length_um:.3g} um"
    return f"{note}\n    stop: {s.stop_kind}" + (f" at pass {s.merge_step:g}" if bool(s.merged) else "")


def event_marks(ax, summary: pd.DataFrame, colour, dashes=""):
    """The onset (a triangle on the axis) and runaway (a vertical line) concentrations of the runs of ``summary``."""
    for s in summary.itertuples():
        if np.isfinite(s.onset_concentration_mEq_l):
            ax.plot([s.onset_concentration_mEq_l], [0.0], marker="^", ms=6, color=colour, clip_on=False, zorder=5)
        if np.isfinite(s.runaway_concentration_mEq_l):
            ax.axvline(
                s.runaway_concentration_mEq_l, color=colour, lw=0.9, ls=(0, (1, 2)) if dashes else "-", alpha=0.8
            )


def no_growth_note(ax, runs: pd.DataFrame):
    """Say so in the panel if none of ``runs`` converted a single particle."""
    if runs.converted_particles.max() == 0:
        ax.text(
            0.5,
            0.5,
            "no growth: no particle converted",
            transform=ax.transAxes,
            ha="center",
            va="center",
            fontsize=8,
            color="0.3",
            bbox=dict(fc="w", ec="0.7", lw=0.6),
        )


def converted_panel(ax, growth: pd.DataFrame, summary: pd.DataFrame, case: str, criteria, title: str):
    """Particles converted on the interior (between the pools) and exterior side against pseudo-time (seaborn: a
    colour per side, a line style per onset criterion); a dotted line where the pools merged."""
    runs = growth[growth.case == case].sort_values("step")
    long = runs.melt(
        id_vars=["criterion", "step"],
        value_vars=[f"converted_{side}" for side in SIDE_COLOURS],
        var_name="side",
        value_name="converted",
    )
    long["side"] = long.side.str.removeprefix("converted_")
    criterion_lines(
        ax, long, criteria, x="step", y="converted", hue="side", hue_order=list(SIDE_COLOURS), palette=SIDE_COLOURS
    )
    merges = {}  # the criteria that merged at each step, named once beside its line
    for criterion in criteria:
        merged = summary[(summary.case == case) & (summary.criterion == criterion) & summary.merged.astype(bool)]
        run = runs[runs.criterion == criterion]
        for step in merged.merge_step:
            merges.setdefault(run.step[run.pseudo_time >= step].min(), []).append(criterion)
    for row, which in merges.items():
        ax.axvline(row, color="0.3", ls=":", lw=0.8)
        ax.text(
            row,
            0.5,
            f" merged ({', '.join(which)})",
            transform=ax.get_xaxis_transform(),
            fontsize=7,
            color="0.3",
            rotation=90,
            va="center",
        )
    no_growth_note(ax, runs)
    ax.set(xlabel=PSEUDO_TIME, ylabel="converted particles", title=title)
    ax.set_ylim(-0.5, max(ax.get_ylim()[1], 2.0))
    ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
    style_legend(ax)


def tip_stress_panel(
    ax,
    runs: pd.DataFrame,
    by: str,
    labels: dict,
    colours: dict,
    sigma_colours: dict,
    title: str,
    dashes=None,
    paper_sigma: bool = False,
):
    """The largest onset-measure radial stress in front of the pools against pseudo-time (the sawtooth of figure
    5b), seaborn: one line per value of ``runs[by]`` (legend ``labels``, ``colours``, optionally ``dashes``), a
    cross after every pass in which particles were converted, a ring around every state reached through a snap; a
    dashed line at each sigma_cr of ``sigma_colours``; with ``paper_sigma``, a dotted line at the paper's
    (:data:`PAPER_SIGMA`, from its text)."""
    runs = runs.sort_values("step").assign(run=runs[by].map(labels))
    lines = dict(hue="run", hue_order=list(labels.values()), palette={labels[k]: colours[k] for k in labels})
    style = {} if dashes is None else dict(style="run", dashes={labels[k]: dashes[k] for k in labels})
    sns.lineplot(runs, x="step", y="tip_radial_stress_kPa", estimator=None, sort=False, lw=1.0, ax=ax, **lines, **style)
    burst = runs.groupby(by).converted_particles.diff().fillna(0.0) > 0  # after a pass that converted particles
    sns.scatterplot(
        runs[burst], x="step", y="tip_radial_stress_kPa", marker="x", s=16, linewidth=1.0, legend=False, ax=ax, **lines
    )
    snapped = runs[runs.snap.astype(bool)] if "snap" in runs else runs.iloc[:0]
    rings = [
        ax.scatter(run.step, run.tip_radial_stress_kPa, s=42, facecolors="none", edgecolors=colours[key], lw=0.9)
        for key, run in snapped.groupby(by, sort=False)
    ]  # a state reached through a snap (sphgag.engine.snap): an open ring around its point
    if rings and ax.get_legend() is not None:
        old = ax.get_legend()
        ax.legend(list(old.legend_handles) + rings[:1], [t.get_text() for t in old.texts] + ["reached through a snap"])
    if paper_sigma:
        ax.axhline(PAPER_SIGMA, color="#b2182b", ls=(0, (1, 1.5)), lw=1.2)
        old = ax.get_legend()
        paper = plt.Line2D([], [], color="#b2182b", ls=(0, (1, 1.5)), lw=1.2)
        ax.legend(list(old.legend_handles) + [paper], [t.get_text() for t in old.texts] + [PAPER_SIGMA_LABEL])
    for sigma, colour in sigma_colours.items():
        ax.axhline(sigma, color=colour, ls=(0, (4, 3)), lw=0.8)
    ax.axhline(0.0, color="0.7", lw=0.6)
    lo, hi = ax.get_ylim()
    lines = sum(1 + str(text).count("\n") for text in labels.values())
    ax.set_ylim(lo, hi + 0.12 * lines * (hi - lo))  # room for the legend above the curves
    sigma_labels(ax, sigma_colours)
    ax.set(xlabel=PSEUDO_TIME, ylabel="tip radial stress (kPa)", title=title)
    style_legend(ax, "upper left", title=None)


def sigma_labels(ax, sigma_colours: dict, gap: float = 0.04):
    """Each sigma_cr's value beside its line at the panel's right edge, in its colour; values whose lines lie within
    ``gap`` of the panel's height of each other share one label (in black), so no two labels overlap."""
    lo, hi = ax.get_ylim()
    groups: list[list] = []
    for sigma in sorted(sigma_colours):
        if groups and sigma - groups[-1][-1] < gap * (hi - lo):
            groups[-1].append(sigma)
        else:
            groups.append([sigma])
    for group in groups:
        colour = sigma_colours[group[0]] if len(group) == 1 else "black"
        text = " " + "/".join(f"{s:g}" for s in group)
        y = 0.5 * (group[0] + group[-1])
        ax.text(1.0, y, text, transform=ax.get_yaxis_transform(), color=colour, fontsize=7, va="center", ha="left")


def of_law(table: pd.DataFrame, law: str) -> pd.DataFrame:
    """The rows of one charge law (column ``charge_law``)."""
    return table[table.charge_law == law]


def snapshot_figure(title: str, rows, layers, lower: float, width: float = 11.0):
    """A figure of snapshot rows (:func:`~sphgag.views.snapshots.snapshot_rows`: ``rows``, each panel framed on its
    pools) under ``title``, the material key above them, and a gridspec cell ``lower`` in high below them (the
    figure's line panels); returns the figure and that cell."""
    _style()
    top = snapshots.rows_height(rows, width)
    fig = plt.figure(figsize=(width, top + lower + 0.8), layout="constrained")
    fig.suptitle(title, x=0.01, ha="left", fontsize=10, fontweight="bold")
    gs = fig.add_gridspec(2, 1, height_ratios=[top, lower])
    snapshots.snapshot_rows(fig, gs[0], rows, layers)
    snapshots.material_key(fig, layers)
    return fig, gs[1]


def finish(fig):
    """The snapshot panels' particles sized to their spacing once the layout is fixed; the figure."""
    snapshots.fit_particle_sizes(fig)
    return fig


# the paper's critical stress in its text: "sigma_cr ~ 61 kPa, determined via failure tests of the medial layer of the
# aorta" (section 2; its figure 5 runs 30, 40 and 60 kPa)
PAPER_SIGMA = 61.0
PAPER_SIGMA_LABEL = "paper's text: sigma_cr ~ 61 kPa (failure tests)"


def fig5(
    growth: pd.DataFrame,
    summary: pd.DataFrame,
    runs_of: dict,
    case: str,
    sigma: float,
    criteria,
    law: str,
    layers,
    n_snapshots: int = 3,
):
    """Figure 5 under one charge law (``law``), one pool set grown alone (``case``, figure 5's set): (a) snapshots
    at sigma_cr = ``sigma`` (``runs_of``: criterion -> snapshots), a row per onset criterion, the states from left
    to right as in the paper's 5a; (b) the tip radial stress against pseudo-time for every sigma_cr, one panel per
    criterion, with the paper's sigma_cr (:data:`PAPER_SIGMA`); (c) the delaminated length against the GAG
    concentration."""
    runs, notes_of = of_law(growth[growth.case == case], law), of_law(summary, law)
    sigmas = sorted(runs.sigma_cr_kPa.unique())
    colours = dict(zip(sigmas, plt.cm.Dark2.colors))
    rows = [
        [
            (runs_of[c], k, f"(a) {c}{' (default)' * (j == 0)}, {sigma:g} kPa")
            for k in snapshots.snapshot_indices(runs_of[c], n_snapshots)
        ]
        for j, c in enumerate(criteria)
    ]
    panels = len(criteria) + 1  # (b) per criterion and (c): in a row of three at most, then in rows of two
    columns = panels if panels <= 3 else 2
    lines = -(-panels // columns)
    fig, lower = snapshot_figure(f"Figure 5: {law_title(law)}", rows, layers, 3.4 * lines)
    bottom = lower.subgridspec(lines, columns)
    tip_axes = []
    for j, criterion in enumerate(criteria):
        ax = fig.add_subplot(bottom[divmod(j, columns)], sharey=tip_axes[0] if tip_axes else None)
        crit = runs[runs.criterion == criterion]
        notes = {s: f"{s:g} kPa: {run_note(notes_of, case=case, sigma_cr_kPa=s, criterion=criterion)}" for s in sigmas}
        tip_stress_panel(
            ax, crit, "sigma_cr_kPa", notes, colours, colours, f"(b) {criterion} onset measure", paper_sigma=True
        )
        no_growth_note(ax, crit)
        tip_axes.append(ax)
    ax = fig.add_subplot(bottom[divmod(len(criteria), columns)])
    criterion_lines(
        ax,
        runs.sort_values("step").assign(sigma_cr=runs.sigma_cr_kPa.map("{:g} kPa".format)),
        criteria,
        x="concentration_mEq_l",
        y="delaminated_length_um",
        hue="sigma_cr",
        palette=palette(sigmas, colours, "{:g} kPa".format),
    )
    for j, criterion in enumerate(criteria):
        for sig in sigmas:
            ended = notes_of[(notes_of.case == case) & (notes_of.criterion == criterion)]
            event_marks(ax, ended[ended.sigma_cr_kPa == sig], colours[sig], dashes=j > 0)
    no_growth_note(ax, runs)
    ax.set(
        xlabel=GAG_CONCENTRATION,
        ylabel="delaminated length (um)",
        title="(c) growth: onset (triangles),\nrunaway (lines)",
    )
    style_legend(ax, "upper left")
    return finish(fig)


def fig6(growth: pd.DataFrame, summary: pd.DataFrame, runs_of: dict, cases, criteria, law: str, layers):
    """Figure 6 under one charge law (``law``), pools at one radius (``cases``: figure 6's sets, e.g. low and high
    separation; ``runs_of``: (case, criterion) -> snapshots): (a, b, ...) a row per set, as the paper's rows (a) and
    (b): the first state, then the last state of every criterion; (c) the particles converted between the pools
    (interior) and away from them (exterior) against pseudo-time, a panel per set."""
    rows = []
    for j, case in enumerate(cases):
        letter = "abdefghij"[j]
        row = [(runs_of[case, criteria[0]], 0, f"({letter}) {case}, first state")]
        row += [
            (runs_of[case, c], len(runs_of[case, c]["steps"]) - 1, f"({letter}) {case}, {c}: last") for c in criteria
        ]
        rows.append(row)
    fig, lower = snapshot_figure(f"Figure 6: {law_title(law)}", rows, layers, 3.0)
    bottom = lower.subgridspec(1, len(cases))
    g, sm = of_law(growth, law), of_law(summary, law)
    for j, case in enumerate(cases):
        converted_panel(fig.add_subplot(bottom[j]), g, sm, case, criteria, f"(c) {case}: converted particles")
    return finish(fig)


def fig7(
    growth: pd.DataFrame,
    summary: pd.DataFrame,
    runs_of: dict,
    case: str,
    sigma: float,
    criteria,
    law: str,
    layers,
    n_snapshots: int = 4,
):
    """Figure 7 under one charge law (``law``), two pools offset in radius (``case``, figure 7's set; ``runs_of``:
    criterion -> snapshots): (a) a row of ``n_snapshots`` snapshots per criterion, as the paper's four; (b) the tip
    radial stress and (c) the converted particles against pseudo-time."""
    rows = [
        [(runs_of[c], k, f"(a) {c}") for k in snapshots.snapshot_indices(runs_of[c], n_snapshots)] for c in criteria
    ]
    fig, lower = snapshot_figure(f"Figure 7: {law_title(law)}", rows, layers, 3.0)
    bottom = lower.subgridspec(1, 2)
    g, sm = of_law(growth, law), of_law(summary, law)
    runs = g[g.case == case]
    ax = fig.add_subplot(bottom[0])
    notes = {c: f"{c}: {run_note(sm, case=case, criterion=c)}" for c in criteria}
    tip_stress_panel(
        ax,
        runs,
        "criterion",
        notes,
        criterion_colours(criteria),
        {sigma: "0.45"},
        f"(b) {case}: tip radial stress, sigma_cr = {sigma:g} kPa",
        criterion_dashes(criteria),
    )
    no_growth_note(ax, runs)
    converted_panel(fig.add_subplot(bottom[1]), g, sm, case, criteria, f"(c) {case}: converted particles")
    return finish(fig)


# figures 5-7 by the name of the rule that draws them: the columns of their pool sets' growth that must be finite, and
# their title
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


def figure(
    name: str, growth: pd.DataFrame, summary: pd.DataFrame, snapshot_paths, poolsets, sigma, criteria, law, laws, layers
):
    """Figure ``name`` (fig5, fig6 or fig7, :data:`FIGURES`) under charge law ``law`` of the runs of its pool sets
    ``poolsets`` at ``sigma`` [kPa]: ``growth`` and ``summary`` are the runs' tables (eq. 2.28 as printed),
    ``snapshot_paths`` their snapshot files by charge law (``laws``), then pool set, then criterion."""
    finite_or_raise(growth[growth.case.isin(poolsets)], FIGURES[name][0], name)
    keys = [(run_law, case, c) for run_law in laws for case in poolsets for c in criteria]
    runs_of = {
        (case, c): snapshots.read_snapshots(path)
        for (run_law, case, c), path in zip(keys, snapshot_paths)
        if run_law == law
    }
    if name == "fig6":
        return fig6(growth, summary, runs_of, poolsets, criteria, law, layers)
    (poolset,) = poolsets
    draw = fig5 if name == "fig5" else fig7
    return draw(growth, summary, {c: runs_of[poolset, c] for c in criteria}, poolset, sigma, criteria, law, layers)
