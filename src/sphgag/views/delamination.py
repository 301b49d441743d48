"""Figures 5-7 of the paper, delamination by damage: one pool grown (figure 5), pools at one radius (figure 6)
and pools offset in radius (figure 7), with their snapshots read from the runs' ``*_snapshots.npz``."""

from __future__ import annotations

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import seaborn as sns

from .style import (
    GAG_CONCENTRATION,
    LAYER_COLOURS,
    _style,
    distinct_colours,
    finite_or_raise,
    law_blocks,
    palette,
    style_legend,
)

SEEDED, CONVERTED = 1, 2  # history origin codes (sphgag.engine.history): a seeded GAG pool, tissue converted by damage
MATERIAL_COLOURS = {SEEDED: LAYER_COLOURS["GAG"], CONVERTED: "#2166ac"}
INTACT_GREYS = (0.84, 0.62)  # intact tissue: the innermost layer light, the outermost dark, the others between


def intact_colours(layers) -> dict:
    """A grey per layer name of ``layers`` (``(name, outer radius)`` bands from the lumen out), lighter inside."""
    names = list(dict.fromkeys(name for name, _ in layers))
    greys = np.linspace(*INTACT_GREYS, len(names)) if len(names) > 1 else INTACT_GREYS[:1]
    return {name: f"{g:.2f}" for name, g in zip(names, greys)}


DAMAGE_CMAP = matplotlib.colors.LinearSegmentedColormap.from_list("damage", ["#ffd300", "#f47b20", "#7f2704"])
SIDE_COLOURS = {"interior": "#1b9e77", "exterior": "#7570b3"}
PSEUDO_TIME = "pseudo-time (concentration levels + damage passes)"


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


def criteria_width(criteria) -> float:
    """The width [in] of a figure with a column of snapshots per onset criterion: 11 in for up to two criteria, as
    wide again per column beyond them (the panels' titles stay legible)."""
    return 11.0 * max(1.0, len(criteria) / 2)


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


def read_snapshots(path) -> dict:
    """Every array of a ``*_snapshots.npz`` of rule delaminate, read into memory."""
    with np.load(path, allow_pickle=False) as data:
        return {name: data[name] for name in data.files}


def snapshot_indices(snap: dict, n: int) -> list:
    """``n`` snapshots spread evenly over a run, the first and the last included (fewer if the run has fewer)."""
    return sorted(set(np.linspace(0, len(snap["steps"]) - 1, n).round().astype(int).tolist()))


def snapshot_window(shown, margin_deg=6.0, min_width_deg=20.0):
    """``(lo, hi)`` reference angles [deg] holding every GAG particle of the ``(snapshot, k)`` pairs with a margin."""
    th = np.concatenate([np.rad2deg(snap["theta"][snap[f"s{k}_history_origin"] > 0]) for snap, k in shown])
    lo, hi = th.min() - margin_deg, th.max() + margin_deg
    if hi - lo < min_width_deg:
        lo, hi = 0.5 * (lo + hi - min_width_deg), 0.5 * (lo + hi + min_width_deg)
    return max(lo, 0.0), min(hi, 90.0)


def in_window(snap: dict, window) -> np.ndarray:
    """The particles whose reference angle is within ``window`` [deg]."""
    th = np.rad2deg(snap["theta"])
    return (th >= window[0]) & (th <= window[1])


def current_polar(snap: dict, k: int, mask) -> tuple:
    """``(angle [deg], radius [um])`` of the ``mask`` particles in snapshot ``k``."""
    x = snap[f"s{k}_x"][mask]
    return np.rad2deg(np.arctan2(x[:, 1], x[:, 0])), np.hypot(x[:, 0], x[:, 1])


def snapshot_status(snap: dict, k: int) -> str:
    """What damage has done by snapshot ``k``, in words."""
    origin, D = snap[f"s{k}_history_origin"], snap[f"s{k}_history_D"]
    converted = int(np.sum(origin == CONVERTED))
    d_max = float(D[origin == 0].max(initial=0.0))
    if converted:
        return f"{converted} converted to GAG"
    return f"max D {d_max:.2f}, none ruptured" if d_max > 0 else "no damage onset"


