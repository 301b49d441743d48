"""The authors' explicit procedure against our equilibria (target ``paper_procedure``;
:mod:`sphgag.studies.paper_procedure`).

Top, one column per pool of figure 4: the tip radial and top hoop Cauchy stresses against the GAG concentration and
the relative residual of every state (the quasi-static solver's norm), with the solver's tolerance. The equilibrium
path is black; the explicit runs are coloured by step factor (the script's step counts times it); passive walls
solid, active walls dashed. Bottom, one column per damage run (pool set and sigma_cr, figures 5-6): the tip stress
(with sigma_cr), the delaminated length and the residual against the script's clock, the pseudo-time over the step
factor (at which every run's loads are the same).
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from . import style

ROWS = (
    ("tip_radial_stress_kPa", "tip radial stress (kPa)"),
    ("top_circ_stress_kPa", "top hoop stress (kPa)"),
    ("residual", "relative residual"),
)
WALL_LINES = {"passive": "-", "active": "--"}


DAMAGE_ROWS = (
    ("tip_radial_stress_kPa", "tip radial stress (kPa)"),
    ("delaminated_length_um", "delaminated length (um)"),
    ("residual", "relative residual"),
)


def figure(equilibrium: pd.DataFrame, runs: pd.DataFrame, damage: pd.DataFrame, tolerance: float, concentration: float):
    """The figure (module docstring) from the equilibrium tables (:func:`sphgag.studies.convergence.measure`), the
    explicit runs' states (:func:`sphgag.studies.paper_procedure.table`, up to ``concentration`` [mEq/l]) and the
    damage runs' rows (:func:`sphgag.studies.paper_procedure.delaminate`)."""
    style._style()
    cases = list(dict.fromkeys(equilibrium.case))
    groups = list(damage.groupby(["pool_set", "sigma_cr_kPa"], sort=False)) if len(damage) else []
    # figure 5's single pools first (no interior side), each by sigma_cr, then the pool pairs of figure 6
    groups.sort(key=lambda kv: (bool(kv[1].interior_particles.notna().any()), kv[0][0], kv[0][1]))
    factors = sorted(set(runs.step_factor) | set(damage.get("step_factor", [])))
    colours = dict(zip(factors, plt.cm.viridis(np.linspace(0.15, 0.85, len(factors)))))
    width = max(2.9 * max(len(cases), len(groups)), 6.0)  # the title and the outside legends fit one column too
    fig = plt.figure(figsize=(width, 7.6 + 7.0 * bool(groups)), layout="constrained")
    top, bottom = fig.subfigures(2, 1, height_ratios=[1.0, 0.92]) if groups else (fig, None)
    _swelling(top, cases, equilibrium, runs, colours, tolerance, concentration)
    if groups:
        _damage(bottom, groups, colours, tolerance)
    title = "The paper's explicit procedure (fixed steps, mass scaling)\nagainst the equilibrium path"
    top.suptitle(title, fontsize=10)  # over the upper block, whose layout makes room for it
    return fig


def _damage(fig, groups, colours, tolerance):
    """The damage runs (module docstring), one column per (pool set, sigma_cr)."""
    axes = fig.subplots(len(DAMAGE_ROWS), len(groups), sharex=True, squeeze=False)
    for col, ((pool_set, sigma), g) in enumerate(groups):
        for row, (column, label) in enumerate(DAMAGE_ROWS):
            ax = axes[row, col]
            for factor, r in g.groupby("step_factor"):
                ax.plot(r.pseudo_time / factor, r[column], color=colours[factor], lw=0.8, label=f"explicit x{factor:g}")
            if column == "tip_radial_stress_kPa":
                ax.axhline(sigma, color="k", lw=0.8, ls="--", label="sigma_cr")
            _dress(
                axes,
                row,
                col,
                column,
                label,
                f"{pool_set}\nsigma_cr = {sigma:g} kPa",
                "pseudo-time / step factor",
                tolerance,
            )
    axes[0, -1].legend(fontsize=6, frameon=False, loc="upper left", bbox_to_anchor=(1.0, 1.0))


def _dress(axes, row, col, column, label, title, xlabel, tolerance):
    """The axes at ``(row, col)``: a residual on a log scale with the solver's tolerance, the column's title on the
    first row, the row's label on the first column, ``xlabel`` on the last row."""
    ax = axes[row, col]
    if column == "residual":
        ax.set_yscale("log")
        ax.axhline(tolerance, color="grey", lw=0.8, ls=":", label="solver tolerance")
    if row == 0:
        ax.set_title(title)
    if col == 0:
        ax.set_ylabel(label)
    if row == axes.shape[0] - 1:
        ax.set_xlabel(xlabel)


def _swelling(fig, cases, equilibrium, runs, colours, tolerance, concentration):
    """Figure 4's pools (module docstring), one column per pool."""
    axes = fig.subplots(len(ROWS), len(cases), sharex=True, squeeze=False)
    eq = equilibrium[equilibrium.stage == "converted"]
    ramp = runs[runs.stage.isin(["convert", "swell"]) & (runs.concentration_mEq_l <= concentration + 1e-9)]
    for col, case in enumerate(cases):
        for row, (column, label) in enumerate(ROWS):
            ax = axes[row, col]
            for wall, line in WALL_LINES.items():
                g = eq[(eq.case == case) & (eq.model == wall)]
                if len(g):
                    ax.plot(
                        g.concentration_mEq_l,
                        g[column],
                        "k" + line,
                        marker="o",
                        ms=3,
                        lw=1.2,
                        label=f"equilibrium, {wall}",
                    )
                for factor in colours:
                    r = ramp[(ramp.case == case) & (ramp.model == wall) & (ramp.step_factor == factor)]
                    if len(r):
                        ax.plot(
                            r.concentration_mEq_l,
                            r[column],
                            line,
                            color=colours[factor],
                            lw=1.0,
                            label=f"explicit x{factor:g}, {wall}",
                        )
            _dress(axes, row, col, column, label, f"case {case}", style.GAG_CONCENTRATION, tolerance)
    axes[-1, -1].legend(fontsize=6, frameon=False, loc="upper left", bbox_to_anchor=(1.0, 1.0))
