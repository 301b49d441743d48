"""TLSPH deformation gradient, internal and hourglass forces, and their exact Jacobian.

Kernels over the flat neighbour arrays of :mod:`sphgag.engine.kernel`:

* deformation gradient ``F_i = sum_j (x_j - x_i) (x) V_j A_i^-1 grad xi_ij`` (eq. 2.9);
* internal force ``f_i = sum_j V_i V_j (P_i grad~xi_ij - P_j grad~xi_ji)`` (eq. 2.11),
  the exact negative gradient of the discrete strain energy ``sum_i V_i W(F_i)``;
* hourglass penalty ``f_i = -sum_j alpha E V_i V_j xi_ij / (2 R_ij^2) (delta_i + delta_j) r_ij/|r_ij|``
  with ``delta_i = (F_i R_ij - r_ij) . r_ij/|r_ij|`` (eqs. 2.14-2.15; the ``paper`` form of the hourglass control,
  below);
* the Jacobian of both with respect to all particle positions (for Newton's method),
  assembled into 2 x 2 blocks of a fixed sparsity pattern.

Each neighbour entry ``e = (i, j, mirror)`` contributes one pair vector ``t``:
``f_i += t`` and ``f_j -= mirror * t``, so linear momentum is conserved pair by
pair (up to the reactions of the mirror planes).

The internal force is the exact negative gradient of ``sum_i V_i W(F_i)``:
``f_i = sum_j V_i V_j (P_i A_i^-1 grad xi_ij - P_j A_j^-1 grad xi_ji)`` is
eq. (2.11) with the corrected gradients of eq. (2.8).

**The hourglass control of a run** (``numerics.hourglass``): eq. (2.14) as printed, or its energy form.
TLSPH's deformation gradient (eq. 2.9) does not see zero-energy particle
modes, so both forms penalise the part of a pair's current separation
``r_ij = x_j - x_i`` that the particle's deformation gradient does not predict,
``d_ij = F~_i R_ij - r_ij``, with the same pair coefficient
``c_ij = alpha E_ij V_i V_j xi_ij / (2 |R_ij|^2)`` (eq. 2.14; :func:`hourglass_coefficients`) and the same stencil
``F~_i`` (:func:`sphgag.engine.kernel.hourglass_gradients`: within each material):

* ``paper``: eq. (2.14) as printed (Ganzenmueller's form): the pair force
  ``-c_ij (delta_i + delta_j) n_ij`` along the current pair direction, with
  ``delta_i = d_ij . n_ij``. It is not the gradient of an energy: its
  stiffness is not symmetric and, where a kernel's deformation is far from
  affine and pairs are squeezed, its geometric part (``delta (I - n n)/|r|``)
  is negative (docs/physics.md, "What fails near the artery's pools").
  Computed with the elastic forces.
* ``energy``: the energy ``E_hg = sum_(i, j) c_ij / 2 |d_ij|^2`` over every
  neighbour entry. ``F~_i`` and ``r_ij`` are linear in the positions and
  ``d_ij`` vanishes for every affine map (the stencil is corrected), so
  ``E_hg = 1/2 u^T K u`` with ``u = x - X`` and a constant, symmetric, positive
  semi-definite ``K``: the force is ``-K u`` and the stiffness ``-K``. Its
  force along a pair is eq. (2.14)'s with ``d_ij`` in place of its projection
  on ``n_ij``, plus the reaction through ``F~`` that makes it conservative. It
  is invariant under rigid rotations (``|Q d| = |d|``).

A form is a :class:`HourglassForm` (a :class:`sphgag.registry.Variant`) of the registry :data:`HOURGLASS_FORMS`, by its
name in the configuration (``numerics.hourglass``, whose schema enumeration is the registry's) and the pipeline's
wildcard ``{form}``; the model asks it for its part of the forces and the stiffness (:meth:`HourglassForm.contribute`).
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np
from numba import njit, prange

from ..physics.materials import HG_E, first_piola, local_deformation, strain_energy, tangent_modulus
from ..registry import Registry, Variant


@njit(cache=True, error_model="numpy")
def hourglass_coefficients(V, ptr, nbr, R, w, props, alpha, out):
    """``alpha E_ij V_i V_j xi_ij / (2 |R_ij|^2)`` per entry (eq. 2.14), E_ij the mean of both particles'."""
    n = V.shape[0]
    for i in range(n):
        for e in range(ptr[i], ptr[i + 1]):
            j = nbr[e]
            E = 0.5 * (props[i, HG_E] + props[j, HG_E])
            out[e] = alpha * E * V[i] * V[j] * w[e] / (2.0 * (R[e, 0] ** 2 + R[e, 1] ** 2))


