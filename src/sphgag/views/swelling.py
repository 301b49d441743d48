"""Figure 4 of the paper, the swelling GAG pools: the pools and the stresses around them against concentration;
and the resolution study of those stresses (figure swelling_convergence, not in the paper)."""

from __future__ import annotations

import textwrap

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import seaborn as sns
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.ticker import NullFormatter, ScalarFormatter

from ..engine.measure import pool_probes
from ..studies.artery import pool_sector
from .style import (
    GAG_CONCENTRATION,
    LAST_CONVERGED,
    PAPER_POOL,
    _style,
    law_title,
    layer_colours,
    long_measures,
    pressure_colour,
    pressure_colours,
    variant_short,
    variants,
)


def pool_geometry_panel(ax, particles: pd.DataFrame, case: dict, probe_length: float, title: str, pool_layers):
    """Figure 4a: the pool (red: its particles of ``pool_layers``), the layers around it, and the probe regions
    (outlines)."""
    pool = pool_sector(case)
    th0 = np.deg2rad(pool.centre_angle_deg)
    half = 0.5 * np.deg2rad(max(pool.angular_extent_deg, 3.0)) + 25.0 / pool.centre_radius
    near = particles[np.abs(particles.theta_rad - th0) < half]
    arc = (near.theta_rad - th0) * pool.centre_radius
    in_pool = pool.contains(near.radius_um, near.theta_rad) & near.layer.isin(pool_layers)
    layer_colour = layer_colours(particles.layer.unique())
    colours = np.where(in_pool, layer_colour["GAG"], near.layer.map(layer_colour))
    ax.scatter(arc, near.radius_um, s=6, c=colours, linewidths=0)
    for name, box in pool_probes(pool, probe_length).items():
        (r0, r1), (t0, t1) = box.r_range, box.theta_range
        a0, a1 = (t0 - th0) * pool.centre_radius, (t1 - th0) * pool.centre_radius
        ax.plot([a0, a1, a1, a0, a0], [r0, r0, r1, r1, r0], lw=0.7, color="k" if name.startswith("tip") else "0.45")
    ax.set(title=title, xlabel="arc from pool centre (um)")
    ax.set_aspect("equal")
    edge = np.abs(arc).max()  # a narrow panel: two ticks, a round arc either side of the centre
    step = 10 ** np.floor(np.log10(0.6 * edge))
    step *= max(m for m in (1, 2, 5) if m * step <= 0.6 * edge)
    ax.set_xticks([-step, step])


TIP, TOP = "tip radial stress (kPa)", "top hoop stress (kPa)"
POOL_MEASURES = {  # the pool figures' columns (tip_stress.csv, convergence.csv) -> (quantity, statistic)
    "tip_radial_stress_kPa": (TIP, "region mean"),
    "tip_peak_radial_stress_kPa": (TIP, "particle peak"),
    "top_circ_stress_kPa": (TOP, "region mean"),
    "pool_volume_change": ("pool volume change", "region mean"),
}
STATISTIC_LINES = dict(
    style="statistic",
    style_order=["region mean", "particle peak"],
    dashes={"region mean": "", "particle peak": (1, 1.65)},
    markers={"region mean": "o", "particle peak": "."},
    markersize=3,
    markeredgewidth=0,
)


