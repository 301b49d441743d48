"""The verification figures (not in the paper): the pool's stress field against Inglis and Lamé
(verification_pool), a circular pool at large strain (verification_circular_pool) and the pressurised crack
against Sneddon and Griffith (verification_crack)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import seaborn as sns
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter

from ..physics import damage
from ..studies import annulus
from ..studies.inclusion import TIP_PARTICLES, observed_order
from .style import _style, palette, style_legend

RATIO_COLOURS = {1.0: "#1b9e77", 2.0: "#d95f02", 3.0: "#7570b3"}


def verification_pool(table: pd.DataFrame, profiles: pd.DataFrame):
    """The pool verification: (a) Lamé field of the circle, (b) hoop stress ahead of the tip against Inglis,
    (c) tip error and (d) traction jump and field error against resolution (log-log, observed order)."""
    _style()
    fig, axes = plt.subplots(1, 4, figsize=(16.0, 3.1))
    Pi = float(table.pressure_kPa.iloc[0])
    _lame_panel(axes[0], table, profiles, Pi)
    _inglis_panel(axes[1], table, profiles, Pi)
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


def _lame_panel(ax, table, profiles, Pi):
    """(a) of :func:`verification_pool`: the circular inclusion's ring means against Lamé's field."""
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


def _inglis_panel(ax, table, profiles, Pi):
    """(b) of :func:`verification_pool`: the hoop stress ahead of the tip against Inglis, per aspect ratio."""
    for ratio, g in table.groupby("aspect_ratio"):
        finest = g.b_over_dx.max()
        p = profiles[(profiles.profile == "axis") & (profiles.aspect_ratio == ratio) & (profiles.b_over_dx == finest)]
        b = float(g.semi_axis_b_um.iloc[0])
        ax.plot(p.s_um / b, p.hoop_exact_kPa / Pi, "-", color=RATIO_COLOURS.get(float(ratio), "k"), lw=1)
        ax.plot(
            p.s_um / b,
            p.hoop_sph_kPa / Pi,
            "o",
            ms=2.5,
            mfc="none",
            color=RATIO_COLOURS.get(float(ratio), "k"),
            label=f"a/b = {ratio:g} (b/dx = {finest:g})",
        )
        row = g[g.b_over_dx == finest].iloc[0]
        ax.plot([0], [row.tip_stress_kPa / Pi], "*", ms=8, color=RATIO_COLOURS.get(float(ratio), "k"))
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


def round_log_ticks(axis):
    """Label a log axis that spans less than a decade at round values only (its minor tick labels overlapped)."""
    axis.set_major_locator(LogLocator(subs=(1.0, 1.5, 2.0, 3.0, 5.0, 7.0)))
    axis.set_major_formatter(FormatStrFormatter("%g"))
    axis.set_minor_formatter(NullFormatter())


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
    round_log_ticks(ax.xaxis)
    style_legend(ax, "upper left", fontsize=6.5, bbox_to_anchor=(1.0, 1.0))


def verification_circular_pool(table: pd.DataFrame):
    """The circular pool at large strain (circular_pool.csv): |relative error| of (a) the pool's volume ratio and
    (b) its lining's radius against dx, log-log; a colour per volume ratio, a line style per pool model, the
    observed order of each line in the legend."""
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
    _style()
    fig, axes = plt.subplots(1, 3, figsize=(11.5, 3.5), layout="constrained")
    spacings = sorted(table.dx_um.unique(), reverse=True)
    colours = dict(zip(spacings, sns.color_palette("viridis", len(spacings))))
    gc = fracture_energy_J_m2 * damage.J_M2
    a = np.linspace(0.8 * table.half_length_um.min(), 1.2 * table.half_length_um.max(), 200)
    ax = axes[0]
    ax.plot(a, damage.griffith_pressure(a, gc, modulus), "k-", lw=1.2, label="Griffith")
    ax.plot(a, damage.dugdale_pressure(a, gc, modulus, critical_stress), "k:", lw=1.0, label="Dugdale")
    for dx in spacings:
        t = table[table.dx_um == dx]
        ax.plot(t.half_length_um, t.critical_pressure_kPa, "o", color=colours[dx], ms=5, label=f"SPH, dx = {dx:g} um")
    ax.set(xlabel="crack half-length a [um]", ylabel="face pressure at growth [kPa]", title="(a) onset of growth")
    ax.legend(frameon=False, fontsize=6.5)
    ax = axes[1]
    ax.plot(a, damage.opening_area(a, 1.0, modulus), "k-", lw=1.2, label="Sneddon")
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
    round_log_ticks(ax.xaxis)
    ax.legend(frameon=False, fontsize=5.5, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    return fig


def verification_annulus(table: pd.DataFrame, orders: pd.DataFrame, exact: pd.DataFrame):
    """The pressurised annulus (annulus.csv, annulus_orders.csv, annulus_exact.csv). Top row, one panel per pool
    model and B/A: the prescribed pressure over the largest the exact solution holds, against the pool volume ratio
    (log), the exact curve of the engine's laws (and the hole's incompressible closed form), the runs' states at
    every spacing, and what each run found above the limit (its discrete limit point, or the largest pressure volume
    control held, still rising). Bottom row, against dx (log-log): |relative error| of the volume ratio and of the hoop
    stress at the hole at every fraction of the limit, with the observed order of the finer pair; and how far the GAG
    particles reach outside the lining (positive: crossed)."""
    _style()
    cases = list(table.groupby(["pool_model", "outer_ratio"], sort=True).groups)
    columns = max(len(cases), 4)  # the bottom row: errors of the volume and of the hoop stress, their legend, the rings
    fig, axes = plt.subplots(2, columns, figsize=(3.0 * columns, 6.2), squeeze=False)
    for spare in axes[0][len(cases) :]:
        spare.axis("off")
    spacings = sorted(table.dx_um.unique(), reverse=True)
    colours = dict(zip(spacings, sns.color_palette("viridis", len(spacings)).as_hex()))
    for ax, (model, ratio) in zip(axes[0], cases):
        _annulus_path(ax, table, exact, model, ratio, colours)
    axes[0][0].legend(frameon=False, fontsize=6, loc="lower right")
    ratios = sorted(table.outer_ratio.unique())
    below = table[(table.fraction < 1.0) & table.state]
    _annulus_errors(axes[1], below, orders, ratios, spacings)
    _annulus_rings(axes[1][3], below, ratios, colours)
    for spare in axes[1][4:]:
        spare.axis("off")
    fig.tight_layout()
    return fig


def _annulus_path(ax, table, exact, model, ratio, colours):
    """One top panel of :func:`verification_annulus`: the pool model ``model`` at B/A ``ratio``."""
    case = table[(table.pool_model == model) & (table.outer_ratio == ratio)]
    top = float(case.limit_pressure_kPa.iloc[0])
    curve = exact[(exact.pool_model == model) & (exact.outer_ratio == ratio)]
    ax.plot(curve.volume_ratio, curve.pressure_kPa / top, color="k", lw=1.0, label="exact (engine's laws)")
    if annulus.ANNULUS_POOL_MODELS[model].empty:  # the incompressible closed form is the empty hole's
        ax.plot(curve.volume_ratio, curve.incompressible_kPa / top, color="0.5", lw=0.8, ls=":", label="incompressible")
    ax.axhline(1.0, color="0.6", lw=0.6, ls="--")
    for dx, g in case.groupby("dx_um"):
        below = g[(g.fraction < 1.0) & g.state]
        ax.plot(below.volume_ratio, below.fraction, "o", ms=3.5, mfc="none", color=colours[dx], label=f"dx = {dx:g} um")
        above = g[g.fraction > 1.0]
        for r in above.itertuples():
            held = r.discrete_limit_kPa if r.beyond_end == "limit point" else r.largest_held_kPa
            ax.plot([ax.get_xlim()[1]], [held / top], "<", ms=4, color=colours[dx], clip_on=False)
    beyond = case[case.fraction > 1.0]
    states = int(beyond.state.sum())
    kind = case.limit_kind.iloc[0]
    ax.set(
        xscale="log",
        xlabel="pool volume ratio J",
        ylabel="Pi / largest exact Pi",
        title=f"{model}, B/A = {ratio:g} ({kind} {top:.1f} kPa)",
        ylim=(0.0, 1.15),
    )
    ax.text(
        0.03,
        0.97,
        f"at {beyond.fraction.max():.2f} x the limit: {states} state{'' if states == 1 else 's'}\n"
        + "; ".join(sorted(set(beyond.beyond_end.astype(str))))
        + " (<: the largest Pi held)",
        transform=ax.transAxes,
        fontsize=6,
        va="top",
    )


def _annulus_errors(row, below, orders, ratios, spacings):
    """The bottom row's error panels of :func:`verification_annulus` and their legend (``row[2]``)."""
    markers = dict(zip(sorted(orders.fraction.unique()), "os^vDP"))
    styles = {"hole": "--", "particles": "-"}
    hues = dict(zip(ratios, sns.color_palette("Dark2", len(ratios)).as_hex()))
    for ax, (error, title) in zip(
        row, (("volume_error", "(a) pool volume ratio"), ("lining_hoop_error", "(b) hoop stress at the hole"))
    ):
        for (model, ratio, f), g in below.groupby(["pool_model", "outer_ratio", "fraction"]):
            g = g.sort_values("dx_um")
            o = orders[(orders.pool_model == model) & (orders.outer_ratio == ratio) & (orders.fraction == f)]
            o = o.set_index("quantity").order_fine
            label = f"{model}, B/A {ratio:g}, {f:g} of the limit: order " + " / ".join(f"{v:.2f}" for v in o)
            ax.loglog(
                g.dx_um,
                np.maximum(g[error].abs(), 1e-5),
                styles.get(model, "-"),
                marker=markers[f],
                ms=3,
                color=hues[ratio],
                lw=0.8,
                label=label,
            )
        ax.axhline(0.01, color="0.6", lw=0.6, ls="--")
        ax.set(xlabel="dx (um)", ylabel="|relative error|", title=title)
        ax.set_xticks(spacings, [f"{d:g}" for d in spacings])
        ax.minorticks_off()
    row[2].axis("off")
    row[2].legend(
        *row[1].get_legend_handles_labels(),
        title="observed order (finer pair):\nvolume ratio / hoop stress",
        title_fontsize=6,
        frameon=False,
        fontsize=5.5,
        loc="center",
    )