def snapshot_panel(ax, snap: dict, k: int, window, radii, layers, label: str):
    """Snapshot ``k`` of a run: the particles of the angular ``window`` at their current angle and radius (axis
    limits ``window`` x ``radii``), true to scale at the pools' radius; intact tissue grey by layer (``layers``:
    ``(name, outer radius)`` bands, :func:`intact_colours`: the media light, the adventitia dark), damaged tissue by
    D, seeded GAG red, GAG converted by damage blue. Marker sizes are set by :func:`fit_particle_sizes` after the
    layout."""
    near = in_window(snap, window)
    origin, D = snap[f"s{k}_history_origin"][near], snap[f"s{k}_history_D"][near]
    th, r = current_polar(snap, k, near)
    outer = [r for _, r in layers]
    band = np.minimum(np.searchsorted(outer, np.hypot(*snap["X"][near].T)), len(layers) - 1)
    grey = intact_colours(layers)
    colours = matplotlib.colors.to_rgba_array([grey[layers[b][0]] for b in band])
    damaged = (origin == 0) & (D > 0)
    colours[damaged] = DAMAGE_CMAP(D[damaged])
    for code in (SEEDED, CONVERTED):
        colours[origin == code] = matplotlib.colors.to_rgba(MATERIAL_COLOURS[code])
    edges = np.where(origin == CONVERTED, "k", np.where(damaged, matplotlib.colors.to_hex(DAMAGE_CMAP(1.0)), "none"))
    ax.scatter(th, r, s=4, c=colours, edgecolors=edges, linewidths=np.where(edges == "none", 0.0, 0.7))
    dx = float(np.sqrt(np.median(snap["volume"])))
    radius = float(np.median(r))
    ax._particle_spacing = (dx, radius)
    ax.set_aspect(180.0 / (np.pi * radius))  # 1 um of arc at the pools' radius as long as 1 um of radius
    ax.set_xlim(*window)
    ax.set_ylim(*radii)
    ax.set_title(
        f"{label}c = {snap['concentrations'][k]:g} mEq/l, pass {int(snap['steps'][k])}: {snapshot_status(snap, k)}",
        fontsize=8,
        loc="left",
    )


def fit_particle_sizes(fig):
    """Draw the snapshot panels' particles one particle spacing wide, now that the layout is fixed."""
    fig.draw_without_rendering()
    for ax in fig.axes:
        if not hasattr(ax, "_particle_spacing"):
            continue
        dx, radius = ax._particle_spacing
        lo, hi = ax.get_xlim()
        points_per_um = ax.get_window_extent().width * 72.0 / fig.dpi / (np.deg2rad(hi - lo) * radius)
        for coll in ax.collections:
            coll.set_sizes([(0.95 * dx * points_per_um) ** 2])


def material_key(fig, layers):
    """The legend of the snapshot panels' colours, above the figure (``layers`` as :func:`snapshot_panel`)."""
    key = {name: (grey, f"intact {name}") for name, grey in intact_colours(layers).items()}
    key[SEEDED] = (MATERIAL_COLOURS[SEEDED], "seeded GAG pool")
    key[CONVERTED] = (MATERIAL_COLOURS[CONVERTED], "GAG converted by damage")
    handles = [
        plt.Line2D([], [], marker="s", ls="none", ms=7, color=colour, label=text) for colour, text in key.values()
    ]
    fig.legend(handles=handles, loc="outside upper center", ncols=len(handles), frameon=False)


def damage_colourbar(fig, cax):
    """The colour bar of the damage of the snapshot panels, in ``cax``."""
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(matplotlib.colors.Normalize(0.0, 1.0), DAMAGE_CMAP), cax=cax)
    bar.set_label("damage D of tissue (eq. 2.28)")


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
    for criterion in criteria:
        merged = summary[(summary.case == case) & (summary.criterion == criterion) & summary.merged.astype(bool)]
        run = runs[runs.criterion == criterion]
        for step in merged.merge_step:
            row = run.step[run.pseudo_time >= step].min()
            ax.axvline(row, color="0.3", ls=":", lw=0.8)
            ax.text(
                row,
                0.5,
                f" merged ({criterion})",
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
    ax, runs: pd.DataFrame, by: str, labels: dict, colours: dict, sigma_colours: dict, title: str, dashes=None
):
    """The largest onset-measure radial stress in front of the pools against pseudo-time (the sawtooth of figure
    5b), seaborn: one line per value of ``runs[by]`` (legend ``labels``, ``colours``, optionally ``dashes``), a
    cross after every pass in which particles were converted, a ring around every state reached through a snap; a
    dashed line at each sigma_cr of ``sigma_colours``."""
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
    for sigma, colour in sigma_colours.items():
        ax.axhline(sigma, color=colour, ls=(0, (4, 3)), lw=0.8)
        ax.text(
            1.0,
            sigma,
            f" {sigma:g}",
            transform=ax.get_yaxis_transform(),
            color=colour,
            fontsize=7,
            va="center",
            ha="left",
        )
    ax.axhline(0.0, color="0.7", lw=0.6)
    lo, hi = ax.get_ylim()
    lines = sum(1 + str(text).count("\n") for text in labels.values())
    ax.set_ylim(lo, hi + 0.12 * lines * (hi - lo))  # room for the legend above the curves
    ax.set(xlabel=PSEUDO_TIME, ylabel="tip radial stress (kPa)", title=title)
    style_legend(ax, "upper left", title=None)


