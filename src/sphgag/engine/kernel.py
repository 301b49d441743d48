"""Spiky kernel, reference neighbour lists and corrected gradients (paper eqs. 2.1-2.8).

Neighbour lists are built once, in the reference configuration (total
Lagrangian SPH, section 2.1), as flat CSR arrays: the entries of particle ``i``
are ``ptr[i]:ptr[i+1]``.

**Symmetry edges.** The quarter annulus is bounded by the mirror planes
``theta = 0`` (``y = 0``) and ``theta = pi/2`` (``x = 0``). We realise the
paper's sliding boundaries as exact mirror symmetry: a particle near an edge
also interacts with the mirror images ("ghosts") of the particles across it.
A ghost's position is always the mirror image of its real particle, so the
normal displacement on the edge is zero and the tangential traction is free,
and every particle has a complete kernel support except at the inner and outer
surfaces. Each entry carries the diagonal of its mirror map, ``mirror[e] =
(s_x, s_y)`` with ``s = +-1``; a ghost of ``j`` sits at ``(s_x x_j, s_y y_j)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from .geometry import Layout

# Mirror maps: identity, mirror across y = 0 (theta = 0), mirror across x = 0 (theta = pi/2).
MIRRORS = np.array([[1.0, 1.0], [1.0, -1.0], [-1.0, 1.0]])


@njit(cache=True)
def spiky(r, h):
    """Spiky kernel xi(R) = 10 (h - R)^3 / (pi h^5) for R < h (eq. 2.4)."""
    if r >= h:
        return 0.0
    return 10.0 * (h - r) ** 3 / (np.pi * h**5)


@njit(cache=True)
def spiky_derivative(r, h):
    """d xi / dR of the spiky kernel (used in eq. 2.3)."""
    if r >= h:
        return 0.0
    return -30.0 * (h - r) ** 2 / (np.pi * h**5)


@njit(cache=True)
def _candidates(X, hp, mirror_codes, hmax, out_ptr, out_j, out_m, fill):
    """Neighbour candidates of every particle within ``h_ij = (h_i + h_j)/2`` (``hp``: per-particle supports), over
    the real particles and their mirror images (codes ``mirror_codes``), by a bucket grid of cell ``hmax``. With
    ``fill`` false, counts them into ``out_ptr[i + 1]``; with ``fill``, writes ``(j, mirror code)`` from
    ``out_ptr[i]`` in the order of increasing ``j``, then code (the order of an all-pairs search)."""
    n = X.shape[0]
    x0, y0 = X[:, 0].min() - hmax, X[:, 1].min() - hmax
    nx = int((X[:, 0].max() + hmax - x0) / hmax) + 1
    ny = int((X[:, 1].max() + hmax - y0) / hmax) + 1
    head = -np.ones(nx * ny, dtype=np.int64)
    nxt = -np.ones(n, dtype=np.int64)
    for j in range(n - 1, -1, -1):  # buckets list their particles by increasing index
        b = int((X[j, 0] - x0) / hmax) * ny + int((X[j, 1] - y0) / hmax)
        nxt[j] = head[b]
        head[b] = j
    found_j = np.empty(64, dtype=np.int64)
    found_m = np.empty(64, dtype=np.int64)
    for i in range(n):
        c = 0
        for m in mirror_codes:
            sx, sy = MIRRORS[m, 0], MIRRORS[m, 1]
            # the ghosts of j near i are the real j near the mirror image of i
            px, py = sx * X[i, 0], sy * X[i, 1]
            bx, by = int((px - x0) // hmax), int((py - y0) // hmax)
            for ix in range(bx - 1, bx + 2):
                if ix < 0 or ix >= nx:
                    continue
                for iy in range(by - 1, by + 2):
                    if iy < 0 or iy >= ny:
                        continue
                    j = head[ix * ny + iy]
                    while j >= 0:
                        dx = sx * X[j, 0] - X[i, 0]
                        dy = sy * X[j, 1] - X[i, 1]
                        d2 = dx * dx + dy * dy
                        h = 0.5 * (hp[i] + hp[j])
                        if d2 < h * h and d2 > 0.0:
                            if c == found_j.shape[0]:
                                found_j = np.concatenate((found_j, np.empty(c, dtype=np.int64)))
                                found_m = np.concatenate((found_m, np.empty(c, dtype=np.int64)))
                            found_j[c] = j
                            found_m[c] = m
                            c += 1
                        j = nxt[j]
        if not fill:
            out_ptr[i + 1] = c
            continue
        order = np.argsort(found_j[:c] * 3 + found_m[:c])
        e = out_ptr[i]
        for k in range(c):
            out_j[e + k] = found_j[order[k]]
            out_m[e + k] = found_m[order[k]]


@njit(cache=True)
def _corrected_gradients(X, V, he, ptr, nbr, mir, R, w, a, s, A_out):
    """Per-entry reference separation R_ij, kernel value, and V_j A_i^-1 grad xi (eqs. 2.3, 2.7, 2.8); ``he``: each
    entry's support ``h_ij``."""
    n = X.shape[0]
    for i in range(n):
        for e in range(ptr[i], ptr[i + 1]):
            j = nbr[e]
            r0 = mir[e, 0] * X[j, 0] - X[i, 0]
            r1 = mir[e, 1] * X[j, 1] - X[i, 1]
            R[e, 0] = r0
            R[e, 1] = r1
            w[e] = spiky(np.sqrt(r0 * r0 + r1 * r1), he[e])
    stencil_gradients(V, he, ptr, nbr, R, np.ones(nbr.shape[0]), a, s, A_out)


