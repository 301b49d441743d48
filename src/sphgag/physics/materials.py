"""Constitutive laws, evaluated particle-wise under plane strain (paper sections 2.4-2.6).

Every particle carries one row of a flat property table ``props[i, :]``; the
same Numba kernel evaluates every material, so changing a particle's material
(e.g. converting a medial particle to GAG) is a change of its row, not a new
particle type. A row describes a constrained mixture:

* **elastin-dominated matrix** (neo-Hookean, eqs. 2.18, 2.21), shear modulus
  ``MU`` (already weighted by its mass fraction), bulk penalty ``LAM`` and
  deposition pre-stretch ``G^e = diag(GR, GT, GZ)`` in the local (r, theta, z)
  frame: ``W^e = MU/2 (tr(G C G) - 3) - MU ln J + LAM/2 (ln J)^2``;
* up to ``MAX_FAMILIES`` **fibre families** (eqs. 2.18-2.19, 2.22) with
  direction ``M = [0, sin a, cos a]`` in (r, theta, z) (stored as ``sin^2 a``), mass fraction ``phi``,
  deposition stretch ``G``, ``I4 = G^2 M.C M`` and
  ``W^k = phi c1/(4 c2) (exp[c2 (I4 - 1)^2] - 1)`` with constants
  ``(c1+, c2+)`` in tension (I4 >= 1) and ``(c1-, c2-)`` in compression;
* **active smooth-muscle tone** (eq. 2.24), a circumferential Cauchy stress
  ``T(l) = TACT l (1 - ((LMAX - l)/(LMAX - LMIN))^2)`` (clipped at zero),
  ``l`` the circumferential stretch from the reference;
* **Gibbs-Donnan swelling** (eqs. 2.25-2.27): ``sigma -= PI I``, i.e.
  ``W -= PI (J - 1)`` (a prescribed swelling pressure), plus, if ``FCD > 0``,
  the Donnan pressure of a conserved fixed charge: ``FCD`` is the fixed-charge
  density per *reference* volume, the current one is ``FCD / J``, and
  ``sigma -= PI_D(J) I`` with ``PI_D = RT (sqrt((FCD/J)^2 + CBATH^2) - CBATH)``
  (eq. 2.26 at the current concentration; :func:`donnan`);
* the **contents' volumetric term** of a GAG particle (``gag.volumetric``; not in eq. 2.27, docs/physics.md):
  ``W += KAPPA u(J)``, ``u`` the form of code ``VOLUMETRIC`` (:mod:`sphgag.physics.volumetric`: none,
  ``(ln J)^2/2``, ``J - 1 - ln J``, ``(J^2 + J^-2 - 2)/8``, each with ``u''(1) = 1``), so ``KAPPA`` is its
  small-strain bulk modulus; the tissue's ``LAM`` term and this one are blended by :func:`convert_to_gag`;
* ``TISSUE``: how much of the particle is tissue (1) rather than GAG (0). It
  does not enter the stress; it decides which neighbours a particle's
  hourglass penalty measures against (:func:`sphgag.engine.kernel.hourglass_gradients`).

Plane strain at a prescribed axial stretch ``lz``: ``C = diag(C_2D, lz^2)``
and ``J = det(F_2D) lz`` (section 2.4.1).

Differences from the printed equations (see docs/physics.md):
(2.18) prints ``mu/2 (I1 - 3 + ln J)``, which is not stress free at ``F = I``;
we use ``mu/2 (I1 - 3) - mu ln J``, whose derivative is the first term of
(2.20). (2.20) then prints ``lambda/2 ln J C^-1`` where the derivative of
(2.18)'s ``lambda/2 (ln J)^2`` is ``lambda ln J C^-1``; we follow (2.18).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..options import Options
from .donnan import GAS_CONSTANT, ChargeLaw, charge_law
from .volumetric import VOLUMETRIC_FORMS, VolumetricForm, kernel_terms

# Column layout of the property table.
MU, LAM, GR, GT, GZ, PI, TACT, LMAX, LMIN, HG_E, NFAM = range(11)
FAM0 = 11
MAX_FAMILIES = 4
FAM_STRIDE = 7
PHI, SIN2, C1P, C2P, C1M, C2M, GF = range(FAM_STRIDE)
FAM_END = FAM0 + MAX_FAMILIES * FAM_STRIDE
TISSUE = FAM_END
FCD, CBATH, RT = FAM_END + 1, FAM_END + 2, FAM_END + 3
KAPPA, VOLUMETRIC = RT + 1, RT + 2  # the GAG contents' volumetric term: modulus and form code (physics.volumetric)
NPROP = VOLUMETRIC + 1


@dataclass(frozen=True)
class GagParameters(Options):
    """The GAG parameters every run shares: ``shear_modulus_kPa`` mu_GAG (eq. 2.27), ``volumetric`` the form of the
    contents' volumetric term (a name of :data:`sphgag.physics.volumetric.VOLUMETRIC_FORMS`; ``none`` is eq. 2.27 as
    printed) and ``lame_lambda_kPa`` its modulus kappa = U''(1) (not in eq. 2.27; docs/physics.md), ``temperature_K`` T
    and ``bath_concentration_mEq_l`` c* of eqs. (2.25-2.26), and ``hourglass_modulus_kPa`` E of eq. (2.14) for GAG
    particles."""

    SECTION = "gag"

    shear_modulus_kPa: float
    lame_lambda_kPa: float
    volumetric: str
    temperature_K: float
    bath_concentration_mEq_l: float
    hourglass_modulus_kPa: float

    def __post_init__(self):
        try:
            VOLUMETRIC_FORMS.lookup(self.volumetric)
        except ValueError as exc:
            raise ValueError(f"gag volumetric: {exc}") from None

    @property
    def bulk(self) -> VolumetricForm:
        """The contents' volumetric form (:mod:`sphgag.physics.volumetric`)."""
        return VOLUMETRIC_FORMS[self.volumetric]


