"""Figures of the paper, drawn from the pipeline's tidy tables (no simulation here)."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import seaborn as sns  # noqa: E402

from ..records.provenance import figure_metadata  # noqa: E402

HOMEOSTATIC_MMHG = 103.0
PRESSURE_COLOURS = {103.0: "#1b9e77", 145.0: "#d95f02", 200.0: "#7570b3"}


def _style():
    plt.rcParams.update(
        {
            "font.size": 9,
            "axes.labelsize": 9,
            "legend.fontsize": 8,
            "axes.spines.top": False,
            "axes.spines.right": False,
            "figure.dpi": 150,
            "savefig.bbox": "tight",
        }
    )


def pressure_colour(p):
    return PRESSURE_COLOURS.get(round(float(p), 6), None)


def palette(levels, colours: dict, label="{:g}".format) -> dict:
    """Seaborn palette of ``levels``: ``label(level)`` -> ``colours[level]`` where ``colours`` has the level, else
    the next unused colour of Dark2 (deterministic, in the order of ``levels``)."""
    spare = iter(c for c in sns.color_palette("Dark2").as_hex() if c not in colours.values())
    return {label(v): colours.get(v) or next(spare) for v in levels}


def long_measures(table: pd.DataFrame, measures: dict, id_vars) -> pd.DataFrame:
    """``table`` in long form: one row per value of a ``measures`` column (column -> (quantity, statistic)) that
    ``table`` has, with its ``quantity`` and ``statistic`` (the facets and line styles of a seaborn figure)."""
    long = table.melt(id_vars=id_vars, value_vars=[c for c in measures if c in table], var_name="column")
    long["quantity"] = long.column.map(lambda c: measures[c][0])
    long["statistic"] = long.column.map(lambda c: measures[c][1])
    return long


def style_legend(ax, loc="best", fontsize=7, **kws):
    """The seaborn legend of ``ax`` without a frame, in small type."""
    sns.move_legend(ax, loc, frameon=False, fontsize=fontsize, **kws)


# the Donnan laws of the pools (sphgag.physics.materials.CHARGE_LAWS, column charge_law of every pool table), as the
# figures name them: the prescribed law is the paper's model, the one to compare with the paper's panels
LAW_TITLES = {
    "prescribed": "prescribed charge law: Pi(c), eqs. 2.25-2.27 as printed (the paper's model: compare with the paper)",
    "conserved": "conserved charge law: Pi at the current concentration c/J (mixture theory; a deviation)",
}
LAW_SHORT = {"prescribed": "prescribed Pi(c), paper", "conserved": "conserved charge, c/J"}


def law_title(law: str) -> str:
    return LAW_TITLES.get(law, f"{law} charge law")


# the pool models of the swelling runs (sphgag.studies.protocols.POOL_MODELS, column pool_model of the pool tables):
# ``particles`` is the paper's; the others are named beside their law in the figures
PAPER_POOL = "particles"
POOL_TITLES = {
    "cavity": "the pool as a pressurised cavity (our deviation: its lining carries Pi, its contents swell uniformly)"
}


def variants(table: pd.DataFrame, laws) -> list[tuple[str, str]]:
    """The (charge law, pool model) pairs of ``table`` in the order of ``laws``, the paper's pool model first (a table
    without a column ``pool_model`` has the paper's only)."""
    pools = list(dict.fromkeys(table.pool_model)) if "pool_model" in table else [PAPER_POOL]
    pools = sorted(pools, key=lambda m: m != PAPER_POOL)
    have = set(zip(table.charge_law, table.pool_model if "pool_model" in table else [PAPER_POOL] * len(table)))
    return [(law, m) for law in laws for m in pools if (law, m) in have]


def paper_pool(table: pd.DataFrame) -> pd.DataFrame:
    """The rows of the paper's pool model (all rows of a table without a column ``pool_model``)."""
    return table[table.pool_model == PAPER_POOL] if "pool_model" in table else table


def variant_title(law: str, pool: str) -> str:
    """The heading of one (charge law, pool model) pair."""
    if pool == PAPER_POOL:
        return law_title(law)
    return f"{LAW_SHORT.get(law, law)}; {POOL_TITLES.get(pool, pool)}"


def variant_short(law: str, pool: str) -> str:
    """The label of one (charge law, pool model) pair: the law's, or, for another pool model, both names."""
    return LAW_SHORT.get(law, law) if pool == PAPER_POOL else f"{law} law, pool as {pool}"


def law_blocks(laws, heights, width: float = 11.0):
    """A figure with one titled block (a sub-figure, constrained layout) per charge law, stacked in the order of
    ``laws`` (``heights`` in inches); returns the figure and the blocks."""
    fig = plt.figure(figsize=(width, sum(heights) + 0.5), layout="constrained")
    blocks = fig.subfigures(len(laws), 1, height_ratios=list(heights), squeeze=False)[:, 0]
    for block, law in zip(blocks, laws):
        block.suptitle(law_title(law), x=0.01, ha="left", fontsize=10, fontweight="bold")
    return fig, list(blocks)


def save(fig, paths, description: str):
    """Save ``fig`` to every path (format from the suffix) with provenance metadata."""
    for path in paths:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        meta = figure_metadata(description)
        if str(path).endswith(".png"):
            meta = {"Title": meta["Title"], "Software": meta["Creator"]}
        elif str(path).endswith(".pdf"):
            meta["CreationDate"] = None  # no timestamp: the same tables give the same bytes
        fig.savefig(path, metadata=meta)
    plt.close(fig)