@dataclass(frozen=True)
class PairData:
    """Per-pair data of the force kernel: geometry, stencil gradients and hourglass coefficients, packed.

    ``pair_geo[p] = (V_i a_ij, V_j a_ji, R_ij)`` for the half list of real pairs,
    ``solo_geo[s] = (V_i a_e, R_e)`` for ghost entries; ``pair_a[p] = (a_ij, a_ji, ah_ij, ah_ji)`` and
    ``solo_a[s] = (a_e, ah_e)`` the corrected gradients of F (eq. 2.9) and of the hourglass stencil's F~;
    ``split``: whether the two stencils differ (a GAG/tissue interface); ``*_hgc`` the hourglass
    coefficients of :func:`hourglass_coefficients` (symmetric in i, j).
    """

    pair_ptr: np.ndarray
    pair_j: np.ndarray
    pair_geo: np.ndarray
    pair_a: np.ndarray
    pair_hgc: np.ndarray
    solo_ptr: np.ndarray
    solo_j: np.ndarray
    solo_geo: np.ndarray
    solo_a: np.ndarray
    solo_hgc: np.ndarray
    split: bool
    ghost_owner: np.ndarray
    ghost_mirror: np.ndarray

    @property
    def arrays(self) -> tuple:
        """The fields in the order :func:`forces_and_stresses` takes them (``pair_ptr`` ... ``ghost_mirror``)."""
        return tuple(getattr(self, f.name) for f in fields(self))

    @classmethod
    def pack(cls, nb, V, hgc, ah=None):
        """``ah``: the hourglass stencil's gradients (:func:`sphgag.engine.kernel.hourglass_gradients`; default the full
        stencil ``nb.a``)."""
        ah = nb.a if ah is None else ah
        pe, pr, se = nb.pair_entry, nb.pair_reverse, nb.solo_entry
        owner = np.repeat(np.arange(V.size), np.diff(nb.ptr))
        pair_geo = np.column_stack([V[owner[pe], None] * nb.a[pe], V[owner[pr], None] * nb.a[pr], nb.R[pe]])
        solo_geo = np.column_stack([V[owner[se], None] * nb.a[se], nb.R[se]])
        pair_a = np.column_stack([nb.a[pe], nb.a[pr], ah[pe], ah[pr]])
        solo_a = np.column_stack([nb.a[se], ah[se]])
        return cls(
            nb.pair_ptr,
            nb.ext[pe].copy(),
            np.ascontiguousarray(pair_geo),
            np.ascontiguousarray(pair_a),
            hgc[pe].copy(),
            nb.solo_ptr,
            nb.ext[se].copy(),
            np.ascontiguousarray(solo_geo),
            np.ascontiguousarray(solo_a),
            hgc[se].copy(),
            not np.array_equal(ah, nb.a),
            nb.ghost_owner,
            nb.ghost_mirror,
        )


NO_EXTRA_STRESS = np.empty((0, 4))


def evaluate_forces(x, pd: PairData, lz, cth, sth, props, xe, fe, FP, f, extra=NO_EXTRA_STRESS):
    """One force evaluation (see :func:`forces_and_stresses`); fills FP = (F, P, F~) and f.

    ``extra`` (N, 4), if given, is added to every particle's P before the forces
    are formed (the viscous stress of section 2.3 in :mod:`sphgag.engine.dynamics`).
    """
    return forces_and_stresses(x, pd.arrays, lz, cth, sth, props, extra, xe, fe, FP, f)