@dataclass(frozen=True)
class Gag(GagParameters):
    """The GAG parameters of one run (:func:`law_gag`): the shared :class:`GagParameters` and the run's Donnan law
    ``charge_law``, a name of the registry :data:`sphgag.physics.donnan.CHARGE_LAWS` (:attr:`law`)."""

    charge_law: str

    def __post_init__(self):
        super().__post_init__()
        try:
            charge_law(self.charge_law)
        except ValueError as exc:
            raise ValueError(f"gag charge_law: {exc} (materials.law_gag gives the parameters of one law)") from None

    @property
    def law(self) -> ChargeLaw:
        """The run's charge law (eqs. 2.25-2.27): how the fixed charge of a GAG particle follows its volume ratio."""
        return charge_law(self.charge_law)


@dataclass(frozen=True)
class GagSection(GagParameters):
    """The ``gag`` configuration section: the :class:`GagParameters` shared by every run, and the Donnan laws
    ``charge_laws`` the runs are made under (names of :data:`sphgag.physics.donnan.CHARGE_LAWS`), one run each
    (:func:`law_gag` gives the parameters of one)."""

    charge_laws: tuple


def law_gag(gag: dict, law: str) -> dict:
    """The ``gag`` parameters of one run under the charge law ``law``: the configuration's ``gag`` section without its
    list ``charge_laws``, with ``charge_law = law`` (a plain dict, as Snakemake params and state files keep it;
    :class:`Gag` is its typed form)."""
    charge_law(law)  # ValueError for a law the registry does not know
    return dict({k: v for k, v in gag.items() if k not in ("charge_laws", "charge_law")}, charge_law=law)


def empty_props(n: int) -> np.ndarray:
    """A property table for ``n`` particles: stress-free, no constituents."""
    p = np.zeros((n, NPROP))
    p[:, GR] = p[:, GT] = p[:, GZ] = 1.0
    p[:, LMAX], p[:, LMIN] = 1.1, 0.6
    p[:, TISSUE] = 1.0
    return p


def set_family(props, rows, k, phi, alpha_deg, c1p, c2p, c1m=None, c2m=None, prestretch=1.0):
    """Fill fibre family ``k`` of the given rows (eqs. 2.19, 2.22; Table 1/2 constants).

    ``c1m, c2m`` (compression, I4 < 1) default to the tension constants.
    """
    if not 0 <= k < MAX_FAMILIES:
        raise ValueError(f"fibre family index {k} outside 0..{MAX_FAMILIES - 1}")
    base = FAM0 + k * FAM_STRIDE
    props[rows, base + PHI] = phi
    props[rows, base + SIN2] = np.sin(np.deg2rad(alpha_deg)) ** 2
    props[rows, base + C1P] = c1p
    props[rows, base + C2P] = c2p
    props[rows, base + C1M] = c1p if c1m is None else c1m
    props[rows, base + C2M] = c2p if c2m is None else c2m
    props[rows, base + GF] = prestretch
    props[rows, NFAM] = np.maximum(props[rows, NFAM], k + 1)