def swelling_lines(data: pd.DataFrame, colours: dict, max_concentration: float, **_):
    """One facet of figure 4 (FacetGrid.map_dataframe): a stress against concentration after conversion, a colour
    per pressure, a line style per statistic; the intact wall's value as a large dot at zero concentration; a cross
    at the last converged state of a run that stopped below ``max_concentration`` (no equilibrium beyond it)."""
    ax = plt.gca()
    conv, intact = data[data.stage == "converted"], data[data.stage == "intact"]
    sns.lineplot(
        conv,
        x="concentration_mEq_l",
        y="value",
        hue="pressure",
        hue_order=list(colours),
        palette=colours,
        estimator=None,
        lw=1.0,
        ax=ax,
        **STATISTIC_LINES,
    )
    sns.scatterplot(
        intact,
        x="concentration_mEq_l",
        y="value",
        hue="pressure",
        palette=colours,
        s=36,
        linewidth=0,
        clip_on=False,
        legend=False,
        ax=ax,
    )
    means = conv[conv.statistic == "region mean"].sort_values("concentration_mEq_l")
    ends = means.groupby("pressure").tail(1)
    ends = ends[ends.concentration_mEq_l < max_concentration - 1e-9]
    if len(ends):
        ax.scatter(
            ends.concentration_mEq_l,
            ends.value,
            marker="X",
            s=40,
            c=[colours[p] for p in ends.pressure],
            edgecolors="k",
            linewidths=0.5,
            zorder=5,
            label=LAST_CONVERGED,
        )
    if (data.quantity == TIP).any():
        ax.axhline(0.0, color="0.7", lw=0.6)


BAND_LIMIT = 0.10  # figure 4 marks where the GCI band first exceeds this fraction of the value
EXTRAPOLATED = "extrapolated (dx -> 0)"
BAND = "GCI band of the finest dx (95 %)"
NO_ORDER = "no order from the three dx (no band)"
NOT_RUN = "resolution bands: not run (snakemake resolution)"


def band_panel(ax, rows: pd.DataFrame):
    """Figure 4's band in one panel: over the configured spacing's curve, the Richardson-extrapolated value (dashed)
    and the GCI band of the finest spacing (grey: the value there +- GCI times its magnitude; gci_band.csv rows of
    one law, pool model, wall, case and stress, converted states); a grey cross at the finest value where the three
    spacings give no order (no band), and a dotted line where the band first exceeds :data:`BAND_LIMIT`. Returns
    that concentration (NaN if it never does)."""
    fine = rows[rows.dx_um == rows.dx_um.min()].sort_values("concentration_mEq_l")
    if rows.dx_um.nunique() < 3:
        return np.nan
    c, v, g = fine.concentration_mEq_l, fine.value, fine.gci_fine
    half = g * v.abs()
    ax.fill_between(c, v - half, v + half, color="0.55", alpha=0.35, lw=0, zorder=1)
    ax.plot(c, fine.extrapolated, color="k", ls="--", lw=0.9, zorder=4)
    none = fine[g.isna()]
    ax.scatter(none.concentration_mEq_l, none.value, marker="x", s=14, color="0.45", lw=0.8, zorder=4)
    wide = fine[g > BAND_LIMIT]
    first = float(wide.concentration_mEq_l.min()) if len(wide) else np.nan
    if np.isfinite(first):
        ax.axvline(first, color="k", ls=":", lw=0.8, zorder=0)
        ax.annotate(
            f"GCI > {BAND_LIMIT:.0%}",
            (first, 1.0),
            xycoords=("data", "axes fraction"),
            xytext=(2, -9),
            textcoords="offset points",
            fontsize=6,
        )
    return first


def volume_panel(ax, resolution: pd.DataFrame, case: str, law: str):
    """The tip radial stress against the pool's volume ratio J at every spacing of the resolution study
    (convergence.csv rows of charge law ``law``, the paper's pool model and one case, converted and at-volume states),
    the walls by line style: the axis on which the spacings agree. Returns the colour of each spacing."""
    rows = resolution[
        (resolution.charge_law == law)
        & (resolution.pool_model == PAPER_POOL)
        & (resolution.case == case)
        & (resolution.stage != "intact")
    ]
    spacings = sorted(resolution.dx_um.unique(), reverse=True)
    shades = dict(zip(spacings, plt.cm.viridis(np.linspace(0.1, 0.85, len(spacings)))))
    for (dx, wall), g in rows.groupby(["dx_um", "model"], sort=False):
        g = g.assign(J=g.pool_volume_change + 1.0).sort_values("J")
        ax.plot(
            g.J,
            g.tip_radial_stress_kPa,
            color=shades[dx],
            ls="-" if wall == "passive" else "--",
            lw=1.0,
            marker="o",
            ms=2.5,
            label=f"dx = {dx:g} um, {wall}",
        )
    ax.set_xscale("log")
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.axhline(0.0, color="0.7", lw=0.6)
    ax.set_xlabel("pool volume ratio J")
    return shades