@njit(cache=True)
def stencil_gradients(V, he, ptr, nbr, R, beta, a, s, A_out):
    """``a_ij = beta_ij V_j A_i^-1 grad xi_ij`` with ``A_i = sum_j beta_ij V_j grad xi_ij (x) R_ij`` (eqs. 2.7-2.8),
    their sums ``s_i`` and ``A_i``; ``he``: each entry's support ``h_ij``; ``beta`` weights the stencil (1: the full
    stencil). A particle whose ``A_i`` is singular gets zero gradients."""
    n = ptr.shape[0] - 1
    for i in range(n):
        a00 = a01 = a10 = a11 = 0.0
        for e in range(ptr[i], ptr[i + 1]):
            r0, r1 = R[e, 0], R[e, 1]
            d = np.sqrt(r0 * r0 + r1 * r1)
            g = spiky_derivative(d, he[e]) / d
            wv = beta[e] * V[nbr[e]]
            # A_i = sum_j V_j grad xi (x) R_j  (eq. 2.8)
            a00 += wv * g * r0 * r0
            a01 += wv * g * r0 * r1
            a10 += wv * g * r1 * r0
            a11 += wv * g * r1 * r1
        det = a00 * a11 - a01 * a10
        A_out[i, 0, 0] = a00
        A_out[i, 0, 1] = a01
        A_out[i, 1, 0] = a10
        A_out[i, 1, 1] = a11
        if det == 0.0:
            i00 = i01 = i10 = i11 = 0.0
        else:
            i00, i01, i10, i11 = a11 / det, -a01 / det, -a10 / det, a00 / det
        s0 = s1 = 0.0
        for e in range(ptr[i], ptr[i + 1]):
            d = np.sqrt(R[e, 0] ** 2 + R[e, 1] ** 2)
            g = beta[e] * V[nbr[e]] * spiky_derivative(d, he[e]) / d
            g0, g1 = g * R[e, 0], g * R[e, 1]
            a[e, 0] = i00 * g0 + i01 * g1
            a[e, 1] = i10 * g0 + i11 * g1
            s0 += a[e, 0]
            s1 += a[e, 1]
        s[i, 0] = s0
        s[i, 1] = s1


