"""Closed-form references: thin-walled means and the exact thick-walled cylinder.

* Thin-walled means (eqs. 2.16-2.17): ``sigma_theta = P r_in / h`` and
  ``lambda_theta = (r_in + h/2) / (R_in + H/2)``.
* Exact finite-strain solution of an **incompressible** thick-walled tube at
  fixed axial stretch ``lz`` for the incompressible part of the same strain
  energy (eq. 2.18 without the volumetric terms): the deformation is
  ``r^2 = r_in^2 + (R^2 - R_in^2) / lz``, ``lambda_theta = r/R``,
  ``lambda_r = 1/(lambda_theta lz)``; radial equilibrium
  ``d sigma_rr/dr = (sigma_tt - sigma_rr)/r`` with ``sigma_rr(r_out) = 0`` gives
  ``P = int_{r_in}^{r_out} (sigma_tt - sigma_rr) dr / r`` and
  ``sigma_rr(r) = -P + int_{r_in}^{r} (sigma_tt - sigma_rr) dr'/r'``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq


def thin_wall_stress(pressure_kPa, r_in, h):
    """Mean circumferential Cauchy stress, eq. (2.16)."""
    return np.asarray(pressure_kPa) * np.asarray(r_in) / np.asarray(h)


def thin_wall_stretch(r_in, h, R_in, H):
    """Mean circumferential stretch, eq. (2.17)."""
    return (np.asarray(r_in) + 0.5 * np.asarray(h)) / (R_in + 0.5 * H)


@dataclass(frozen=True)
class MeanBehaviour:
    """Incompressible part of eq. (2.18): neo-Hookean ``mu`` plus fibre families ``(alpha_deg, c1, c2)``."""

    mu: float
    families: tuple

    def hoop_minus_radial(self, lt, lz):
        """``sigma_tt - sigma_rr = lt dW/dlt`` at circumferential stretch ``lt`` (incompressible)."""
        lt = np.asarray(lt, dtype=float)
        lr = 1.0 / (lt * lz)
        out = self.mu * (lt**2 - lr**2)
        for alpha, c1, c2 in self.families:
            s2 = np.sin(np.deg2rad(alpha)) ** 2
            I4 = s2 * lt**2 + (1.0 - s2) * lz**2
            out = out + c1 * s2 * lt**2 * (I4 - 1.0) * np.exp(c2 * (I4 - 1.0) ** 2)
        return out


@dataclass(frozen=True)
class ThickWallState:
    """Exact state of the tube at one inner radius."""

    pressure_kPa: float
    r_in: float
    r_out: float
    radius: np.ndarray
    radial_stress: np.ndarray
    circ_stress: np.ndarray

    @property
    def outer_diameter(self):
        return 2.0 * self.r_out

    @property
    def inner_diameter(self):
        return 2.0 * self.r_in


class ThickWallTube:
    """Exact incompressible thick-walled tube (plane strain at fixed ``lz``) for a material law.

    ``material.hoop_minus_radial(lambda_theta, lz)`` must return
    ``sigma_tt - sigma_rr`` for the incompressible state with those stretches.
    """

    def __init__(self, material, R_in, R_out, lz, n_gauss=64):
        self.material, self.R_in, self.R_out, self.lz = material, float(R_in), float(R_out), float(lz)
        self._xg, self._wg = np.polynomial.legendre.leggauss(n_gauss)

    def radius(self, R, r_in):
        return np.sqrt(r_in**2 + (np.asarray(R) ** 2 - self.R_in**2) / self.lz)

    def _integral(self, r_in, R_a, R_b):
        """``int (sigma_tt - sigma_rr) dr / r`` between reference radii R_a and R_b (Gauss-Legendre in R)."""
        R_a, R_b = np.broadcast_arrays(np.asarray(R_a, float), np.asarray(R_b, float))
        R = R_a[..., None] + 0.5 * (self._xg + 1.0) * (R_b - R_a)[..., None]
        w = 0.5 * (R_b - R_a)[..., None] * self._wg
        r = self.radius(R, r_in)
        d = self.material.hoop_minus_radial(r / R, self.lz)
        # dr / r = R dR / (lz r^2)
        return np.sum(w * d * R / (self.lz * r * r), axis=-1)

    def pressure(self, r_in):
        """Lumen pressure [kPa] that holds the inner radius at ``r_in``."""
        return float(self._integral(r_in, self.R_in, self.R_out))

    def inner_radius(self, pressure_kPa, bracket=None):
        """Inner radius at the given pressure (inverse of :meth:`pressure`)."""
        lo, hi = bracket or (0.3 * self.R_in, 4.0 * self.R_in)
        return brentq(lambda r: self.pressure(r) - pressure_kPa, lo, hi, xtol=1e-12, rtol=1e-14)

    def state(self, pressure_kPa, n=201):
        """Transmural radial and circumferential Cauchy stress at ``pressure_kPa``."""
        r_in = self.inner_radius(pressure_kPa)
        R = np.linspace(self.R_in, self.R_out, n)
        r = self.radius(R, r_in)
        P = self.pressure(r_in)
        srr = -P + self._integral(r_in, np.full(n, self.R_in), R)
        d = self.material.hoop_minus_radial(r / R, self.lz)
        return ThickWallState(P, r_in, float(r[-1]), r, srr, srr + d)