@njit(cache=True, error_model="numpy")
def extend(x, ghost_owner, ghost_mirror, xe):
    """``xe``: the positions ``x`` followed by their ghosts' (mirror images across the symmetry planes)."""
    n = x.shape[0]
    for i in range(n):
        xe[i, 0] = x[i, 0]
        xe[i, 1] = x[i, 1]
    for g in range(ghost_owner.shape[0]):
        o = ghost_owner[g]
        xe[n + g, 0] = ghost_mirror[g, 0] * x[o, 0]
        xe[n + g, 1] = ghost_mirror[g, 1] * x[o, 1]


@njit(cache=True, error_model="numpy")
def _deformation_gradients(xe, pair_ptr, pair_j, pair_a, solo_ptr, solo_j, solo_a, split, FP, n):
    """Pass 1a of :func:`forces_and_stresses`: ``F_i = sum_j (x_j - x_i) (x) a_ij`` (eq. 2.9) and the hourglass
    stencil's ``F~_i`` into ``FP[:, :4]`` and ``FP[:, 8:]``, over the half list of pairs (the separation of a pair
    serves both of its particles; ghost entries from their real side)."""
    for i in range(n):
        for k in range(4):
            FP[i, k] = 0.0
            FP[i, 8 + k] = 0.0
    for i in range(n):
        xi0, xi1 = xe[i, 0], xe[i, 1]
        f00 = f01 = f10 = f11 = 0.0
        h00 = h01 = h10 = h11 = 0.0
        for p in range(pair_ptr[i], pair_ptr[i + 1]):
            j = pair_j[p]
            d0 = xe[j, 0] - xi0
            d1 = xe[j, 1] - xi1
            f00 += d0 * pair_a[p, 0]
            f01 += d0 * pair_a[p, 1]
            f10 += d1 * pair_a[p, 0]
            f11 += d1 * pair_a[p, 1]
            FP[j, 0] -= d0 * pair_a[p, 2]  # x_i - x_j = -d
            FP[j, 1] -= d0 * pair_a[p, 3]
            FP[j, 2] -= d1 * pair_a[p, 2]
            FP[j, 3] -= d1 * pair_a[p, 3]
            if split:
                h00 += d0 * pair_a[p, 4]
                h01 += d0 * pair_a[p, 5]
                h10 += d1 * pair_a[p, 4]
                h11 += d1 * pair_a[p, 5]
                FP[j, 8] -= d0 * pair_a[p, 6]
                FP[j, 9] -= d0 * pair_a[p, 7]
                FP[j, 10] -= d1 * pair_a[p, 6]
                FP[j, 11] -= d1 * pair_a[p, 7]
        for s in range(solo_ptr[i], solo_ptr[i + 1]):
            j = solo_j[s]
            d0 = xe[j, 0] - xi0
            d1 = xe[j, 1] - xi1
            f00 += d0 * solo_a[s, 0]
            f01 += d0 * solo_a[s, 1]
            f10 += d1 * solo_a[s, 0]
            f11 += d1 * solo_a[s, 1]
            if split:
                h00 += d0 * solo_a[s, 2]
                h01 += d0 * solo_a[s, 3]
                h10 += d1 * solo_a[s, 2]
                h11 += d1 * solo_a[s, 3]
        FP[i, 0] += f00
        FP[i, 1] += f01
        FP[i, 2] += f10
        FP[i, 3] += f11
        if split:
            FP[i, 8] += h00
            FP[i, 9] += h01
            FP[i, 10] += h10
            FP[i, 11] += h11
        else:  # one stencil: F~ = F
            for k in range(4):
                FP[i, 8 + k] = FP[i, k]


