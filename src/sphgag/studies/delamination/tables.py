"""The records of a delamination run and the tables made of them (paper section 2.7, figures 5-7): a row of
``results/delamination/growth.csv`` per damage-and-relax pass (:class:`Pass`), a row of ``summary.csv`` per run
(:func:`run_summary`) and the statistics it holds (growth rates, outcome), the run's labels (:func:`labelled`), what the
pools do at each level of the ramp (:func:`level_classes`, the delamination map) and the pool as a pressurised crack
(:func:`griffith`, the closed form of :func:`sphgag.physics.fracture.griffith_pool`).

**Dissipated energy**: raising ``D`` at fixed deformation releases ``dD W_0 V`` (``W_0``
the intact strain energy density of eq. 2.23, ``V`` the particle's reference area), per
unit axial length; divided by the delaminated length it is an energy per unit
delaminated area (J/m^2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ...engine.geometry import Sector
from ...physics import fracture, materials
from .front import Islands
from .settings import Settings

# the labels of a run (:func:`labelled`), the first columns of both tables
RUN_LABELS = ["case", "sigma_cr_kPa", "criterion", "candidates", "dx_um", "damage_law", "fracture_energy_J_m2"]
GROWTH_COLUMNS = [
    *RUN_LABELS,
    "step",
    "pseudo_time",
    "concentration_mEq_l",
    "converted_particles",
    "converted_interior",
    "converted_exterior",
    "delaminated_length_um",
    "islands",
    "island_particles",
    "island_distance_um",
    "tip_radial_stress_kPa",
    "residual",
    "snap",
]
SUMMARY_COLUMNS = [
    *RUN_LABELS,
    "onset_concentration_mEq_l",
    "final_length_um",
    "islands",
    "island_particles",
    "island_distance_um",
    "outcome",
    "stop",
    "snaps",
    "snap_length_um",
    "growth_rate_um_per_pseudo_time",
    "growth_rate_um_per_mEq_l",
    "merged",
    "merge_step",
    "dissipated_energy_J_m2",
    "max_residual",
]


@dataclass
class Pass:
    """One damage-and-relax pass (a row of growth.csv, before the run's labels)."""

    step: int
    concentration: float
    converted: tuple
    length: float
    islands: Islands
    tip_stress: float
    residual: float
    snap: bool = False  # reached through a snap (sphgag.engine.snap)


@dataclass
class Result:
    """What a run returns: its rows (growth.csv before the labels), its summary (:func:`run_summary`), its snapshots and
    its final state."""

    growth: pd.DataFrame
    summary: dict
    snapshots: list = field(default_factory=list)  # (step, solver.State, ParticleHistory)
    final: tuple | None = None  # (solver.State, ParticleHistory) at the end


def growth_table(rows: list[Pass]) -> pd.DataFrame:
    """The rows of a run (growth.csv before the run's labels), one per :class:`Pass`."""
    return pd.DataFrame(
        [
            dict(
                step=k,
                pseudo_time=r.step,
                concentration_mEq_l=r.concentration,
                converted_particles=r.converted[0],
                converted_interior=r.converted[1],
                converted_exterior=r.converted[2],
                delaminated_length_um=r.length,
                islands=r.islands.count,
                island_particles=r.islands.particles,
                island_distance_um=r.islands.distance_um,
                tip_radial_stress_kPa=r.tip_stress,
                residual=r.residual,
                snap=r.snap,
            )
            for k, r in enumerate(rows)
        ]
    )


def run_summary(
    growth: pd.DataFrame,
    last: Pass,
    stop: str,
    stop_level: float,
    *,
    onset_concentration: float,
    merge_step: int | None,
    dissipated: float,
    passes: int,
    snaps: int,
    snap_length: float,
    max_residual: float,
    pressure_mmHg: float,
    concentration_step: float,
) -> dict:
    """The summary of a run (summary.csv before the run's labels) from its rows ``growth`` (:func:`growth_table`), its
    last row ``last``, why it stopped (``stop``) and in which level of the ramp (``stop_level`` [mEq/l]), and its
    tallies: the concentration of the first onset, the pass at which the pools merged (None if they did not), the
    energy damage released [kPa um^2 per unit axial length], the passes, the snaps and the length they gained [um],
    the largest residual, the lumen pressure carried at the end [mmHg]; ``concentration_step`` of the ramp
    (:func:`growth_rates`)."""
    rate_t, rate_c = growth_rates(growth, concentration_step)
    length = last.length
    first_c, first_length = first_level_growth(growth)
    return dict(
        onset_concentration_mEq_l=onset_concentration,
        final_length_um=length,
        islands=last.islands.count,
        island_particles=last.islands.particles,
        island_distance_um=last.islands.distance_um,
        outcome=outcome(stop, length, merge_step is not None),
        first_growth_concentration_mEq_l=first_c,
        first_level_length_um=first_length,
        max_tip_radial_stress_kPa=float(growth.tip_radial_stress_kPa.max()),
        growth_rate_um_per_pseudo_time=rate_t,
        growth_rate_um_per_mEq_l=rate_c,
        merged=merge_step is not None,
        merge_step=merge_step if merge_step is not None else np.nan,
        dissipated_energy_J_m2=1e-3 * dissipated / length if length > 0 else np.nan,
        dissipated_energy_kPa_um2=dissipated,
        stop=stop,
        stop_level_mEq_l=stop_level,
        passes=passes,
        snaps=snaps,
        snap_length_um=snap_length,
        max_residual=max_residual,
        pressure_mmHg=pressure_mmHg,
    )


def growth_rates(growth: pd.DataFrame, concentration_step: float) -> tuple[float, float]:
    """Delaminated length per pseudo-time and per mEq/l, over the part of the run in which the pools grew.

    Per pseudo-time: final length / passes from the last pass before the first rupture to the end. Per mEq/l:
    final length / concentration from the level before the first rupture's to the end (so that growth within a
    single level still has a finite rate). Both are 0 without growth.
    """
    grown = growth[growth.delaminated_length_um > 0]
    if not len(grown):
        return 0.0, 0.0
    length = float(growth.delaminated_length_um.iloc[-1])
    first = grown.iloc[0]
    t_span = growth.pseudo_time.iloc[-1] - first.pseudo_time + 1
    c_span = growth.concentration_mEq_l.iloc[-1] - first.concentration_mEq_l + concentration_step
    return length / t_span, length / c_span


def first_level_growth(growth: pd.DataFrame) -> tuple[float, float]:
    """``(concentration, length)``: the first concentration level at which the pools grew, and the length they grew
    at that level (snaps included); ``(nan, 0)`` without growth."""
    grew = growth.delaminated_length_um.diff() > 0
    if not grew.any():
        return np.nan, 0.0
    c = float(growth.concentration_mEq_l[grew].iloc[0])
    level = growth[np.isclose(growth.concentration_mEq_l, c)].delaminated_length_um
    return c, float(level.iloc[-1] - level.iloc[0])


def outcome(stop: str, length: float, merged: bool) -> str:
    """What a run did: ``merges``, ``grows`` (it ended growing, for the reason in ``stop``), ``arrests`` (it grew and
    stopped at the highest concentration) or ``no growth``."""
    if merged:
        return "merges"
    if length <= 0.0:
        return "no growth"
    return "arrests" if stop == "arrested" else "grows"


#: what a pool does at one level of the concentration ramp (the delamination map, :func:`level_classes`)
LEVEL_CLASSES = ("no onset", "onset, arrested", "propagation", "no equilibrium")


def level_classes(growth: pd.DataFrame, summary: dict, levels) -> pd.DataFrame:
    """What the pools of one run do at each concentration ``levels`` of its ramp (one of :data:`LEVEL_CLASSES`).

    * below the level the run stopped in (``stop_level_mEq_l``), or in it if the run ended arrested there, the pools
      came to a stable state: ``no onset`` if damage has not begun (sigma_cr of eq. 2.28 not reached) by that level,
      ``onset, arrested`` otherwise (whatever they grew on the way);
    * in and beyond the level the run stopped in without arresting: ``propagation`` if it stopped during that level's
      damage passes (merged, maximum extent, symmetry edge, pass limit, or a damage pass with no stable state after
      it), ``no equilibrium`` if the ramp could not reach the level at all (the swollen wall has no stable state
      there, before any new damage: the limit point of figure 4's swelling, or a failure of the discretisation).

    Rows: ``concentration_mEq_l``, ``state``, ``delaminated_length_um`` (at the level's last equilibrium; NaN beyond
    the run).
    """
    stop_level, stop = float(summary["stop_level_mEq_l"]), str(summary["stop"])
    onset = float(summary["onset_concentration_mEq_l"])
    reached = growth.concentration_mEq_l.to_numpy()
    beyond = "propagation" if np.any(np.abs(reached - stop_level) < 1e-9) else "no equilibrium"
    rows = []
    for c in levels:
        at = growth[np.abs(reached - c) < 1e-9]
        stable = c < stop_level - 1e-9 or (stop == "arrested" and c <= stop_level + 1e-9)
        if stable:
            state = "onset, arrested" if onset <= c + 1e-9 else "no onset"
        else:
            state = beyond
        length = float(at.delaminated_length_um.iloc[-1]) if len(at) else np.nan
        rows.append(dict(concentration_mEq_l=float(c), state=state, delaminated_length_um=length))
    return pd.DataFrame(rows)


def labelled(result: Result, case: str, settings: Settings, dx: float) -> tuple[pd.DataFrame, pd.DataFrame]:
    """``(growth, summary)`` of one run with the labels of ``results/delamination/{growth,summary}.csv``."""
    labels = dict(
        case=case,
        sigma_cr_kPa=settings.critical_stress_kPa,
        criterion=settings.criterion,
        candidates=settings.candidates,
        dx_um=float(dx),
        damage_law=settings.damage_law,
        fracture_energy_J_m2=settings.fracture_energy_J_m2,
    )  # the keys of RUN_LABELS
    growth = result.growth.assign(**labels)[GROWTH_COLUMNS]
    summary = pd.DataFrame([dict(labels, **result.summary)])
    return growth, summary[SUMMARY_COLUMNS + [c for c in summary.columns if c not in SUMMARY_COLUMNS]]


def paper_law(table: pd.DataFrame) -> pd.DataFrame:
    """The rows of a delamination table grown by eq. (2.28) as printed (the paper's figures and claims)."""
    return table[table.damage_law == "paper"] if "damage_law" in table else table


def griffith(sectors: list[Sector], fracture_energy_J_m2: float, modulus: float, gag: dict, concentration: float):
    """The closed form of a pool as a pressurised straight crack (:func:`sphgag.physics.fracture.griffith_pool`), in
    the media's plane-strain modulus ``E'`` [kPa], as summary columns: the concentration at which Griffith's criterion
    makes the longest seeded pool (half-length half its arc) propagate, and the half-length it needs at
    ``concentration``, both under Pi(c) of eqs. (2.25-2.26) (the prescribed law; the conserved law's Pi is lower where
    the pool has swollen)."""
    a = max(0.5 * np.deg2rad(s.angular_extent_deg) * s.centre_radius for s in sectors)
    gag = materials.Gag.of(gag)
    pool = fracture.griffith_pool(
        a,
        fracture_energy_J_m2 * fracture.J_M2,
        modulus,
        concentration,
        gag.bath_concentration_mEq_l,
        gag.temperature_K,
    )
    return dict(
        griffith_pool_half_length_um=float(a),
        griffith_pressure_kPa=float(pool.pressure),
        griffith_concentration_mEq_l=float(pool.concentration),
        griffith_half_length_um=float(pool.half_length),
    )