def mean_behaviour(n, mu, lam, families, hourglass_modulus):
    """Property table of the mean-behaviour model (eq. 2.18, Table 1).

    ``families`` is a sequence of ``(alpha_deg, c1, c2)``: axial (0 deg),
    circumferential (SMC + collagen, 90 deg) and the two diagonal families
    (+-alpha_0). No deposition pre-stretch, same constants in tension and compression.
    """
    p = empty_props(n)
    rows = np.arange(n)
    p[:, MU] = mu
    p[:, LAM] = lam
    p[:, HG_E] = hourglass_modulus
    for k, (alpha, c1, c2) in enumerate(families):
        set_family(p, rows, k, 1.0, alpha, c1, c2)
    return merge_identical_families(p)


def merge_identical_families(props):
    """Lump fibre families that are identical in plane strain (e.g. the diagonal pair +-alpha_0).

    Under plane strain (no theta-z shear) families at +alpha and -alpha have the same
    I4 and the same in-plane stress, so one family with the summed mass fraction is
    exact and halves the exponentials per particle.
    """
    out = props.copy()
    for row in np.unique(props[:, FAM0:FAM_END], axis=0, return_index=True)[1]:
        rows = np.flatnonzero((props[:, FAM0:FAM_END] == props[row, FAM0:FAM_END]).all(axis=1))
        fams = []
        for k in range(int(props[row, NFAM])):
            f = props[row, FAM0 + k * FAM_STRIDE : FAM0 + (k + 1) * FAM_STRIDE].copy()
            for g in fams:
                if np.array_equal(np.delete(g, PHI), np.delete(f, PHI)):
                    g[PHI] += f[PHI]
                    break
            else:
                fams.append(f)
        out[np.ix_(rows, np.arange(FAM0, FAM_END))] = 0.0
        for k, f in enumerate(fams):
            out[np.ix_(rows, np.arange(FAM0 + k * FAM_STRIDE, FAM0 + (k + 1) * FAM_STRIDE))] = f
        out[rows, NFAM] = len(fams)
    return out


# ---------------------------------------------------------------------------
# Constitutive kernels in the particle's local reference frame (e_r, e_theta).
# c_rr, c_tt, c_rt are the in-plane components of C = F^T F in that frame.
# ---------------------------------------------------------------------------


@njit(cache=True, error_model="numpy")
def _fibre_terms(I4, c1p, c2p, c1m, c2m):
    """W(I4), W'(I4), W''(I4) of c1/(4 c2) (exp[c2 (I4-1)^2] - 1) (eqs. 2.18, 2.22)."""
    E = I4 - 1.0
    if E >= 0.0:
        c1, c2 = c1p, c2p
    else:
        c1, c2 = c1m, c2m
    if c2 == 0.0:
        return 0.25 * c1 * E * E, 0.5 * c1 * E, 0.5 * c1
    ex = np.exp(c2 * E * E)
    return 0.25 * c1 / c2 * (ex - 1.0), 0.5 * c1 * E * ex, 0.5 * c1 * ex * (1.0 + 2.0 * c2 * E * E)


@njit(cache=True, error_model="numpy", inline="always")
def _fibre_slope(I4, c1p, c2p, c1m, c2m):
    """W'(I4) = c1/2 (I4 - 1) exp[c2 (I4 - 1)^2] alone (eqs. 2.20, 2.22; the stress needs nothing else)."""
    E = I4 - 1.0
    if E >= 0.0:
        return 0.5 * c1p * E * np.exp(c2p * E * E)
    return 0.5 * c1m * E * np.exp(c2m * E * E)


@njit(cache=True, error_model="numpy", inline="always")
def _active_tension(lam, tmax, lmax, lmin):
    """Active Cauchy stress T(lambda) of eq. (2.24) and dT/dlambda, clipped at zero."""
    span = lmax - lmin
    u = (lmax - lam) / span
    t = tmax * lam * (1.0 - u * u)
    if t <= 0.0:
        return 0.0, 0.0
    return t, tmax * ((1.0 - u * u) + 2.0 * lam * u / span)