@njit(cache=True, error_model="numpy", parallel=True)
def piola_stresses(lz, cth, sth, props, extra, FP, n):
    """Pass 1b of :func:`forces_and_stresses`: ``P_i`` (eq. 2.10) from ``F_i`` and row ``i`` of ``props``, parallel
    over particles, or over integration points (:mod:`sphgag.engine.quadrature`) (Numba threads); returns the smallest
    det(F_2D) (NaN stress where det <= 0)."""
    dets = np.empty(n)
    for i in prange(n):
        f00, f01, f10, f11 = FP[i, 0], FP[i, 1], FP[i, 2], FP[i, 3]
        det = f00 * f11 - f01 * f10
        dets[i] = det
        if det > 0.0:
            FP[i, 4], FP[i, 5], FP[i, 6], FP[i, 7] = first_piola(f00, f01, f10, f11, lz, cth[i], sth[i], props, i)
            if extra.shape[0]:
                for k in range(4):
                    FP[i, 4 + k] += extra[i, k]
        else:  # inverted (or NaN, which the caller detects from the positions and stresses)
            FP[i, 4] = FP[i, 5] = FP[i, 6] = FP[i, 7] = np.nan
    dmin = np.inf
    for i in range(n):
        dmin = min(dmin, dets[i])
    return dmin


@njit(cache=True, error_model="numpy")
def forces_and_stresses(x, pd, lz, cth, sth, props, extra, xe, fe, FP, f):
    """One force evaluation: F (eq. 2.9), P (eq. 2.10) and the forces of eqs. (2.11), (2.14); ``pd``: the packed pair
    data (:attr:`PairData.arrays`).

    Pass 1: ``F_i = sum_j (x_j - x_i) (x) a_ij`` and the hourglass deformation gradient
    ``F~_i`` of the weighted stencil ``ah`` (:func:`sphgag.engine.kernel.hourglass_gradients`;
    ``F~ = F`` without a GAG/tissue interface), accumulated over the half list of pairs
    (:func:`_deformation_gradients`), then ``P_i`` from each particle's material row
    (:func:`piola_stresses`, parallel); ``FP[i] = (F_i, P_i, F~_i)`` (row-major).
    Pass 2, over the half list of real pairs: the two directed pair vectors
    ``t_ij = V_i P_i a_ij - c_ij delta_ij n_ij`` (``f_i += t_ij``, ``f_j -= t_ij``)
    and ``t_ji`` share the separation and the division, so each pair is
    visited once; ghost entries (mirror images at the end of ``xe``/``fe``)
    are visited from their real side and folded back through the mirror.
    The hourglass term uses ``delta n = ((F~_i R - r) . r) r / |r|^2``
    (eq. 2.15 with ``n = r/|r|``). Returns the smallest det(F_2D); a particle
    with det <= 0 gets NaN stress.
    """
    pair_ptr, pair_j, pair_geo, pair_a, pair_hgc, solo_ptr, solo_j, solo_geo, solo_a, solo_hgc = pd[:10]
    split, ghost_owner, ghost_mirror = pd[10], pd[11], pd[12]
    n = x.shape[0]
    extend(x, ghost_owner, ghost_mirror, xe)
    _deformation_gradients(xe, pair_ptr, pair_j, pair_a, solo_ptr, solo_j, solo_a, split, FP, n)
    dmin = piola_stresses(lz, cth, sth, props, extra, FP, n)
    fe[:, :] = 0.0
    for i in range(n):
        xi0, xi1 = xe[i, 0], xe[i, 1]
        g00, g01, g10, g11 = FP[i, 8], FP[i, 9], FP[i, 10], FP[i, 11]
        p00, p01, p10, p11 = FP[i, 4], FP[i, 5], FP[i, 6], FP[i, 7]
        fi0 = fi1 = 0.0
        for p in range(pair_ptr[i], pair_ptr[i + 1]):
            j = pair_j[p]
            r0 = xe[j, 0] - xi0
            r1 = xe[j, 1] - xi1
            rr = r0 * r0 + r1 * r1
            R0, R1 = pair_geo[p, 4], pair_geo[p, 5]
            # delta_ij + delta_ji: t_ji carries r_ji = -r and R_ji = -R, so both
            # directions add ((F_i + F_j) R) . r - 2 |r|^2
            s00, s01, s10, s11 = g00 + FP[j, 8], g01 + FP[j, 9], g10 + FP[j, 10], g11 + FP[j, 11]
            q = (s00 * R0 + s01 * R1) * r0 + (s10 * R0 + s11 * R1) * r1
            h = pair_hgc[p] * (q - 2.0 * rr) / rr
            a0, a1, b0, b1 = pair_geo[p, 0], pair_geo[p, 1], pair_geo[p, 2], pair_geo[p, 3]
            d0 = p00 * a0 + p01 * a1 - (FP[j, 4] * b0 + FP[j, 5] * b1) - h * r0
            d1 = p10 * a0 + p11 * a1 - (FP[j, 6] * b0 + FP[j, 7] * b1) - h * r1
            fi0 += d0
            fi1 += d1
            fe[j, 0] -= d0
            fe[j, 1] -= d1
        for s in range(solo_ptr[i], solo_ptr[i + 1]):
            j = solo_j[s]
            r0 = xe[j, 0] - xi0
            r1 = xe[j, 1] - xi1
            rr = r0 * r0 + r1 * r1
            R0, R1 = solo_geo[s, 2], solo_geo[s, 3]
            qi = (g00 * R0 + g01 * R1) * r0 + (g10 * R0 + g11 * R1) * r1
            h = solo_hgc[s] * (qi - rr) / rr
            d0 = p00 * solo_geo[s, 0] + p01 * solo_geo[s, 1] - h * r0
            d1 = p10 * solo_geo[s, 0] + p11 * solo_geo[s, 1] - h * r1
            fi0 += d0
            fi1 += d1
            fe[j, 0] -= d0
            fe[j, 1] -= d1
        fe[i, 0] += fi0
        fe[i, 1] += fi1
    for i in range(n):
        f[i, 0] = fe[i, 0]
        f[i, 1] = fe[i, 1]
    for g in range(ghost_owner.shape[0]):
        o = ghost_owner[g]
        f[o, 0] += ghost_mirror[g, 0] * fe[n + g, 0]
        f[o, 1] += ghost_mirror[g, 1] * fe[n + g, 1]
    return dmin


