"""The settings of one delamination run (paper section 2.7): the ``delamination`` configuration section
(config/schema.yaml), its damage law among them (``damage_law``: eq. 2.28 as printed by default), with the run's own
critical stress sigma_cr, onset criterion and, for a law with a fracture energy, G_c, and the concentration ramp they
make."""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from ...physics import damage
from ..candidates import CANDIDATE_RULES
from ..onset import CRITERIA

#: the G_c of a run of the damage law with a fracture energy (its wildcard ``gc``: J/m^2) that is no number but the
#: energy the paper's damage law dissipated in its matched run (the same pool set at the same sigma_cr and criterion)
MATCHED = "paper"


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
    # candidates.CANDIDATE_RULES: the particles touching the pool (the paper), or the window
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