@njit(cache=True, error_model="numpy", inline="always")
def _fibre_I4(props, i, base, c_tt, lz):
    """I4 = G^2 M.C M of a family with M = [0, sin a, cos a] (eqs. 2.19, 2.22)."""
    s2 = props[i, base + SIN2]
    return props[i, base + GF] ** 2 * (s2 * c_tt + (1.0 - s2) * lz * lz)


@njit(cache=True, error_model="numpy", inline="always")
def donnan(J, c0, cb, rt):
    """Donnan pressure of a conserved fixed charge: ``(PI_D, dPI_D/dJ, W_D)`` at volume ratio ``J`` (eq. 2.26).

    ``c0`` is the fixed-charge density per reference volume [mEq/l], ``c0/J``
    the current one, ``cb`` the bath's mobile-ion concentration, ``rt`` = R T
    in kPa per mEq/l. ``W_D = -int_1^J PI_D dj`` is the energy whose
    derivative ``dW_D/dJ = -PI_D`` gives the stress ``-PI_D I``.
    """
    if c0 == 0.0:
        return 0.0, 0.0, 0.0
    c = c0 / J
    root = np.sqrt(c * c + cb * cb)
    pi = rt * (root - cb)
    dpi = -rt * c * c / (J * root)

    def prim(j):  # an antiderivative of sqrt((c0/j)^2 + cb^2)
        return np.sqrt(c0 * c0 + cb * cb * j * j) - c0 * np.arcsinh(c0 / (cb * j))

    w = -rt * (prim(J) - prim(1.0) - cb * (J - 1.0))
    return pi, dpi, w


@njit(cache=True, error_model="numpy", inline="always")
def _volumetric(props, i, J, lnJ):
    """``(U, h, k)`` of the volumetric terms: the tissue's ``LAM/2 (ln J)^2`` (eqs. 2.18, 2.21) plus the GAG contents'
    ``KAPPA u(J)`` of the form ``VOLUMETRIC`` (:mod:`sphgag.physics.volumetric`), with ``h = J U'(J)`` (their
    stress is ``h C^-1``) and ``k = J dh/dJ = J (U' + J U'')``."""
    lam = props[i, LAM]
    U, h, k = 0.5 * lam * lnJ * lnJ, lam * lnJ, lam
    kappa = props[i, KAPPA]
    if kappa != 0.0:
        u, du, d2u = kernel_terms(int(props[i, VOLUMETRIC]), J)
        U += kappa * u
        h += kappa * J * du
        k += kappa * J * (du + J * d2u)
    return U, h, k


@njit(cache=True, error_model="numpy", inline="always")
def pk2(c_rr, c_tt, c_rt, lz, props, i):
    """Second Piola-Kirchhoff stress ``(S_rr, S_tt, S_rt)`` of particle ``i``.

    Elastin (2.18/2.21): ``MU (G^2 - C^-1) + LAM ln J C^-1``; the GAG contents' volumetric term: ``J U'(J) C^-1``
    (:func:`_volumetric`); swelling (2.27):
    ``-(PI + PI_D(J)) J C^-1``; fibres (2.20/2.22): ``2 phi W'(I4) G^2 sin^2 a e_t e_t``;
    active tone (2.24): ``J T(l) / l^2 e_t e_t`` with ``l^2 = C_tt``.
    """
    det2 = c_rr * c_tt - c_rt * c_rt
    J = lz * np.sqrt(det2)
    mu = props[i, MU]
    pi = props[i, PI] + donnan(J, props[i, FCD], props[i, CBATH], props[i, RT])[0]
    h = _volumetric(props, i, J, np.log(J))[1]
    beta = (mu - h + pi * J) / det2  # coefficient of -C^-1 det C
    s_rr = mu * props[i, GR] ** 2 - beta * c_tt
    s_tt = mu * props[i, GT] ** 2 - beta * c_rr
    s_rt = beta * c_rt
    for k in range(int(props[i, NFAM])):
        base = FAM0 + k * FAM_STRIDE
        s2 = props[i, base + SIN2]
        if s2 == 0.0 or props[i, base + PHI] == 0.0:
            continue  # the axial family (no in-plane stress under plane strain), or a family a particle has lost
        I4 = _fibre_I4(props, i, base, c_tt, lz)
        w1 = _fibre_slope(I4, props[i, base + C1P], props[i, base + C2P], props[i, base + C1M], props[i, base + C2M])
        s_tt += 2.0 * props[i, base + PHI] * w1 * props[i, base + GF] ** 2 * s2
    if props[i, TACT] != 0.0:
        t = _active_tension(np.sqrt(c_tt), props[i, TACT], props[i, LMAX], props[i, LMIN])[0]
        s_tt += J * t / c_tt
    return s_rr, s_tt, s_rt