@njit(cache=True, error_model="numpy")
def energy_densities(F, lz, cth, sth, props, W):
    """Strain energy density W_i of every particle (diagnostics and tests)."""
    for i in range(F.shape[0]):
        c_rr, c_tt, c_rt = local_deformation(F[i, 0, 0], F[i, 0, 1], F[i, 1, 0], F[i, 1, 1], cth[i], sth[i])[4:]
        W[i] = strain_energy(c_rr, c_tt, c_rt, lz, props, i)


@njit(cache=True, error_model="numpy")
def pair_force_scale(V, ptr, a, P, out):
    """Per particle ``V_i |P_i| sum_j |a_ij|``: the size of the stress fluxes through its stencil."""
    n = V.shape[0]
    for i in range(n):
        pn = np.sqrt(P[i, 0, 0] ** 2 + P[i, 0, 1] ** 2 + P[i, 1, 0] ** 2 + P[i, 1, 1] ** 2)
        acc = 0.0
        for e in range(ptr[i], ptr[i + 1]):
            acc += np.sqrt(a[e, 0] ** 2 + a[e, 1] ** 2)
        out[i] = V[i] * pn * acc


# ---------------------------------------------------------------------------
# Jacobian d f / d x in 2 x 2 blocks
# ---------------------------------------------------------------------------


