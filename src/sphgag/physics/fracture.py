"""Closed forms of linear fracture mechanics for a pressurised straight crack in plane strain.

The references a damage law with a fracture energy is verified against (a pool that splits
the media is a crack whose faces carry the swelling pressure), and the estimates of what
toughness a pool of a given size can overcome. A crack of half-length ``a`` in an infinite
linear solid of plane-strain modulus ``E' = 2 mu / (1 - nu)`` (4 mu when incompressible)
carries a uniform pressure ``p`` on its faces:

* energy release rate ``G = pi a p^2 / E'`` (Irwin);
* Griffith's critical pressure ``p_c = sqrt(E' G_c / (pi a))``, where ``G = G_c``;
* opening profile ``w(x) = (4 p / E') sqrt(a^2 - x^2)`` and opening area per unit depth
  ``V = 2 pi a^2 p / E'`` (Sneddon 1946);
* Irwin's cohesive length ``ell_ch = E' G_c / sigma_c^2``: Griffith holds for ``a >> ell_ch``.
  A Dugdale zone (constant cohesive stress ``sigma_c`` up to the opening ``G_c / sigma_c``)
  gives ``(8 a / (pi ell_ch)) ln sec(pi p_c / (2 sigma_c)) = 1``, below Griffith for short cracks;
* a swelling pool as such a crack (:func:`griffith_pool`): its faces carry the swelling pressure Pi(c) of
  eqs. (2.25-2.26), so Griffith's ``p_c`` is a fixed-charge concentration, and Pi(c) a critical half-length;
* crack band (Bazant & Oh 1983): a softening law smeared over a band of width ``h``
  dissipates ``G_c`` per unit crack area when its post-peak strain is
  ``shape G_c / (sigma_c h)`` (``shape`` = 2 for linear softening).

Units: kPa and um throughout, so energies per area are in kPa um; 1 J/m^2 = 1e3 kPa um.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from . import donnan

J_M2 = 1.0e3  # kPa um per J/m^2


def plane_strain_modulus(shear_modulus, poisson_ratio=0.5):
    """``E' = E / (1 - nu^2) = 2 mu / (1 - nu)``; ``4 mu`` for an incompressible solid."""
    return 2.0 * np.asarray(shear_modulus, dtype=float) / (1.0 - poisson_ratio)


def energy_release_rate(half_length, pressure, modulus):
    """``G = pi a p^2 / E'`` [kPa um] of a crack of half-length ``a`` [um] under face pressure ``p`` [kPa]."""
    return np.pi * half_length * np.square(pressure) / modulus


def griffith_pressure(half_length, fracture_energy, modulus):
    """Griffith's critical face pressure ``p_c = sqrt(E' G_c / (pi a))`` [kPa]; ``G_c`` in kPa um."""
    return np.sqrt(modulus * fracture_energy / (np.pi * half_length))


def griffith_half_length(pressure, fracture_energy, modulus):
    """The half-length at which the face pressure ``p`` reaches Griffith's: ``a_c = E' G_c / (pi p^2)`` [um]."""
    return modulus * fracture_energy / (np.pi * np.square(pressure))


class GriffithPool(NamedTuple):
    """Griffith's criterion for a swelling pool (:func:`griffith_pool`)."""

    pressure: float  # the critical face pressure p_c [kPa] of the pool's half-length
    concentration: float  # the fixed-charge concentration [mEq/l] whose swelling pressure is p_c
    half_length: float  # the half-length [um] at which the swelling pressure of the given concentration is critical


def griffith_pool(half_length, fracture_energy, modulus, concentration, bath_concentration, temperature_K):
    """A GAG pool of half-length ``a`` [um] as a pressurised straight crack whose faces carry the swelling pressure
    Pi(c) of eqs. (2.25-2.26) (bath concentration c* [mEq/l], temperature T): Griffith's critical pressure ``p_c``
    [kPa] (:func:`griffith_pressure`), the concentration [mEq/l] at which Pi reaches it, and the half-length
    (:func:`griffith_half_length`) that Pi(``concentration``) makes critical; ``G_c`` in kPa um."""
    p_c = griffith_pressure(half_length, fracture_energy, modulus)
    pi = donnan.swelling_pressure(concentration, bath_concentration, temperature_K)
    return GriffithPool(
        p_c,
        donnan.concentration_for_pressure(p_c, bath_concentration, temperature_K),
        griffith_half_length(pi, fracture_energy, modulus),
    )


def opening(x, half_length, pressure, modulus):
    """Sneddon's opening profile ``w(x) = (4 p / E') sqrt(a^2 - x^2)`` [um] (0 beyond the tips)."""
    return 4.0 * pressure / modulus * np.sqrt(np.maximum(half_length**2 - np.square(x), 0.0))


def opening_area(half_length, pressure, modulus):
    """Sneddon's opening area per unit depth ``V = 2 pi a^2 p / E'`` [um^2] (the integral of :func:`opening`)."""
    return 2.0 * np.pi * half_length**2 * pressure / modulus


def cohesive_length(modulus, fracture_energy, strength):
    """Irwin's characteristic length ``ell_ch = E' G_c / sigma_c^2`` [um]."""
    return modulus * fracture_energy / strength**2


def dugdale_pressure(half_length, fracture_energy, modulus, strength):
    """The critical face pressure with a Dugdale cohesive zone: ``(8 a / (pi ell_ch)) ln sec(pi p / (2 sigma_c)) = 1``
    solved for ``p`` [kPa]: the strength for ``a << ell_ch``, Griffith's for ``a >> ell_ch``."""
    ell = cohesive_length(modulus, fracture_energy, strength)
    return 2.0 * strength / np.pi * np.arccos(np.exp(-np.pi * ell / (8.0 * half_length)))


def band_softening_strain(fracture_energy, strength, band_width, shape=2.0):
    """The post-peak strain of a crack band of width ``h`` [um] that dissipates ``G_c`` per unit crack area:
    ``shape G_c / (sigma_c h)`` (Bazant & Oh 1983; ``shape`` = 2 for linear softening)."""
    return shape * fracture_energy / (strength * band_width)
