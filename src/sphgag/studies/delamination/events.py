"""The concentrations of a growth run's events between the ramp's levels (section 2.7): the onset, the runaway and the
merge, each bisected between the last level at rest below it and the level it happened in, by probes that continue
from a run's state at rest (:meth:`.growth.GrowthRun.branch`)."""

from __future__ import annotations

import dataclasses
import logging
from typing import TYPE_CHECKING

import numpy as np

from ...engine import snap, solver
from ...engine.loading import Load
from .tables import RUNAWAY_KINDS, Critical, Stop

if TYPE_CHECKING:
    from .growth import GrowthRun

log = logging.getLogger("sphgag")


class LimitPoint(solver.SimulationError):
    """A concentration step past the largest concentration the pools hold with their damage frozen (``limit``,
    mEq/l, found by volume control: :func:`sphgag.engine.pool_volume.continue_path`)."""

    def __init__(self, run: str, load: Load, reason: str, limit: float):
        super().__init__(run, load, reason)
        self.limit = float(limit)


def _reaches_onset(probe: GrowthRun, c: float) -> bool:
    """At ``c`` (history fixed, no damage yet) the onset measure reaches sigma_cr at a candidate (eq. 2.28); a
    concentration without equilibrium counts as reached."""
    try:
        probe.raise_concentration(c)
    except (LimitPoint, snap.NoStableState):
        return True
    return probe.next_history().begun


#: growth at a fixed concentration has run away once it has taken a pool to this many times the largest extent at rest
#: it started the level from: a probe of the runaway concentration stops there (or at ``max_extent_deg``, the run's own
#: cap, if smaller), and a run whose level got that far before a snap came to rest at no equilibrium is ``unstable``
RUNAWAY_EXTENT_FACTOR = 2.0


def _runs_away(probe: GrowthRun, c: float) -> bool:
    """Growth from the probe's state at rest, at ``c``, does not arrest (or ``c`` has no equilibrium): it merges,
    reaches an edge or a layer, or takes a pool to :data:`RUNAWAY_EXTENT_FACTOR` times its extent at rest."""
    settings = probe.settings
    cap = min(settings.max_extent_deg, RUNAWAY_EXTENT_FACTOR * float(probe.front.extent_deg(probe.hist).max()))
    probe.settings = dataclasses.replace(settings, max_extent_deg=cap)
    try:
        return probe.settle_level(c)[0] != "arrested"
    finally:  # a probe that arrests is where the next probes start, with the run's own cap
        probe.settings = settings


def critical(run: GrowthRun, stop: Stop, before: GrowthRun, before_onset: GrowthRun | None) -> Critical:
    """The concentrations of the run's events (:class:`Critical`), each bisected between the last level below
    it (the run at rest there: ``before_onset`` for the onset, ``before`` for the runaway) and the level it
    happened in; ``run`` is unchanged."""
    onset = runaway = np.nan
    if before_onset is not None:
        onset = _bisect(run, before_onset, run.onset_c, _reaches_onset, "onset")
    if stop.kind in RUNAWAY_KINDS:
        runaway = _bisect(run, before, stop.level, _runs_away, "runaway")
    run.model.set_props(run.material)
    run.solver.reset()
    return Critical(
        onset=onset,
        runaway=runaway,
        merge=runaway if stop.kind == "merged" else np.nan,
        limit=run.limit_c,
        arrested_length=before.rows[-1].length if before.rows else 0.0,
    )


def _bisect(run: GrowthRun, below: GrowthRun, above: float, happens, what: str) -> float:
    """The concentration between ``below``'s (at rest, the event not yet happened) and ``above`` (where it
    happened) at which ``happens(probe, c)`` first holds, bisected to ``bisection_tolerance_mEq_l``: the middle of
    the last bracket. Each probe continues from the highest state at rest below it (:meth:`GrowthRun.branch`)."""
    lo, hi = below.concentration, float(above)
    while hi - lo > run.settings.bisection_tolerance_mEq_l:
        c = 0.5 * (lo + hi)
        probe = below.branch()
        probe.name = f"{run.name} ({what} probe)"
        run.model.set_props(below.material)
        run.solver.reset()
        if happens(probe, c):
            hi = c
        else:
            lo, below = c, probe
    log.info("[%s] %s concentration %.2f mEq/l (between %.2f and %.2f)", run.name, what, 0.5 * (lo + hi), lo, hi)
    return 0.5 * (lo + hi)