# the paper's figure 4 in its text: "the radial stresses change from compressive to tensile, typically exceeding
# approximately 50 kPa for GAG concentration greater than 100 mEq/l" (the caption of figure 4)
PAPER_TIP = dict(stress_kPa=50.0, from_mEq_l=100.0)
PAPER_TIP_LABEL = "paper's text: tip radial stress\n> ~50 kPa above 100 mEq/l"
PAPER_TIP_STYLE = dict(color="#b2182b", lw=3.0, alpha=0.35, solid_capstyle="butt")


def paper_tip_mark(ax, max_concentration: float):
    """The paper's value on a tip radial stress panel of figure 4: a band at 50 kPa from 100 mEq/l to
    ``max_concentration`` (:data:`PAPER_TIP`, from the paper's caption of its figure 4)."""
    ax.plot([PAPER_TIP["from_mEq_l"], max_concentration], [PAPER_TIP["stress_kPa"]] * 2, **PAPER_TIP_STYLE)


def fig4(
    tips: pd.DataFrame,
    particles: pd.DataFrame,
    cases: dict,
    probe_length: float,
    law: str,
    max_concentration,
    pressures=(),
    *,
    pool_layers,
    band: pd.DataFrame | None = None,
    resolution: pd.DataFrame | None = None,
):
    """Figure 4 under one charge law (``law``, column ``charge_law``), laid out as the paper's: (a) the pools, a
    column per pool (case I-IV); then one block per pool model (column ``pool_model``, the paper's first) and wall
    (passive (b), active (c)): the tip radial stress (top row) and the top hoop stress (bottom row) against
    concentration (seaborn facets of tip_stress.csv, a colour per pressure). The tip radial stress panels mark the
    paper's "~50 kPa above 100 mEq/l" (:func:`paper_tip_mark`). A run's line ends at its last converged state (a
    cross if that is below ``max_concentration``). The colours are those of the pressures of the table and
    ``pressures`` together (figure 3's, so that a pressure has one colour in both figures). ``pool_layers``: the
    layers a pool's particles are in (``bilayer.pool_layers``).

    With the resolution study (``band``: gci_band.csv, ``resolution``: convergence.csv; target ``resolution``), the
    panels of its pools and walls draw its extrapolated curve and GCI band (:func:`band_panel`), and a last row
    plots the tip radial stress against the pool volume ratio at every spacing (:func:`volume_panel`); without it,
    the figure says so."""
    _style()
    names = sorted(cases, key=lambda k: cases[k]["angular_extent_deg"])
    tips = tips if "pool_model" in tips else tips.assign(pool_model=PAPER_POOL)
    tips = tips[tips.charge_law == law]
    pools = [pool for _, pool in variants(tips, [law])]
    models = [m for m in ("passive", "active") if m in set(tips.model)]
    levels = sorted(tips.pressure_mmHg.unique())
    colours = pressure_colours([*pressures, *levels])
    hues = {f"{p:g} mmHg": pressure_colour(colours, p) for p in levels}
    long = _tip_and_top(tips)
    blocks = [(pool, m) for pool in pools for m in models]
    panels = [(pool, m, q) for pool, m in blocks for q in (TIP, TOP)]
    rows = ["(a)", *("|".join(p) for p in panels), *(["volume"] if resolution is not None else [])]
    facets = dict(row="panel", col="case", row_order=rows, col_order=names, sharex=False, sharey="row")
    grid = sns.FacetGrid(long, **facets, height=1.9, aspect=2.5 / 1.9)
    grid.map_dataframe(swelling_lines, colours=hues, max_concentration=max_concentration)
    grid.set_titles("")
    grid.set_axis_labels(GAG_CONCENTRATION, "")
    for ax in grid.axes[1 : 1 + len(panels)].flat:  # one concentration axis: a run that ended early ends short
        ax.set_xlim(-0.04 * max_concentration, 1.04 * max_concentration)
    _block_headings(grid, blocks, panels, max_concentration)
    for ax, name in zip(grid.axes[0], names):
        pool_geometry_panel(
            ax,
            particles,
            cases[name],
            probe_length,
            f"(a) case {name}: {cases[name]['angular_extent_deg']:g} deg",
            pool_layers,
        )
    grid.axes[0, 0].set_ylabel("radius (um)")
    legend = dict(grid._legend_data)
    legend[PAPER_TIP_LABEL] = Line2D([], [], **PAPER_TIP_STYLE)
    _resolution_panels(grid, legend, panels, names, law, len(blocks), band, resolution)
    grid.add_legend(legend_data=legend, label_order=list(legend), fontsize=7)
    title = textwrap.fill(f"Figure 4: {law_title(law)}", 75)
    grid.tight_layout()
    fig = grid.figure
    fig.suptitle(title, x=0.01, y=1.0, ha="left", va="top", fontsize=10, fontweight="bold")
    fig.subplots_adjust(top=fig.subplotpars.top - (0.2 + 0.17 * title.count("\n")) / fig.get_figheight())
    return grid.figure


