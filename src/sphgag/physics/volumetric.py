"""The volumetric term ``U(J)`` of a GAG pool's contents (``gag.volumetric``): none (eq. 2.27 as printed) or a bulk
term of our own (a deviation, docs/physics.md "GAG bulk term (a deviation)").

A GAG particle is the modified neo-Hookean solid of eq. (2.27) with the Gibbs-Donnan swelling pressure,
``W = mu_GAG/2 (I1 - 3) - mu_GAG ln J - Pi (J - 1)`` (Cauchy stress ``mu_GAG (B - I)/J - Pi I``). A form adds
``U(J) = kappa u(J)`` with ``kappa = gag.lame_lambda_kPa`` and ``u''(1) = 1``, so every form has the same small-strain
bulk modulus ``kappa`` (:func:`unit_terms` gives ``u, u', u''``; :data:`kernel_terms` is it compiled); its Cauchy
stress is ``U'(J) I``:

* ``none``, eq. (2.27) as printed: ``u = 0``;
* ``log_squared``, the elastin's term of eq. (2.21) at the GAG's modulus: ``u = (ln J)^2 / 2``; its stress
  ``kappa ln J / J`` fades with J, and with a prescribed Pi the contents' law
  ``mu/2 (I1 - 3) - mu ln J + U - Pi (J - 1)`` loses ellipticity (equibiaxial swelling, plane strain) where
  ``mu (J + 1) + kappa (1 - ln J) < 0``: J = 2.82 at ``kappa / mu = 100``;
* ``convex``: ``u = J - 1 - ln J``, stress ``kappa (1 - 1/J)``, saturating at ``kappa``; ``u'' = 1/J^2 > 0``;
* ``hartmann_neff``: ``u = (J^q + J^-q - 2) / (2 q^2)`` with ``q = 2`` (Hartmann & Neff 2003, IJSS 40:2767), stress
  ``kappa (J - J^-3) / 4``, growing without bound; ``u'' = (1 + 3 J^-4) / 4 > 0``.

The plane-strain acoustic tensor of the contents at an equibiaxial state has the eigenvalues ``mu`` and
``mu + mu/J + J U''(J)`` (:mod:`sphgag.physics.ellipticity`): with ``U'' > 0`` (``none``, ``convex``,
``hartmann_neff``) the law is elliptic at every J; a prescribed Pi, affine in det F, does not change it.

The tissue (elastin, eq. 2.21) keeps its own ``LAM/2 (ln J)^2`` (the column ``LAM`` of
:mod:`sphgag.physics.materials`); the contents' term is the columns ``KAPPA`` (its modulus) and ``VOLUMETRIC`` (the
form's :attr:`VolumetricForm.code`), which :func:`sphgag.physics.materials.convert_to_gag` blends in with the weight
``1 - g`` of the conversion homotopy while the tissue's fades with ``g``. The exact circular pool
(:mod:`sphgag.physics.cavity`), the pool as a cavity (:mod:`sphgag.engine.pool_cavity`) and the finite-element
reference (:mod:`sphgag.studies.fe_swelling`) take the same form, by :meth:`VolumetricForm.terms`.

A form is a :class:`VolumetricForm` (a :class:`sphgag.registry.Variant`) of the registry :data:`VOLUMETRIC_FORMS`, by
its name in the configuration (``gag.volumetric``, whose schema enumeration is the registry's); a new one is a branch of
:func:`unit_terms` (the Numba kernels evaluate it by its code) and an entry of :data:`VOLUMETRIC_FORMS`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..registry import Registry, Variant

NONE, LOG_SQUARED, CONVEX, HARTMANN_NEFF = range(4)  # the forms' codes (the property column VOLUMETRIC)


def unit_terms(code, J):
    """``(u, u', u'')`` at the volume ratio ``J`` of the form ``code`` with unit modulus ``u''(1) = 1`` (module
    docstring); any other code: zero. Plain arithmetic: a float or an array ``J``, in Python or Numba."""
    if code == LOG_SQUARED:
        lnJ = np.log(J)
        return 0.5 * lnJ * lnJ, lnJ / J, (1.0 - lnJ) / (J * J)
    if code == CONVEX:
        return J - 1.0 - np.log(J), 1.0 - 1.0 / J, 1.0 / (J * J)
    if code == HARTMANN_NEFF:  # q = 2
        J2 = J * J
        return (J2 + 1.0 / J2 - 2.0) / 8.0, 0.25 * (J - 1.0 / (J2 * J)), 0.25 * (1.0 + 3.0 / (J2 * J2))
    return 0.0 * J, 0.0 * J, 0.0 * J


#: :func:`unit_terms` compiled for the constitutive kernels (:mod:`sphgag.physics.materials`)
kernel_terms = njit(cache=True, error_model="numpy", inline="always")(unit_terms)


@dataclass(frozen=True)
class VolumetricForm(Variant):
    """A volumetric term ``U = kappa u(J)`` of the GAG contents (module docstring).

    name : its name (``gag.volumetric``).
    title : how the figures and the schema name it.
    code : its code in the property column ``VOLUMETRIC`` (a branch of :func:`unit_terms`).
    elliptic : ``u'' > 0`` at every J, so the swollen contents stay elliptic under a prescribed Pi.
    paper : eq. (2.27) as printed.

    It owns the key ``gag.volumetric`` (with ``gag.lame_lambda_kPa``, every form's kappa).
    """

    name: str
    title: str
    code: int
    elliptic: bool
    paper: bool = False

    def terms(self, J, kappa: float = 1.0):
        """``(U, U', U'')`` at the volume ratio ``J`` (a float or an array) with the modulus ``kappa`` [kPa]."""
        J = np.asarray(J, dtype=float)
        return tuple(kappa * t for t in unit_terms(self.code, J))

    def stress(self, J, kappa: float = 1.0):
        """``U'(J)``: the contents' Cauchy stress of the term (an isotropic ``U'(J) I``)."""
        return self.terms(J, kappa)[1]


#: the registry of the contents' volumetric forms, by name (``gag.volumetric``; the paper's first)
VOLUMETRIC_FORMS: Registry[VolumetricForm] = Registry(
    "volumetric form",
    (
        VolumetricForm("none", "eq. (2.27) as printed: no volumetric term", NONE, elliptic=True, paper=True),
        VolumetricForm(
            "log_squared", "kappa/2 (ln J)^2, the elastin's term: loses ellipticity at J ~ 2.8", LOG_SQUARED, False
        ),
        VolumetricForm("convex", "kappa (J - 1 - ln J): elliptic at every J, stress saturating at kappa", CONVEX, True),
        VolumetricForm(
            "hartmann_neff", "kappa (J^2 + J^-2 - 2)/8 (Hartmann-Neff, q = 2): elliptic at every J", HARTMANN_NEFF, True
        ),
    ),
)


def form(name) -> VolumetricForm:
    """The registered form ``name`` (ValueError naming the registered forms for any other)."""
    return VOLUMETRIC_FORMS.lookup(name)
