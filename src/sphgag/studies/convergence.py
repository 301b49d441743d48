"""Resolution study of the GAG-pool stresses (figure 4 protocol at several particle spacings).

For one particle spacing: the passive homeostatic state (figure 2b), pressurised
to the study's lumen pressure under pressure control, then every chosen pool
converted and swollen (:func:`swell_cases`, rule ``swelling_convergence_dx``,
which saves the states), then measured (:func:`measure`, rule
``swelling_convergence_stresses``, so that ``swelling.probe_length_um`` reruns
only the measurement). The rows carry the quantities whose convergence the
study measures: the tip radial stress averaged over
``swelling.probe_length_um`` and its particle peak, the top hoop stress and the
pool's volume change, with the residual of each converged state.
"""

from __future__ import annotations

import pandas as pd

from . import artery, protocols

COLUMNS = [
    "dx_um",
    "particles",
    "case",
    "concentration_mEq_l",
    "tip_radial_stress_kPa",
    "tip_peak_radial_stress_kPa",
    "top_circ_stress_kPa",
    "pool_volume_change",
    "residual",
]


def swell_cases(
    dx: float,
    bilayer: dict,
    numerics: dict,
    homeostasis: dict,
    swelling: dict,
    gag: dict,
    cases: dict,
    pressure_mmHg: float,
    name: str = "convergence",
) -> dict[str, list[protocols.PoolState]]:
    """The converged states of every study pool at particle spacing ``dx`` [um]: the passive wall pressurised at
    this spacing, then each pool converted and swollen (:func:`sphgag.studies.protocols.swell_pool`)."""
    p = dict(bilayer, dx_um=float(dx))
    wall = artery.bilayer_model(p, numerics, name=name)
    h = protocols.homeostasis(wall, numerics, homeostasis)
    start = protocols.pressurise(wall, h.state, pressure_mmHg, numerics)
    return {
        case: protocols.swell_pool(
            case_model(dx, bilayer, numerics, gag, entry, f"{name}_{case}"), start, numerics, swelling
        )
        for case, entry in cases.items()
    }


def case_model(dx: float, bilayer: dict, numerics: dict, gag: dict, entry: dict, name: str):
    """The bi-layered wall at spacing ``dx`` with the pool ``entry`` (a ``swelling.cases`` entry) seeded."""
    return artery.bilayer_model(
        dict(bilayer, dx_um=float(dx)), numerics, name=name, pool=artery.pool_sector(entry), gag=gag
    )


def measure(
    dx: float,
    bilayer: dict,
    numerics: dict,
    gag: dict,
    cases: dict,
    states: dict[str, list[protocols.PoolState]],
    probe_length: float,
    name: str = "convergence",
) -> pd.DataFrame:
    """Rows of ``results/swelling/convergence.csv`` for one particle spacing (converted stage only): the pool
    stresses (:func:`sphgag.studies.protocols.pool_table`) of the states of :func:`swell_cases`."""
    tables = []
    for case, entry in cases.items():
        model = case_model(dx, bilayer, numerics, gag, entry, f"{name}_{case}")
        table = protocols.pool_table(model, states[case], artery.pool_sector(entry), probe_length, gag)
        tables.append(table[table.stage == "converted"].assign(dx_um=float(dx), particles=model.n, case=case))
    out = pd.concat(tables, ignore_index=True)
    return out[COLUMNS + [c for c in out.columns if c not in COLUMNS]]


def bar(table: pd.DataFrame, concentration: float, columns=("tip_radial_stress_kPa", "pool_volume_change")):
    """Relative change of ``columns`` at ``concentration`` between the two finest spacings, per case."""
    rows = []
    fine = sorted(table.dx_um.unique())[:2]
    for case, g in table.groupby("case", sort=False):
        at = g[(g.concentration_mEq_l - concentration).abs() < 1e-9].set_index("dx_um")
        row = dict(case=case, dx_fine_um=fine[0], dx_coarse_um=fine[1])
        for col in columns:
            a, b = at.loc[fine[0], col], at.loc[fine[1], col]
            row[f"{col}_change"] = float(abs(a - b) / max(abs(a), 1e-12))
        rows.append(row)
    return pd.DataFrame(rows)