def _tip_and_top(tips: pd.DataFrame) -> pd.DataFrame:
    """Figure 4's measures of ``tips`` in long form, each row keyed by its panel (``panel``: the pool model, the wall
    and the stress); no peak of the intact wall."""
    long = long_measures(
        tips.assign(pressure=tips.pressure_mmHg.map("{:g} mmHg".format)),
        {c: POOL_MEASURES[c] for c in ("tip_radial_stress_kPa", "tip_peak_radial_stress_kPa", "top_circ_stress_kPa")},
        ["pool_model", "model", "case", "stage", "pressure", "concentration_mEq_l"],
    )
    long = long[(long.stage == "converted") | (long.statistic == "region mean")]
    return long.assign(panel=long.pool_model + "|" + long.model + "|" + long.quantity)


def _block_headings(grid, blocks, panels, max_concentration):
    """Figure 4's block letters and walls above their rows (as the paper's (b) and (c)), the paper's tip mark, the
    stresses' labels, and the concentration axis labelled below each block only (:func:`fig4`)."""
    for k, (pool, m) in enumerate(blocks):  # the block's letter and wall above its rows, as the paper's (b) and (c)
        top = 1 + 2 * k
        heading = f"({'bcdefghijklmnopqrstuvwxyz'[k]}) {m} model"
        heading += "" if pool == PAPER_POOL else f", pool as {pool}"
        grid.axes[top, 0].set_title(heading, loc="left", fontweight="bold")
        for ax in grid.axes[top]:
            paper_tip_mark(ax, max_concentration)
        grid.axes[top, 0].set_ylabel(TIP)
        grid.axes[top + 1, 0].set_ylabel(TOP)
    for ax in grid.axes[1 : 1 + len(panels) - 1].flat:  # the concentration axis is labelled below each block only
        ax.set_xlabel("")
    for k in range(len(blocks) - 1):
        for ax in grid.axes[1 + 2 * k + 1]:
            ax.set_xlabel(GAG_CONCENTRATION)


