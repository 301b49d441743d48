"""The numerical variants of the study side by side (target ``variants``): figure 4's first pool and figure 5's pool
under each form of the hourglass control (eq. 2.14 as printed, and its energy form)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from .style import _style, distinct_colours, style_legend


def form_label(form: str, forms: dict, default: str) -> str:
    """The legend's label of the hourglass form ``form``: its label of ``forms`` (its name if it has none), marked
    where it is the configured ``default``."""
    label = forms.get(form) or form
    return f"{label} (default)" if form == default else label


def stop_note(summary: pd.DataFrame) -> str:
    """One line per form: how figure 5's pool run ended, and its onset and runaway concentrations."""

    def c(value):
        return f"{value:.1f}" if np.isfinite(value) else "-"

    return "\n".join(
        f"{r.hourglass}: {r.stop_kind}, {r.final_length_um:.0f} um\n  onset {c(r.onset_concentration_mEq_l)}, "
        f"runaway {c(r.runaway_concentration_mEq_l)} mEq/l"
        for r in summary.itertuples()
    )


def hourglass_comparison(
    swelling: pd.DataFrame, growth: pd.DataFrame, summary: pd.DataFrame, forms: dict, default: str
) -> plt.Figure:
    """(a) figure 4's first pool: the tip radial stress and (b) the pool's volume ratio against the GAG concentration;
    (c) figure 5's pool: the delaminated length and (d) the tip radial stress against pseudo-time; a line per form,
    every state converged; a cross marks each run's last equilibrium, where it stopped (``stop_kind`` in the note).
    ``forms``: each form's legend label by its name (:data:`sphgag.engine.forces.HOURGLASS_FORMS`, as the rule passes
    them), in the order of the lines."""
    _style()
    colours = dict(zip(forms, distinct_colours(len(forms))))
    fig, axes = plt.subplots(1, 4, figsize=(13.0, 3.3), layout="constrained")
    converted = swelling[swelling.stage == "converted"]
    for form in forms:
        sw = converted[converted.hourglass == form]
        g = growth[growth.hourglass == form]
        kw = dict(color=colours[form], label=form_label(form, forms, default), lw=1.4)
        axes[0].plot(sw.concentration_mEq_l, sw.tip_radial_stress_kPa, marker="o", ms=3, **kw)
        axes[1].plot(sw.concentration_mEq_l, 1.0 + sw.pool_volume_change, marker="o", ms=3, **kw)
        axes[2].plot(g.step, g.delaminated_length_um, **kw)
        axes[3].plot(g.step, g.tip_radial_stress_kPa, **kw)
        if len(g):  # the run's last equilibrium: where it stopped
            for ax, y in ((axes[2], g.delaminated_length_um), (axes[3], g.tip_radial_stress_kPa)):
                ax.plot(g.step.iloc[-1], y.iloc[-1], marker="X", ms=7, color=colours[form], ls="none")
    case = swelling.case.iloc[0] if len(swelling) else ""
    axes[0].set(
        xlabel="GAG concentration (mEq/l)", ylabel="tip radial stress (kPa)", title=f"(a) figure 4, case {case}"
    )
    axes[1].set(xlabel="GAG concentration (mEq/l)", ylabel="pool volume / reference", title="(b) its swelling")
    axes[1].set_yscale("log")
    axes[2].set(xlabel="pseudo-time (levels + damage passes)", ylabel="delaminated length (um)", title="(c) figure 5")
    axes[3].set(xlabel="pseudo-time (levels + damage passes)", ylabel="onset measure at the tip (kPa)", title="(d)")
    if len(summary):
        sigma = summary.sigma_cr_kPa.iloc[0]
        axes[3].axhline(sigma, color="0.4", lw=0.8, ls=":")
        axes[2].text(0.02, 0.98, stop_note(summary), transform=axes[2].transAxes, va="top", fontsize=6.5)
    axes[0].legend()
    style_legend(axes[0], fontsize=7)
    return fig
