"""Ellipticity of a particle's law: the smallest eigenvalue of its plane-strain acoustic tensor over all directions.

The acoustic tensor of the law at the deformation gradient ``F`` in the reference direction ``n`` (``|n| = 1``) is
``Q_ik(n) = A_iJkL n_J n_L`` with ``A = dP/dF`` the first elasticity tensor (eq. 2.10 differentiated,
:func:`sphgag.physics.materials.tangent_modulus`, in plane strain at the axial stretch ``lz``). The law is strongly
elliptic at ``F`` where ``Q(n)`` is positive definite for every ``n``; where its smallest eigenvalue reaches zero a
state with a jump of the deformation gradient across a line of normal ``n`` costs no extra stress, and a
non-uniform state of a pool's contents is as good as the uniform one (docs/physics.md, "GAG bulk term (a
deviation)").

For the GAG contents (eq. 2.27 with the volumetric term ``U = kappa u(J)`` of :mod:`sphgag.physics.volumetric`),
``W = mu/2 (I1 - 3) - mu ln J + U(J) - Pi (J - 1)``, at the equibiaxial swelling ``F = sqrt(J) I`` (``lz = 1``),
``Q(n) = mu I + J^2 f''(J) m m^T`` with ``m = F^-T n`` and ``f = -mu ln J + U - Pi (J - 1)``: its eigenvalues are
``mu`` and ``mu + mu/J + J U''(J)`` (:func:`equibiaxial_eigenvalue`), in every direction; a prescribed Pi, affine in
det F, drops out. :func:`swollen_contents` evaluates the engine's kernels there, and :func:`loss_of_ellipticity`
finds the first J where the smallest eigenvalue reaches zero.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from . import materials
from .volumetric import VOLUMETRIC_FORMS


def smallest_acoustic_eigenvalue(F, lz: float, props: np.ndarray, i: int = 0, directions: int = 180) -> float:
    """The smallest eigenvalue [kPa] of the acoustic tensor ``Q(n)`` of particle ``i`` of the property table
    ``props`` at the in-plane deformation gradient ``F`` (2 x 2, the particle's reference angle 0) and axial stretch
    ``lz``, over ``directions`` reference directions ``n = (cos a, sin a)``, ``a`` evenly spaced in ``[0, pi)``."""
    F = np.asarray(F, dtype=float)
    C, A = np.empty((3, 3)), np.empty((4, 4))
    materials.tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], lz, 1.0, 0.0, props, i, C, A)
    A = A.reshape(2, 2, 2, 2)  # A[a, B, c, D] = dP_aB / dF_cD
    a = np.linspace(0.0, np.pi, int(directions), endpoint=False)
    n = np.column_stack([np.cos(a), np.sin(a)])
    Q = np.einsum("iJkL,nJ,nL->nik", A, n, n)
    Q = 0.5 * (Q + Q.transpose(0, 2, 1))  # the law has an energy: Q is symmetric (to round-off)
    return float(np.linalg.eigvalsh(Q)[:, 0].min())


def contents_props(form: str, mu: float, kappa: float, pi: float = 0.0) -> np.ndarray:
    """The property table of one GAG particle (eq. 2.27): shear modulus ``mu``, the prescribed swelling pressure
    ``pi`` [kPa] and the volumetric term ``kappa u(J)`` of ``form`` (:func:`sphgag.physics.materials.convert_to_gag`
    of a stress-free particle)."""
    props = materials.empty_props(1)
    materials.convert_to_gag(props, [0], 1.0, mu, 0.0, pi, kappa=kappa, volumetric=form)
    return props


def swollen_contents(J: float, form: str, mu: float, kappa: float, pi: float = 0.0, directions: int = 180) -> float:
    """:func:`smallest_acoustic_eigenvalue` of the GAG contents (:func:`contents_props`) at the equibiaxial swelling
    ``F = sqrt(J) I``, ``lz = 1``."""
    F = np.sqrt(J) * np.eye(2)
    return smallest_acoustic_eigenvalue(F, 1.0, contents_props(form, mu, kappa, pi), 0, directions)


def equibiaxial_eigenvalue(J, form: str, mu: float, kappa: float):
    """The closed form of :func:`swollen_contents`: ``min(mu, mu + mu/J + J U''(J))`` (module docstring)."""
    J = np.asarray(J, dtype=float)
    return np.minimum(mu, mu + mu / J + J * VOLUMETRIC_FORMS.lookup(form).terms(J, kappa)[2])


def loss_of_ellipticity(form: str, mu: float, kappa: float, pi: float = 0.0, top: float = 100.0) -> float:
    """The smallest volume ratio ``J`` in ``[1, top]`` at which the swollen contents (:func:`swollen_contents`) lose
    ellipticity (their smallest eigenvalue reaches zero): sampled at 400 ratios evenly spaced in ln J, refined by
    brentq; ``inf`` where it stays positive up to ``top``."""

    def lowest(j):  # the state is isotropic in the plane: a few directions find the smallest eigenvalue
        return swollen_contents(j, form, mu, kappa, pi, directions=4)

    J = np.geomspace(1.0, top, 400)
    values = np.array([lowest(j) for j in J])
    below = np.flatnonzero(values <= 0.0)
    if not below.size:
        return float("inf")
    k = int(below[0])
    if k == 0:
        return 1.0
    return float(brentq(lowest, J[k - 1], J[k], xtol=1e-12))
