"""Exact plane-strain field around a pressurised elliptical hole (Inglis 1913; Muskhelishvili).

An infinite, isotropic, linear-elastic plate (shear modulus ``mu``, Poisson's
ratio ``nu``, plane strain, Kolosov constant ``kappa = 3 - 4 nu``) contains the
elliptical hole ``x^2/a^2 + y^2/b^2 = 1`` (``a >= b > 0``, major axis along x).
The hole boundary carries a uniform internal pressure ``p`` (normal traction
``-p``, tension positive, so ``p > 0`` pushes the boundary outward); the plate
is stress free at infinity.

Method (Muskhelishvili, *Some Basic Problems of the Mathematical Theory of
Elasticity*, Sections 41, 48-56). The conformal map

    z = omega(zeta) = R (zeta + m / zeta),   R = (a + b) / 2,   m = (a - b) / (a + b),

takes ``|zeta| >= 1`` onto the exterior of the hole (``|zeta| = 1`` onto its
boundary). With ``phi`` and ``psi`` Muskhelishvili's complex potentials written
as functions of ``zeta``, the boundary condition for a uniform pressure is

    phi(s) + omega(s) / conj(omega'(s)) * conj(phi'(s)) + conj(psi(s)) = -p omega(s),  |s| = 1,

and its solution, holomorphic in ``|zeta| > 1`` and vanishing at infinity (no
net force on the hole, no stress at infinity), is

    phi(zeta) = -p R m / zeta,
    psi(zeta) = -p R (1 + m^2) zeta / (zeta^2 - m).

The stresses and displacements follow from the Kolosov-Muskhelishvili formulas

    sxx + syy            = 4 Re phi'(z),
    syy - sxx + 2 i sxy  = 2 [conj(z) phi''(z) + psi'(z)],
    2 mu (ux + i uy)     = kappa phi(z) - z conj(phi'(z)) - conj(psi(z)),

with ``d/dz = (1 / omega'(zeta)) d/dzeta``. For ``a = b`` (``m = 0``) this is
Lame's solution ``phi = 0``, ``psi = -p R^2 / z``:
``srr = -p (R/r)^2``, ``stt = p (R/r)^2``, ``ur = p R^2 / (2 mu r)``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["field", "map_parameters", "zeta_of_z", "tip_hoop_stress"]


def map_parameters(a: float, b: float) -> tuple[float, float]:
    """``(R, m)`` of the conformal map ``z = R (zeta + m / zeta)`` for the ellipse with semi-axes a >= b > 0."""
    a = float(a)
    b = float(b)
    if not (a >= b > 0.0):
        raise ValueError(f"need a >= b > 0, got a={a}, b={b}")
    return 0.5 * (a + b), (a - b) / (a + b)


def zeta_of_z(z, R: float, m: float):
    """Invert ``z = R (zeta + m / zeta)`` on the exterior, choosing per point the root with ``|zeta| >= 1``.

    The two roots of ``R zeta^2 - z zeta + R m = 0`` have product ``m <= 1``, so
    the one of larger modulus is the exterior one; picking it per point avoids
    any dependence on the branch cut of the complex square root.
    """
    z = np.asarray(z, dtype=complex)
    s = np.sqrt(z * z - 4.0 * R * R * m)
    z1 = (z + s) / (2.0 * R)
    z2 = (z - s) / (2.0 * R)
    return np.where(np.abs(z1) >= np.abs(z2), z1, z2)


def field(x, y, a, b, p, mu, nu) -> dict:
    """Displacements and stresses at points ``(x, y)`` outside (or on) the pressurised elliptical hole.

    Uses Muskhelishvili's complex potentials in the mapped plane of
    ``z = R (zeta + m / zeta)``, ``R = (a + b)/2``, ``m = (a - b)/(a + b)``:
    ``phi = -p R m / zeta``, ``psi = -p R (1 + m^2) zeta / (zeta^2 - m)``
    (see the module docstring). Plane strain, ``kappa = 3 - 4 nu``.

    Returns a dict of arrays shaped like ``x``: ``ux, uy`` (displacements),
    ``sxx, syy, sxy`` (Cauchy stresses, linear theory, tension positive) and
    ``srr, stt, srt`` (the same stresses in the polar frame of each point,
    ``e_r = (x, y) / |(x, y)|``). Points inside the hole are not meaningful.
    """
    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    R, m = map_parameters(a, b)
    kappa = 3.0 - 4.0 * nu
    z = x + 1j * y
    zeta = zeta_of_z(z, R, m)
    zi = 1.0 / zeta
    zi2 = zi * zi

    # omega and its derivatives in zeta
    w1 = R * (1.0 - m * zi2)  # omega'(zeta)
    w2 = 2.0 * R * m * zi2 * zi  # omega''(zeta)

    # phi and its zeta derivatives
    phi = -p * R * m * zi
    phi_1 = p * R * m * zi2
    phi_2 = -2.0 * p * R * m * zi2 * zi

    # psi and its zeta derivative
    c = p * R * (1.0 + m * m)
    den = zeta * zeta - m
    psi = -c * zeta / den
    psi_1 = c * (zeta * zeta + m) / (den * den)

    # derivatives with respect to z (chain rule)
    Phi = phi_1 / w1  # phi'(z)
    dPhi = (phi_2 * w1 - phi_1 * w2) / (w1 * w1 * w1)  # phi''(z)
    dPsi = psi_1 / w1  # psi'(z)

    s_sum = 4.0 * Phi.real
    s_dev = 2.0 * (np.conj(z) * dPhi + dPsi)  # syy - sxx + 2 i sxy
    sxx = 0.5 * (s_sum - s_dev.real)
    syy = 0.5 * (s_sum + s_dev.real)
    sxy = 0.5 * s_dev.imag

    u = (kappa * phi - z * np.conj(Phi) - np.conj(psi)) / (2.0 * mu)

    # polar frame: stt - srr + 2 i srt = (syy - sxx + 2 i sxy) e^{2 i theta}
    r = np.abs(z)
    e2 = np.where(r > 0, (z / np.where(r > 0, r, 1.0)) ** 2, 1.0)
    p_dev = s_dev * e2
    srr = 0.5 * (s_sum - p_dev.real)
    stt = 0.5 * (s_sum + p_dev.real)
    srt = 0.5 * p_dev.imag

    return {
        "ux": u.real,
        "uy": u.imag,
        "sxx": sxx,
        "syy": syy,
        "sxy": sxy,
        "srr": srr,
        "stt": stt,
        "srt": srt,
    }


def tip_hoop_stress(a: float, b: float, p: float) -> float:
    """Inglis' hoop stress at the end of the major axis ``(a, 0)``: ``p (2 a / b - 1)`` (equals ``syy`` there)."""
    map_parameters(a, b)
    return float(p) * (2.0 * float(a) / float(b) - 1.0)
