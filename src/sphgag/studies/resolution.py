"""The resolution studies' tables: each result at every particle spacing with its observed order, extrapolated value
and grid convergence index (:mod:`sphgag.studies.gci`, Celik et al. 2008), from the rows the studies' simulations wrote:

* figure 4's pools (:mod:`sphgag.studies.convergence`): :func:`swelling_gci` (``results/swelling/gci.csv``) and
  :func:`swelling_band` (``gci_band.csv``, figure 4's bands);
* the delamination runs (:mod:`sphgag.studies.delamination.convergence`): :func:`delamination_gci`
  (``results/delamination/gci.csv``);
* the pressurised annulus (:mod:`sphgag.studies.annulus`): :func:`annulus_orders`.

The simulations do not import this module, so that an edit of the GCI reruns no simulation.
"""

from __future__ import annotations

import pandas as pd

from . import annulus, volume_states
from .gci import TIDY_RESULTS, estimate, tidy
from .inclusion import observed_order

GCI_KEYS = ["charge_law", "pool_model", "model", "case", "pressure_mmHg", "quantity", "at"]
SWELLING_GCI_COLUMNS = [*GCI_KEYS[:-1], "at", "dx_um", "value", *TIDY_RESULTS]
AT_VOLUME = {  # quantity at a given volume ratio J <- its column
    "concentration_at_volume_mEq_l": "concentration_mEq_l",
    "tip_radial_stress_at_volume_kPa": "tip_radial_stress_kPa",
    "top_circ_stress_at_volume_kPa": "top_circ_stress_kPa",
}
AT_CONCENTRATION = {  # quantity at a given concentration <- its column
    "tip_radial_stress_kPa": "tip_radial_stress_kPa",
    "top_circ_stress_kPa": "top_circ_stress_kPa",
    "volume_ratio": "pool_volume_change",
}


def swelling_gci(table: pd.DataFrame, concentrations, pressure_mmHg: float) -> pd.DataFrame:
    """``results/swelling/gci.csv`` from the resolution study's table: per charge law, pool model, wall (column
    ``model``), case and quantity,
    at each volume ratio of the study (``at`` = J: the concentration that holds it, the tip radial and top hoop
    stresses there) and at each of ``concentrations`` (``at`` in mEq/l: the tip radial and top hoop stresses and the
    volume ratio J), its value at every spacing with the observed order, the extrapolated value and the GCI of the
    three finest (:func:`sphgag.studies.gci.tidy`). ``pressure_mmHg``: the study's lumen pressure."""
    base = table.assign(pressure_mmHg=float(pressure_mmHg), volume_ratio=table.pool_volume_change + 1.0)
    rows = []
    at_volume = base[base.stage == volume_states.STAGE]
    for quantity, column in AT_VOLUME.items():
        rows.append(at_volume.assign(quantity=quantity, at=at_volume.volume_ratio.round(6), value=at_volume[column]))
    on_path = base[(base.stage == "converted") & base.concentration_mEq_l.isin([float(c) for c in concentrations])]
    for quantity, column in AT_CONCENTRATION.items():
        value = on_path[column] + (1.0 if column == "pool_volume_change" else 0.0)
        rows.append(on_path.assign(quantity=quantity, at=on_path.concentration_mEq_l, value=value))
    values = pd.concat(rows, ignore_index=True)[GCI_KEYS + ["dx_um", "value"]]
    values = values.sort_values(["charge_law", "pool_model", "model", "case", "quantity", "at", "dx_um"], kind="stable")
    return tidy(values, GCI_KEYS)[SWELLING_GCI_COLUMNS]


BAND_KEYS = ["charge_law", "pool_model", "model", "case", "pressure_mmHg", "stage", "concentration_mEq_l", "quantity"]
BAND_QUANTITIES = ["tip_radial_stress_kPa", "top_circ_stress_kPa"]


def swelling_band(table: pd.DataFrame, pressure_mmHg: float) -> pd.DataFrame:
    """``results/swelling/gci_band.csv``, figure 4's bands: the GCI of the tip radial and top hoop stresses
    (``quantity``) of the resolution study's intact wall and of every converted state on the concentration ramp,
    per charge law, pool model, wall and case; one row per spacing with the estimate of the three finest
    (:func:`sphgag.studies.gci.tidy`). ``pressure_mmHg``: the study's lumen pressure."""
    on_ramp = table[table.stage.isin(["intact", "converted"])].assign(pressure_mmHg=float(pressure_mmHg))
    values = on_ramp.melt(
        id_vars=[k for k in BAND_KEYS if k != "quantity"] + ["dx_um"],
        value_vars=BAND_QUANTITIES,
        var_name="quantity",
    )
    values = values.sort_values(BAND_KEYS + ["dx_um"], kind="stable")
    return tidy(values[BAND_KEYS + ["dx_um", "value"]], BAND_KEYS)


#: the concentrations of a run's events whose convergence the study measures (summary.csv columns)
CONVERGED_QUANTITIES = ("onset_concentration_mEq_l", "runaway_concentration_mEq_l", "merge_concentration_mEq_l")
DELAMINATION_GCI_COLUMNS = ["charge_law", "criterion", "case", "quantity", "dx_um", "value", *TIDY_RESULTS]


def delamination_gci(convergence: pd.DataFrame) -> pd.DataFrame:
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
        return pd.DataFrame(columns=DELAMINATION_GCI_COLUMNS)
    return tidy(pd.concat(values, ignore_index=True), keys + ["quantity"])[DELAMINATION_GCI_COLUMNS]


def annulus_orders(table: pd.DataFrame) -> pd.DataFrame:
    """The observed order of each measure's error at three spacings (the finest three of each case): per
    (``pool_model``, ``outer_ratio``, ``fraction``, ``quantity``) the finest spacing's value, the exact value, its
    relative error, the observed order of the errors (:func:`sphgag.studies.observed_order`) of the two
    finer spacings and of the two coarser ones, and the grid convergence index estimate of the three values
    (:func:`sphgag.studies.gci.estimate`, which does not know the exact value: its extrapolated value is checked
    against it)."""
    rows = []
    below = table[(table.fraction < 1.0) & table.state]
    for (model, ratio, f), case in below.groupby(["pool_model", "outer_ratio", "fraction"], sort=True):
        case = case.sort_values("dx_um").head(3)
        if len(case) < 3:
            continue
        h = case.dx_um.to_numpy()
        for q, exact_column in annulus.MEASURES.items():
            value, exact = case[q].to_numpy(), case[exact_column].to_numpy()
            err = value / exact - 1.0
            est = estimate(h, value)
            rows.append(
                dict(
                    pool_model=model,
                    outer_ratio=ratio,
                    fraction=f,
                    quantity=q,
                    dx_um=h[0],
                    value=value[0],
                    exact=exact[0],
                    error=value[0] / exact[0] - 1.0,
                    order_fine=observed_order(h[:2], err[:2]),
                    order_coarse=observed_order(h[1:], err[1:]),
                    extrapolated=est.extrapolated,
                    extrapolated_error=est.extrapolated / exact[0] - 1.0,
                    gci_fine=est.gci_fine,
                )
            )
    return pd.DataFrame(rows)