@njit(cache=True, error_model="numpy")
def volumetric_stress(props, J, out):
    """``out[i] = U_i'(J[i])``: the Cauchy stress ``U'(J) I`` of the terms of particle i's strain energy that depend
    on ``J`` alone (eqs. 2.18, 2.21, 2.26-2.27): ``U = -MU ln J + LAM/2 (ln J)^2 + KAPPA u(J) - PI (J - 1) + W_D(J)``,
    so ``U' = (h - MU) / J - PI - PI_D(J)`` with ``h = J (LAM ln J / J + KAPPA u')`` of :func:`_volumetric` (the
    isotropic part of :func:`pk2` that is not ``MU G^2``). The stress recovery averages it
    (:mod:`sphgag.engine.measure`)."""
    for i in range(J.shape[0]):
        h = _volumetric(props, i, J[i], np.log(J[i]))[1]
        pi = props[i, PI] + donnan(J[i], props[i, FCD], props[i, CBATH], props[i, RT])[0]
        out[i] = (h - props[i, MU]) / J[i] - pi


@njit(cache=True, error_model="numpy")
def material_tangent(c_rr, c_tt, c_rt, lz, props, i, C):
    """Material tangent ``2 dS/dC`` of particle ``i`` into ``C`` (3 x 3, Voigt order rr, tt, rt).

    The derivative of the stress of :func:`pk2` (eqs. 2.20-2.24, 2.27).

    Elastin + volumetric terms + swelling: ``(k - PI J - PI_D' J^2) C^-1 (x) C^-1 + 2 beta I_{C^-1}`` with
    ``beta = MU - h + PI J`` (``PI`` including the Donnan ``PI_D(J)``; ``h = J U'``, ``k = J (U' + J U'')`` of
    :func:`_volumetric`, ``h = LAM ln J`` and ``k = LAM`` for the elastin alone) and ``I_{C^-1}`` the symmetrised
    identity on C^-1;
    fibres: ``4 phi W''(I4) G^4 sin^4 a`` on (tt, tt); active tone (no major
    symmetry): ``S_tt^act C^-1`` on row tt plus ``J (T'/l^2 - 2 T/l^3)/l`` on (tt, tt).
    """
    det2 = c_rr * c_tt - c_rt * c_rt
    J = lz * np.sqrt(det2)
    i_rr, i_tt, i_rt = c_tt / det2, c_rr / det2, -c_rt / det2
    pd, dpd, _ = donnan(J, props[i, FCD], props[i, CBATH], props[i, RT])
    pi = props[i, PI] + pd
    _, h, k = _volumetric(props, i, J, np.log(J))
    beta = props[i, MU] - h + pi * J
    a = k - pi * J - dpd * J * J
    b = 2.0 * beta
    C[0, 0] = (a + b) * i_rr * i_rr
    C[1, 1] = (a + b) * i_tt * i_tt
    C[0, 1] = C[1, 0] = a * i_rr * i_tt + b * i_rt * i_rt
    C[0, 2] = C[2, 0] = (a + b) * i_rr * i_rt
    C[1, 2] = C[2, 1] = (a + b) * i_tt * i_rt
    C[2, 2] = a * i_rt * i_rt + 0.5 * b * (i_rr * i_tt + i_rt * i_rt)
    for k in range(int(props[i, NFAM])):
        base = FAM0 + k * FAM_STRIDE
        s2 = props[i, base + SIN2]
        if s2 == 0.0 or props[i, base + PHI] == 0.0:
            continue  # as in pk2: 0 x W'' would be NaN where W'' overflows (a GAG particle stretched many-fold)
        I4 = _fibre_I4(props, i, base, c_tt, lz)
        w2 = _fibre_terms(I4, props[i, base + C1P], props[i, base + C2P], props[i, base + C1M], props[i, base + C2M])[2]
        C[1, 1] += 4.0 * props[i, base + PHI] * w2 * props[i, base + GF] ** 4 * s2 * s2
    if props[i, TACT] != 0.0:
        l = np.sqrt(c_tt)
        t, dt = _active_tension(l, props[i, TACT], props[i, LMAX], props[i, LMIN])
        sa = J * t / c_tt
        C[1, 0] += sa * i_rr
        C[1, 1] += sa * i_tt + J * (dt / c_tt - 2.0 * t / (c_tt * l)) / l
        C[1, 2] += sa * i_rt