def _annulus_rings(ax, below, ratios, colours):
    """The bottom row's last panel of :func:`verification_annulus`: how far the GAG particles reach past the lining."""
    crossing = below[below.pool_model.isin([annulus.ANNULUS_POOL_MODELS.paper.name])]  # the paper's particles only
    for (ratio, dx), g in crossing.groupby(["outer_ratio", "dx_um"]):
        style = "-" if ratio == ratios[0] else "--"
        ax.plot(
            g.fraction,
            g.ring_crossing_um,
            style,
            marker="o",
            ms=3,
            lw=0.8,
            color=colours[dx],
            label=f"B/A {ratio:g}, dx {dx:g}",
        )
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set(xlabel="Pi / largest exact Pi", ylabel="GAG beyond the lining (um)", title="(c) order of the rings")
    ax.legend(frameon=False, fontsize=5.5)


def verification_profiles(rings: pd.DataFrame, table: pd.DataFrame, pressure_mmHg: float):
    """The walls' transmural stress against the exact thick wall (profiles_rings.csv, profiles.csv), one column per
    wall. Top rows: the radial and the hoop stress at ``pressure_mmHg`` and the configuration's spacing against the
    current radius, the exact curves of each layer and the SPH rings raw (the first lumen load and recovery of the
    table: open circles) and treated (the last of each: dots). Bottom row, against dx (log-log): the largest radial
    error at any ring (at its material point, % of P) for every lumen load (line style) and recovery (colour), with
    the acceptance's 2 % of P."""
    _style()
    walls = list(dict.fromkeys(table.wall))
    loads, recoveries = list(dict.fromkeys(table.lumen_load)), list(dict.fromkeys(table.recovery))
    raw, treated = (loads[0], recoveries[0]), (loads[-1], recoveries[-1])
    fig, axes = plt.subplots(3, len(walls), figsize=(3.6 * len(walls), 8.4), squeeze=False)
    hues = dict(zip(recoveries, sns.color_palette("Dark2", len(recoveries)).as_hex()))
    dashes = dict(zip(loads, ("--", "-", ":", "-.")))
    for k, wall in enumerate(walls):
        at = rings[(rings.wall == wall) & np.isclose(rings.pressure_mmHg, pressure_mmHg)]
        coarse = at[at.dx_um == at.dx_um.max()]
        finest = at[(at.dx_um == at.dx_um.min()) & (at.lumen_load == raw[0]) & (at.recovery == raw[1])]
        for ax, stress, exact, name in (
            (axes[0][k], "radial_stress_kPa", "exact_radial_kPa", "radial"),
            (axes[1][k], "circ_stress_kPa", "exact_circ_kPa", "hoop"),
        ):
            for j, (_, layer) in enumerate(finest.groupby("layer", sort=False)):
                ax.plot(layer.radius_um, layer[exact], color="k", lw=1.0, label="exact" if j == 0 else None)
            for (load, rec), marker in ((raw, dict(mfc="none", color="0.45")), (treated, dict(color=hues[treated[1]]))):
                g = coarse[(coarse.lumen_load == load) & (coarse.recovery == rec)].sort_values("ring")
                ax.plot(g.radius_um, g[stress], "o", ms=3.0, label=f"{load} load, {rec} reading", **marker)
            dx = coarse.dx_um.max()
            ax.set(
                xlabel="current radius (um)",
                ylabel=f"{name} stress (kPa)",
                title=f"{wall}, {pressure_mmHg:g} mmHg, dx = {dx:g} um",
            )
        axes[0][k].legend(frameon=False, fontsize=6, loc="lower right")
        ax = axes[2][k]
        for (load, rec), g in table[table.wall == wall].groupby(["lumen_load", "recovery"], sort=False):
            worst = g.groupby("dx_um").material_radial_max_pct.max()
            ax.loglog(
                worst.index,
                np.maximum(worst.to_numpy(), 1e-3),
                dashes[load],
                marker="o",
                ms=3,
                lw=0.9,
                color=hues[rec],
                label=f"{load} load, {rec}",
            )
        ax.axhline(2.0, color="0.6", lw=0.6, ls="--")
        spacings = sorted(table[table.wall == wall].dx_um.unique())
        ax.set_xticks(spacings, [f"{d:.3g}" for d in spacings])
        ticks = [t for t in (0.5, 1, 2, 5, 10, 20, 50, 100) if t <= 1.5 * table.material_radial_max_pct.max()]
        ax.set_yticks(ticks, [f"{t:g}" for t in ticks])
        ax.minorticks_off()
        ax.set(xlabel="dx (um)", ylabel="largest |radial error| (% of P)", title=f"{wall}: every ring, every pressure")
    handles, labels = axes[2][0].get_legend_handles_labels()
    title = "bottom row: lumen load (line style) and stress reading (colour); dashed grey: 2 % of P"
    fig.legend(handles, labels, loc="lower center", ncol=3, frameon=False, fontsize=7, title=title, title_fontsize=7)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    return fig
