"""Figure 4 under the authors' settings, one at a time (target ``paper_settings``;
:mod:`sphgag.studies.paper_settings`).

One panel per pool of figure 4, at the highest concentration of the study: for each setting (a row), the step it makes
in the tip radial stress from the authors' value to ours, read both ways (circles: from the authors' configuration,
that setting switched to ours; squares: from ours, that setting switched to theirs, sign turned so that both read
authors' -> ours), passive walls blue, active walls red. A step of 0 means the setting changes nothing there; the
whole difference, ours - the authors', is the panel's title. The axis is linear up to 10 kPa and logarithmic beyond.
A missing marker: one end of that step has no equilibrium at that concentration (the ablation table says why).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from . import style

WALL_COLOURS = {"passive": "#3b6fb6", "active": "#d1352b"}
DIRECTION_MARKERS = {"from_script": ("o", "from the authors' configuration"), "from_ours": ("s", "from ours")}
#: the small vertical offset of each (wall, direction) so that no two markers of a row hide each other
OFFSETS = {
    ("passive", "from_script"): -0.24,
    ("passive", "from_ours"): -0.08,
    ("active", "from_script"): 0.08,
    ("active", "from_ours"): 0.24,
}


def figure(steps: pd.DataFrame):
    """The figure (module docstring) from the steps table (:func:`sphgag.studies.paper_settings.steps`)."""
    style._style()
    top = steps.concentration_mEq_l.max()
    at = steps[np.isclose(steps.concentration_mEq_l, top) & (steps.quantity == "tip_radial_stress_kPa")]
    cases = list(dict.fromkeys(at.case))
    settings = list(dict.fromkeys(at.setting))
    reach = 2.0 * max(float(np.nanmax(np.abs(at.step))) if at.step.notna().any() else 10.0, 10.0)  # every marker in
    fig, axes = plt.subplots(
        1,
        len(cases),
        figsize=(4.6 * len(cases) + 1.6, 0.45 * len(settings) + 2.2),
        sharey=True,
        squeeze=False,
        layout="constrained",
    )
    for ax, case in zip(axes[0], cases):
        g = at[at.case == case]
        titles = []
        for (model, direction), rows in g.groupby(["model", "direction"], sort=False):
            y = np.array([settings.index(s) for s in rows.setting]) + OFFSETS.get((model, direction), 0.0)
            marker, label = DIRECTION_MARKERS[direction]
            ax.scatter(
                rows.step,
                y,
                marker=marker,
                s=28,
                color=WALL_COLOURS.get(model, "k"),
                facecolor="none" if direction == "from_ours" else WALL_COLOURS.get(model, "k"),
                label=f"{model}, {label}",
                zorder=3,
            )
        for model, rows in g.groupby("model", sort=False):
            r = rows.iloc[0]
            titles.append(f"{model}: {r.script:.0f} (authors') -> {r.ours:.0f} kPa (ours)")
        ax.axvline(0.0, color="0.5", lw=0.8)
        ax.set_xscale("symlog", linthresh=10.0)
        ax.set_xlim(-reach, reach)
        ax.set_yticks(range(len(settings)), [s.replace("_", " ") for s in settings])
        ax.set_ylim(len(settings) - 0.5, -0.5)
        ax.grid(axis="x", color="0.9")
        ax.set_xlabel(f"step in tip radial stress at {top:g} mEq/l (kPa)")
        ax.set_title(f"case {case}\n" + "\n".join(titles), fontsize=8)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=2, fontsize=7, frameon=False)
    return fig
