"""Figure 1 of the paper: the particle layout of the bi-layered wall, the kernel and the layers' composition."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from ..engine.kernel import spiky, spiky_derivative
from .style import _style, layer_colours


def fig1(particles: pd.DataFrame, mass_fractions: dict, support_factor: float, dx: float, layers=None):
    """Figure 1: (a) the particles of the layered quarter annulus by layer, (b) the spiky kernel and its
    derivative over the support, (c) the constituent mass fractions of each layer (``layers``: their names from the
    lumen outwards; by default those of ``mass_fractions``)."""
    layers = list(layers or mass_fractions)
    layer_colour = layer_colours([*layers, *particles.layer.unique()])

    _style()
    fig = plt.figure(figsize=(11, 3.8))
    gs = fig.add_gridspec(1, 4, width_ratios=[1.3, 1.1, 1.0, 0.8])
    ax = fig.add_subplot(gs[0])
    for layer, g in particles.groupby("layer"):
        ax.scatter(g.x_um, g.y_um, s=1.2, color=layer_colour[layer], label=f"{layer} ({len(g)})")
    ax.set_aspect("equal")
    ax.set(xlabel="x (um)", ylabel="y (um)", title=f"(a) {len(particles)} particles, dx = {dx:g} um")
    ax.legend(frameon=False, markerscale=6, loc="lower left")
    zoom = fig.add_subplot(gs[1])
    sector = particles[np.abs(np.rad2deg(particles.theta_rad) - 45.0) < 3.0]
    for layer, g in sector.groupby("layer"):
        zoom.scatter(g.x_um, g.y_um, s=g.volume_um2 * 0.6, color=layer_colour[layer])
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
    bottom = np.zeros(len(layers))
    colours = {"elastin": "#8c6d31", "smc": "#e7969c", "collagen": "#6b6ecf"}
    for constituent in ("elastin", "smc", "collagen"):
        vals = np.array([mass_fractions[l].get(constituent, 0.0) for l in layers])
        axc.bar(layers, vals, bottom=bottom, color=colours[constituent], label=constituent)
        bottom += vals
    axc.set(ylabel="mass fraction", title="(c) composition")
    if len(layers) > 2:  # more names than fit side by side
        axc.tick_params(axis="x", labelrotation=45)
    axc.legend(frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    return fig