@njit(cache=True, error_model="numpy")
def strain_energy(c_rr, c_tt, c_rt, lz, props, i):
    """Strain energy density W of particle ``i`` (eqs. 2.18, 2.21-2.23, 2.27; active tone has none).

    ``MU/2 (tr(G C G) - 3) - MU ln J + LAM/2 (ln J)^2 + KAPPA u(J) - PI (J - 1) + W_D(J) + sum_k phi_k W_k(I4_k)``.
    """
    J = lz * np.sqrt(c_rr * c_tt - c_rt * c_rt)
    lnJ = np.log(J)
    mu = props[i, MU]
    I1 = props[i, GR] ** 2 * c_rr + props[i, GT] ** 2 * c_tt + props[i, GZ] ** 2 * lz * lz
    W = 0.5 * mu * (I1 - 3.0) - mu * lnJ + _volumetric(props, i, J, lnJ)[0] - props[i, PI] * (J - 1.0)
    W += donnan(J, props[i, FCD], props[i, CBATH], props[i, RT])[2]
    for k in range(int(props[i, NFAM])):
        base = FAM0 + k * FAM_STRIDE
        if props[i, base + PHI] == 0.0:
            continue
        I4 = _fibre_I4(props, i, base, c_tt, lz)
        w0 = _fibre_terms(I4, props[i, base + C1P], props[i, base + C2P], props[i, base + C1M], props[i, base + C2M])[0]
        W += props[i, base + PHI] * w0
    return W


# ---------------------------------------------------------------------------
# Global x-y frame: F -> P = F S and dP/dF
# ---------------------------------------------------------------------------


@njit(cache=True, error_model="numpy", inline="always")
def local_deformation(f00, f01, f10, f11, cth, sth):
    """``F_loc = F Q`` with Q = [e_r, e_theta] of the reference angle, and its ``C_loc``."""
    l00 = f00 * cth + f01 * sth
    l10 = f10 * cth + f11 * sth
    l01 = -f00 * sth + f01 * cth
    l11 = -f10 * sth + f11 * cth
    return l00, l01, l10, l11, l00 * l00 + l10 * l10, l01 * l01 + l11 * l11, l00 * l01 + l10 * l11


@njit(cache=True, error_model="numpy", inline="always")
def first_piola(f00, f01, f10, f11, lz, cth, sth, props, i):
    """First Piola-Kirchhoff stress ``P = F S`` (eq. 2.10) of particle ``i`` in global x-y.

    ``(cth, sth)``: cos/sin of the particle's reference angle. Returns
    ``(P00, P01, P10, P11)``.
    """
    l00, l01, l10, l11, c_rr, c_tt, c_rt = local_deformation(f00, f01, f10, f11, cth, sth)
    s_rr, s_tt, s_rt = pk2(c_rr, c_tt, c_rt, lz, props, i)
    # P = F_loc S_loc Q^T
    m00 = l00 * s_rr + l01 * s_rt
    m01 = l00 * s_rt + l01 * s_tt
    m10 = l10 * s_rr + l11 * s_rt
    m11 = l10 * s_rt + l11 * s_tt
    return m00 * cth - m01 * sth, m00 * sth + m01 * cth, m10 * cth - m11 * sth, m10 * sth + m11 * cth


_VOIGT = np.array([[0, 2], [2, 1]])


