"""Closed-form references: thin-walled means and the exact (semi-analytical) thick-walled tube.

* Thin-walled means (eqs. 2.16-2.17): ``sigma_theta = P r_in / h`` and
  ``lambda_theta = (r_in + h/2) / (R_in + H/2)``.
* Finite-strain solution of an **incompressible**, possibly layered,
  thick-walled tube at fixed axial stretch ``lz`` (plane strain) for the
  incompressible part of the same constituents: the deformation is
  ``r^2 = r_in^2 + (R^2 - R_in^2) / lz``, ``lambda_theta = r/R``,
  ``lambda_r = 1/(lambda_theta lz)``; radial equilibrium
  ``d sigma_rr/dr = (sigma_tt - sigma_rr)/r`` with ``sigma_rr(r_out) = 0`` gives
  ``P = int_{r_in}^{r_out} (sigma_tt - sigma_rr) dr / r`` and
  ``sigma_rr(r) = -P + int_{r_in}^{r} (sigma_tt - sigma_rr) dr'/r'``.
  Integrals are Gauss-Legendre in R, layer by layer (exact to round-off for
  the smooth integrands).

The constituent laws here are written from the paper's equations
independently of :mod:`sphgag.physics.materials` (no shared code), so that comparing
SPH with them checks the discretisation *and* the transcription of the laws.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq


def thin_wall_stress(pressure_kPa, r_in, h):
    """Mean circumferential Cauchy stress, eq. (2.16)."""
    return np.asarray(pressure_kPa) * np.asarray(r_in) / np.asarray(h)


def thin_wall_stretch(r_in, h, R_in, H):
    """Mean circumferential stretch, eq. (2.17)."""
    return (np.asarray(r_in) + 0.5 * np.asarray(h)) / (R_in + 0.5 * H)


@dataclass(frozen=True)
class Family:
    """A fibre family of eqs. (2.18)/(2.22): ``phi c1/(4 c2) (exp[c2 (I4 - 1)^2] - 1)``, ``I4 = G^2 M.C M``.

    ``alpha_deg`` is measured from the axial direction (``M = [0, sin a, cos a]``);
    ``(c1m, c2m)`` apply in compression (``I4 < 1``), default: the tension constants.
    """

    phi: float
    alpha_deg: float
    c1: float
    c2: float
    c1m: float | None = None
    c2m: float | None = None
    prestretch: float = 1.0

    def hoop(self, lt, lz):
        """Contribution ``lt dW/dlt`` to ``sigma_tt - sigma_rr`` (incompressible)."""
        s2 = np.sin(np.deg2rad(self.alpha_deg)) ** 2
        g2 = self.prestretch**2
        E = g2 * (s2 * lt**2 + (1.0 - s2) * lz**2) - 1.0
        c1 = np.where(E >= 0.0, self.c1, self.c1 if self.c1m is None else self.c1m)
        c2 = np.where(E >= 0.0, self.c2, self.c2 if self.c2m is None else self.c2m)
        # lt dW/dlt = lt * phi c1/2 E exp(c2 E^2) * dI4/dlt, dI4/dlt = 2 g2 s2 lt
        with np.errstate(over="ignore"):  # root brackets may probe absurd stretches: inf is the right answer
            return self.phi * c1 * E * np.exp(c2 * E * E) * g2 * s2 * lt**2


@dataclass(frozen=True)
class Mixture:
    """Incompressible constrained mixture (eqs. 2.18, 2.21-2.24).

    Elastin-dominated matrix ``mu/2 (tr(G C G) - 3)`` with deposition stretch
    ``G = diag(Gr, Gt, Gz)`` (``mu`` already weighted by its mass fraction),
    fibre families, and active tone ``T(lt)`` (eq. 2.24, clipped at zero) added
    to the circumferential Cauchy stress.
    """

    mu: float
    families: tuple = ()
    Gr: float = 1.0
    Gt: float = 1.0
    tmax: float = 0.0
    lmax: float = 1.1
    lmin: float = 0.6

    def active(self, lt):
        """Active circumferential Cauchy stress T(lt) of eq. (2.24), clipped at zero."""
        u = (self.lmax - lt) / (self.lmax - self.lmin)
        return np.maximum(self.tmax * lt * (1.0 - u * u), 0.0)

    def hoop_minus_radial(self, lt, lz):
        """``sigma_tt - sigma_rr`` at circumferential stretch ``lt`` and axial stretch ``lz`` (eqs. 2.21-2.24)."""
        lt = np.asarray(lt, dtype=float)
        lr = 1.0 / (lt * lz)
        out = self.mu * ((self.Gt * lt) ** 2 - (self.Gr * lr) ** 2)
        for fam in self.families:
            out = out + fam.hoop(lt, lz)
        if self.tmax:
            out = out + self.active(lt)
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
    layer: np.ndarray = field(default=None)


class ThickWallTube:
    """Exact incompressible thick-walled tube of one or more layers (plane strain at fixed ``lz``).

    ``layers`` is a sequence of ``(R_a, R_b, law, name)`` in the reference
    configuration, inner to outer; ``law.hoop_minus_radial(lt, lz)`` gives
    ``sigma_tt - sigma_rr`` of the incompressible state with those stretches.
    """

    def __init__(self, layers, lz, n_gauss=64):
        self.layers = [(float(a), float(b), law, name) for a, b, law, name in layers]
        self.R_in, self.R_out = self.layers[0][0], self.layers[-1][1]
        self.lz = float(lz)
        self._xg, self._wg = np.polynomial.legendre.leggauss(n_gauss)

    @classmethod
    def single(cls, law, R_in, R_out, lz, name="wall"):
        return cls([(R_in, R_out, law, name)], lz)

    def radius(self, R, r_in):
        return np.sqrt(r_in**2 + (np.asarray(R) ** 2 - self.R_in**2) / self.lz)

    def _segment(self, r_in, R_a, R_b, law):
        """``int (sigma_tt - sigma_rr) dr / r`` for reference radii from R_a to R_b within one layer."""
        R_a, R_b = np.broadcast_arrays(np.asarray(R_a, float), np.asarray(R_b, float))
        R = R_a[..., None] + 0.5 * (self._xg + 1.0) * (R_b - R_a)[..., None]
        w = 0.5 * (R_b - R_a)[..., None] * self._wg
        r = self.radius(R, r_in)
        d = law.hoop_minus_radial(r / R, self.lz)
        return np.sum(w * d * R / (self.lz * r * r), axis=-1)  # dr / r = R dR / (lz r^2)

    def _integral(self, r_in, R):
        """``int_{R_in}^{R} (sigma_tt - sigma_rr) dr / r`` for an array of reference radii R."""
        R = np.asarray(R, float)
        total = np.zeros_like(R)
        for a, b, law, _ in self.layers:
            hi = np.clip(R, a, b)
            total += np.where(R > a, self._segment(r_in, np.full_like(R, a), hi, law), 0.0)
        return total

    def pressure(self, r_in):
        """Lumen pressure [kPa] that holds the inner radius at ``r_in``."""
        return float(self._integral(r_in, np.array([self.R_out]))[0])

    def inner_radius(self, pressure_kPa, bracket=None):
        """Inner radius at the given pressure (inverse of :meth:`pressure`)."""
        lo, hi = bracket or (0.3 * self.R_in, 4.0 * self.R_in)
        return brentq(lambda r: self.pressure(r) - pressure_kPa, lo, hi, xtol=1e-12, rtol=1e-14)

    def state(self, pressure_kPa, n_per_layer=101):
        """Transmural radial and circumferential Cauchy stress at ``pressure_kPa``."""
        r_in = self.inner_radius(pressure_kPa)
        P = self.pressure(r_in)
        R_all, srr_all, stt_all, names = [], [], [], []
        for a, b, law, name in self.layers:
            R = np.linspace(a, b, n_per_layer)
            r = self.radius(R, r_in)
            srr = -P + self._integral(r_in, R)
            R_all.append(r)
            srr_all.append(srr)
            stt_all.append(srr + law.hoop_minus_radial(r / R, self.lz))
            names += [name] * n_per_layer
        r = np.concatenate(R_all)
        return ThickWallState(
            P, r_in, float(r[-1]), r, np.concatenate(srr_all), np.concatenate(stt_all), np.array(names)
        )
