"""The records of a delamination run and the tables made of them (paper section 2.7, figures 5-7): a row of
``results/delamination/growth.csv`` per damage-and-relax pass (:class:`Pass`), a row of ``summary.csv`` per run
(:func:`run_summary`) and the statistics it holds (growth rates, outcome), the run's labels (:func:`labelled`), what the
pools do at each level of the ramp (:func:`level_classes`, the delamination map) and the pool as a pressurised crack
(:func:`griffith`, the closed form of :func:`sphgag.physics.damage.griffith_pool`).

**Dissipated energy**: raising ``D`` at fixed deformation releases ``dD W_0 V`` (``W_0``
the intact strain energy density of eq. 2.23, ``V`` the particle's reference area), per
unit axial length (``dissipated_energy_kPa_um2``, finite for every run: a sum over the particles whose D grew); divided
by the delaminated length it is an energy per unit delaminated area (``dissipated_energy_J_m2``, J/m^2; NaN where
nothing was delaminated: there is no area to divide by).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ...engine.geometry import Sector
from ...physics import damage, materials
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
    "stop_kind",
    "onset_concentration_mEq_l",
    "runaway_concentration_mEq_l",
    "merge_concentration_mEq_l",
    "limit_concentration_mEq_l",
    "arrested_length_um",
    "final_length_um",
    "passes",
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


#: how a growth run ends (``stop_kind`` of summary.csv), each a result of the run except ``numerical``:
#: ``arrested`` (the pools came to rest at every level up to the ramp's end), ``merged`` (two pools joined),
#: ``unstable`` (growth at a fixed concentration did not arrest: the run stopped at ``max_extent_deg``), ``edge`` (the
#: front reached a symmetry edge), ``layer`` (the front reached another layer or a free surface), ``limit point``
#: (the pools have no equilibrium at the level: the concentration they hold, with the damage frozen, has a maximum
#: below it, found by volume control, after a concentration step with no equilibrium on its path or after a damage
#: pass whose snap came to rest at no equilibrium, under the pass's history: ``limit_concentration_mEq_l``),
#: ``numerical`` (a snap came to rest at no equilibrium and volume control found no limit point below the level, or
#: the run's pass budget ended) and ``not run`` (the run had no damage law to grow by, e.g. no G_c to match: its pools
#: were seeded only). A level whose growth had run away before it lost equilibrium ends ``unstable``.
STOP_KINDS = ("arrested", "merged", "unstable", "edge", "layer", "limit point", "numerical", "not run")
#: the stops at which growth at a fixed concentration did not arrest (their level has a runaway concentration)
RUNAWAY_KINDS = ("merged", "unstable", "edge", "layer")


@dataclass(frozen=True)
class Stop:
    """Where a run ended: ``kind`` (one of :data:`STOP_KINDS`), ``reason`` (what happened, at which level of the ramp
    and after which pass) and ``level``, the ramp's concentration it stopped in [mEq/l]."""

    kind: str
    reason: str
    level: float

    def __post_init__(self):
        if self.kind not in STOP_KINDS:
            raise ValueError(f"stop kind must be one of {', '.join(STOP_KINDS)}, got {self.kind!r}")


