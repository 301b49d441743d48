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
(:func:`sphgag.physics.materials.convert_to_gag`).

**A law with a fracture energy** (:class:`FractureEnergyLaw`, ``damage_law: fracture_energy``).
Eq. (2.28) ruptures a particle after a fixed extra stretch, so the energy a particle
dissipates is that of its own volume and the energy per delaminated area scales with the
band the damage localises in, i.e. with the particle size. The crack band approach (Bazant
& Oh 1983) fixes the energy per unit volume instead: a band of width ``h`` dissipates
``g = G_c / h``, so its area dissipates ``G_c`` at every spacing. Damage that scales the
energy as ``(1 - D) W`` dissipates ``Y dD`` with ``Y = W_0`` (the intact energy density, the
thermodynamic force of ``D``), so the law is written in ``Y``: onset as the paper's (the
radial stress reaches ``sigma_cr``; its ``Y_on`` is recorded), then eq. (2.28)'s shape in the
normalised energy beyond onset,

    D = 2^(x^2) - 1,     x = (Y_max - Y_on) / (Y_f - Y_on) in [0, 1],

with ``Y_max`` the largest ``Y`` since onset. Its dissipation from onset to rupture is
``int Y dD = Y_on + K (Y_f - Y_on)`` with ``K = 1 - int_0^1 (2^(x^2) - 1) dx`` (:data:`SHAPE_K`),
so ``Y_f = Y_on + (g - Y_on) / K`` makes it exactly ``g``, whatever the deformation path.
Where ``g <= Y_on`` the band is too wide for ``G_c`` (snap-back of the softening branch): the
particle ruptures at onset and dissipates ``Y_on``.

This module holds the laws and their bookkeeping as pure functions of flat arrays;
the delamination protocol decides when to call them. A law is a class of the registry :data:`DAMAGE_LAWS` (a
:class:`sphgag.registry.Variant` by its class attributes ``name``, ``title``, ``paper``, ``keys``); it builds itself
from a run's settings (``of``). The configuration selects the law of the delamination runs by name
(``delamination.damage_law``); the fracture-energy runs (``delamination.fracture_energy``) grow by
:class:`FractureEnergyLaw` beside them. The delamination tables name the law in their column ``damage_law``.

**Fracture closed forms**: linear fracture mechanics of a pressurised straight crack in plane strain, the references
a law with a fracture energy is verified against (a pool that splits the media is a crack whose faces carry the
swelling pressure), and the estimates of what toughness a pool of a given size can overcome. A crack of half-length
``a`` in an infinite linear solid of plane-strain modulus ``E' = 2 mu / (1 - nu)`` (4 mu when incompressible) carries a
uniform pressure ``p`` on its faces:

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