def pressure_diameter_panels(
    ax_pd,
    ax_ss,
    states: pd.DataFrame,
    exact: pd.DataFrame,
    label="SPH",
    colour="k",
    marker="o",
    exact_label="exact thick wall",
):
    """Pressure-outer diameter and mean circumferential stress-stretch (figure 3a), one model."""
    ax_pd.plot(exact.outer_diameter_um, exact.pressure_mmHg, "-", color=colour, lw=1.2, label=exact_label)
    ax_pd.plot(states.outer_diameter_um, states.pressure_mmHg, marker, mfc="none", color=colour, ms=4, label=label)
    ax_ss.plot(exact.mean_circ_stretch, exact.mean_circ_stress_kPa, "-", color=colour, lw=1.2, label=exact_label)
    ax_ss.plot(
        states.mean_circ_stretch, states.mean_circ_stress_kPa, marker, mfc="none", color=colour, ms=4, label=label
    )


def mark_homeostasis(ax_pd, ax_ss, exact: pd.DataFrame):
    """Horizontal and vertical lines at the homeostatic pressure (figure 3a)."""
    row = exact.iloc[(exact.pressure_mmHg - HOMEOSTATIC_MMHG).abs().argmin()]
    for ax, x, y in (
        (ax_pd, row.outer_diameter_um, HOMEOSTATIC_MMHG),
        (ax_ss, row.mean_circ_stretch, row.mean_circ_stress_kPa),
    ):
        ax.axhline(y, color="0.6", lw=0.6, ls=":")
        ax.axvline(x, color="0.6", lw=0.6, ls=":")


def fig3a_mean(states: pd.DataFrame, exact: pd.DataFrame, max_error: float):
    """Figure 3a for the mean-behaviour model: SPH points over the exact curves."""
    _style()
    fig, (ax_pd, ax_ss) = plt.subplots(2, 1, figsize=(3.4, 5.6))
    pressure_diameter_panels(ax_pd, ax_ss, states, exact)
    mark_homeostasis(ax_pd, ax_ss, exact)
    ax_pd.set(xlabel="outer diameter (um)", ylabel="pressure (mmHg)", title="mean-behaviour model")
    ax_ss.set(xlabel="mean circumferential stretch (eq. 2.17)", ylabel="mean circumferential stress (kPa)")
    ax_pd.legend(loc="upper left", frameon=False)
    ax_pd.text(
        0.98,
        0.04,
        f"max |OD error| (10-200 mmHg)\n= {100 * max_error:.2f} %",
        transform=ax_pd.transAxes,
        ha="right",
        va="bottom",
        fontsize=7,
    )
    fig.tight_layout()
    return fig


def transmural_panels(ax_r, ax_t, profiles: pd.DataFrame, model: str, border_um=None):
    """Radial (top) and circumferential (bottom) Cauchy stress across the wall, one line per pressure."""
    data = profiles[profiles.model == model]
    for P, grp in data.groupby("pressure_mmHg"):
        c = pressure_colour(P)
        ex = grp[grp.source == "exact"]
        sph = grp[grp.source == "sph"]
        if len(ex):
            ax_r.plot(ex.radius_um, ex.radial_stress_kPa, "-", color=c, lw=1.1)
            ax_t.plot(ex.radius_um, ex.circ_stress_kPa, "-", color=c, lw=1.1)
        ax_r.plot(sph.radius_um, sph.radial_stress_kPa, "o", mfc="none", color=c, ms=3.5, label=f"{P:g} mmHg")
        ax_t.plot(sph.radius_um, sph.circ_stress_kPa, "o", mfc="none", color=c, ms=3.5)
    if border_um is not None:
        for ax in (ax_r, ax_t):
            ax.axvline(border_um, color="0.4", ls="--", lw=0.8)
    ax_r.set(ylabel="radial stress (kPa)")
    ax_t.set(xlabel="current radius (um)", ylabel="circumferential stress (kPa)")


def fig3b(profiles: pd.DataFrame):
    """Figure 3b: transmural stresses of the mean-behaviour model with the exact thick-wall profiles."""
    _style()
    fig, (ax_r, ax_t) = plt.subplots(2, 1, figsize=(3.4, 5.6), sharex=True)
    transmural_panels(ax_r, ax_t, profiles, "mean")
    ax_r.set_title("mean-behaviour model")
    handles, labels = ax_r.get_legend_handles_labels()
    handles.append(plt.Line2D([], [], color="k", lw=1.1))
    labels.append("exact thick wall")
    handles.append(plt.Line2D([], [], color="k", marker="o", mfc="none", ls="none", ms=3.5))
    labels.append("SPH (ring means)")
    ax_r.legend(handles, labels, frameon=False, loc="lower right")
    fig.tight_layout()
    return fig


def finite_or_raise(df: pd.DataFrame, columns, what: str):
    """Refuse to draw a figure from non-finite data."""
    bad = [c for c in columns if not np.isfinite(df[c].to_numpy(dtype=float)).all()]
    if bad:
        raise ValueError(f"{what}: non-finite values in {bad}; refusing to draw a figure from them")


MODEL_STYLE = {"passive": dict(color="k", marker="o", ls="-"), "active": dict(color="0.55", marker="^", ls="--")}
LAYER_COLOURS = {"media": "#3b6fb6", "adventitia": "#2e9e5b", "GAG": "#d1352b"}


def bilayer_pressure_diameter_panels(ax_pd, ax_ss, table: pd.DataFrame, exact: dict):
    """Figure 3a for the bi-layered model: passive and active, SPH points over the semi-analytical curves."""
    for model in ("passive", "active"):
        st = MODEL_STYLE[model]
        pressure_diameter_panels(
            ax_pd,
            ax_ss,
            table[table.model == model],
            exact[model],
            label=f"SPH {model}",
            colour=st["color"],
            marker=st["marker"],
            exact_label=f"semi-analytical {model}",
        )


def normalised_position(radius, profile):
    """(r - r_in) / (r_out - r_in) of a radius within a profile's wall."""
    r = profile.radius_um
    return (radius - r.min()) / (r.max() - r.min())


