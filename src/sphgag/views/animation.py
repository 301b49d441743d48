"""An animation of a delamination run: its ParaView series (:mod:`sphgag.views.paraview`) drawn frame by frame.

Each frame is one saved state of the run (section 2.7: the first converged state of every concentration level, the
states the run kept, and the last), zoomed on the pools: tissue particles coloured by their radial Cauchy stress
(eq. 2.10; the stress of the onset criterion, eq. 2.28), partly damaged tissue (0 < D < 1, eq. 2.28), GAG particles
of the seeded pools and tissue that ruptured and became GAG in colours of their own, and in the title the GAG
concentration and the damage pass (pseudo-time) of the state. The view is the same in every frame; the colour range
is each frame's own (the largest radial stress magnitude of the tissue in view), stated on the colour bar, so that
the stresses of the early frames are as visible as those of a swollen, cracked pool's.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from matplotlib.cm import ScalarMappable  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

from ..engine.history import DAMAGED, SEEDED  # noqa: E402
from . import overlap  # noqa: E402

ORIGIN_COLOURS = {SEEDED: "#222222", DAMAGED: "#1b9e77"}  # off the stress colour map: black and green
PARTLY_DAMAGED = "#d95f02"  # tissue with 0 < D < 1: orange, off the stress colour map too
STRESS_MAP = "RdBu_r"
MARGIN_UM = 40.0  # the view: the GAG particles of the last frame and this margin around them
FRAME_SECONDS = 0.6


def view(frames, margin: float = MARGIN_UM) -> tuple:
    """``(x0, x1, y0, y1)``: the GAG particles of the last frame and ``margin`` around them [um]."""
    last = frames[-1]
    gag = last.data["origin"] > 0
    x = last.x[gag] if gag.any() else last.x
    return x[:, 0].min() - margin, x[:, 0].max() + margin, x[:, 1].min() - margin, x[:, 1].max() + margin


def partly_damaged(frame) -> np.ndarray:
    """Tissue particles with 0 < D < 1 (damage started, not ruptured)."""
    return (frame.data["origin"] == 0) & (frame.data["damage"] > 0.0) & (frame.data["damage"] < 1.0)


def stress_range(frame, box) -> float:
    """The colour range of one frame: the largest radial stress magnitude of its intact tissue in the view [kPa]."""
    x0, x1, y0, y1 = box
    inside = (frame.x[:, 0] >= x0) & (frame.x[:, 0] <= x1) & (frame.x[:, 1] >= y0) & (frame.x[:, 1] <= y1)
    shown = inside & (frame.data["origin"] == 0) & ~partly_damaged(frame)
    return float(np.abs(frame.data["cauchy_rr_kPa"][shown]).max()) if shown.any() else 1.0


def spacing(frame) -> float:
    """The particle spacing [um]: the median distance of a particle to its nearest neighbour in the reference."""
    X = frame.data["reference_position"][:, :2]
    return float(np.median(cKDTree(X).query(X, k=2)[0][:, 1]))


def write(path, frames, title: str) -> Path:
    """The frames of a run (:class:`sphgag.views.paraview.Frame`) as an animated GIF at ``path``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    box = view(frames)
    fig, ax = plt.subplots(figsize=(5.4, 4.4), dpi=100)
    fig.subplots_adjust(left=0.14, right=0.74, bottom=0.11, top=0.82)
    cax = fig.add_axes([0.78, 0.11, 0.025, 0.71])
    ax.set(xlim=box[:2], ylim=box[2:], aspect="equal")
    fig.canvas.draw()
    # a marker as wide as 80 % of the particle spacing, in points (72 per inch) at the axes' drawn scale
    width_in = ax.get_window_extent().width / fig.dpi
    size = (0.8 * spacing(frames[0]) * 72.0 * width_in / (box[1] - box[0])) ** 2
    scale = ScalarMappable(Normalize(-1.0, 1.0), STRESS_MAP)  # one colour bar, its range set per frame
    bar = fig.colorbar(scale, cax=cax)

    def draw(k):
        ax.clear()
        f = frames[k]
        vmax = stress_range(f, box)
        scale.set_clim(-vmax, vmax)
        bar.set_label(f"radial Cauchy stress [kPa]\nthis frame: -{vmax:.3g} to +{vmax:.3g}")
        partly = partly_damaged(f)
        tissue = (f.data["origin"] == 0) & ~partly
        ax.scatter(*f.x[tissue].T, c=f.data["cauchy_rr_kPa"][tissue], cmap=STRESS_MAP, norm=scale.norm, s=size, lw=0)
        ax.scatter(*f.x[partly].T, color=PARTLY_DAMAGED, s=size, lw=0)
        for origin, colour in ORIGIN_COLOURS.items():
            members = f.data["origin"] == origin
            ax.scatter(*f.x[members].T, color=colour, s=size, lw=0)
        ax.set(xlim=box[:2], ylim=box[2:], aspect="equal", xlabel="x [um]", ylabel="y [um]")
        c = float(f.data["concentration_mEq_l"].max())
        step = f.data["pseudo_time"][0]
        ax.set_title(
            f"{title}\nc = {c:g} mEq/l, pass {step:g}\nblack: seeded GAG, green: ruptured, orange: damaged (0 < D < 1)",
            fontsize=8,
        )
        return []

    animation = FuncAnimation(fig, draw, frames=len(frames), blit=False)
    animation.save(path, writer=PillowWriter(fps=1.0 / FRAME_SECONDS))
    draw(len(frames) - 1)  # the last frame, the one with the most text, is the one checked
    overlap.record(fig, path)
    plt.close(fig)
    return path