def block_pattern(ptr, nbr, owner=None):
    """Sparsity of the Jacobian: every pair of particles sharing a stencil.

    Returns ``(indptr, indices, blockmap, map_ptr)``: a block-CSR pattern and,
    for stencil i with nodes ``[owner[i], nbr[ptr[i]:ptr[i+1]]]`` (size m),
    ``blockmap[map_ptr[i] + p*m + q]`` = block index of (node p, node q). The stencils are the particles'
    (``owner`` None: stencil i is particle i's) or those of integration points (:mod:`sphgag.engine.quadrature`:
    ``nbr`` their neighbour particles, ``owner`` each point's particle).
    """
    stencils = ptr.shape[0] - 1
    owner = np.arange(stencils) if owner is None else np.asarray(owner, dtype=np.int64)
    n = int(owner.max()) + 1 if owner.size else 0
    counts = np.diff(ptr) + 1
    map_ptr = np.zeros(stencils + 1, dtype=np.int64)
    np.cumsum(counts * counts, out=map_ptr[1:])
    rows = np.empty(map_ptr[-1], dtype=np.int64)
    cols = np.empty(map_ptr[-1], dtype=np.int64)
    _pattern_pairs(ptr, nbr, owner, map_ptr, rows, cols)
    keys = rows * n + cols
    uniq, inverse = np.unique(keys, return_inverse=True)
    brow, bcol = uniq // n, uniq % n
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(brow, minlength=n), out=indptr[1:])
    return indptr, bcol.astype(np.int64), inverse.astype(np.int64), map_ptr


@njit(cache=True)
def _pattern_pairs(ptr, nbr, owner, map_ptr, rows, cols):
    n = ptr.shape[0] - 1
    for i in range(n):
        m = ptr[i + 1] - ptr[i] + 1
        base = map_ptr[i]
        for p in range(m):
            rp = owner[i] if p == 0 else nbr[ptr[i] + p - 1]
            for q in range(m):
                rq = owner[i] if q == 0 else nbr[ptr[i] + q - 1]
                rows[base + p * m + q] = rp
                cols[base + p * m + q] = rq


@njit(cache=True, error_model="numpy")
def jacobian_blocks(x, V, ptr, nbr, mir, a, s, ah, sh, R, hgc, F, Fh, lz, cth, sth, props, blockmap, map_ptr, data):
    """Add ``d(f_int + f_hg)/dx`` (eqs. 2.11, 2.14-2.15) to the 2 x 2 blocks ``data`` (:func:`block_pattern`).

    Elastic part: ``-sum_i V_i B_i^T A_i B_i`` with ``F_i = sum_p (M_p x_p) (x) b_p``
    (node 0 = i with b = -s_i, node k = entry k with b = a_ik). Hourglass part:
    derivative of the pair vectors ``c delta n`` through the hourglass gradient
    ``F~_i`` (node vectors ``-sh_i``, ``ah_ik``), ``r`` and ``n``. Over integration points
    (:mod:`sphgag.engine.quadrature`: stencil i is point i, its nodes its owner and its neighbour particles) the pair
    coefficients ``hgc`` must be zero (their hourglass control is the energy form): the pair term reads ``x[i]`` as
    the stencil's own particle.
    """
    n = ptr.shape[0] - 1  # stencils: the particles', or the integration points' (engine.quadrature)
    C = np.empty((3, 3))
    A = np.empty((4, 4))
    for i in range(n):
        tangent_modulus(F[i, 0, 0], F[i, 0, 1], F[i, 1, 0], F[i, 1, 1], lz, cth[i], sth[i], props, i, C, A)
        e0 = ptr[i]
        m = ptr[i + 1] - e0 + 1
        base = map_ptr[i]
        # node data: b vectors and mirror diagonals
        b = np.empty((m, 2))
        M = np.empty((m, 2))
        b[0, 0], b[0, 1] = -s[i, 0], -s[i, 1]
        M[0, 0], M[0, 1] = 1.0, 1.0
        for k in range(1, m):
            e = e0 + k - 1
            b[k, 0], b[k, 1] = a[e, 0], a[e, 1]
            M[k, 0], M[k, 1] = mir[e, 0], mir[e, 1]
        # T[q, c, d, B] = sum_D A[cB, dD] b_q[D]
        T = np.empty((m, 2, 2, 2))
        for q in range(m):
            for c in range(2):
                for d in range(2):
                    for B in range(2):
                        T[q, c, d, B] = A[2 * c + B, 2 * d] * b[q, 0] + A[2 * c + B, 2 * d + 1] * b[q, 1]
        Vi = V[i]
        for p in range(m):
            for q in range(m):
                blk = blockmap[base + p * m + q]
                for c in range(2):
                    for d in range(2):
                        v = b[p, 0] * T[q, c, d, 0] + b[p, 1] * T[q, c, d, 1]
                        data[blk, c, d] -= Vi * M[p, c] * M[q, d] * v

        _hourglass_blocks(i, x, nbr, R, hgc, ah, sh, Fh, M, b, e0, m, blockmap, base, data)