def hourglass_gradients(nb: Neighbours, V, tissue):
    """Stencil weights and corrected gradients of the hourglass penalty (eqs. 2.8, 2.14-2.15) at a GAG/tissue interface.

    The hourglass penalty (eq. 2.14) punishes the part of a pair's separation
    that the particle's deformation gradient does not predict. Across the
    boundary of a soft GAG pool the real displacement field has a kink, which
    an F averaged over both materials cannot predict, so a penalty measured
    with it resists the kink itself (a stiff spurious interface layer, the
    ringing at the interface). The penalty is therefore measured within each
    material: pair ``(i, j)`` has weight ``beta_ij = 1 - |tissue_i - tissue_j|``
    (1 within tissue or within GAG, 0 across, continuous while a particle is
    converted), and its hourglass deformation gradient ``F~_i`` comes from the
    same weighted stencil with its own correction matrix, so it is exact for
    any deformation that is affine on each side. The elastic ``F`` (eq. 2.9)
    keeps the full stencil: the two materials stay coupled through it.

    Returns ``(beta, ah, sh)``: per-entry weights, weighted corrected gradients
    ``ah`` (like ``nb.a``) and their sums ``sh``; if every weight is 1, ``ah``
    and ``sh`` are ``nb.a`` and ``nb.s`` themselves.
    """
    owner = np.repeat(np.arange(V.size), np.diff(nb.ptr))
    beta = 1.0 - np.abs(tissue[owner] - tissue[nb.nbr])
    if np.all(beta == 1.0):
        return beta, nb.a, nb.s
    ah, sh, A = np.empty_like(nb.a), np.empty_like(nb.s), np.empty_like(nb.A)
    stencil_gradients(V, nb.he, nb.ptr, nb.nbr, nb.R, beta, ah, sh, A)
    # a (nearly) rank-deficient own-material stencil (an isolated GAG particle) keeps the full stencil
    det = A[:, 0, 0] * A[:, 1, 1] - A[:, 0, 1] * A[:, 1, 0]
    tr = A[:, 0, 0] + A[:, 1, 1]
    full = np.abs(nb.A[:, 0, 0] + nb.A[:, 1, 1])
    fallback = (det <= 1e-6 * tr * tr) | (np.abs(tr) < 1e-6 * full)
    entries = np.repeat(fallback, np.diff(nb.ptr))
    ah[entries], sh[fallback] = nb.a[entries], nb.s[fallback]
    return beta, ah, sh


@dataclass(frozen=True)
class Neighbours:
    """Reference neighbour lists and corrected kernel gradients (flat CSR arrays).

    ptr : (N+1,) CSR offsets; entries of particle i are ``ptr[i]:ptr[i+1]``.
    nbr : (E,) neighbour index j of each entry.
    mirror : (E, 2) diagonal of the mirror map of each entry (ghost = mirror * x_j).
    R : (E, 2) reference separation ``mirror * X_j - X_i`` (``R_j`` in eq. 2.1).
    w : (E,) kernel value xi(|R_j|) (eq. 2.4).
    a : (E, 2) ``V_j A_i^-1 grad xi(R_j)``: volume-weighted corrected gradient (eq. 2.8).
    s : (N, 2) ``sum_j a_ij``.
    A : (N, 2, 2) correction matrices (eq. 2.8).
    h : the largest kernel support (a uniform layout's support).
    hp : (N,) kernel support of each particle; a pair's is ``h_ij = (h_i + h_j) / 2`` (graded spacing).
    he : (E,) each entry's support ``h_ij``.
    ext : (E,) uint32 index of each entry's neighbour in the *extended* particle
        array (real particles ``0..N-1`` followed by the ghosts), used by the
        force kernel so that its inner loop needs no mirror logic.
    ghost_owner : (G,) real particle whose mirror image each ghost is.
    ghost_mirror : (G, 2) mirror diagonal of each ghost.
    pair_ptr, pair_entry, pair_reverse : half list of the real pairs ``i < j``:
        for particle i, ``pair_entry[pair_ptr[i]:pair_ptr[i+1]]`` are its entries
        ``i -> j`` with ``j > i`` and ``pair_reverse`` the matching entries ``j -> i``
        (the force kernel handles both directions of a pair at once).
    solo_ptr, solo_entry : the ghost entries of each particle (one direction only).
    """

    ptr: np.ndarray
    nbr: np.ndarray
    mirror: np.ndarray
    R: np.ndarray
    w: np.ndarray
    a: np.ndarray
    s: np.ndarray
    A: np.ndarray
    h: float
    hp: np.ndarray
    he: np.ndarray
    ext: np.ndarray
    ghost_owner: np.ndarray
    ghost_mirror: np.ndarray
    pair_ptr: np.ndarray
    pair_entry: np.ndarray
    pair_reverse: np.ndarray
    solo_ptr: np.ndarray
    solo_entry: np.ndarray

    @property
    def n_entries(self) -> int:
        return self.nbr.shape[0]

    def counts(self) -> np.ndarray:
        return np.diff(self.ptr)