def bilayer_transmural_panels(ax_r, ax_t, profiles: pd.DataFrame):
    """Figure 3c: passive (solid) and active (dashed) transmural stresses against the normalised wall position."""
    borders = []
    for model in ("passive", "active"):
        st = MODEL_STYLE[model]
        data = profiles[profiles.model == model]
        for P, grp in data.groupby("pressure_mmHg"):
            c = pressure_colour(P)
            ex, sph = grp[grp.source == "exact"], grp[grp.source == "sph"]
            xe, xs = normalised_position(ex.radius_um, ex), normalised_position(sph.radius_um, ex)
            ax_r.plot(xe, ex.radial_stress_kPa, ls=st["ls"], color=c, lw=1.0)
            ax_t.plot(xe, ex.circ_stress_kPa, ls=st["ls"], color=c, lw=1.0)
            ax_r.plot(xs, sph.radial_stress_kPa, st["marker"], mfc="none", color=c, ms=3.2)
            ax_t.plot(xs, sph.circ_stress_kPa, st["marker"], mfc="none", color=c, ms=3.2)
            media = ex[ex.layer == "media"]
            borders.append(float(normalised_position(media.radius_um.max(), ex)))
    for ax in (ax_r, ax_t):
        ax.axvline(np.mean(borders), color="0.3", ls=":", lw=0.9)
    ax_t.text(np.mean(borders), 0.97, " adventitia", transform=ax_t.get_xaxis_transform(), fontsize=7, va="top")
    ax_t.text(np.mean(borders), 0.97, "media ", transform=ax_t.get_xaxis_transform(), fontsize=7, va="top", ha="right")
    ax_r.set(ylabel="radial stress (kPa)")
    ax_t.set(xlabel="normalised wall position (r - r_in)/(r_out - r_in)", ylabel="circumferential stress (kPa)")


def fig3(mean_states, mean_exact, bilayer, bilayer_exact: dict, profiles: pd.DataFrame):
    """Figure 3, complete: (a) pressure-diameter and stress-stretch of the mean, passive and active models;
    (b) transmural stresses of the mean model; (c) of the bi-layered passive and active models."""
    _style()
    fig, axes = plt.subplots(2, 4, figsize=(13.5, 6.2))
    pressure_diameter_panels(axes[0, 0], axes[1, 0], mean_states, mean_exact)
    mark_homeostasis(axes[0, 0], axes[1, 0], mean_exact)
    bilayer_pressure_diameter_panels(axes[0, 1], axes[1, 1], bilayer, bilayer_exact)
    mark_homeostasis(axes[0, 1], axes[1, 1], bilayer_exact["passive"])
    for ax in axes[0, :2]:
        ax.set(xlabel="outer diameter (um)", ylabel="pressure (mmHg)")
        ax.legend(frameon=False, loc="upper left", fontsize=7)
    for ax in axes[1, :2]:
        ax.set(xlabel="mean circumferential stretch (eq. 2.17)", ylabel="mean circumferential stress (kPa)")
    axes[0, 0].set_title("(a) mean-behaviour model")
    axes[0, 1].set_title("(a) bi-layered model")
    transmural_panels(axes[0, 2], axes[1, 2], profiles, "mean")
    axes[0, 2].set_title("(b) mean-behaviour model")
    bilayer_transmural_panels(axes[0, 3], axes[1, 3], profiles)
    axes[0, 3].set_title("(c) bi-layered model")
    handles = [plt.Line2D([], [], color=pressure_colour(P), lw=1.2, label=f"{P:g} mmHg") for P in PRESSURE_COLOURS]
    handles += [
        plt.Line2D([], [], color="k", marker="o", mfc="none", ls="-", label="passive / mean: SPH, exact"),
        plt.Line2D([], [], color="k", marker="^", mfc="none", ls="--", label="active: SPH, exact"),
    ]
    axes[1, 3].legend(handles=handles, frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(0.0, 0.9))
    fig.tight_layout()
    return fig