@njit(cache=True, error_model="numpy")
def _hourglass_blocks(i, x, nbr, R, hgc, ah, sh, Fh, M, b, e0, m, blockmap, base, data):
    """The hourglass pairs' part of :func:`jacobian_blocks` for particle ``i`` (its ``m`` nodes from entry ``e0``,
    mirror diagonals ``M``, the blocks of its stencil from ``blockmap[base]``): derivative of the pair vectors
    ``c delta n`` through ``F~_i`` (node vectors ``-sh_i``, ``ah_ik``; ``b`` is overwritten with them), ``r`` and
    ``n``."""
    b[0, 0], b[0, 1] = -sh[i, 0], -sh[i, 1]
    for k in range(1, m):
        b[k, 0], b[k, 1] = ah[e0 + k - 1, 0], ah[e0 + k - 1, 1]
    F00, F01, F10, F11 = Fh[i, 0, 0], Fh[i, 0, 1], Fh[i, 1, 0], Fh[i, 1, 1]
    for k in range(1, m):
        e = e0 + k - 1
        c = hgc[e]
        if c == 0.0:  # no penalty across a GAG/tissue interface
            continue
        j = nbr[e]
        sx, sy = M[k, 0], M[k, 1]
        r0 = sx * x[j, 0] - x[i, 0]
        r1 = sy * x[j, 1] - x[i, 1]
        d = np.sqrt(r0 * r0 + r1 * r1)
        n0, n1 = r0 / d, r1 / d
        q0 = F00 * R[e, 0] + F01 * R[e, 1]
        q1 = F10 * R[e, 0] + F11 * R[e, 1]
        qn = q0 * n0 + q1 * n1
        delta = qn - d
        # d delta / d r = (q - (n.q) n)/d - n
        u0 = (q0 - qn * n0) / d - n0
        u1 = (q1 - qn * n1) / d - n1
        # H = c [n (x) u + delta (I - n n)/d]
        h00 = c * (n0 * u0 + delta * (1.0 - n0 * n0) / d)
        h01 = c * (n0 * u1 - delta * n0 * n1 / d)
        h10 = c * (n1 * u0 - delta * n1 * n0 / d)
        h11 = c * (n1 * u1 + delta * (1.0 - n1 * n1) / d)
        for p in range(m):
            coef = c * (b[p, 0] * R[e, 0] + b[p, 1] * R[e, 1])
            mn0, mn1 = M[p, 0] * n0, M[p, 1] * n1
            g00, g01 = coef * n0 * mn0, coef * n0 * mn1
            g10, g11 = coef * n1 * mn0, coef * n1 * mn1
            if p == 0:
                g00 -= h00
                g01 -= h01
                g10 -= h10
                g11 -= h11
            if p == k:
                g00 += h00 * sx
                g01 += h01 * sy
                g10 += h10 * sx
                g11 += h11 * sy
            bi = blockmap[base + p]  # (node 0, node p)
            data[bi, 0, 0] -= g00
            data[bi, 0, 1] -= g01
            data[bi, 1, 0] -= g10
            data[bi, 1, 1] -= g11
            bj = blockmap[base + k * m + p]  # (node k, node p)
            data[bj, 0, 0] += sx * g00
            data[bj, 0, 1] += sx * g01
            data[bj, 1, 0] += sy * g10
            data[bj, 1, 1] += sy * g11


