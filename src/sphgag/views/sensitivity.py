"""The sensitivity study's figures (not in the paper): the Morris and Sobol indices (figure
sensitivity) and the delamination map (figure delamination_map)."""

from __future__ import annotations

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from ..studies.sensitivity import MORRIS, SENSITIVITY_METHODS
from .style import GAG_CONCENTRATION, LAST_CONVERGED, _style, is_paper_law, law_short, paper_pool

SENSITIVITY_OUTPUTS = {  # results/sensitivity/indices.csv output -> axis label
    "tip_radial_stress_kPa": "tip radial stress (kPa)",
    "top_circ_stress_kPa": "top hoop stress (kPa)",
    "pool_volume_change": "pool volume change",
    "onset_concentration_mEq_l": "onset concentration (mEq/l)",
    "runaway_concentration_mEq_l": "runaway concentration (mEq/l)",
    "final_length_um": "delaminated length (um)",
    "propagated": "propagated (0/1)",
}


INPUT_LABEL = "input label"  # the gid of an input's label on a Morris panel (declutter)


def input_label(path: str) -> str:
    """A sensitivity input's dotted path without its unit: ``gag.shear_modulus_kPa`` -> ``gag.shear_modulus``."""
    section, _, leaf = path.rpartition(".")
    for unit in ("_kPa", "_mmHg", "_um", "_deg", "_K", "_mEq_l"):
        leaf = leaf.removesuffix(unit)
    return f"{section}.{leaf}" if section else leaf


def _no_indices(ax, rows: pd.DataFrame):
    used = int(rows.samples_used.iloc[0]) if len(rows) else 0
    total = used + int(rows.samples_missing.iloc[0]) if len(rows) else 0
    ax.text(
        0.5,
        0.5,
        f"no indices\n({used} of {total} samples usable\nor the output does not vary)",
        ha="center",
        va="center",
        transform=ax.transAxes,
        fontsize=7,
        color="0.4",
    )


def morris_panel(ax, rows: pd.DataFrame, labelled: int = 4):
    """mu* (with its bootstrap interval) against sigma, one point per input; the ``labelled`` largest named."""
    wide = rows.pivot_table(index="input", columns="index", values="value", sort=False)
    star = rows[rows["index"] == "mu_star"].set_index("input")
    if not star.value.max() > 0:  # no indices, or an output that no input changes
        return _no_indices(ax, rows)
    ax.errorbar(
        star.value,
        wide.loc[star.index, "sigma"],
        xerr=[star.value - star.conf_low, star.conf_high - star.value],
        fmt="o",
        ms=3.5,
        color="#3b6fb6",
        ecolor="0.6",
        elinewidth=0.8,
        capsize=0,
    )
    top = star.value.sort_values(ascending=False).index[:labelled]
    top = [name for name in top if star.value[name] >= 0.05 * star.value.max()]  # the visible ones
    for name in top:
        ax.annotate(
            input_label(name),
            (star.value[name], wide.loc[name, "sigma"]),
            fontsize=6,
            xytext=(3, 2),
            textcoords="offset points",
            gid=INPUT_LABEL,
        )
    lim = max(float(star.conf_high.max()), float(wide.sigma.max()), 1e-12) * 1.1
    ax.plot([0, lim], [0, lim], ls=":", lw=0.7, color="0.5")  # sigma = mu*: strongly non-linear or interacting
    ax.set_xlim(0, lim)
    ax.set_ylim(0, lim)
    ax.set_xlabel("mu*")
    ax.set_ylabel("sigma")


#: the colours of a method's indices in an index panel, in the order of its table (Sobol: S1, ST)
INDEX_COLOURS = ("#1b9e77", "#d95f02", "#7570b3", "#e7298a")


def index_panel(ax, rows: pd.DataFrame):
    """Each index of a method per input with its interval (horizontal bars): Sobol's S1 and ST, or a plug-in's."""
    if not rows.value.abs().max() > 0:
        return _no_indices(ax, rows)
    names = list(dict.fromkeys(rows.input))
    indices = list(dict.fromkeys(rows["index"]))
    y, step = np.arange(len(names)), 0.72 / len(indices)
    for k, (index, colour) in enumerate(zip(indices, INDEX_COLOURS)):
        r = rows[rows["index"] == index].set_index("input").loc[names]
        ax.barh(
            y + (k - (len(indices) - 1) / 2) * step,
            r.value,
            height=step * 17.0 / 18.0,  # 0.34 for two indices, to the bit (0.36 - 0.02 is not)
            color=colour,
            label=index,
            xerr=[r.value - r.conf_low, r.conf_high - r.value],
            error_kw=dict(lw=0.8, ecolor="0.3"),
        )
    ax.set_yticks(y, [input_label(n) for n in names], fontsize=6)
    ax.invert_yaxis()
    ax.axvline(0, color="0.5", lw=0.6)
    ax.set_xlabel(f"{SENSITIVITY_METHODS[rows.method.iloc[0]].title} index")
    ax.legend(loc="lower right", fontsize=6, frameon=False)


#: a method's own panel (SENSITIVITY_METHODS, by its name); any other method's indices are drawn as bars (index_panel)
PANELS = {MORRIS.name: morris_panel}