def _resolution_panels(grid, legend, panels, names, law, n_blocks, band, resolution):
    """Figure 4's resolution study (:func:`fig4`): the GCI band and extrapolated curve on its pools' panels, the last
    row of the tip radial stress at every spacing, and their legend entries (into ``legend``); or the note that it
    was not run."""
    if band is not None:
        converted = band[(band.stage == "converted") & (band.charge_law == law)]
        quantity = {TIP: "tip_radial_stress_kPa", TOP: "top_circ_stress_kPa"}
        for k, (pool, m, q) in enumerate(panels):
            for ax, name in zip(grid.axes[1 + k], names):
                rows_ = converted[
                    (converted.pool_model == pool)
                    & (converted.model == m)
                    & (converted.case == name)
                    & (converted.quantity == quantity[q])
                ]
                if len(rows_):
                    band_panel(ax, rows_)
        legend[BAND] = Patch(color="0.55", alpha=0.35, lw=0)
        legend[EXTRAPOLATED] = Line2D([], [], color="k", ls="--", lw=0.9)
        legend[NO_ORDER] = Line2D([], [], color="0.45", marker="x", ls="", lw=0.8)
    else:
        legend[NOT_RUN] = Line2D([], [], ls="")
    if resolution is not None:
        for ax, name in zip(grid.axes[-1], names):
            shades = volume_panel(ax, resolution, name, law)
        for dx, colour in shades.items():
            legend[f"resolution study: dx = {dx:g} um"] = Line2D([], [], color=colour, marker="o", ms=2.5, lw=1.0)
        grid.axes[-1, 0].set_ylabel(TIP)
        grid.axes[-1, 0].set_title(f"({'bcdefghijklmnopqrstuvwxyz'[n_blocks]}) every dx", loc="left")
        for wall, dashes in (("passive", "-"), ("active", "--")):
            legend[f"resolution study: {wall} (every dx)"] = Line2D([], [], color="0.3", ls=dashes, lw=1.0)


def swelling_convergence(table: pd.DataFrame, laws=None):
    """Resolution study (seaborn facets of convergence.csv): tip radial stress (mean over the probe, and particle
    peak), top hoop stress and pool volume change against concentration, a colour per particle spacing, a column
    per pool, wall, charge law and pool model (``laws``: their order; default: as in the table)."""
    _style()
    table = table if "pool_model" in table else table.assign(pool_model=PAPER_POOL)
    table = table if "model" in table else table.assign(model="passive")
    pairs = variants(table, laws or list(dict.fromkeys(table.charge_law)))
    spacings = sorted(table.dx_um.unique(), reverse=True)
    shades = dict(zip([f"{dx:g} um" for dx in spacings], plt.cm.viridis(np.linspace(0.1, 0.85, len(spacings)))))
    cases, walls = list(dict.fromkeys(table.case)), list(dict.fromkeys(table.model))
    column = {
        (law, pool, w, c): f"case {c}, {w}\n{variant_short(law, pool)}"
        for law, pool in pairs
        for w in walls
        for c in cases
    }
    long = long_measures(
        table.assign(
            dx=table.dx_um.map("{:g} um".format),
            facet=[column.get(key) for key in zip(table.charge_law, table.pool_model, table.model, table.case)],
        ),
        POOL_MEASURES,
        ["facet", "dx", "concentration_mEq_l"],
    )
    quantities = list(dict.fromkeys(q for q, _ in POOL_MEASURES.values()))
    grid = sns.relplot(
        long,
        kind="line",
        x="concentration_mEq_l",
        y="value",
        hue="dx",
        hue_order=list(shades),
        palette=shades,
        row="quantity",
        row_order=quantities,
        col="facet",
        col_order=list(column.values()),
        estimator=None,
        lw=1.0,
        height=7.0 / 3,
        aspect=3.4 / (7.0 / 3),
        facet_kws=dict(sharey=False, margin_titles=True),
        **STATISTIC_LINES,
    )
    grid.set_titles(row_template="", col_template="{col_name}")
    grid.set_axis_labels(GAG_CONCENTRATION, "")
    for ax, quantity in zip(grid.axes[:, 0], quantities):
        ax.set_ylabel(quantity)
    for ax in grid.axes[0]:
        ax.axhline(0.0, color="0.7", lw=0.6)
    grid.tight_layout()
    return grid.figure