def snapshot_grid(fig, spec, columns, layers):
    """Snapshot panels in ``spec`` (a gridspec cell of ``fig``, a figure or a law's block): ``columns`` is a list of
    lists of ``(snapshot, k, label)``, one list per column, each column with one angular window; the damage colour
    bar beside them."""
    rows = max(len(col) for col in columns)
    grid = spec.subgridspec(rows, len(columns) + 1, width_ratios=[1.0] * len(columns) + [0.015])
    windows = [snapshot_window([(snap, k) for snap, k, _ in col]) for col in columns]
    r = np.concatenate(
        [current_polar(snap, k, in_window(snap, w))[1] for col, w in zip(columns, windows) for snap, k, _ in col]
    )
    dx = float(np.sqrt(np.median(columns[0][0][0]["volume"])))
    radii = (r.min() - dx, r.max() + dx)  # one radial range: every panel of the grid has the same scale
    for j, (col, window) in enumerate(zip(columns, windows)):
        for i, (snap, k, label) in enumerate(col):
            ax = fig.add_subplot(grid[i, j])
            snapshot_panel(ax, snap, k, window, radii, layers, label)
            if i == len(col) - 1:
                ax.set_xlabel("current angle (deg)")
            if j == 0:
                ax.set_ylabel("radius (um)")
    damage_colourbar(fig, fig.add_subplot(grid[:, -1]))


def criterion_snapshots(block, snapshots: dict, criteria, n_snapshots: int, label: str, layers, rows):
    """In ``block`` (a law's sub-figure), above: one column of ``n_snapshots`` snapshots per onset criterion
    (``snapshots``: criterion -> snapshots; titles "(a) <criterion><label>"), ``rows`` parts high; returns the
    gridspec cell left below (3 parts)."""
    columns = [
        [
            (snapshots[c], k, f"(a) {c}{' (default)' * (j == 0)}{label}")
            for k in snapshot_indices(snapshots[c], n_snapshots)
        ]
        for j, c in enumerate(criteria)
    ]
    gs = block.add_gridspec(2, 1, height_ratios=[rows, 3.0])
    snapshot_grid(block, gs[0], columns, layers)
    return gs[1]


def of_law(table: pd.DataFrame, law: str) -> pd.DataFrame:
    """The rows of one charge law (column ``charge_law``)."""
    return table[table.charge_law == law]


