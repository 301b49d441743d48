"""Delamination and coalescence: damage-driven growth of GAG pools (paper section 2.7, figures 5-7).

One module per concept:

* :mod:`.settings`: the settings of one run (:class:`Settings`) and its concentration ramp;
* :mod:`.front`: the pools' front: damage candidates, connectivity of the converted particles, delaminated length,
  islands (:class:`Front`);
* :mod:`.growth`: the staggered protocol of one run, seeding, damage passes, snaps (:class:`GrowthRun`,
  :func:`grow`);
* :mod:`.tables`: a run's records and the tables of them: rows, summary and its statistics, labels, the
  delamination map's classes, the pool as a pressurised crack (:func:`griffith`);
* :mod:`.snapshots`: a run's snapshots on disk, from which it can restart;
* :mod:`.convergence`: the resolution study;
* :mod:`.runs`: the pipeline's runs: one pool set grown and labelled (:func:`delaminate`), one point of the
  delamination map (:func:`map_point`).

The names the pipeline, the tests and the benchmarks use are imported here.
"""

from .convergence import CONVERGED_QUANTITIES, GCI_COLUMNS, convergence_study, gci_table
from .front import CONTACT_DX, Front, Islands
from .growth import DamageUpdate, GrowthRun, LimitPoint, grow, intact_energy, onset_measure, seeded_only
from .runs import crack_modulus, delaminate, fracture_energy, map_point
from .settings import MATCHED, Settings
from .snapshots import load_snapshot, save_snapshots
from .tables import (
    GROWTH_COLUMNS,
    LEVEL_CLASSES,
    STOP_KINDS,
    SUMMARY_COLUMNS,
    Critical,
    Pass,
    Result,
    Stop,
    first_level_growth,
    griffith,
    growth_rates,
    growth_table,
    labelled,
    level_classes,
    outcome,
    paper_law,
    run_summary,
)

__all__ = [
    "CONTACT_DX",
    "CONVERGED_QUANTITIES",
    "MATCHED",
    "GCI_COLUMNS",
    "STOP_KINDS",
    "Critical",
    "LimitPoint",
    "Stop",
    "gci_table",
    "GROWTH_COLUMNS",
    "LEVEL_CLASSES",
    "SUMMARY_COLUMNS",
    "DamageUpdate",
    "Front",
    "GrowthRun",
    "Islands",
    "Pass",
    "Result",
    "Settings",
    "convergence_study",
    "crack_modulus",
    "delaminate",
    "fracture_energy",
    "first_level_growth",
    "griffith",
    "grow",
    "growth_rates",
    "growth_table",
    "intact_energy",
    "labelled",
    "level_classes",
    "load_snapshot",
    "map_point",
    "onset_measure",
    "outcome",
    "paper_law",
    "run_summary",
    "save_snapshots",
    "seeded_only",
]
