"""Damage of the medial tissue ahead of a swelling pool (paper section 2.7, eq. 2.28).

A candidate particle starts to damage when its radial Cauchy stress (current
polar frame) exceeds the critical stress ``sigma_cr``; its radial stretch at that
moment, ``lambda_r,onset``, is recorded. Beyond it the damage grows with the
extra radial stretch,

    D = exp((dlambda_r / tau)^2) - 1,     dlambda_r = lambda_r - lambda_r,onset,

the squared form of eq. (2.28): only it makes the paper's condition
``tau >= dlambda_r / sqrt(ln 2)`` give ``D <= 1`` (the authors' script uses it too).
We fix ``tau = rupture_stretch_increment / sqrt(ln 2)``, so that ``D`` reaches 1
(complete rupture) exactly when the radial stretch has grown by
``rupture_stretch_increment`` beyond onset. Damage never decreases.

The damaged strain energy is ``(1 - D) W`` with ``W`` the whole constrained
mixture of eq. (2.23) (:func:`weaken`): every constituent's energy, and the active
tone, is scaled by ``1 - D``, so stress and tangent are exactly ``(1 - D)`` times
the intact ones. The hourglass stiffness (eq. 2.14) is a property of the
discretisation and is left alone. A particle with ``D = 1`` becomes a GAG particle
(:func:`sphgag.materials.convert_to_gag`).

This module holds the law and its bookkeeping as pure functions of flat arrays;
the delamination protocol decides when to call them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import materials

LN2 = np.log(2.0)


@dataclass(frozen=True)
class DamageLaw:
    """Eq. (2.28) with its two parameters.

    critical_stress_kPa : sigma_cr, the radial Cauchy stress at onset (the paper: 30, 40, 60; ~61 kPa measured).
    rupture_stretch_increment : extra radial stretch beyond onset at which D = 1 (the paper: 5-10 %).
    """

    critical_stress_kPa: float
    rupture_stretch_increment: float

    def __post_init__(self):
        if not self.rupture_stretch_increment > 0.0:
            raise ValueError(f"rupture_stretch_increment must be positive, got {self.rupture_stretch_increment}")

    @property
    def tau(self) -> float:
        """The rate parameter of eq. (2.28), ``tau = rupture_stretch_increment / sqrt(ln 2)``."""
        return self.rupture_stretch_increment / np.sqrt(LN2)

    def damage(self, stretch_beyond_onset) -> np.ndarray:
        """``D = exp((dlambda / tau)^2) - 1`` for ``dlambda >= 0``, 0 below, 1 at and beyond rupture (eq. 2.28)."""
        d = np.maximum(np.asarray(stretch_beyond_onset, dtype=float), 0.0)
        return np.minimum(np.expm1(np.minimum((d / self.tau) ** 2, LN2)), 1.0)  # exponent capped where D = 1


@dataclass
class DamageState:
    """Per-particle damage history: ``D`` and the radial stretch at onset (NaN before onset)."""

    D: np.ndarray
    onset_stretch: np.ndarray

    @classmethod
    def intact(cls, n: int) -> DamageState:
        return cls(np.zeros(n), np.full(n, np.nan))

    @property
    def ruptured(self) -> np.ndarray:
        return self.D >= 1.0

    def update(self, law: DamageLaw, candidates: np.ndarray, radial_stress, radial_stretch) -> np.ndarray:
        """Advance the history with the current radial Cauchy stress and stretch; returns the particles whose D grew.

        Only ``candidates`` can start to damage (onset: ``sigma_rr >= sigma_cr``); a particle
        that has started keeps damaging with its stretch, whatever its stress. D never decreases.
        """
        onset = np.zeros(self.D.size, dtype=bool)
        onset[candidates] = True
        onset &= np.isnan(self.onset_stretch) & (np.asarray(radial_stress) >= law.critical_stress_kPa)
        self.onset_stretch[onset] = np.asarray(radial_stretch)[onset]
        started = ~np.isnan(self.onset_stretch)
        new = np.zeros_like(self.D)
        new[started] = law.damage(np.asarray(radial_stretch)[started] - self.onset_stretch[started])
        grew = new > self.D
        self.D = np.maximum(self.D, new)
        return np.flatnonzero(grew)


def radial_stretch(F: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Stretch of the reference radial direction ``e_R`` of each particle, ``|F e_R|`` (F from eq. 2.9)."""
    eR = np.column_stack([np.cos(theta), np.sin(theta)])
    return np.linalg.norm(np.einsum("nab,nb->na", F, eR), axis=1)


def weaken(props: np.ndarray, D: np.ndarray) -> np.ndarray:
    """A copy of ``props`` whose strain energy is ``(1 - D) W`` per particle (section 2.7).

    ``W`` (eqs. 2.21-2.23) is linear in the elastin constants ``MU``, ``LAM`` and in each
    fibre family's mass fraction, so scaling them by ``1 - D`` scales the energy, the stress
    and the tangent exactly; the active tone (eq. 2.24) is scaled alike. Swelling and the
    hourglass stiffness are not part of ``W`` and stay.
    """
    out = props.copy()
    keep = 1.0 - np.clip(np.asarray(D, dtype=float), 0.0, 1.0)
    for col in (materials.MU, materials.LAM, materials.TACT):
        out[:, col] *= keep
    for k in range(materials.MAX_FAMILIES):
        out[:, materials.FAM0 + k * materials.FAM_STRIDE + materials.PHI] *= keep
    return out