def fig5(
    growth: pd.DataFrame,
    summary: pd.DataFrame,
    snapshots: dict,
    case: str,
    sigma: float,
    criteria,
    laws,
    layers,
    n_snapshots: int = 3,
):
    """Figure 5, one pool set grown alone (``case``, figure 5's set), one block per charge law (``laws``): (a)
    snapshots at sigma_cr = ``sigma`` (``snapshots``: (law, criterion) -> snapshots), one column per onset criterion;
    (b) the tip radial stress against pseudo-time for every sigma_cr, one panel per criterion; (c) the delaminated
    length against the GAG concentration."""
    _style()
    runs = growth[growth.case == case]
    sigmas = sorted(runs.sigma_cr_kPa.unique())
    colours = dict(zip(sigmas, plt.cm.Dark2.colors))
    rows = 1.3 * max(len(snapshot_indices(snap, n_snapshots)) for snap in snapshots.values())
    fig, blocks = law_blocks(laws, [0.3 + rows + 3.0] * len(laws), criteria_width(criteria))
    for block, law in zip(blocks, laws):
        own, notes_of = of_law(runs, law), of_law(summary, law)
        lower = criterion_snapshots(
            block,
            {c: snapshots[law, c] for c in criteria},
            criteria,
            n_snapshots,
            f", {sigma:g} kPa: ",
            layers,
            rows,
        )
        bottom = lower.subgridspec(1, len(criteria) + 1)
        tip_axes = []
        for j, criterion in enumerate(criteria):
            ax = block.add_subplot(bottom[j], sharey=tip_axes[0] if tip_axes else None)
            crit = own[own.criterion == criterion]
            notes = {
                s: f"{s:g} kPa: {run_note(notes_of, case=case, sigma_cr_kPa=s, criterion=criterion)}" for s in sigmas
            }
            tip_stress_panel(
                ax, crit, "sigma_cr_kPa", notes, colours, colours, f"(b) {criterion} onset measure, {case}"
            )
            no_growth_note(ax, crit)
            tip_axes.append(ax)
        ax = block.add_subplot(bottom[-1])
        criterion_lines(
            ax,
            own.sort_values("step").assign(sigma_cr=own.sigma_cr_kPa.map("{:g} kPa".format)),
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
        no_growth_note(ax, own)
        ax.set(
            xlabel=GAG_CONCENTRATION,
            ylabel="delaminated length (um)",
            title=f"(c) growth, {case}: onset (triangles), runaway (lines)",
        )
        style_legend(ax, "upper left")
    material_key(fig, layers)
    fit_particle_sizes(fig)
    return fig


def fig6(growth: pd.DataFrame, summary: pd.DataFrame, snapshots: dict, cases, criteria, laws, layers):
    """Figure 6, pools at one radius (``cases``: figure 6's sets, e.g. low and high separation), one block per charge
    law (``laws``; ``snapshots``: (law, case, criterion) -> snapshots): (a, b, ...) the first snapshot and the last
    one of every criterion, a column per set; (c) the particles converted between the pools (interior) and away from
    them (exterior) against pseudo-time."""
    _style()
    n_rows = 1 + len(criteria)
    fig, blocks = law_blocks(laws, [0.3 + 1.25 * n_rows + 3.0] * len(laws))
    for block, law in zip(blocks, laws):
        gs = block.add_gridspec(2, 1, height_ratios=[1.25 * n_rows, 3.0])
        columns = []
        for j, case in enumerate(cases):
            letter, first = "abdefghij"[j], snapshots[law, case, criteria[0]]
            col = [(first, 0, f"({letter}) {case}, first state: ")]
            col += [
                (snapshots[law, case, c], len(snapshots[law, case, c]["steps"]) - 1, f"({letter}) {case}, {c}: ")
                for c in criteria
            ]
            columns.append(col)
        snapshot_grid(block, gs[0], columns, layers)
        bottom = gs[1].subgridspec(1, len(cases))
        g, sm = of_law(growth, law), of_law(summary, law)
        for j, case in enumerate(cases):
            converted_panel(block.add_subplot(bottom[j]), g, sm, case, criteria, f"(c) {case}: converted particles")
    material_key(fig, layers)
    fit_particle_sizes(fig)
    return fig


def fig7(
    growth: pd.DataFrame,
    summary: pd.DataFrame,
    snapshots: dict,
    case: str,
    sigma: float,
    criteria,
    laws,
    layers,
    n_snapshots: int = 4,
):
    """Figure 7, two pools offset in radius (``case``, figure 7's set), one block per charge law (``laws``;
    ``snapshots``: (law, criterion) -> snapshots): (a) ``n_snapshots`` snapshots per criterion; (b) the tip radial
    stress and (c) the converted particles against pseudo-time."""
    _style()
    rows = 1.15 * max(len(snapshot_indices(snap, n_snapshots)) for snap in snapshots.values())
    fig, blocks = law_blocks(laws, [0.3 + rows + 3.0] * len(laws), criteria_width(criteria))
    for block, law in zip(blocks, laws):
        lower = criterion_snapshots(
            block, {c: snapshots[law, c] for c in criteria}, criteria, n_snapshots, ": ", layers, rows
        )
        bottom = lower.subgridspec(1, 2)
        g, sm = of_law(growth, law), of_law(summary, law)
        runs = g[g.case == case]
        ax = block.add_subplot(bottom[0])
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
        converted_panel(block.add_subplot(bottom[1]), g, sm, case, criteria, f"(c) {case}: converted particles")
    material_key(fig, layers)
    fit_particle_sizes(fig)
    return fig


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
    name: str, growth: pd.DataFrame, summary: pd.DataFrame, snapshot_paths, poolsets, sigma, criteria, laws, layers
):
    """Figure ``name`` (fig5, fig6 or fig7, :data:`FIGURES`) of the runs of its pool sets ``poolsets`` at ``sigma``
    [kPa]: ``growth`` and ``summary`` are the runs' tables (eq. 2.28 as printed), ``snapshot_paths`` their snapshot
    files by charge law, then pool set, then criterion."""
    finite_or_raise(growth[growth.case.isin(poolsets)], FIGURES[name][0], name)
    keys = [(law, case, c) for law in laws for case in poolsets for c in criteria]
    snapshots = {key: read_snapshots(path) for key, path in zip(keys, snapshot_paths)}
    if name == "fig6":
        return fig6(growth, summary, snapshots, poolsets, criteria, laws, layers)
    (poolset,) = poolsets
    by_criterion = {(law, c): snapshots[law, poolset, c] for law in laws for c in criteria}
    draw = fig5 if name == "fig5" else fig7
    return draw(growth, summary, by_criterion, poolset, sigma, criteria, laws, layers)