def build_neighbours(X, volume, h, mirrors=(1, 2)) -> Neighbours:
    """Neighbour lists in the reference configuration: the pairs within ``h_ij = (h_i + h_j) / 2``.

    ``h``: the kernel support, one value or one per particle (graded spacing). ``mirrors`` lists the symmetry planes
    whose ghosts join the stencils (1: y = 0, 2: x = 0); pass ``()`` for a free body.
    """
    X = np.ascontiguousarray(X, dtype=float)
    V = np.ascontiguousarray(volume, dtype=float)
    codes = np.array((0,) + tuple(mirrors), dtype=np.int64)
    n = X.shape[0]
    hp = np.ascontiguousarray(np.broadcast_to(np.asarray(h, dtype=float), (n,)))
    ptr = np.zeros(n + 1, dtype=np.int64)
    _candidates(X, hp, codes, float(hp.max()), ptr, np.empty(0, np.int64), np.empty(0, np.int64), False)
    np.cumsum(ptr[1:], out=ptr[1:])
    E = int(ptr[-1])
    nbr = np.empty(E, dtype=np.int64)
    code = np.empty(E, dtype=np.int64)
    _candidates(X, hp, codes, float(hp.max()), ptr, nbr, code, True)
    mir = MIRRORS[code]
    counts = np.diff(ptr)
    owner = np.repeat(np.arange(n), counts)
    he = 0.5 * (hp[owner] + hp[nbr])
    R = np.empty((E, 2))
    w = np.empty(E)
    a = np.empty((E, 2))
    s = np.empty((n, 2))
    A = np.empty((n, 2, 2))
    _corrected_gradients(X, V, he, ptr, nbr, mir, R, w, a, s, A)
    cond = np.linalg.cond(A)
    if not np.all(np.isfinite(cond)) or cond.max() > 1e8:
        raise ValueError(
            f"singular SPH correction matrix (max condition number {cond.max():.3g}); "
            f"increase the kernel support h = {hp.min():g}-{hp.max():g}"
        )
    # ghosts: one per distinct (particle, mirror) pair among the mirrored entries
    ghost_key = np.unique(nbr[code > 0] * 3 + code[code > 0])
    ghost_owner = ghost_key // 3
    ghost_mirror = MIRRORS[ghost_key % 3]
    ext = nbr.copy()
    ghost = code > 0
    ext[ghost] = n + np.searchsorted(ghost_key, nbr[ghost] * 3 + code[ghost])
    # half list of real pairs, and the ghost ("solo") entries
    upper = ~ghost & (owner < nbr)
    lower = ~ghost & (owner > nbr)
    pair_entry = np.flatnonzero(upper)  # sorted by owner, then j
    key_lower = nbr[lower] * n + owner[lower]  # (j, i) of entries j -> i, reindexed as (i, j)
    order = np.argsort(key_lower)
    pair_reverse = np.flatnonzero(lower)[order]
    if not np.array_equal(np.sort(key_lower), owner[upper] * n + nbr[upper]):
        raise AssertionError("neighbour lists are not symmetric")
    solo_entry = np.flatnonzero(ghost)
    return Neighbours(
        ptr=ptr,
        nbr=nbr,
        mirror=mir,
        R=R,
        w=w,
        a=a,
        s=s,
        A=A,
        h=float(hp.max()),
        hp=hp,
        he=he,
        ext=ext.astype(np.uint32),
        ghost_owner=ghost_owner.astype(np.int64),
        ghost_mirror=np.ascontiguousarray(ghost_mirror),
        pair_ptr=_offsets(owner[pair_entry], n),
        pair_entry=pair_entry,
        pair_reverse=pair_reverse,
        solo_ptr=_offsets(owner[solo_entry], n),
        solo_entry=solo_entry,
    )


def _offsets(sorted_owner, n):
    ptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(sorted_owner, minlength=n), out=ptr[1:])
    return ptr


def for_layout(layout: Layout, support_factor: float) -> Neighbours:
    """Neighbours of a quarter-annulus layout with ``h_i = support_factor * spacing_i`` and both mirror planes."""
    return build_neighbours(layout.X, layout.volume, support_factor * layout.spacing, mirrors=(1, 2))
