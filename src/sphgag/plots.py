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