def fig1(particles: pd.DataFrame, mass_fractions: dict, support_factor: float, dx: float):
    """Figure 1: (a) the particles of the bi-layered quarter annulus by layer, (b) the spiky kernel and its
    derivative over the support, (c) the constituent mass fractions of each layer."""
    from ..engine.kernel import spiky, spiky_derivative

    _style()
    fig = plt.figure(figsize=(11, 3.8))
    gs = fig.add_gridspec(1, 4, width_ratios=[1.3, 1.1, 1.0, 0.8])
    ax = fig.add_subplot(gs[0])
    for layer, g in particles.groupby("layer"):
        ax.scatter(g.x_um, g.y_um, s=1.2, color=LAYER_COLOURS.get(layer, "k"), label=f"{layer} ({len(g)})")
    ax.set_aspect("equal")
    ax.set(xlabel="x (um)", ylabel="y (um)", title=f"(a) {len(particles)} particles, dx = {dx:g} um")
    ax.legend(frameon=False, markerscale=6, loc="lower left")
    zoom = fig.add_subplot(gs[1])
    sector = particles[np.abs(np.rad2deg(particles.theta_rad) - 45.0) < 3.0]
    for layer, g in sector.groupby("layer"):
        zoom.scatter(g.x_um, g.y_um, s=g.volume_um2 * 0.6, color=LAYER_COLOURS.get(layer, "k"))
    zoom.set_aspect("equal")
    zoom.set(xlabel="x (um)", title="(a) 6 deg sector\n(symbol area ~ volume)")
    axk = fig.add_subplot(gs[2])
    h = support_factor * dx
    r = np.linspace(0.0, h * 1.05, 300)
    axk.plot(r / dx, [spiky(v, h) * h * h for v in r], "k-", label="xi h^2")
    axk.plot(r / dx, [spiky_derivative(v, h) * h**3 for v in r], "k--", label="d xi/dR h^3")
    for k in range(1, int(support_factor) + 1):
        axk.axvline(k, color="0.7", lw=0.6)
    axk.axvline(support_factor, color="r", lw=0.8)
    axk.set(xlabel="R / dx", title=f"(b) spiky kernel, h = {support_factor:g} dx")
    axk.legend(frameon=False)
    axc = fig.add_subplot(gs[3])
    bottom = np.zeros(2)
    colours = {"elastin": "#8c6d31", "smc": "#e7969c", "collagen": "#6b6ecf"}
    for constituent in ("elastin", "smc", "collagen"):
        vals = np.array([mass_fractions[l].get(constituent, 0.0) for l in ("media", "adventitia")])
        axc.bar(["media", "adventitia"], vals, bottom=bottom, color=colours[constituent], label=constituent)
        bottom += vals
    axc.set(ylabel="mass fraction", title="(c) composition")
    axc.legend(frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    return fig


def pool_geometry_panel(ax, particles: pd.DataFrame, case: dict, probe_length: float, title: str):
    """Figure 4a: the pool (red), the media and adventitia around it, and the probe regions (outlines)."""
    from ..engine.measure import pool_probes
    from ..studies.artery import pool_sector

    pool = pool_sector(case)
    th0 = np.deg2rad(pool.centre_angle_deg)
    half = 0.5 * np.deg2rad(max(pool.angular_extent_deg, 3.0)) + 25.0 / pool.centre_radius
    near = particles[np.abs(particles.theta_rad - th0) < half]
    arc = (near.theta_rad - th0) * pool.centre_radius
    in_pool = pool.contains(near.radius_um, near.theta_rad) & (near.layer == "media")
    colours = np.where(in_pool, LAYER_COLOURS["GAG"], near.layer.map(LAYER_COLOURS).fillna("k"))
    ax.scatter(arc, near.radius_um, s=6, c=colours, linewidths=0)
    for name, box in pool_probes(pool, probe_length).items():
        (r0, r1), (t0, t1) = box.r_range, box.theta_range
        a0, a1 = (t0 - th0) * pool.centre_radius, (t1 - th0) * pool.centre_radius
        ax.plot([a0, a1, a1, a0, a0], [r0, r0, r1, r1, r0], lw=0.7, color="k" if name.startswith("tip") else "0.45")
    ax.set(title=title, xlabel="arc from pool centre (um)")
    ax.set_aspect("equal")


GAG_CONCENTRATION = "GAG concentration (mEq/l)"
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


LAST_CONVERGED = "last converged state (run stopped)"


def fig4(tips: pd.DataFrame, particles: pd.DataFrame, cases: dict, probe_length: float, laws, max_concentration):
    """Figure 4: (a) the pools; then for each charge law (``laws``, column ``charge_law``) and pool model (column
    ``pool_model``, the paper's first) the passive and active tip radial and top hoop stress vs concentration
    (seaborn facets of tip_stress.csv: a row per law, pool model, model and stress, a column per pool, a colour per
    pressure). A run's line ends at its last converged state (a cross if that is below ``max_concentration``)."""
    _style()
    names = sorted(cases, key=lambda k: cases[k]["angular_extent_deg"])
    tips = tips if "pool_model" in tips else tips.assign(pool_model=PAPER_POOL)
    pairs = variants(tips, laws)
    models = [m for m in ("passive", "active") if m in set(tips.model)]
    pressures = palette(sorted(tips.pressure_mmHg.unique()), PRESSURE_COLOURS, "{:g} mmHg".format)
    long = long_measures(
        tips.assign(pressure=tips.pressure_mmHg.map("{:g} mmHg".format)),
        {c: POOL_MEASURES[c] for c in ("tip_radial_stress_kPa", "tip_peak_radial_stress_kPa", "top_circ_stress_kPa")},
        ["charge_law", "pool_model", "model", "case", "stage", "pressure", "concentration_mEq_l"],
    )
    long = long[(long.stage == "converted") | (long.statistic == "region mean")]  # no peak of the intact wall
    blocks = [(law, pool, m) for law, pool in pairs for m in models]
    letters = {block: "bcdefghijklmnopqrstuvwxyz"[k] for k, block in enumerate(blocks)}

    def label(block, q):
        law, pool, m = block
        return f"({letters[block]}) {m}, {variant_short(law, pool)}\n{q}"

    long["panel"] = [
        label((law, pool, m), q) for law, pool, m, q in zip(long.charge_law, long.pool_model, long.model, long.quantity)
    ]
    panels = [label(b, q) for b in blocks for q in (TIP, TOP)]
    grid = sns.FacetGrid(
        long,
        row="panel",
        col="case",
        row_order=["(a)"] + panels,
        col_order=names,
        sharex=False,
        sharey="row",
        height=2.1,
        aspect=3.0 / 2.1,
    )
    grid.map_dataframe(swelling_lines, colours=pressures, max_concentration=max_concentration)
    grid.add_legend()
    grid.set_titles("")
    grid.set_axis_labels(GAG_CONCENTRATION, "")
    for ax, panel in zip(grid.axes[1:, 0], panels):
        ax.set_ylabel(panel)
    for ax in grid.axes[1:].flat:  # one concentration axis: a run that ended early ends short of the others
        ax.set_xlim(-0.04 * max_concentration, 1.04 * max_concentration)
    for k, (law, pool) in enumerate(pairs):  # a heading above each law's (and pool model's) rows
        grid.axes[1 + 2 * len(models) * k, 0].set_title(
            variant_title(law, pool), loc="left", fontweight="bold", fontsize=9
        )
    for ax, name in zip(grid.axes[0], names):
        pool_geometry_panel(
            ax, particles, cases[name], probe_length, f"(a) case {name}: {cases[name]['angular_extent_deg']:g} deg"
        )
    grid.axes[0, 0].set_ylabel("radius (um)")
    grid.tight_layout()
    return grid.figure


RATIO_COLOURS = {1.0: "#1b9e77", 2.0: "#d95f02", 3.0: "#7570b3"}


def verification_pool(table: pd.DataFrame, profiles: pd.DataFrame):
    """The pool verification: (a) Lamé field of the circle, (b) hoop stress ahead of the tip against Inglis,
    (c) tip error and (d) traction jump and field error against resolution (log-log, observed order)."""
    from ..studies.inclusion import TIP_PARTICLES, observed_order

    _style()
    fig, axes = plt.subplots(1, 4, figsize=(16.0, 3.1))
    Pi = float(table.pressure_kPa.iloc[0])
    colour = lambda r: RATIO_COLOURS.get(float(r), "k")  # noqa: E731
    ax = axes[0]
    rings = profiles[profiles.profile == "rings"]
    if len(rings):
        b = float(table[table.aspect_ratio == 1.0].semi_axis_b_um.iloc[0])
        for k, (res, g) in enumerate(sorted(rings.groupby("b_over_dx"), key=lambda t: t[0])[-2:]):
            mk = "os"[k]
            ax.plot(
                g.radius_um / b, g.radial_sph_kPa / Pi, mk, ms=3, mfc="none", color="C0", label=f"SPH b/dx = {res:g}"
            )
            ax.plot(g.radius_um / b, g.circ_sph_kPa / Pi, mk, ms=3, mfc="none", color="C3")
        g = rings[rings.b_over_dx == rings.b_over_dx.max()].sort_values("radius_um")
        ax.plot(g.radius_um / b, g.radial_exact_kPa / Pi, "-", color="C0", lw=1, label=r"Lamé $\sigma_{rr}$")
        ax.plot(g.radius_um / b, g.circ_exact_kPa / Pi, "-", color="C3", lw=1, label=r"Lamé $\sigma_{\theta\theta}$")
        ax.axvline(1.0, color="0.7", lw=0.6)
    ax.set(xlabel="r / R", ylabel="stress / Pi", title="(a) circular inclusion: ring means")
    ax.legend(frameon=False, fontsize=6.5)
    ax = axes[1]
    for ratio, g in table.groupby("aspect_ratio"):
        finest = g.b_over_dx.max()
        p = profiles[(profiles.profile == "axis") & (profiles.aspect_ratio == ratio) & (profiles.b_over_dx == finest)]
        b = float(g.semi_axis_b_um.iloc[0])
        ax.plot(p.s_um / b, p.hoop_exact_kPa / Pi, "-", color=colour(ratio), lw=1)
        ax.plot(
            p.s_um / b,
            p.hoop_sph_kPa / Pi,
            "o",
            ms=2.5,
            mfc="none",
            color=colour(ratio),
            label=f"a/b = {ratio:g} (b/dx = {finest:g})",
        )
        row = g[g.b_over_dx == finest].iloc[0]
        ax.plot([0], [row.tip_stress_kPa / Pi], "*", ms=8, color=colour(ratio))
        ax.plot([0], [row.reference_kPa / Pi], "_", ms=14, mew=1.5, color="k")
    ax.set(
        xlim=(0, None),
        xlabel="distance ahead of the tip / b",
        ylabel="hoop stress / Pi",
        title="(b) ahead of the tip: SPH (o), Inglis (-)",
    )
    ax.text(
        0.98,
        0.97,
        f"* fit of the first {TIP_PARTICLES} particles\n- Inglis Pi (2a/b - 1)",
        transform=ax.transAxes,
        ha="right",
        va="top",
        fontsize=6.5,
    )
    ax.legend(frameon=False, fontsize=6.5, loc="center right")
    ratios = sorted(table.aspect_ratio.unique())
    errors = table.assign(
        tip=table.rel_error.abs(),
        first=table.first_particle_rel_error.abs(),
        field=table.field_rms_error_kPa / Pi,
        jump=np.maximum(table.traction_jump_kPa / Pi, 1e-4),
    )
    orders = {r: observed_order(g.dx_um, g.rel_error) for r, g in table.groupby("aspect_ratio")}
    resolution_panel(
        axes[2],
        errors,
        {"tip": ("tip stress", "o", ""), "first": ("first particle", "X", (1, 1.65))},
        palette(ratios, RATIO_COLOURS, lambda r: f"a/b = {r:g}: order {orders[r]:.2f}"),
    )
    axes[2].axhline(0.05, color="0.6", lw=0.6, ls="--")
    axes[2].set(ylabel="|relative error|", title="(c) tip stress and first particle")
    resolution_panel(
        axes[3],
        errors,
        {"field": ("field rms error", "o", ""), "jump": ("traction jump", "s", (3.7, 1.6))},
        palette(ratios, RATIO_COLOURS, "a/b = {:g}".format),
    )
    axes[3].set(ylabel="/ Pi", title="(d) field rms error, traction jump")
    fig.tight_layout()
    return fig


def resolution_panel(ax, errors: pd.DataFrame, measures: dict, ratios: dict):
    """Errors of the pool verification against dx / b, log-log (seaborn): a colour per aspect ratio (``ratios``:
    legend label -> colour, in the order of the sorted ratios), a marker and line style per ``measures`` column
    (column -> (name, marker, dashes)); the legend beside the axes."""
    labels = dict(zip(sorted(errors.aspect_ratio.unique()), ratios))
    long = errors.assign(dx_over_b=errors.dx_um / errors.semi_axis_b_um, ratio=errors.aspect_ratio.map(labels))
    long = long.melt(id_vars=["ratio", "dx_over_b"], value_vars=list(measures), var_name="measure")
    long["measure"] = long.measure.map(lambda c: measures[c][0])
    sns.lineplot(
        long,
        x="dx_over_b",
        y="value",
        hue="ratio",
        hue_order=list(ratios),
        palette=ratios,
        style="measure",
        style_order=[name for name, _, _ in measures.values()],
        markers={name: marker for name, marker, _ in measures.values()},
        dashes={name: dashes for name, _, dashes in measures.values()},
        estimator=None,
        lw=1.0,
        markersize=4,
        ax=ax,
    )
    ax.set(xscale="log", yscale="log", xlabel="dx / b")
    style_legend(ax, "upper left", fontsize=6.5, bbox_to_anchor=(1.0, 1.0))


def verification_circular_pool(table: pd.DataFrame):
    """The circular pool at large strain (circular_pool.csv): |relative error| of (a) the pool's volume ratio and
    (b) its lining's radius against dx, log-log; a colour per volume ratio, a line style per pool model, the
    observed order of each line in the legend."""
    from ..studies.inclusion import observed_order

    _style()
    fig, axes = plt.subplots(1, 2, figsize=(11.0, 3.2))
    ratios = sorted(table.target_volume_ratio.unique())
    colours = dict(zip(ratios, sns.color_palette("Dark2", len(ratios)).as_hex()))
    styles = dict(zip(sorted(table.pool_model.unique()), ["-", "--", ":", "-."]))
    for ax, column, title in (
        (axes[0], "volume_error", "(a) pool volume ratio"),
        (axes[1], "lining_error", "(b) radius of the lining"),
    ):
        for (model, ratio), g in table.groupby(["pool_model", "target_volume_ratio"]):
            g = g.sort_values("dx_um")
            order = observed_order(g.dx_um, g[column])
            ax.loglog(
                g.dx_um,
                np.maximum(g[column].abs(), 1e-5),
                styles[model],
                marker="o",
                ms=3.5,
                color=colours[ratio],
                label=f"{model}, J = {ratio:g}: order {order:.2f}",
            )
        ax.axhline(0.02, color="0.6", lw=0.6, ls="--")
        ax.set(xlabel="dx (um)", ylabel="|relative error|", title=title)
        ax.set_xticks(sorted(table.dx_um.unique()), [f"{d:g}" for d in sorted(table.dx_um.unique())])
        ax.minorticks_off()
    axes[1].legend(frameon=False, fontsize=6.5, loc="upper left", bbox_to_anchor=(1.02, 1.0))
    ended = table[table.volume_error.isna()].groupby(["pool_model", "dx_um"]).target_volume_ratio.min()
    if len(ended):
        paths = "; ".join(f"{m}, dx = {d:g} um, from J = {j:g}" for (m, d), j in ended.items())
        text = f"no equilibrium (the path ended): {paths}"
        fig.text(0.01, 0.01, text, fontsize=6.5, va="bottom")
    fig.tight_layout(rect=(0, 0.05 if len(ended) else 0, 1, 1))
    return fig


def verification_crack(table: pd.DataFrame, modulus: float, fracture_energy_J_m2: float, critical_stress: float):
    """The pressurised crack (pressurised_crack.csv): (a) the pressure at which it grows against Griffith's (and
    Dugdale's, for the cohesive length), a marker per spacing; (b) the opening area before growth against Sneddon's;
    (c) the three relative errors against dx, log-log, a colour per half-length."""
    from ..physics import fracture

    _style()
    fig, axes = plt.subplots(1, 3, figsize=(11.5, 3.5), layout="constrained")
    spacings = sorted(table.dx_um.unique(), reverse=True)
    colours = dict(zip(spacings, sns.color_palette("viridis", len(spacings))))
    gc = fracture_energy_J_m2 * fracture.J_M2
    a = np.linspace(0.8 * table.half_length_um.min(), 1.2 * table.half_length_um.max(), 200)
    ax = axes[0]
    ax.plot(a, fracture.griffith_pressure(a, gc, modulus), "k-", lw=1.2, label="Griffith")
    ax.plot(a, fracture.dugdale_pressure(a, gc, modulus, critical_stress), "k:", lw=1.0, label="Dugdale")
    for dx in spacings:
        t = table[table.dx_um == dx]
        ax.plot(t.half_length_um, t.critical_pressure_kPa, "o", color=colours[dx], ms=5, label=f"SPH, dx = {dx:g} um")
    ax.set(xlabel="crack half-length a [um]", ylabel="face pressure at growth [kPa]", title="(a) onset of growth")
    ax.legend(frameon=False, fontsize=6.5)
    ax = axes[1]
    ax.plot(a, fracture.opening_area(a, 1.0, modulus), "k-", lw=1.2, label="Sneddon")
    for dx in spacings:
        t = table[table.dx_um == dx]
        ax.plot(
            t.half_length_um, t.opening_area_um2 / t.pressure_kPa, "o", color=colours[dx], ms=5, label=f"dx = {dx:g} um"
        )
    ax.set(
        xlabel="crack half-length a [um]",
        ylabel="opening area / pressure [um^2/kPa]",
        title="(b) opening before growth",
    )
    ax.legend(frameon=False, fontsize=6.5)
    ax = axes[2]
    lengths = sorted(table.nominal_half_length_um.unique())  # a on the grid differs by up to dx / 2
    hue = dict(zip(lengths, sns.color_palette("rocket", len(lengths))))
    for measure, marker, name in (
        ("rel_error", "o", "onset vs Griffith"),
        ("area_rel_error", "s", "area vs Sneddon"),
        ("energy_rel_error", "^", "energy vs G_c"),
    ):
        for length in lengths:
            t = table[table.nominal_half_length_um == length].sort_values("dx_um")
            ax.plot(
                t.dx_um,
                t[measure].abs(),
                marker=marker,
                color=hue[length],
                lw=0.8,
                ms=4,
                label=f"{name}, a = {length:g} um",
            )
    ax.axhline(0.1, color="0.5", lw=0.6, ls="--")
    ax.axhline(0.05, color="0.5", lw=0.6, ls=":")
    ax.set(
        xscale="log", yscale="log", xlabel="dx [um]", ylabel="|relative error|", title="(c) errors against resolution"
    )
    ax.legend(frameon=False, fontsize=5.5, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    return fig


def swelling_convergence(table: pd.DataFrame, laws=None):
    """Resolution study (seaborn facets of convergence.csv): tip radial stress (mean over the probe, and particle
    peak), top hoop stress and pool volume change against concentration, a colour per particle spacing, a column
    per pool, charge law and pool model (``laws``: their order; default: as in the table)."""
    _style()
    table = table if "pool_model" in table else table.assign(pool_model=PAPER_POOL)
    pairs = variants(table, laws or list(dict.fromkeys(table.charge_law)))
    spacings = sorted(table.dx_um.unique(), reverse=True)
    shades = dict(zip([f"{dx:g} um" for dx in spacings], plt.cm.viridis(np.linspace(0.1, 0.85, len(spacings)))))
    cases = list(dict.fromkeys(table.case))
    column = {(law, pool, c): f"case {c}\n{variant_short(law, pool)}" for law, pool in pairs for c in cases}
    long = long_measures(
        table.assign(
            dx=table.dx_um.map("{:g} um".format),
            facet=[column.get(key) for key in zip(table.charge_law, table.pool_model, table.case)],
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


# --- delamination (figures 5-7) ---------------------------------------------------------------------------------------

SEEDED, CONVERTED = 1, 2  # history origin codes (sphgag.engine.history): a seeded GAG pool, tissue converted by damage
MATERIAL_COLOURS = {"media": "0.84", "adventitia": "0.62", SEEDED: LAYER_COLOURS["GAG"], CONVERTED: "#2166ac"}
DAMAGE_CMAP = matplotlib.colors.LinearSegmentedColormap.from_list("damage", ["#ffd300", "#f47b20", "#7f2704"])
SIDE_COLOURS = {"interior": "#1b9e77", "exterior": "#7570b3"}
CRITERION_DASHES = ("", (3.7, 1.6))  # the default onset criterion (solid), the other one (dashed)
CRITERION_COLOURS = ("k", "#d95f02")
PSEUDO_TIME = "pseudo-time (concentration levels + damage passes)"


def criterion_lines(ax, data, criteria, **spec):
    """One line per run of ``data`` (seaborn's ``spec``: x, y, hue, palette), styled by its onset criterion: the
    default solid, the other dashed."""
    sns.lineplot(
        data,
        style="criterion",
        style_order=list(criteria),
        dashes=dict(zip(criteria, CRITERION_DASHES)),
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


def snapshot_panel(ax, snap: dict, k: int, window, radii, media_outer_um: float, label: str):
    """Snapshot ``k`` of a run: the particles of the angular ``window`` at their current angle and radius (axis
    limits ``window`` x ``radii``), true to scale at the pools' radius; intact tissue grey (media light, adventitia
    dark), damaged tissue by D, seeded GAG red, GAG converted by damage blue. Marker sizes are set by
    :func:`fit_particle_sizes` after the layout."""
    near = in_window(snap, window)
    origin, D = snap[f"s{k}_history_origin"][near], snap[f"s{k}_history_D"][near]
    th, r = current_polar(snap, k, near)
    media = np.hypot(*snap["X"][near].T) <= media_outer_um
    colours = matplotlib.colors.to_rgba_array(
        np.where(media, MATERIAL_COLOURS["media"], MATERIAL_COLOURS["adventitia"])
    )
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


def material_key(fig):
    """The legend of the snapshot panels' colours, above the figure."""
    key = {
        "media": "intact media",
        "adventitia": "intact adventitia",
        SEEDED: "seeded GAG pool",
        CONVERTED: "GAG converted by damage",
    }
    handles = [
        plt.Line2D([], [], marker="s", ls="none", ms=7, color=MATERIAL_COLOURS[m], label=text)
        for m, text in key.items()
    ]
    fig.legend(handles=handles, loc="outside upper center", ncols=4, frameon=False)


def damage_colourbar(fig, cax):
    """The colour bar of the damage of the snapshot panels, in ``cax``."""
    bar = fig.colorbar(matplotlib.cm.ScalarMappable(matplotlib.colors.Normalize(0.0, 1.0), DAMAGE_CMAP), cax=cax)
    bar.set_label("damage D of tissue (eq. 2.28)")


def run_note(summary: pd.DataFrame, **labels) -> str:
    """Onset, growth, merging and an early stop of the run with these labels (summary.csv), in a few words."""
    sel = np.logical_and.reduce([summary[k] == v for k, v in labels.items()])
    if not sel.any():
        return "not run"
    s = summary[sel].iloc[0]
    if not np.isfinite(s.onset_concentration_mEq_l):
        note = "no damage onset"
    else:
        note = f"damage onset at {s.onset_concentration_mEq_l:g} mEq/l, {s.final_length_um:.3g} um delaminated"
        note += f", merged at pass {s.merge_step:g}" if bool(s.merged) else ""
    note += f", {s.snaps:g} snap{'s' if s.snaps != 1 else ''}" if s.get("snaps", 0) else ""
    # the stop's kind, without its details (those are in summary.csv), on a second line of the legend
    return note + (f"\n    stop: {s.stop.split(' (')[0]}" if s.stop != "arrested" else "")


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


def snapshot_grid(fig, spec, columns, media_outer_um):
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
            snapshot_panel(ax, snap, k, window, radii, media_outer_um, label)
            if i == len(col) - 1:
                ax.set_xlabel("current angle (deg)")
            if j == 0:
                ax.set_ylabel("radius (um)")
    damage_colourbar(fig, fig.add_subplot(grid[:, -1]))


def criterion_snapshots(block, snapshots: dict, criteria, n_snapshots: int, label: str, media_outer_um: float, rows):
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
    snapshot_grid(block, gs[0], columns, media_outer_um)
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
    media_outer_um: float,
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
    fig, blocks = law_blocks(laws, [0.3 + rows + 3.0] * len(laws))
    for block, law in zip(blocks, laws):
        own, notes_of = of_law(runs, law), of_law(summary, law)
        lower = criterion_snapshots(
            block,
            {c: snapshots[law, c] for c in criteria},
            criteria,
            n_snapshots,
            f", {sigma:g} kPa: ",
            media_outer_um,
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
        no_growth_note(ax, own)
        ax.set(xlabel=GAG_CONCENTRATION, ylabel="delaminated length (um)", title=f"(c) growth, {case}")
        style_legend(ax, "upper left")
    material_key(fig)
    fit_particle_sizes(fig)
    return fig


def fig6(growth: pd.DataFrame, summary: pd.DataFrame, snapshots: dict, cases, criteria, laws, media_outer_um: float):
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
        snapshot_grid(block, gs[0], columns, media_outer_um)
        bottom = gs[1].subgridspec(1, len(cases))
        g, sm = of_law(growth, law), of_law(summary, law)
        for j, case in enumerate(cases):
            converted_panel(block.add_subplot(bottom[j]), g, sm, case, criteria, f"(c) {case}: converted particles")
    material_key(fig)
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
    media_outer_um: float,
    n_snapshots: int = 4,
):
    """Figure 7, two pools offset in radius (``case``, figure 7's set), one block per charge law (``laws``;
    ``snapshots``: (law, criterion) -> snapshots): (a) ``n_snapshots`` snapshots per criterion; (b) the tip radial
    stress and (c) the converted particles against pseudo-time."""
    _style()
    rows = 1.15 * max(len(snapshot_indices(snap, n_snapshots)) for snap in snapshots.values())
    fig, blocks = law_blocks(laws, [0.3 + rows + 3.0] * len(laws))
    for block, law in zip(blocks, laws):
        lower = criterion_snapshots(
            block, {c: snapshots[law, c] for c in criteria}, criteria, n_snapshots, ": ", media_outer_um, rows
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
            dict(zip(criteria, CRITERION_COLOURS)),
            {sigma: "0.45"},
            f"(b) {case}: tip radial stress, sigma_cr = {sigma:g} kPa",
            dict(zip(criteria, CRITERION_DASHES)),
        )
        no_growth_note(ax, runs)
        converted_panel(block.add_subplot(bottom[1]), g, sm, case, criteria, f"(c) {case}: converted particles")
    material_key(fig)
    fit_particle_sizes(fig)
    return fig


# ---------------------------------------------------------------------------
# Sensitivity study (issue 17): indices and the delamination map
# ---------------------------------------------------------------------------

SENSITIVITY_OUTPUTS = {  # results/sensitivity/indices.csv output -> axis label
    "tip_radial_stress_kPa": "tip radial stress (kPa)",
    "top_circ_stress_kPa": "top hoop stress (kPa)",
    "pool_volume_change": "pool volume change",
    "onset_concentration_mEq_l": "onset concentration (mEq/l)",
    "final_length_um": "delaminated length (um)",
    "propagated": "propagated (0/1)",
}


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
        )
    lim = max(float(star.conf_high.max()), float(wide.sigma.max()), 1e-12) * 1.1
    ax.plot([0, lim], [0, lim], ls=":", lw=0.7, color="0.5")  # sigma = mu*: strongly non-linear or interacting
    ax.set_xlim(0, lim)
    ax.set_ylim(0, lim)
    ax.set_xlabel("mu*")
    ax.set_ylabel("sigma")


def sobol_panel(ax, rows: pd.DataFrame):
    """S1 and ST per input with their bootstrap intervals (horizontal bars)."""
    if not rows.value.abs().max() > 0:
        return _no_indices(ax, rows)
    names = list(dict.fromkeys(rows.input))
    y = np.arange(len(names))
    for offset, (index, colour) in zip((-0.18, 0.18), (("S1", "#1b9e77"), ("ST", "#d95f02"))):
        r = rows[rows["index"] == index].set_index("input").loc[names]
        ax.barh(
            y + offset,
            r.value,
            height=0.34,
            color=colour,
            label=index,
            xerr=[r.value - r.conf_low, r.conf_high - r.value],
            error_kw=dict(lw=0.8, ecolor="0.3"),
        )
    ax.set_yticks(y, [input_label(n) for n in names], fontsize=6)
    ax.invert_yaxis()
    ax.axvline(0, color="0.5", lw=0.6)
    ax.set_xlabel("Sobol index")
    ax.legend(loc="lower right", fontsize=6, frameon=False)


def sensitivity(indices: pd.DataFrame, laws):
    """Morris mu* against sigma (every input) and Sobol S1 and ST with their intervals (the chosen inputs): a row per
    output, a column per method and charge law."""
    _style()
    laws = [law for law in laws if law in set(indices.charge_law)]
    columns = [(m, law) for m in ("morris", "sobol") if m in set(indices.method) for law in laws]
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
            (morris_panel if method == "morris" else sobol_panel)(ax, rows)
            if i == 0:
                ax.set_title(f"{'Morris' if method == 'morris' else 'Sobol'}: {LAW_SHORT.get(law, law)}", fontsize=8)
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
    return fig


MAP_COLOURS = {
    "no onset": "#d9d9d9",
    "onset, arrested": "#fdb863",
    "propagation": "#b2182b",
    "no equilibrium": "#542788",
}


def delamination_map(table: pd.DataFrame, swelling: pd.DataFrame, cases: dict, pressure_mmHg: float, laws):
    """The delamination map: a panel per charge law (row) and sigma_cr (column), pool angular extent (x) against
    concentration level (y), each cell coloured by what the pool does there (:data:`delamination.LEVEL_CLASSES`).
    On the prescribed law's panels, the end of figure 4's swelling runs of the passive wall at ``pressure_mmHg``
    (``swelling``: tip_stress.csv): a limit point where there is one (a star), else the last converged state of a run
    that stops early (a cross)."""
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
            if law == "prescribed":
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
            ax.set_title(f"{LAW_SHORT.get(law, law)}\nsigma_cr = {sigma:g} kPa", fontsize=8)
            if i == len(laws) - 1:
                ax.set_xlabel("pool angular extent (deg)")
            if j == 0:
                ax.set_ylabel(GAG_CONCENTRATION)
    handles = [matplotlib.patches.Patch(color=c, label=s) for s, c in MAP_COLOURS.items()]
    handles += [
        matplotlib.lines.Line2D([], [], marker="*", ls="", color="k", label="figure 4 swelling: limit point"),
        matplotlib.lines.Line2D([], [], marker="x", ls="", color="k", label="figure 4 swelling: " + LAST_CONVERGED),
    ]
    fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize=7, frameon=False)
    return fig