@dataclass(frozen=True)
class Critical:
    """The concentrations [mEq/l] at which a run's events happen, found by bisection between the ramp's levels to
    ``bisection_tolerance_mEq_l`` (NaN where the event did not happen): ``onset`` (the onset measure reaches sigma_cr,
    eq. 2.28), ``runaway`` (growth at a fixed concentration no longer arrests), ``merge`` (that growth ends with two
    pools joined) and ``limit`` (the largest concentration the pool holds with its damage frozen, from volume
    control); ``arrested_length``: the delaminated length [um] at the last level that arrested."""

    onset: float = np.nan
    runaway: float = np.nan
    merge: float = np.nan
    limit: float = np.nan
    arrested_length: float = 0.0


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
    stop: Stop,
    critical: Critical,
    *,
    onset_level: float,
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
    last row ``last``, where it stopped (:class:`Stop`), the concentrations of its events (:class:`Critical`) and its
    tallies: the ramp's level of the first onset, the pass at which the pools merged (None if they did not), the
    energy damage released [kPa um^2 per unit axial length], the passes, the snaps and the length they gained [um],
    the largest residual, the lumen pressure carried at the end [mmHg]; ``concentration_step`` of the ramp
    (:func:`growth_rates`)."""
    rate_t, rate_c = growth_rates(growth, concentration_step)
    length = last.length
    first_c, first_length = first_level_growth(growth)
    return dict(
        stop_kind=stop.kind,
        onset_concentration_mEq_l=critical.onset,
        runaway_concentration_mEq_l=critical.runaway,
        merge_concentration_mEq_l=critical.merge,
        limit_concentration_mEq_l=critical.limit,
        arrested_length_um=critical.arrested_length,
        final_length_um=length,
        passes=passes,
        islands=last.islands.count,
        island_particles=last.islands.particles,
        island_distance_um=last.islands.distance_um,
        outcome=outcome(stop.kind, length),
        stop=stop.reason,
        onset_level_mEq_l=onset_level,
        first_growth_concentration_mEq_l=first_c,
        first_level_length_um=first_length,
        max_tip_radial_stress_kPa=float(growth.tip_radial_stress_kPa.max()),
        growth_rate_um_per_pseudo_time=rate_t,
        growth_rate_um_per_mEq_l=rate_c,
        merged=merge_step is not None,
        merge_step=merge_step if merge_step is not None else np.nan,
        dissipated_energy_J_m2=1e-3 * dissipated / length if length > 0 else np.nan,
        dissipated_energy_kPa_um2=dissipated,
        stop_level_mEq_l=stop.level,
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


def outcome(stop_kind: str, length: float) -> str:
    """What a run did: ``merges``, ``grows`` (it ended growing: its growth did not arrest, or the run could not follow
    it), ``arrests`` (it grew and came to rest at the ramp's end) or ``no growth``."""
    if stop_kind == "merged":
        return "merges"
    if length <= 0.0:
        return "no growth"
    return "arrests" if stop_kind == "arrested" else "grows"


#: what a pool does at one level of the concentration ramp (the delamination map, :func:`level_classes`)
LEVEL_CLASSES = ("no onset", "onset, arrested", "propagation", "no equilibrium")


def level_classes(growth: pd.DataFrame, summary: dict, levels) -> pd.DataFrame:
    """What the pools of one run do at each concentration ``levels`` of its ramp (one of :data:`LEVEL_CLASSES`).

    * below the level the run stopped in (``stop_level_mEq_l``), or in it if the run ended arrested there, the pools
      came to a stable state: ``no onset`` if damage has not begun (sigma_cr of eq. 2.28 not reached) by that level,
      ``onset, arrested`` otherwise (whatever they grew on the way);
    * in and beyond the level the run stopped in without arresting: ``propagation`` if it stopped during that level's
      damage passes (merged, maximum extent, symmetry edge, pass limit, a damage pass with no stable state after it,
      or one past the limit point of its history), ``no equilibrium`` if the ramp could not reach the level at all
      (the swollen wall has no stable state there, before any new damage: the limit point of figure 4's swelling, or
      a failure of the discretisation).

    Rows: ``concentration_mEq_l``, ``state``, ``delaminated_length_um`` (at the level's last equilibrium; NaN beyond
    the run).
    """
    stop_level, kind = float(summary["stop_level_mEq_l"]), str(summary["stop_kind"])
    onset = float(summary["onset_concentration_mEq_l"])
    reached = growth.concentration_mEq_l.to_numpy()
    beyond = "propagation" if np.any(np.abs(reached - stop_level) < 1e-9) else "no equilibrium"
    rows = []
    for c in levels:
        at = growth[np.abs(reached - c) < 1e-9]
        stable = c < stop_level - 1e-9 or (kind == "arrested" and c <= stop_level + 1e-9)
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


def griffith(sectors: list[Sector], fracture_energy_J_m2: float, modulus: float, gag: dict, concentration: float):
    """The closed form of a pool as a pressurised straight crack (:func:`sphgag.physics.damage.griffith_pool`), in
    the media's plane-strain modulus ``E'`` [kPa], as summary columns: the concentration at which Griffith's criterion
    makes the longest seeded pool (half-length half its arc) propagate, and the half-length it needs at
    ``concentration``, both under Pi(c) of eqs. (2.25-2.26) (the prescribed law; the conserved law's Pi is lower where
    the pool has swollen)."""
    a = max(0.5 * np.deg2rad(s.angular_extent_deg) * s.centre_radius for s in sectors)
    gag = materials.Gag.of(gag)
    pool = damage.griffith_pool(
        a,
        fracture_energy_J_m2 * damage.J_M2,
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