Units: kPa and um throughout, so energies per area are in kPa um; 1 J/m^2 = 1e3 kPa um (:data:`J_M2`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, NamedTuple

import numpy as np
from scipy.special import erfi

from ..registry import Registry, Variant
from . import donnan, materials

#: the configuration key of a law with a fracture energy G_c: its runs are the fracture-energy runs, beside Griffith
FRACTURE_ENERGY = "delamination.fracture_energy"
J_M2 = 1.0e3  # kPa um per J/m^2: energies per area are in kPa um
LN2 = np.log(2.0)
# K = 1 - int_0^1 (2^(x^2) - 1) dx = 2 - sqrt(pi / ln 2) erfi(sqrt(ln 2)) / 2 (FractureEnergyLaw)
SHAPE_K = float(2.0 - 0.5 * np.sqrt(np.pi / LN2) * erfi(np.sqrt(LN2)))


def shape(x) -> np.ndarray:
    """Eq. (2.28)'s shape in a normalised variable: ``2^(x^2) - 1`` on [0, 1], 0 below, 1 beyond."""
    x = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    return np.minimum(np.expm1(x * x * LN2), 1.0)


class Law(Variant):
    """The variant protocol of a damage law, held by the class (its instances carry a run's parameters): ``name``,
    ``title``, ``paper`` and ``keys`` as class attributes, and :meth:`check` a class method."""

    @classmethod
    def check(cls, config, key: str) -> None:
        """The law's keys are checked by the schema (their ranges) and by its constructor. As the section's law
        (``delamination.damage_law``) it needs no setting a run lacks: a law with a fracture energy has its G_c per run
        (the fracture-energy runs, ``delamination.fracture_energy``), none in the section."""
        if FRACTURE_ENERGY in cls.keys:
            usable = ", ".join(n for n, law in DAMAGE_LAWS.items() if FRACTURE_ENERGY not in law.keys)
            raise ValueError(
                f"{key} = {cls.name!r} needs a G_c per run: it grows the runs of delamination.fracture_energy, beside "
                f"the section's law (one of {usable})"
            )


@dataclass(frozen=True)
class DamageLaw(Law):
    """Eq. (2.28) with its two parameters.

    critical_stress_kPa : sigma_cr, the radial Cauchy stress at onset (the paper: 30, 40, 60; ~61 kPa measured).
    rupture_stretch_increment : extra radial stretch beyond onset at which D = 1 (the paper: 5-10 %).
    """

    critical_stress_kPa: float
    rupture_stretch_increment: float
    name: ClassVar[str] = "paper"
    title: ClassVar[str] = "eq. (2.28) as printed: rupture a fixed radial stretch beyond onset"
    paper: ClassVar[bool] = True
    keys: ClassVar[tuple[str, ...]] = ("delamination.critical_stress_kPa", "delamination.rupture_stretch_increment")

    @classmethod
    def of(cls, settings) -> DamageLaw:
        """The law of a run's settings (``critical_stress_kPa``, ``rupture_stretch_increment``)."""
        return cls(settings.critical_stress_kPa, settings.rupture_stretch_increment)

    def __post_init__(self):
        if not self.rupture_stretch_increment > 0.0:
            raise ValueError(f"rupture_stretch_increment must be positive, got {self.rupture_stretch_increment}")

    @property
    def rupture(self) -> str:
        return f"rupture at +{self.rupture_stretch_increment:.3g} radial stretch"

    @property
    def tau(self) -> float:
        """The rate parameter of eq. (2.28), ``tau = rupture_stretch_increment / sqrt(ln 2)``."""
        return self.rupture_stretch_increment / np.sqrt(LN2)

    def damage(self, stretch_beyond_onset) -> np.ndarray:
        """``D = exp((dlambda / tau)^2) - 1`` for ``dlambda >= 0``, 0 below, 1 at and beyond rupture (eq. 2.28)."""
        d = np.maximum(np.asarray(stretch_beyond_onset, dtype=float), 0.0)
        return np.minimum(np.expm1(np.minimum((d / self.tau) ** 2, LN2)), 1.0)  # exponent capped where D = 1

    def damage_at(self, stretch, onset_stretch, energy, onset_energy, band_width) -> np.ndarray:
        """D of particles past onset (:meth:`DamageState.update`): the stretch beyond onset alone."""
        return self.damage(np.asarray(stretch) - np.asarray(onset_stretch))


@dataclass(frozen=True)
class FractureEnergyLaw(Law):
    """Onset at ``sigma_cr`` as eq. (2.28), then a softening that dissipates ``G_c / h`` per unit volume of a band of
    width ``h`` (crack band; module docstring).

    critical_stress_kPa : sigma_cr, the radial Cauchy stress (onset measure) at onset.
    fracture_energy_J_m2 : G_c, the energy dissipated per unit new delaminated area.
    """

    critical_stress_kPa: float
    fracture_energy_J_m2: float
    name: ClassVar[str] = "fracture_energy"
    title: ClassVar[str] = "a fracture energy G_c per delaminated area (crack band; our deviation)"
    paper: ClassVar[bool] = False
    keys: ClassVar[tuple[str, ...]] = ("delamination.critical_stress_kPa", FRACTURE_ENERGY)

    @classmethod
    def of(cls, settings) -> FractureEnergyLaw:
        """The law of a run's settings (``critical_stress_kPa``, ``fracture_energy_J_m2``)."""
        return cls(settings.critical_stress_kPa, settings.fracture_energy_J_m2)

    def __post_init__(self):
        if not self.fracture_energy_J_m2 > 0.0:
            raise ValueError(f"fracture_energy_J_m2 must be positive, got {self.fracture_energy_J_m2}")

    @property
    def rupture(self) -> str:
        return f"rupture after G_c = {self.fracture_energy_J_m2:.3g} J/m^2 per band area"

    def dissipation_density(self, band_width) -> np.ndarray:
        """``g = G_c / h`` [kPa = kJ/m^3] of a band of width ``h`` [um]."""
        return self.fracture_energy_J_m2 * J_M2 / np.asarray(band_width, dtype=float)

    def rupture_energy(self, onset_energy, band_width) -> np.ndarray:
        """``Y_f = Y_on + (g - Y_on) / K``: the intact energy density at which ``D = 1`` (``Y_on`` if ``g <= Y_on``)."""
        y0 = np.asarray(onset_energy, dtype=float)
        return y0 + np.maximum(self.dissipation_density(band_width) - y0, 0.0) / SHAPE_K

    def damage_at(self, stretch, onset_stretch, energy, onset_energy, band_width) -> np.ndarray:
        """``D = 2^(x^2) - 1`` with ``x = (Y - Y_on) / (Y_f - Y_on)`` (1 at once where ``Y_f = Y_on``)."""
        y, y0 = np.asarray(energy, dtype=float), np.asarray(onset_energy, dtype=float)
        span = self.rupture_energy(y0, band_width) - y0
        x = np.divide(y - y0, span, out=np.where(y >= y0, 1.0, 0.0), where=span > 0.0)
        return shape(x)

    def damage_rate(self, energy, onset_energy, band_width) -> np.ndarray:
        """``dD/dY`` on the loading branch (``Y > Y_on``, below rupture; 0 elsewhere): the law's tangent term,
        ``d(sigma)/d(lambda) = (1 - D) W_0'' - (dD/dY) W_0'^2`` in one dimension."""
        y, y0 = np.asarray(energy, dtype=float), np.asarray(onset_energy, dtype=float)
        span = self.rupture_energy(y0, band_width) - y0
        x = np.divide(y - y0, span, out=np.zeros_like(y), where=span > 0.0)
        inside = (x > 0.0) & (x < 1.0)
        rate = 2.0 * LN2 * x * np.exp2(x * x) / np.where(span > 0.0, span, 1.0)
        return np.where(inside, rate, 0.0)

    def dissipated(self, D_before, D_after, onset_energy, band_width) -> np.ndarray:
        """``int Y dD`` [kPa] from ``D_before`` to ``D_after`` along the law (per unit volume): ``g`` from 0 to 1."""
        y0 = np.asarray(onset_energy, dtype=float)
        span = self.rupture_energy(y0, band_width) - y0
        x0, x1 = (np.sqrt(np.log1p(np.clip(d, 0.0, 1.0)) / LN2) for d in (D_before, D_after))
        # int Y dD = [Y D] - int D dY, with Y = y0 + span x and D = 2^(x^2) - 1
        return y0 * (shape(x1) - shape(x0)) + span * (
            x1 * shape(x1) - x0 * shape(x0) - (_shape_integral(x1) - _shape_integral(x0))
        )


def _shape_integral(x) -> np.ndarray:
    """``int_0^x (2^(s^2) - 1) ds = sqrt(pi / ln 2) erfi(sqrt(ln 2) x) / 2 - x``."""
    x = np.asarray(x, dtype=float)
    return 0.5 * np.sqrt(np.pi / LN2) * erfi(np.sqrt(LN2) * x) - x


#: the registry of damage laws, by name (the paper's first): each builds itself from a run's settings (``of``); a new
#: law is a :class:`Law` with ``of``, ``damage_at`` and ``rupture``, registered here (docs/contributing.md)
DAMAGE_LAWS: Registry[type[Law]] = Registry("damage law", (DamageLaw, FractureEnergyLaw))


def matches_paper(gc) -> bool:
    """Whether the G_c of a fracture-energy run (the pipeline's wildcard ``gc``: a number in J/m^2, or the name of
    the paper's law) is the energy the paper's law (:data:`DAMAGE_LAWS`, ``paper``) dissipated in the matched run."""
    return isinstance(gc, str) and gc in DAMAGE_LAWS and DAMAGE_LAWS[gc].paper


@dataclass
class DamageState:
    """Per-particle damage history: ``D``, and the radial stretch and intact energy density ``W_0`` at onset (NaN
    before onset)."""

    D: np.ndarray
    onset_stretch: np.ndarray
    onset_energy: np.ndarray

    @classmethod
    def intact(cls, n: int) -> DamageState:
        return cls(np.zeros(n), np.full(n, np.nan), np.full(n, np.nan))

    @property
    def ruptured(self) -> np.ndarray:
        return self.D >= 1.0

    def update(self, law, candidates, radial_stress, radial_stretch, energy=None, band_width=None) -> np.ndarray:
        """Advance the history with the current radial Cauchy stress, radial stretch and intact energy density ``W_0``
        (eq. 2.23; needed by :class:`FractureEnergyLaw`, with the band width ``h`` [um] of each particle); returns
        the particles whose D grew.

        Only ``candidates`` can start to damage (onset: ``sigma_rr >= sigma_cr``); a particle
        that has started keeps damaging with its stretch (or energy), whatever its stress. D never decreases.
        """
        n = self.D.size
        stretch = np.asarray(radial_stretch, dtype=float)
        energy = np.full(n, np.nan) if energy is None else np.asarray(energy, dtype=float)
        width = np.full(n, np.nan) if band_width is None else np.broadcast_to(np.asarray(band_width, float), (n,))
        onset = np.zeros(n, dtype=bool)
        onset[candidates] = True
        onset &= np.isnan(self.onset_stretch) & (np.asarray(radial_stress) >= law.critical_stress_kPa)
        self.onset_stretch[onset] = stretch[onset]
        self.onset_energy[onset] = energy[onset]
        s = ~np.isnan(self.onset_stretch)
        new = np.zeros_like(self.D)
        new[s] = law.damage_at(stretch[s], self.onset_stretch[s], energy[s], self.onset_energy[s], width[s])
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


# ---------------------------------------------------------------------------
# Closed forms of linear fracture mechanics (module docstring, "Fracture closed forms")
# ---------------------------------------------------------------------------


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