def sensitivity(indices: pd.DataFrame, laws):
    """Morris mu* against sigma (every input) and Sobol S1 and ST with their intervals (the chosen inputs): a row per
    output, a column per method and charge law."""
    _style()
    laws = [law for law in laws if law in set(indices.charge_law)]
    columns = [(m, law) for m in SENSITIVITY_METHODS if m in set(indices.method) for law in laws]
    outputs = [o for o in SENSITIVITY_OUTPUTS if o in set(indices.output)]
    fig, axes = plt.subplots(
        len(outputs),
        len(columns),
        figsize=(3.2 * len(columns), 2.5 * len(outputs)),
        squeeze=False,
        layout="constrained",
    )
    for i, output in enumerate(outputs):
        for j, (method, law) in enumerate(columns):
            ax = axes[i, j]
            rows = indices[(indices.method == method) & (indices.charge_law == law) & (indices.output == output)]
            PANELS.get(method, index_panel)(ax, rows)
            if i == 0:
                ax.set_title(f"{SENSITIVITY_METHODS[method].title}: {law_short(law)}", fontsize=8)
            if j == 0:
                ax.annotate(
                    SENSITIVITY_OUTPUTS[output],
                    (-0.42, 0.5),
                    xycoords="axes fraction",
                    rotation=90,
                    ha="center",
                    va="center",
                    fontsize=8,
                    fontweight="bold",
                )
    declutter(fig)
    return fig


def declutter(fig):
    """Leave out an input's label where it would cover the label of a more influential input (drawn before it), as
    the figure is laid out."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        kept = []
        for text in [t for t in ax.texts if t.get_gid() == INPUT_LABEL]:
            box = text.get_window_extent(renderer)
            if any(box.overlaps(other) for other in kept):
                text.remove()
            else:
                kept.append(box)


MAP_COLOURS = {
    "no onset": "#d9d9d9",
    "onset, arrested": "#fdb863",
    "propagation": "#b2182b",
    "no equilibrium": "#542788",
}


def delamination_map(table: pd.DataFrame, swelling: pd.DataFrame, cases: dict, pressure_mmHg: float, laws):
    """The delamination map: a panel per charge law (row) and sigma_cr (column), pool angular extent (x) against
    concentration level (y), each cell coloured by what the pool does there
    (:data:`sphgag.studies.delamination.tables.LEVEL_CLASSES`). On the paper's charge law's panels (prescribed), the end
    of figure 4's swelling runs of the passive wall at ``pressure_mmHg`` (``swelling``: tip_stress.csv): a limit point
    where there is one (a star), else the last converged state of a run that stops early (a cross)."""
    _style()
    laws = [law for law in laws if law in set(table.charge_law)]
    sigmas = sorted(table.sigma_cr_kPa.unique())
    widths = sorted(table.angular_extent_deg.unique())
    levels = sorted(table.concentration_mEq_l.unique())
    step = levels[1] - levels[0] if len(levels) > 1 else levels[0]
    fig, axes = plt.subplots(
        len(laws),
        len(sigmas),
        figsize=(3.3 * len(sigmas) + 0.8, 3.0 * len(laws) + 0.6),
        squeeze=False,
        sharex=True,
        sharey=True,
        layout="constrained",
    )
    swelling = paper_pool(swelling)  # the delamination runs' pools are the paper's particles
    ends = swelling[(swelling.model == "passive") & np.isclose(swelling.pressure_mmHg, pressure_mmHg)]
    for i, law in enumerate(laws):
        for j, sigma in enumerate(sigmas):
            ax = axes[i, j]
            t = table[(table.charge_law == law) & (table.sigma_cr_kPa == sigma)]
            for r in t.itertuples():
                x = widths.index(r.angular_extent_deg)
                ax.add_patch(
                    matplotlib.patches.Rectangle(
                        (x - 0.5, r.concentration_mEq_l - step / 2), 1.0, step, color=MAP_COLOURS[r.state], lw=0
                    )
                )
            if is_paper_law(law):
                for name, width in cases.items():
                    run = ends[(ends.charge_law == law) & (ends.case == name)]
                    if run.empty:
                        continue
                    x = float(np.interp(width, widths, range(len(widths))))
                    limit = run.limit_concentration_mEq_l.dropna()
                    if len(limit):
                        ax.plot(x, limit.iloc[0], "*", color="k", ms=9, mec="w", mew=0.6)
                    elif run.path_end.iloc[-1] != "complete":
                        ax.plot(x, run.concentration_mEq_l.max(), "x", color="k", ms=7, mew=1.6)
                    ax.annotate(
                        f"case {name}", (x, levels[0] - step / 2), fontsize=6, ha="center", va="bottom", color="0.2"
                    )
            ax.set_xlim(-0.5, len(widths) - 0.5)
            ax.set_ylim(levels[0] - step / 2, levels[-1] + step / 2)
            ax.set_xticks(range(len(widths)), [f"{w:g}" for w in widths])
            ax.set_title(f"{law_short(law)}\nsigma_cr = {sigma:g} kPa", fontsize=8)
            if i == len(laws) - 1:
                ax.set_xlabel("pool angular extent (deg)")
            if j == 0:
                ax.set_ylabel(GAG_CONCENTRATION)
    handles = [matplotlib.patches.Patch(color=c, label=s) for s, c in MAP_COLOURS.items()]
    handles += [
        matplotlib.lines.Line2D([], [], marker="*", ls="", color="k", label="figure 4 swelling: limit point"),
        matplotlib.lines.Line2D([], [], marker="x", ls="", color="k", label="figure 4 swelling: " + LAST_CONVERGED),
    ]
    columns = max(1, min(3, int(fig.get_figwidth() // 3.3)))  # as many columns as the figure is wide for
    fig.legend(handles=handles, loc="outside lower center", ncol=columns, fontsize=7, frameon=False)
    return fig
