"""An animation of a delamination run: its ParaView series (:mod:`sphgag.views.paraview`) drawn frame by frame.

Each frame is one saved state of the run (section 2.7: the first converged state of every concentration level, the
states the run kept, and the last), zoomed on the pools: tissue particles coloured by their radial Cauchy stress
(eq. 2.10; the stress of the onset criterion, eq. 2.28), GAG particles of the seeded pools and tissue that ruptured
and became GAG in their own colours, and in the title the GAG concentration and the damage pass (pseudo-time) of the
state. The colour range and the view are the same in every frame.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

from ..engine.history import DAMAGED, SEEDED  # noqa: E402

ORIGIN_COLOURS = {SEEDED: "#222222", DAMAGED: "#1b9e77"}  # off the stress colour map: black and green
MARGIN_UM = 40.0  # the view: the GAG particles of the last frame and this margin around them
FRAME_SECONDS = 0.6


def view(frames, margin: float = MARGIN_UM) -> tuple:
    """``(x0, x1, y0, y1)``: the GAG particles of the last frame and ``margin`` around them [um]."""
    last = frames[-1]
    gag = last.data["origin"] > 0
    x = last.x[gag] if gag.any() else last.x
    return x[:, 0].min() - margin, x[:, 0].max() + margin, x[:, 1].min() - margin, x[:, 1].max() + margin


def stress_range(frames, box) -> float:
    """The largest radial stress magnitude of the tissue inside the view over all frames (the colour range)."""
    x0, x1, y0, y1 = box
    peak = 0.0
    for f in frames:
        inside = (f.x[:, 0] >= x0) & (f.x[:, 0] <= x1) & (f.x[:, 1] >= y0) & (f.x[:, 1] <= y1) & (f.data["origin"] == 0)
        if inside.any():
            peak = max(peak, float(np.abs(f.data["cauchy_rr_kPa"][inside]).max()))
    return peak or 1.0


def spacing(frame) -> float:
    """The particle spacing [um]: the median distance of a particle to its nearest neighbour in the reference."""
    X = frame.data["reference_position"][:, :2]
    return float(np.median(cKDTree(X).query(X, k=2)[0][:, 1]))


def write(path, frames, title: str) -> Path:
    """The frames of a run (:class:`sphgag.views.paraview.Frame`) as an animated GIF at ``path``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    box = view(frames)
    vmax = stress_range(frames, box)
    fig, ax = plt.subplots(figsize=(5.4, 4.4), dpi=100)
    fig.subplots_adjust(left=0.14, right=0.78, bottom=0.11, top=0.86)
    cax = fig.add_axes([0.82, 0.11, 0.025, 0.75])
    ax.set(xlim=box[:2], ylim=box[2:], aspect="equal")
    fig.canvas.draw()
    # a marker as wide as 80 % of the particle spacing, in points (72 per inch) at the axes' drawn scale
    width_in = ax.get_window_extent().width / fig.dpi
    size = (0.8 * spacing(frames[0]) * 72.0 * width_in / (box[1] - box[0])) ** 2

    def draw(k):
        ax.clear()
        f = frames[k]
        tissue = f.data["origin"] == 0
        scatter = ax.scatter(
            *f.x[tissue].T, c=f.data["cauchy_rr_kPa"][tissue], cmap="RdBu_r", vmin=-vmax, vmax=vmax, s=size, lw=0
        )
        for origin, colour in ORIGIN_COLOURS.items():
            members = f.data["origin"] == origin
            ax.scatter(*f.x[members].T, color=colour, s=size, lw=0)
        ax.set(xlim=box[:2], ylim=box[2:], aspect="equal", xlabel="x [um]", ylabel="y [um]")
        c = float(f.data["concentration_mEq_l"].max())
        step = f.data["pseudo_time"][0]
        ax.set_title(f"{title}\nc = {c:g} mEq/l, pass {step:g}   (black: seeded GAG, green: ruptured)", fontsize=8)
        if k == 0:
            fig.colorbar(scatter, cax=cax, label="radial Cauchy stress [kPa]")
        return []

    animation = FuncAnimation(fig, draw, frames=len(frames), blit=False)
    animation.save(path, writer=PillowWriter(fps=1.0 / FRAME_SECONDS))
    plt.close(fig)
    return path
