"""The settings of one delamination run (paper section 2.7) and the choices they name.

* :class:`Settings`: the ``delamination`` configuration section (config/schema.yaml), its damage law among them
  (``damage_law``: eq. 2.28 as printed by default), with the run's own critical stress sigma_cr, onset criterion and,
  for a law with a fracture energy, G_c, and the concentration ramp they make.
* **Onset criteria** (:data:`CRITERIA`, ``delamination.criteria``, wildcard ``{criterion}``): the radial Cauchy stress
  a damage candidate compares with sigma_cr in eq. (2.28).
* **Candidate rules** (:data:`CANDIDATE_RULES`, ``delamination.candidates``): which intact particles the damage law
  tests against sigma_cr. Every rule starts from the same set, the authors' script's
  (:meth:`sphgag.studies.delamination.front.Front.candidates`): tissue particles of the media, off the wall surfaces,
  in a pool's radial band (the reference radii of its seeded sector) and within ``delamination.candidate_window_deg``
  of the pool's current angular extent. A rule admits a subset of it, pool by pool. The paper compares "the radial
  stress at the tip of the pool" with sigma_cr (section 2.7): the particles in contact with the pool (``contact``);
  the authors' script tests the whole window (``window``), so damage can form islands ahead of a pool
  (docs/physics.md, "Damage candidates").

A criterion is an :class:`OnsetCriterion` and a rule a :class:`CandidateRule`, each a
:class:`sphgag.registry.Variant` of its registry. The configuration's schema (:func:`sphgag.config.schema`) is built
from both registries, and the pipeline's wildcard ``{criterion}`` from the criteria's, so a new criterion or rule is
one function and one entry here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields

import numpy as np

from ...engine import measure
from ...engine.history import ParticleHistory
from ...engine.model import Evaluation, Model
from ...physics import damage
from ...registry import Registry, Variant

#: the G_c of a run of the damage law with a fracture energy (its wildcard ``gc``: J/m^2) that is no number but the
#: energy the paper's damage law dissipated in its matched run (the same pool set at the same sigma_cr and criterion)
MATCHED = "paper"


@dataclass(frozen=True)
class OnsetCriterion(Variant):
    """``measure(model, ev, history, candidates, settings)``: the radial Cauchy stress (eq. 2.10, current polar
    frame) at the ``candidates`` that the onset test of eq. (2.28) compares with sigma_cr (``settings``: the run's
    :class:`sphgag.studies.delamination.settings.Settings`). ``title``: what the measure is; ``paper``: the paper's
    measure. ``averages``: the measure averages over ``settings.averaging_length_um``, a key the criterion then owns
    (:meth:`check`: that length at least the coarsest particle spacing it is run at)."""

    name: str
    title: str
    measure: Callable[[Model, Evaluation, ParticleHistory, np.ndarray, object], np.ndarray]
    averages: bool = False
    paper: bool = False

    @property
    def keys(self) -> tuple[str, ...]:
        return ("delamination.averaging_length_um",) if self.averages else ()

    def check(self, config, key: str) -> None:
        """An averaging criterion averages over more than one particle at the coarsest spacing it is run at (the
        wall's ``bilayer.dx_um`` and ``delamination.convergence.dx_um``)."""
        if not self.averages:
            return
        de = config["delamination"]
        coarsest = max([config.get("bilayer", {}).get("dx_um", 0)] + de["convergence"]["dx_um"])
        if de["averaging_length_um"] < coarsest:
            raise ValueError(
                f"delamination.averaging_length_um = {de['averaging_length_um']} is below the coarsest "
                f"particle spacing ({coarsest:g} um): the average of {self.name} would be a single particle's value"
            )


def particle_stress(model: Model, ev: Evaluation, hist: ParticleHistory, cand: np.ndarray, settings) -> np.ndarray:
    """The candidate particle's own radial stress (the paper's measure)."""
    return measure.cauchy_polar(ev)[0][cand]


def averaged_stress(model: Model, ev: Evaluation, hist: ParticleHistory, cand: np.ndarray, settings) -> np.ndarray:
    """The radial stress of the intact pool layers (the media) averaged over a disc of diameter
    ``settings.averaging_length_um`` around the candidate (:func:`sphgag.engine.measure.averaging_matrix`): the same
    length at every resolution."""
    lay = model.layout
    intact = np.flatnonzero(lay.pool_mask & ~hist.gag)
    W = measure.averaging_matrix(lay, settings.averaging_length_um, intact, rows=cand)
    return W @ measure.cauchy_polar(ev)[0]


#: the registry of onset criteria, by name (``delamination.criteria``, wildcard ``{criterion}``; the paper's first)
CRITERIA: Registry[OnsetCriterion] = Registry(
    "onset criterion",
    (
        OnsetCriterion(
            "particle", "the candidate particle's own radial stress (the paper's)", particle_stress, paper=True
        ),
        OnsetCriterion(
            "averaged",
            "the intact media's radial stress averaged over a disc of averaging_length_um",
            averaged_stress,
            averages=True,
        ),
    ),
)


@dataclass(frozen=True)
class CandidateRule(Variant):
    """``admits(front, history, pool)``: the particles (a mask over all of them) that may be candidates of pool
    ``pool`` (an index of ``front.sectors``), within the window of :class:`sphgag.studies.delamination.front.Front`.
    ``title``: which particles; ``paper``: the rule of the paper's text. A rule owns no key beyond
    ``delamination.candidates`` (the window, ``delamination.candidate_window_deg``, is every rule's)."""

    name: str
    title: str
    admits: Callable[[object, ParticleHistory, int], np.ndarray]
    paper: bool = False


def anywhere(front, hist: ParticleHistory, pool: int) -> np.ndarray:
    """Every particle of the window (the authors' script)."""
    return np.ones(hist.n, dtype=bool)


def in_contact(front, hist: ParticleHistory, pool: int) -> np.ndarray:
    """The particles with a GAG particle of the pool (seeded or converted) within the contact distance in the
    reference configuration (:meth:`sphgag.studies.delamination.front.Front.touching`): the tip of the pool (the
    paper)."""
    return front.touching(hist, pool)


#: the registry of candidate rules, by name (``delamination.candidates``; the paper's first)
CANDIDATE_RULES: Registry[CandidateRule] = Registry(
    "candidate rule",
    (
        CandidateRule(
            "contact", "the particles touching the pool, within the window (the paper's text)", in_contact, paper=True
        ),
        CandidateRule("window", "every particle within the window of the pool (the authors' script)", anywhere),
    ),
)


@dataclass(frozen=True)
class Settings:
    """The ``delamination`` configuration of one run (see config/schema.yaml)."""

    critical_stress_kPa: float
    rupture_stretch_increment: float
    criterion: str
    averaging_length_um: float
    candidate_window_deg: float
    damage_tolerance: float
    concentration_step_mEq_l: float
    max_concentration_mEq_l: float
    max_passes: int
    max_extent_deg: float
    conversion_steps: int
    bisection_tolerance_mEq_l: float = 0.5  # onset, runaway and merge concentrations are bisected to this bracket
    # damage.DAMAGE_LAWS: the section's law (eq. 2.28 as printed by default), or the fracture-energy runs' law
    damage_law: str = damage.DAMAGE_LAWS.paper.name
    fracture_energy_J_m2: float = np.nan  # G_c of the fracture_energy law
    # CANDIDATE_RULES: the particles touching the pool (the paper), or the window
    candidates: str = "contact"

    def __post_init__(self):
        if self.criterion not in CRITERIA:
            raise ValueError(f"criterion must be one of {', '.join(CRITERIA)}, got {self.criterion!r}")
        if self.candidates not in CANDIDATE_RULES:
            raise ValueError(f"candidates must be one of {', '.join(CANDIDATE_RULES)}, got {self.candidates!r}")
        if self.damage_law not in damage.DAMAGE_LAWS:
            raise ValueError(f"damage_law must be one of {', '.join(damage.DAMAGE_LAWS)}, got {self.damage_law!r}")

    @classmethod
    def config_keys(cls) -> tuple[str, ...]:
        """The keys of the ``delamination`` configuration section that every run reads (:meth:`from_config`); sigma_cr,
        the onset criterion and the G_c of a fracture-energy run are each run's own."""
        own = ("critical_stress_kPa", "criterion", "fracture_energy_J_m2")
        return tuple(f.name for f in fields(cls) if f.name not in own)

    @classmethod
    def params(cls, de: dict, *own: str, **extra) -> dict:
        """A delamination job's settings (its rule's params ``delamination``), in one shape for every job: the keys of
        the section ``de`` that every run reads (:meth:`config_keys`, in their order), then ``extra``, then the
        section's keys ``own`` (a study that runs at the section's own sigma_cr, ``critical_stress_kPa``, a float as
        configured). A run with sigma_cr and a criterion of its own has them as its job's typed wildcards
        (:mod:`sphgag.jobs`), not here, so that adding a sigma_cr reruns no other run."""
        return dict({k: de[k] for k in cls.config_keys()}, **extra, **{k: de[k] for k in own})

    @staticmethod
    def of_law(de: dict, law: str) -> dict:
        """The ``delamination`` section ``de`` as the runs of charge law ``law`` of figures 5-7 read it: the ramp's top
        is ``max_concentration_by_law_mEq_l[law]`` where that is given, else ``max_concentration_mEq_l``."""
        top = de.get("max_concentration_by_law_mEq_l", {}).get(law, de["max_concentration_mEq_l"])
        return dict(de, max_concentration_mEq_l=top)

    @classmethod
    def from_config(
        cls, de: dict, critical_stress_kPa: float, criterion: str, fracture_energy_J_m2: float | None = None
    ) -> Settings:
        """The settings of one run from the ``delamination`` configuration section (its :meth:`config_keys`, the
        damage law ``damage_law`` among them), with the G_c ``fracture_energy_J_m2`` of a law that has one."""
        own = dict(critical_stress_kPa=float(critical_stress_kPa), criterion=criterion)
        if fracture_energy_J_m2 is not None:
            own["fracture_energy_J_m2"] = float(fracture_energy_J_m2)
        return cls(**own, **{k: de[k] for k in cls.config_keys()})

    @classmethod
    def at_section(cls, de: dict, criterion: str) -> Settings:
        """The settings of a run at the section's own sigma_cr (``critical_stress_kPa``): the studies that run at the
        configured critical stress (the resolution study, the variants, the sensitivity study's samples)."""
        return cls.from_config(de, de["critical_stress_kPa"], criterion)

    @property
    def law(self) -> damage.Law:
        """The run's damage law, from the registry :data:`sphgag.physics.damage.DAMAGE_LAWS`."""
        return damage.DAMAGE_LAWS[self.damage_law].of(self)

    @property
    def levels(self) -> np.ndarray:
        """Concentrations [mEq/l] of the ramp, 0 excluded, ``max_concentration_mEq_l`` included."""
        n = int(np.ceil(self.max_concentration_mEq_l / self.concentration_step_mEq_l - 1e-9))
        return np.linspace(0.0, self.max_concentration_mEq_l, n + 1)[1:]
