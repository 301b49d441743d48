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

import logging

import pandas as pd

from ..engine import solver
from ..engine.numerics import Numerics
from . import artery, volume_states
from .pool_swelling import PoolState, pool_table, swell_pool
from .wall_loading import homeostasis as homeostasis_
from .wall_loading import wall_at

log = logging.getLogger("sphgag")

COLUMNS = [
    "dx_um",
    "particles",
    "model",
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
    numerics: Numerics,
    homeostasis: dict,
    swelling: dict,
    gag: dict,
    cases: dict,
    pressure_mmHg: float,
    calibration: dict,
    active: bool = False,
    name: str = "convergence",
    volume_ratios=(),
    graded: dict | None = None,
) -> dict[str, list[PoolState]]:
    """The converged states of every study pool at particle spacing ``dx`` [um]: the passive or ``active`` wall at
    this spacing at ``pressure_mmHg`` by the path of the pressure-diameter sweep (:func:`sphgag.studies.wall_loading.
    wall_at`; ``calibration``: the ``bilayer_calibration`` section, its activation pressure and steps), then each
    pool converted and swollen (:func:`sphgag.studies.pool_swelling.swell_pool`), followed by the states at which it
    holds each of ``volume_ratios`` (:func:`sphgag.studies.volume_states.at_volume_ratios`, stage ``at volume``).
    Each pool's wall is laid out around it (its ends cell boundaries, graded by ``graded``), the pressurised wall's
    state carried onto it (:func:`sphgag.studies.artery.carried`)."""
    start = pressurised_wall(dx, bilayer, numerics, homeostasis, calibration, active, pressure_mmHg, name)
    wall = dict(bilayer, dx_um=float(dx))
    out = {}
    for case, entry in cases.items():
        model = case_model(dx, bilayer, numerics, gag, entry, f"{name}_{case}", graded)
        carried = solver.State(start.load, artery.carried(wall, start.x, model.layout), None, None)
        path = swell_pool(model, carried, numerics, swelling)
        out[case] = path + list(volume_states.at_volume_ratios(model, path, volume_ratios, numerics).values())
    return out


def series(states: dict[str, list[PoolState]], run: str) -> list:
    """The states of :func:`swell_cases` as one saved series (:func:`sphgag.records.state.save_series`: each state's
    info with its case), each case's path and its concentrations at the volume ratios logged."""
    out = [(s.x, s.load, dict(s.info(), case=case), None) for case, ss in states.items() for s in ss]
    largest = max(s.residual for ss in states.values() for s in ss)
    log.info("[%s] %d converged states of %d pools, largest residual %.2e", run, len(out), len(states), largest)
    for case, ss in states.items():
        path = [s for s in ss if s.stage == "converted"]
        held = ", ".join(f"{s.concentration:.4g}" for s in ss if s.stage == "at volume") or "none"
        log.info(
            "[%s] case %s: path up to %g mEq/l (end: %s); concentrations at the volume ratios: %s",
            run,
            case,
            path[-1].concentration,
            ss[-1].path_end,
            held,
        )
    return out


def pressurised_wall(
    dx: float,
    bilayer: dict,
    numerics: Numerics,
    homeostasis: dict,
    calibration: dict,
    active: bool,
    pressure_mmHg: float,
    name: str,
):
    """The converged state of the passive or ``active`` wall at particle spacing ``dx`` [um] and ``pressure_mmHg``:
    the homeostatic state (figure 2b), then the path of the pressure-diameter sweep
    (:func:`sphgag.studies.wall_loading.wall_at`)."""
    wall = artery.bilayer_model(dict(bilayer, dx_um=float(dx)), numerics, name=name)
    path_solver = numerics.solver(wall)
    h = homeostasis_(wall, numerics, homeostasis, path_solver=path_solver)
    return wall_at(wall, h.state, numerics, calibration, active, pressure_mmHg, path_solver)


def case_model(dx: float, bilayer: dict, numerics: Numerics, gag: dict, entry: dict, name: str, graded=None):
    """The bi-layered wall at spacing ``dx`` with the pool ``entry`` (a ``swelling.cases`` entry) seeded, laid out
    around it (graded by ``graded``, :mod:`sphgag.engine.geometry`)."""
    return artery.bilayer_model(dict(bilayer, dx_um=float(dx)), numerics, name, artery.pool_sector(entry), gag, graded)


def measure(
    dx: float,
    bilayer: dict,
    numerics: Numerics,
    gag: dict,
    cases: dict,
    states: dict[str, list[PoolState]],
    probe_length: float,
    wall: str = "passive",
    name: str = "convergence",
    graded: dict | None = None,
    tip_probe: str = "region",
) -> pd.DataFrame:
    """Rows of ``results/swelling/convergence.csv`` for one particle spacing and ``wall`` (column ``model``:
    passive or active): the pool stresses (:func:`sphgag.studies.pool_swelling.pool_table`, the tips of
    ``tip_probe``) of the states of :func:`swell_cases`, the intact wall, the converted pools on their path and the
    pools at their volume ratios."""
    tables = []
    for case, entry in cases.items():
        model = case_model(dx, bilayer, numerics, gag, entry, f"{name}_{case}", graded)
        table = pool_table(model, states[case], artery.pool_sector(entry), probe_length, gag, tip_probe)
        kept = table[table.stage.isin(["intact", "converted", volume_states.STAGE])]
        tables.append(kept.assign(dx_um=float(dx), particles=model.n, model=wall, case=case))
    out = pd.concat(tables, ignore_index=True)
    return out[COLUMNS + [c for c in out.columns if c not in COLUMNS]]


def measure_saved(
    saved,
    dx: float,
    bilayer: dict,
    numerics: Numerics,
    gag: dict,
    cases: dict,
    probe_length: float,
    wall: str,
    name: str,
    graded: dict | None = None,
) -> pd.DataFrame:
    """The rows of one run of the study (rule ``swelling_convergence_stresses``) from its saved states ``saved`` (the
    series of :func:`series`): :func:`measure`, first the run's charge law and pool model; each case's last state
    logged."""
    states = {case: [PoolState.from_saved(s) for s in saved if s.info["case"] == case] for case in cases}
    table = measure(dx, bilayer, numerics, gag, cases, states, probe_length, wall, name, graded)
    table.insert(0, "charge_law", gag["charge_law"])
    table.insert(1, "pool_model", table.pop("pool_model"))
    for case, g in table.groupby("case", sort=False):
        last = g.iloc[-1]
        log.info(
            "[%s] case %s, %d particles: at %g mEq/l tip %.1f kPa (peak %.1f), top %.1f kPa, pool volume change %+.3f",
            name,
            case,
            int(last.particles),
            last.concentration_mEq_l,
            last.tip_radial_stress_kPa,
            last.tip_peak_radial_stress_kPa,
            last.top_circ_stress_kPa,
            last.pool_volume_change,
        )
    return table


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