@njit(cache=True, error_model="numpy")
def tangent_modulus(f00, f01, f10, f11, lz, cth, sth, props, i, C, A):
    """First elasticity tensor ``A[2a+B, 2c+D] = dP_aB / dF_cD`` of particle ``i``, global x-y.

    ``A_aBcD = delta_ac S_BD + F_aE (2 dS/dC)_EBFD F_cF`` (eq. 2.10 differentiated) evaluated with the
    reference indices in the local frame, then rotated. ``C``: (3, 3) scratch.
    """
    l00, l01, l10, l11, c_rr, c_tt, c_rt = local_deformation(f00, f01, f10, f11, cth, sth)
    s_rr, s_tt, s_rt = pk2(c_rr, c_tt, c_rt, lz, props, i)
    material_tangent(c_rr, c_tt, c_rt, lz, props, i, C)
    FL = np.empty((2, 2))
    FL[0, 0], FL[0, 1], FL[1, 0], FL[1, 1] = l00, l01, l10, l11
    SL = np.empty((2, 2))
    SL[0, 0], SL[1, 1], SL[0, 1], SL[1, 0] = s_rr, s_tt, s_rt, s_rt
    Q = np.empty((2, 2))
    Q[0, 0], Q[0, 1], Q[1, 0], Q[1, 1] = cth, -sth, sth, cth
    Al = np.zeros((2, 2, 2, 2))  # (global a, local b, global c, local d)
    for a_ in range(2):
        for b in range(2):
            for c in range(2):
                for d in range(2):
                    v = SL[b, d] if a_ == c else 0.0
                    for e in range(2):
                        for f in range(2):
                            v += FL[a_, e] * C[_VOIGT[e, b], _VOIGT[f, d]] * FL[c, f]
                    Al[a_, b, c, d] = v
    for a_ in range(2):
        for B in range(2):
            for c in range(2):
                for D in range(2):
                    v = 0.0
                    for b in range(2):
                        for d in range(2):
                            v += Q[B, b] * Q[D, d] * Al[a_, b, c, d]
                    A[2 * a_ + B, 2 * c + D] = v


def convert_to_gag(
    props,
    rows,
    fraction,
    shear_modulus,
    hourglass_modulus,
    swelling_pressure=0.0,
    kappa=0.0,
    volumetric="none",
    fixed_charge=None,
):
    """Turn ``rows`` of a property table a ``fraction`` of the way into GAG (eq. 2.27), in place.

    A GAG particle is the modified neo-Hookean solid ``mu_GAG`` (no deposition
    stretch, no fibres, no active tone) plus the Gibbs-Donnan swelling pressure
    ``Pi``: Cauchy stress ``mu_GAG (B - I)/J - Pi I`` (eq. 2.27), plus the
    contents' volumetric term ``kappa u(J)`` of the form ``volumetric`` (a name of
    :data:`sphgag.physics.volumetric.VOLUMETRIC_FORMS`; stress ``kappa u'(J) I``; not in
    eq. 2.27, docs/physics.md; ``none``: eq. 2.27 as printed).
    Conversion is a change of the particle's row, nothing else. For
    ``0 < fraction < 1`` the row is a homotopy that the quasi-static solver can
    follow in steps: the original constituents keep a weight ``g`` that falls
    from 1 to 0 log-uniformly (``g = (1 - s) 10^(-4 s)``: the stiffness drops by
    four decades before it vanishes, so the state changes evenly along the path
    instead of all at its end), moduli are blended with it (the tissue's
    ``LAM (ln J)^2`` fades with ``g``, the contents' ``KAPPA`` rises with
    ``1 - g``) and the deposition stretches go as ``G^g`` (det G stays 1);
    ``fraction = 1`` is exactly the GAG material.
    """
    form = VOLUMETRIC_FORMS.lookup(volumetric)
    s = float(fraction)
    g = (1.0 - s) * 10.0 ** (-4.0 * s)
    p = props[rows]
    p[:, MU] = g * p[:, MU] + (1.0 - g) * shear_modulus
    p[:, LAM] *= g
    p[:, KAPPA] = g * p[:, KAPPA] + (1.0 - g) * kappa
    p[:, VOLUMETRIC] = form.code
    for col in (GR, GT, GZ):
        p[:, col] = p[:, col] ** g
    for k in range(MAX_FAMILIES):
        p[:, FAM0 + k * FAM_STRIDE + PHI] *= g
    p[:, TACT] *= g
    p[:, TISSUE] *= g
    p[:, HG_E] = g * p[:, HG_E] + (1.0 - g) * hourglass_modulus
    p[:, PI] = swelling_pressure
    if fixed_charge is not None:
        c0, cb, temperature = fixed_charge
        p[:, PI] = 0.0
        p[:, FCD], p[:, CBATH], p[:, RT] = c0, cb, GAS_CONSTANT * temperature / 1000.0
    props[rows] = p
    return props
