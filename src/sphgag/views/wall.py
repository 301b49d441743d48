"""Figure 3 of the paper, the mean-behaviour and bi-layered wall models: pressure-diameter and stress-stretch
(figure 3a, also drawn alone for the mean model), the transmural stresses of the mean model (3b) and of the
bi-layered passive and active models (3c)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from .style import _style, pressure_colour, pressure_colours


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


def mark_homeostasis(ax_pd, ax_ss, exact: pd.DataFrame, homeostatic_mmHg: float):
    """Horizontal and vertical lines at the homeostatic pressure ``homeostatic_mmHg`` (figure 3a)."""
    row = exact.iloc[(exact.pressure_mmHg - homeostatic_mmHg).abs().argmin()]
    for ax, x, y in (
        (ax_pd, row.outer_diameter_um, homeostatic_mmHg),
        (ax_ss, row.mean_circ_stretch, row.mean_circ_stress_kPa),
    ):
        ax.axhline(y, color="0.6", lw=0.6, ls=":")
        ax.axvline(x, color="0.6", lw=0.6, ls=":")


def fig3a_mean(states: pd.DataFrame, exact: pd.DataFrame, max_error: float, homeostatic_mmHg: float):
    """Figure 3a for the mean-behaviour model: SPH points over the exact curves, lines at the homeostatic pressure
    ``homeostatic_mmHg`` (configuration: homeostasis.target_pressure_mmHg)."""
    _style()
    fig, (ax_pd, ax_ss) = plt.subplots(2, 1, figsize=(3.4, 5.6))
    pressure_diameter_panels(ax_pd, ax_ss, states, exact)
    mark_homeostasis(ax_pd, ax_ss, exact, homeostatic_mmHg)
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


def transmural_panels(ax_r, ax_t, profiles: pd.DataFrame, model: str, colours: dict, border_um=None):
    """Radial (top) and circumferential (bottom) Cauchy stress across the wall, one line per pressure (``colours``:
    :func:`~sphgag.views.style.pressure_colours`)."""
    data = profiles[profiles.model == model]
    for P, grp in data.groupby("pressure_mmHg"):
        c = pressure_colour(colours, P)
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
    transmural_panels(ax_r, ax_t, profiles, "mean", pressure_colours(profiles.pressure_mmHg))
    ax_r.set_title("mean-behaviour model")
    handles, labels = ax_r.get_legend_handles_labels()
    handles.append(plt.Line2D([], [], color="k", lw=1.1))
    labels.append("exact thick wall")
    handles.append(plt.Line2D([], [], color="k", marker="o", mfc="none", ls="none", ms=3.5))
    labels.append("SPH (ring means)")
    ax_r.legend(handles, labels, frameon=False, loc="lower right")
    fig.tight_layout()
    return fig


MODEL_STYLE = {"passive": dict(color="k", marker="o", ls="-"), "active": dict(color="0.55", marker="^", ls="--")}


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


def layer_runs(profile: pd.DataFrame) -> list[tuple[str, float]]:
    """``(layer, outermost radius)`` of each run of one layer in a profile ordered by radius, from the lumen out."""
    p = profile.sort_values("radius_um")
    start = p.layer.ne(p.layer.shift()).cumsum()
    return [(g.layer.iloc[0], float(g.radius_um.max())) for _, g in p.groupby(start, sort=True)]


def bilayer_transmural_panels(ax_r, ax_t, profiles: pd.DataFrame, colours: dict):
    """Figure 3c: passive (solid) and active (dashed) transmural stresses against the normalised wall position, a
    colour per pressure (``colours``: :func:`~sphgag.views.style.pressure_colours`); a dotted line at every border
    between layers, each layer named beside it."""
    borders = []
    for model in ("passive", "active"):
        st = MODEL_STYLE[model]
        data = profiles[profiles.model == model]
        for P, grp in data.groupby("pressure_mmHg"):
            c = pressure_colour(colours, P)
            ex, sph = grp[grp.source == "exact"], grp[grp.source == "sph"]
            xe, xs = normalised_position(ex.radius_um, ex), normalised_position(sph.radius_um, ex)
            ax_r.plot(xe, ex.radial_stress_kPa, ls=st["ls"], color=c, lw=1.0)
            ax_t.plot(xe, ex.circ_stress_kPa, ls=st["ls"], color=c, lw=1.0)
            ax_r.plot(xs, sph.radial_stress_kPa, st["marker"], mfc="none", color=c, ms=3.2)
            ax_t.plot(xs, sph.circ_stress_kPa, st["marker"], mfc="none", color=c, ms=3.2)
            runs = layer_runs(ex)  # the same layers in every profile
            borders.append([float(normalised_position(r, ex)) for _, r in runs[:-1]])
    names, mean_borders = [name for name, _ in runs], np.mean(borders, axis=0)
    for border in mean_borders:
        for ax in (ax_r, ax_t):
            ax.axvline(border, color="0.3", ls=":", lw=0.9)
    at = ax_t.get_xaxis_transform()
    if len(names) > 1:
        ax_t.text(mean_borders[-1], 0.97, f" {names[-1]}", transform=at, fontsize=7, va="top")
    for name, border in zip(names, mean_borders):
        ax_t.text(border, 0.97, f"{name} ", transform=at, fontsize=7, va="top", ha="right")
    ax_r.set(ylabel="radial stress (kPa)")
    ax_t.set(xlabel="normalised wall position\n(r - r_in)/(r_out - r_in)", ylabel="circumferential stress (kPa)")


def fig3(mean_states, mean_exact, bilayer, bilayer_exact: dict, profiles: pd.DataFrame, homeostatic_mmHg: float):
    """Figure 3, complete: (a) pressure-diameter and stress-stretch of the mean, passive and active models, lines at
    the homeostatic pressure ``homeostatic_mmHg``; (b) transmural stresses of the mean model; (c) of the bi-layered
    passive and active models (a colour per pressure of ``profiles``)."""
    _style()
    colours = pressure_colours(profiles.pressure_mmHg)
    fig, axes = plt.subplots(2, 4, figsize=(13.5, 6.2))
    pressure_diameter_panels(axes[0, 0], axes[1, 0], mean_states, mean_exact)
    mark_homeostasis(axes[0, 0], axes[1, 0], mean_exact, homeostatic_mmHg)
    bilayer_pressure_diameter_panels(axes[0, 1], axes[1, 1], bilayer, bilayer_exact)
    mark_homeostasis(axes[0, 1], axes[1, 1], bilayer_exact["passive"], homeostatic_mmHg)
    for ax in axes[0, :2]:
        ax.set(xlabel="outer diameter (um)", ylabel="pressure (mmHg)")
        ax.legend(frameon=False, loc="upper left", fontsize=7)
    for ax in axes[1, :2]:
        ax.set(xlabel="mean circumferential stretch (eq. 2.17)", ylabel="mean circumferential stress (kPa)")
    axes[0, 0].set_title("(a) mean-behaviour model")
    axes[0, 1].set_title("(a) bi-layered model")
    transmural_panels(axes[0, 2], axes[1, 2], profiles, "mean", colours)
    axes[0, 2].set_title("(b) mean-behaviour model")
    bilayer_transmural_panels(axes[0, 3], axes[1, 3], profiles, colours)
    axes[0, 3].set_title("(c) bi-layered model")
    handles = [plt.Line2D([], [], color=c, lw=1.2, label=f"{P:g} mmHg") for P, c in colours.items()]
    handles += [
        plt.Line2D([], [], color="k", marker="o", mfc="none", ls="-", label="passive / mean: SPH, exact"),
        plt.Line2D([], [], color="k", marker="^", mfc="none", ls="--", label="active: SPH, exact"),
    ]
    axes[1, 3].legend(handles=handles, frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(0.0, 0.9))
    fig.tight_layout()
    return fig
