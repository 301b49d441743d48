"""A damage law of one file: after onset at sigma_cr (as eq. 2.28), D grows linearly with the radial stretch beyond
onset and reaches 1 at ``rupture_stretch_increment``."""

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from sphgag.physics.damage import DAMAGE_LAWS, Law

REGISTRY = DAMAGE_LAWS


@dataclass(frozen=True)
class LinearLaw(Law):
    """``D = dlambda_r / rupture_stretch_increment`` beyond onset, capped at 1."""

    critical_stress_kPa: float
    rupture_stretch_increment: float
    name: ClassVar[str] = "linear"
    title: ClassVar[str] = "linear softening in the radial stretch beyond onset (a test)"
    paper: ClassVar[bool] = False
    keys: ClassVar[tuple[str, ...]] = ("delamination.critical_stress_kPa", "delamination.rupture_stretch_increment")

    @classmethod
    def of(cls, settings) -> "LinearLaw":
        return cls(settings.critical_stress_kPa, settings.rupture_stretch_increment)

    @property
    def rupture(self) -> str:
        return f"rupture at +{self.rupture_stretch_increment:.3g} radial stretch (linear)"

    def damage_at(self, stretch, onset_stretch, energy, onset_energy, band_width) -> np.ndarray:
        d = np.asarray(stretch, dtype=float) - np.asarray(onset_stretch, dtype=float)
        return np.clip(d / self.rupture_stretch_increment, 0.0, 1.0)


VARIANT = LinearLaw
