"""Figures of the paper, drawn from the pipeline's tidy tables (no simulation here)."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .provenance import figure_metadata  # noqa: E402

HOMEOSTATIC_MMHG = 103.0
PRESSURE_COLOURS = {103.0: "#1b9e77", 145.0: "#d95f02", 200.0: "#7570b3"}


def _style():
    plt.rcParams.update({
        "font.size": 9, "axes.labelsize": 9, "legend.fontsize": 8, "axes.spines.top": False,
        "axes.spines.right": False, "figure.dpi": 150, "savefig.bbox": "tight",
    })


def pressure_colour(p):
    return PRESSURE_COLOURS.get(round(float(p), 6), None)


def save(fig, paths, description: str):
    """Save ``fig`` to every path (format from the suffix) with provenance metadata."""
    for path in paths:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        meta = figure_metadata(description)
        if str(path).endswith(".png"):
            meta = {"Title": meta["Title"], "Software": meta["Creator"]}
        fig.savefig(path, metadata=meta)
    plt.close(fig)


def pressure_diameter_panels(ax_pd, ax_ss, states: pd.DataFrame, exact: pd.DataFrame, label="SPH", colour="k",
                             marker="o", exact_label="exact thick wall"):
    """Pressure-outer diameter and mean circumferential stress-stretch (figure 3a), one model."""
    ax_pd.plot(exact.outer_diameter_um, exact.pressure_mmHg, "-", color=colour, lw=1.2, label=exact_label)
    ax_pd.plot(states.outer_diameter_um, states.pressure_mmHg, marker, mfc="none", color=colour, ms=4, label=label)
    ax_ss.plot(exact.mean_circ_stretch, exact.mean_circ_stress_kPa, "-", color=colour, lw=1.2, label=exact_label)
    ax_ss.plot(states.mean_circ_stretch, states.mean_circ_stress_kPa, marker, mfc="none", color=colour, ms=4,
               label=label)


def mark_homeostasis(ax_pd, ax_ss, exact: pd.DataFrame):
    """Horizontal and vertical lines at the homeostatic pressure (figure 3a)."""
    row = exact.iloc[(exact.pressure_mmHg - HOMEOSTATIC_MMHG).abs().argmin()]
    for ax, x, y in ((ax_pd, row.outer_diameter_um, HOMEOSTATIC_MMHG),
                     (ax_ss, row.mean_circ_stretch, row.mean_circ_stress_kPa)):
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
    ax_pd.text(0.98, 0.04, f"max |OD error| (10-200 mmHg)\n= {100 * max_error:.2f} %", transform=ax_pd.transAxes,
               ha="right", va="bottom", fontsize=7)
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
        pressure_diameter_panels(ax_pd, ax_ss, table[table.model == model], exact[model], label=f"SPH {model}",
                                 colour=st["color"], marker=st["marker"], exact_label=f"semi-analytical {model}")


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
    handles += [plt.Line2D([], [], color="k", marker="o", mfc="none", ls="-", label="passive / mean: SPH, exact"),
                plt.Line2D([], [], color="k", marker="^", mfc="none", ls="--", label="active: SPH, exact")]
    axes[1, 3].legend(handles=handles, frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(0.0, 0.9))
    fig.tight_layout()
    return fig


def fig1(particles: pd.DataFrame, mass_fractions: dict, support_factor: float, dx: float):
    """Figure 1: (a) the particles of the bi-layered quarter annulus by layer, (b) the spiky kernel and its
    derivative over the support, (c) the constituent mass fractions of each layer."""
    from .kernel import spiky, spiky_derivative

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
    from .artery import pool_sector
    from .measure import pool_probes

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


def swelling_panels(ax_tip, ax_top, runs: pd.DataFrame):
    """Tip radial and top hoop stress against concentration, one line per pressure; intact values filled."""
    for P, g in runs.groupby("pressure_mmHg"):
        c = pressure_colour(P)
        conv = g[g.stage == "converted"].sort_values("concentration_mEq_l")
        intact = g[g.stage == "intact"]
        ax_tip.plot(conv.concentration_mEq_l, conv.tip_radial_stress_kPa, "-o", color=c, ms=2.5, lw=1.0,
                    label=f"{P:g} mmHg")
        if "tip_peak_radial_stress_kPa" in conv:
            ax_tip.plot(conv.concentration_mEq_l, conv.tip_peak_radial_stress_kPa, ":", color=c, lw=0.9)
        ax_top.plot(conv.concentration_mEq_l, conv.top_circ_stress_kPa, "-o", color=c, ms=2.5, lw=1.0)
        ax_tip.plot(np.zeros(len(intact)), intact.tip_radial_stress_kPa, "o", color=c, ms=6, clip_on=False)
        ax_top.plot(np.zeros(len(intact)), intact.top_circ_stress_kPa, "o", color=c, ms=6, clip_on=False)
    ax_tip.axhline(0.0, color="0.7", lw=0.6)


def fig4(tips: pd.DataFrame, particles: pd.DataFrame, cases: dict, probe_length: float):
    """Figure 4: (a) the pools; (b) passive and (c) active tip radial and top hoop stress vs concentration."""
    _style()
    names = sorted(cases, key=lambda k: cases[k]["angular_extent_deg"])
    models = [m for m in ("passive", "active") if m in set(tips.model)]
    nrow = 1 + 2 * len(models)
    fig, axes = plt.subplots(nrow, len(names), figsize=(3.0 * len(names), 2.3 * nrow), squeeze=False)
    for j, name in enumerate(names):
        pool_geometry_panel(axes[0, j], particles, cases[name], probe_length,
                            f"(a) case {name}: {cases[name]['angular_extent_deg']:g} deg")
    axes[0, 0].set_ylabel("radius (um)")
    for i, model in enumerate(models):
        letter = "bc"[i]
        for j, name in enumerate(names):
            ax_tip, ax_top = axes[1 + 2 * i, j], axes[2 + 2 * i, j]
            runs = tips[(tips.model == model) & (tips.case == name)]
            swelling_panels(ax_tip, ax_top, runs)
            ax_tip.set_title(f"({letter}) {model}, case {name}")
            ax_top.set_xlabel("GAG concentration (mEq/l)")
        axes[1 + 2 * i, 0].set_ylabel("tip radial stress (kPa)")
        axes[2 + 2 * i, 0].set_ylabel("top hoop stress (kPa)")
    # shared y-limits per row make the cases comparable
    for row in axes[1:]:
        lo = min(ax.get_ylim()[0] for ax in row)
        hi = max(ax.get_ylim()[1] for ax in row)
        for ax in row:
            ax.set_ylim(lo, hi)
    axes[1, -1].legend(frameon=False, fontsize=7)
    axes[1, 0].text(0.02, 0.02, "solid: mean over the tip region\ndotted: particle peak", transform=axes[1, 0].transAxes,
                    fontsize=6.5, va="bottom")
    fig.tight_layout()
    return fig


RATIO_COLOURS = {1.0: "#1b9e77", 2.0: "#d95f02", 3.0: "#7570b3"}


def verification_pool(table: pd.DataFrame, profiles: pd.DataFrame):
    """The pool verification: (a) Lamé field of the circle, (b) hoop stress ahead of the tip against Inglis,
    (c) tip error and (d) traction jump and field error against resolution (log-log, observed order)."""
    from .inclusion import observed_order, tip_fit, TIP_PARTICLES

    _style()
    fig, axes = plt.subplots(1, 4, figsize=(13.5, 3.1))
    Pi = float(table.pressure_kPa.iloc[0])
    colour = lambda r: RATIO_COLOURS.get(float(r), "k")  # noqa: E731
    ax = axes[0]
    rings = profiles[profiles.profile == "rings"]
    if len(rings):
        b = float(table[table.aspect_ratio == 1.0].semi_axis_b_um.iloc[0])
        for k, (res, g) in enumerate(sorted(rings.groupby("b_over_dx"), key=lambda t: t[0])[-2:]):
            mk = "os"[k]
            ax.plot(g.radius_um / b, g.radial_sph_kPa / Pi, mk, ms=3, mfc="none", color="C0",
                    label=f"SPH b/dx = {res:g}")
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
        ax.plot(p.s_um / b, p.hoop_sph_kPa / Pi, "o", ms=2.5, mfc="none", color=colour(ratio),
                label=f"a/b = {ratio:g} (b/dx = {finest:g})")
        row = g[g.b_over_dx == finest].iloc[0]
        ax.plot([0], [row.tip_stress_kPa / Pi], "*", ms=8, color=colour(ratio))
        ax.plot([0], [row.reference_kPa / Pi], "_", ms=14, mew=1.5, color="k")
    ax.set(xlim=(0, None), xlabel="distance ahead of the tip / b", ylabel="hoop stress / Pi",
           title="(b) ahead of the tip: SPH (o), Inglis (-)")
    ax.text(0.98, 0.97, f"* fit of the first {TIP_PARTICLES} particles\n- Inglis Pi (2a/b - 1)",
            transform=ax.transAxes, ha="right", va="top", fontsize=6.5)
    ax.legend(frameon=False, fontsize=6.5, loc="center right")
    ax = axes[2]
    for ratio, g in table.groupby("aspect_ratio"):
        h = g.dx_um / g.semi_axis_b_um
        ax.loglog(h, g.rel_error.abs(), "o-", color=colour(ratio), ms=3,
                  label=f"a/b = {ratio:g}: order {observed_order(g.dx_um, g.rel_error):.2f}")
        ax.loglog(h, g.first_particle_rel_error.abs(), "x:", color=colour(ratio), ms=3, lw=0.7)
    ax.axhline(0.05, color="0.6", lw=0.6, ls="--")
    ax.set(xlabel="dx / b", ylabel="|relative error|", title="(c) tip stress (o) and first particle (x)")
    ax.legend(frameon=False, fontsize=6.5)
    ax = axes[3]
    for ratio, g in table.groupby("aspect_ratio"):
        h = g.dx_um / g.semi_axis_b_um
        ax.loglog(h, g.field_rms_error_kPa / Pi, "o-", color=colour(ratio), ms=3, label=f"a/b = {ratio:g}")
        ax.loglog(h, np.maximum(g.traction_jump_kPa / Pi, 1e-4), "s--", color=colour(ratio), ms=3, mfc="none", lw=0.7)
    ax.set(xlabel="dx / b", ylabel="/ Pi", title="(d) field rms error (o), traction jump (s)")
    ax.legend(frameon=False, fontsize=6.5)
    fig.tight_layout()
    return fig


def swelling_convergence(table: pd.DataFrame):
    """Resolution study: tip radial stress (mean over the probe, and particle peak), top hoop stress and pool
    volume change against concentration, one line per particle spacing, one column per pool."""
    _style()
    cases = list(dict.fromkeys(table.case))
    fig, axes = plt.subplots(3, len(cases), figsize=(3.4 * len(cases), 7.0), squeeze=False)
    spacings = sorted(table.dx_um.unique(), reverse=True)
    shades = plt.cm.viridis(np.linspace(0.1, 0.85, len(spacings)))
    for j, case in enumerate(cases):
        for dx, colour in zip(spacings, shades):
            g = table[(table.case == case) & (table.dx_um == dx)].sort_values("concentration_mEq_l")
            c = g.concentration_mEq_l
            axes[0, j].plot(c, g.tip_radial_stress_kPa, "-o", ms=2.5, color=colour, label=f"dx = {dx:g} um")
            axes[0, j].plot(c, g.tip_peak_radial_stress_kPa, ":", color=colour, lw=0.9)
            axes[1, j].plot(c, g.top_circ_stress_kPa, "-o", ms=2.5, color=colour)
            axes[2, j].plot(c, g.pool_volume_change, "-o", ms=2.5, color=colour)
        axes[0, j].set_title(f"case {case}")
        axes[0, j].axhline(0.0, color="0.7", lw=0.6)
        axes[2, j].set_xlabel("GAG concentration (mEq/l)")
    axes[0, 0].set_ylabel("tip radial stress (kPa)\n(solid: probe mean, dotted: peak)")
    axes[1, 0].set_ylabel("top hoop stress (kPa)")
    axes[2, 0].set_ylabel("pool volume change")
    axes[0, -1].legend(frameon=False, fontsize=7)
    fig.tight_layout()
    return fig
