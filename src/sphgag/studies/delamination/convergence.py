"""The resolution study of delamination (``results/delamination/convergence.csv``): the study's pool sets (figure 5's
pool and a pair) grown from the passive wall pressurised at each particle spacing, under every onset criterion (eq.
2.28, section 2.7), and the discretisation error of the concentrations of their events (``gci.csv``,
:func:`gci_table`)."""

from __future__ import annotations

import pandas as pd

from ...engine.numerics import Numerics
from .. import artery, gci, protocols
from .growth import grow
from .settings import Settings
from .tables import labelled

#: the concentrations of a run's events whose convergence the study measures (summary.csv columns)
CONVERGED_QUANTITIES = ("onset_concentration_mEq_l", "runaway_concentration_mEq_l", "merge_concentration_mEq_l")
GCI_COLUMNS = [
    "charge_law",
    "criterion",
    "case",
    "quantity",
    "dx_um",
    "value",
    "observed_order",
    "extrapolated",
    "gci_fine",
    "order_in_range",
]


def convergence_study(
    dx: float,
    bilayer: dict,
    numerics: Numerics,
    homeostasis: dict,
    de: dict,
    gag: dict,
    name: str = "delamination_convergence",
) -> pd.DataFrame:
    """Rows of ``results/delamination/convergence.csv`` for one particle spacing: every pool set of ``de["pool_sets"]``
    at ``critical_stress_kPa``, every onset criterion, from the passive wall pressurised at this spacing."""
    p = dict(bilayer, dx_um=float(dx))
    _, start = protocols.pressurised_wall(p, numerics, homeostasis, de["pressure_mmHg"], name)
    rows = []
    for case, pools in de["pool_sets"].items():
        sectors = [artery.pool_sector(s) for s in pools]
        for criterion in de["criteria"]:
            settings = Settings.at_section(de, criterion)
            model = artery.bilayer_model(p, numerics, name=f"{name}_{case}_{criterion}")
            result = grow(model, start, sectors, settings, numerics, gag, model.props)
            rows.append(labelled(result, case, settings, dx)[1].assign(particles=model.n))
    return pd.concat(rows, ignore_index=True)


def gci_table(convergence: pd.DataFrame) -> pd.DataFrame:
    """``results/delamination/gci.csv``: per charge law, criterion, case and event concentration
    (:data:`CONVERGED_QUANTITIES`), its value at every spacing of the resolution study, and, where there are three
    spacings, the observed order, the extrapolated value and the fine-grid convergence index of the three finest
    (:func:`sphgag.studies.gci.tidy`; NaN where the event did not happen at all three)."""
    keys = ["charge_law", "criterion", "case"]
    present = [q for q in CONVERGED_QUANTITIES if q in convergence and convergence[q].notna().any()]
    values = [
        runs[keys + ["dx_um"]].assign(quantity=q, value=runs[q].astype(float))
        for _, runs in convergence.groupby(keys, sort=False)
        for q in present
    ]
    if not values:
        return pd.DataFrame(columns=GCI_COLUMNS)
    return gci.tidy(pd.concat(values, ignore_index=True), keys + ["quantity"])[GCI_COLUMNS]