@dataclass(frozen=True)
class HourglassForm(Variant):
    """A form of the hourglass control of eq. (2.14): what it adds to a model's forces and stiffness, given the pair
    coefficients ``c_ij`` and the stencil ``F~`` the forms share. It owns the key ``numerics.hourglass`` (with
    ``numerics.hourglass_alpha``, every form's alpha). ``short``: its label in a figure's legend (its name if
    empty)."""

    name: str
    title: str
    paper: bool = False
    short: str = ""

    def contribute(self, model, ah, sh, hgc) -> tuple[np.ndarray, np.ndarray | None]:
        """``(hgc, K)``: the coefficients of eq. (2.14)'s pair forces, which the elastic kernels compute with the
        elastic forces (this module's kernels), and the 2 x 2 blocks of a constant stiffness ``K`` whose forces
        are ``-K (x - X)`` (None: no such part). ``model`` gives the neighbour lists and the blocks' pattern
        (:func:`block_pattern`); ``ah, sh`` the stencil of ``F~``."""
        raise NotImplementedError


@dataclass(frozen=True)
class PairForm(HourglassForm):
    """Eq. (2.14) as printed: the pair forces along the current pair direction, computed with the elastic forces."""

    def contribute(self, model, ah, sh, hgc):
        return hgc, None


@dataclass(frozen=True)
class EnergyForm(HourglassForm):
    """The energy ``E_hg = sum c_ij / 2 |d_ij|^2``: a constant stiffness ``K`` (:func:`energy_stiffness_blocks`), no
    pair forces in the elastic kernels (their coefficients are zero)."""

    def contribute(self, model, ah, sh, hgc):
        nb = model.stencil
        stiffness = np.zeros((model.block_indices.size, 2, 2))
        energy_stiffness_blocks(nb.ptr, nb.nbr, nb.mirror, nb.R, ah, sh, hgc, model.blockmap, model.map_ptr, stiffness)
        return np.zeros_like(hgc), stiffness


#: the registry of hourglass forms, by name (``numerics.hourglass``, wildcard ``{form}``; the paper's first)
HOURGLASS_FORMS: Registry[HourglassForm] = Registry(
    "hourglass form",
    (
        PairForm(
            "paper",
            "eq. (2.14) as printed: pair forces along the current pair direction",
            paper=True,
            short="eq. (2.14) as printed",
        ),
        EnergyForm(
            "energy",
            "the energy form of eq. (2.14): a symmetric, positive semi-definite stiffness",
            short="energy form of eq. (2.14)",
        ),
    ),
)


@njit(cache=True)
def energy_stiffness_blocks(ptr, nbr, mir, R, ah, sh, hgc, blockmap, map_ptr, data):
    """Add ``K`` of ``E_hg = sum_e c_e/2 |d_e|^2`` to the 2 x 2 blocks ``data`` (pattern of
    :func:`block_pattern`).

    For entry ``e = (i, j)`` of particle i's stencil (node 0 = i, node k = entry k, mirror signs ``M``):
    ``d_e = sum_p g_p M_p x_p`` with ``g_0 = 1 - sh_i . R_e``, ``g_k = ah_k . R_e`` and ``-1`` added at
    the node of j (``r_e = M_j x_j - x_i``); each component separately, so the blocks are diagonal.
    """
    n = ptr.shape[0] - 1
    for i in range(n):
        e0 = ptr[i]
        m = ptr[i + 1] - e0 + 1
        base = map_ptr[i]
        M = np.ones((m, 2))
        for k in range(1, m):
            M[k, 0], M[k, 1] = mir[e0 + k - 1, 0], mir[e0 + k - 1, 1]
        g = np.empty(m)
        for k in range(1, m):
            e = e0 + k - 1
            c = hgc[e]
            if c == 0.0:
                continue
            g[0] = 1.0 - (sh[i, 0] * R[e, 0] + sh[i, 1] * R[e, 1])
            for p in range(1, m):
                g[p] = ah[e0 + p - 1, 0] * R[e, 0] + ah[e0 + p - 1, 1] * R[e, 1]
            g[k] -= 1.0
            for p in range(m):
                cp = c * g[p]
                for q in range(m):
                    blk = blockmap[base + p * m + q]
                    v = cp * g[q]
                    data[blk, 0, 0] += v * M[p, 0] * M[q, 0]
                    data[blk, 1, 1] += v * M[p, 1] * M[q, 1]
