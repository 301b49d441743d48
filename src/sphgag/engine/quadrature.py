"""Integration points of an interface-fitted particle layout: each material computes its deformation gradient from its
own side (the particle analogue of an interface-fitted mesh; :func:`sphgag.studies.artery.bilayer_model` with
``fitted``).

Eq. (2.9)'s corrected gradient ``F_i = sum_j (x_j - x_i) (x) V_j A_i^-1 grad xi_ij`` over a stencil that straddles a
material interface averages F across it, where the displacement has a kink (F jumps): no polynomial correction can
represent that, and the error in a band one kernel wide does not shrink with the spacing (first order in global
outputs; docs/physics.md, "Interface-fitted particles"). Here, as finite elements put element edges on an interface:

* particles sit on every material interface of the reference configuration (:func:`sphgag.engine.geometry.
  quarter_annulus` with ``fitted``: a ring at each layer border) and belong to both sides;
* every particle carries one **integration point** per side it belongs to (:meth:`sphgag.engine.geometry.Layout.
  points`): its owner, its side's material (a row of the property table, pre-stretch included), a volume share (each
  region's shares sum to its exact area) and its stencil, the particles of its side, interface particles included,
  each weighted by its share on that side;
* point ``q`` of owner ``o`` has ``F_q = sum_e (M_e x_j - x_o) (x) a_e`` over its stencil (eq. 2.9 on one side),
  ``M_e`` the entry's mirror, with ``a_e = V_j A_q^-1 grad xi(R_e)`` and ``A_q = sum_e V_j grad xi(R_e) (x) R_e``
  (eqs. 2.7-2.8) made integration-consistent (:func:`consistent_gradients`, below);
* the energy is ``sum_q V_q W_q(F_q)`` (eqs. 2.18-2.24 with the side's row), and the forces and the exact Jacobian
  are its derivatives: ``f_o += V_q P_q s_q`` and ``f_j -= M_e V_q P_q a_e`` (eq. 2.11 per point,
  ``s_q = sum_e a_e``); an interface particle receives forces from both sides.

Continuity across the interface is exact (shared particles), and the traction continuity is variational (one energy):
no new unknown and no penalty. A field that is affine on each side is reproduced exactly on each side. One-sided
stencils alone leave the band along an interface out of balance under a piecewise-uniform stress (up to a third of
``|P| dx`` per particle in the bimaterial patch test): the corrected gradients do not integrate consistently there.
:func:`consistent_gradients` makes them do so (variationally consistent integration), once per layout, and the
bimaterial patch test then holds to round-off (``tests/test_quadrature.py``). The hourglass control is the energy form
of eq. (2.14) over each point's stencil (pairs within a side only): :class:`sphgag.engine.forces.EnergyForm` on the
model's :attr:`sphgag.engine.model.Model.stencil`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numba import njit, prange

from .forces import NO_EXTRA_STRESS, block_pattern, piola_stresses
from .geometry import Layout
from .kernel import Neighbours, stencil_gradients
from .loading import lumen_area_gradient


@dataclass(frozen=True)
class Quadrature:
    """The integration points of a fitted layout and their one-sided stencils (flat CSR arrays over points).

    owner, layer, volume : (Q,) each point's particle, its side (an index of ``layout.layer_names``) and its volume
        share [um^2].
    first : (N,) each particle's first point (its own layer's).
    ptr, nbr : CSR offsets (Q + 1,) and each entry's neighbour *point* (the neighbour's point on the same side).
    particle : (E,) each entry's neighbour particle (``owner[nbr]``).
    mirror, R, w, he : (E, 2), (E, 2), (E,), (E,) the entry's mirror diagonal, reference separation ``M X_j - X_o``,
        kernel value and support (as :class:`sphgag.engine.kernel.Neighbours`).
    a, s, A : (E, 2), (Q, 2), (Q, 2, 2) the gradients of each point's stencil (eq. 2.8's, made integration-consistent
        by :func:`consistent_gradients`), their sums and eq. (2.8)'s correction matrices (before that change): the
        correction matrices (eqs. 2.7-2.8).
    layout : the points as a layout (positions and angles of their owners, their sides as layers, their volume
        shares): the material tables of a fitted model are built on it, one row per point.
    """

    owner: np.ndarray
    layer: np.ndarray
    volume: np.ndarray
    first: np.ndarray
    ptr: np.ndarray
    nbr: np.ndarray
    particle: np.ndarray
    mirror: np.ndarray
    R: np.ndarray
    w: np.ndarray
    he: np.ndarray
    a: np.ndarray
    s: np.ndarray
    A: np.ndarray
    layout: Layout

    @property
    def n_points(self) -> int:
        return self.owner.size

    @property
    def n_entries(self) -> int:
        return self.nbr.size

    @property
    def shared(self) -> np.ndarray:
        """The particles with more than one point (on an interface)."""
        return np.flatnonzero(np.bincount(self.owner) > 1)


def build(layout: Layout, nb: Neighbours, free_surface=None, loaded_surface=None) -> Quadrature:
    """The integration points of ``layout`` (:meth:`Layout.points`) and their one-sided stencils, cut from the full
    reference neighbour lists ``nb`` (same supports and mirror planes): point ``q`` keeps the entries of its owner
    whose neighbour has a point on ``q``'s side. Their gradients are made integration-consistent
    (:func:`consistent_gradients`), with the traction-free surface ``free_surface`` (default: the outer surface) and
    the surface ``loaded_surface`` that the lumen pressure loads (default: the inner surface; its particles ordered
    along it, as :func:`sphgag.engine.loading.lumen_area_gradient` takes them)."""
    if len(layout.layer_names) > 1 and not layout.fitted:
        raise ValueError("integration points of several layers need particles on their interfaces (a fitted layout)")
    owner, layer, volume = layout.points()
    n, q_count = layout.n, owner.size
    point_at = -np.ones((n, len(layout.layer_names)), dtype=np.int64)
    point_at[owner, layer] = np.arange(q_count)
    counts = np.diff(nb.ptr)[owner]
    q_of = np.repeat(np.arange(q_count), counts)
    starts = np.repeat(nb.ptr[owner], counts)
    entry = starts + np.arange(q_of.size) - np.repeat(np.cumsum(counts) - counts, counts)
    target = point_at[nb.nbr[entry], layer[q_of]]
    keep = target >= 0
    entry, q_of, target = entry[keep], q_of[keep], target[keep]
    ptr = np.zeros(q_count + 1, dtype=np.int64)
    np.cumsum(np.bincount(q_of, minlength=q_count), out=ptr[1:])
    E = entry.size
    a, s, A = np.empty((E, 2)), np.empty((q_count, 2)), np.empty((q_count, 2, 2))
    R, he = np.ascontiguousarray(nb.R[entry]), np.ascontiguousarray(nb.he[entry])
    stencil_gradients(volume, he, ptr, target, R, np.ones(E), a, s, A)
    cond = np.linalg.cond(A)
    if not np.all(np.isfinite(cond)) or cond.max() > 1e8:
        worst = int(np.argmax(np.where(np.isfinite(cond), cond, np.inf)))
        raise ValueError(
            f"singular one-sided correction matrix at particle {owner[worst]} ({layout.layer_names[layer[worst]]} "
            f"side; condition number {cond[worst]:.3g}): increase the kernel support"
        )
    free = np.zeros(n, dtype=bool)
    free[layout.outer_surface if free_surface is None else free_surface] = True
    loaded = np.full((q_count, 2), np.nan)
    inner = layout.inner_surface if loaded_surface is None else loaded_surface
    if inner.size:  # the lumen load's reference -dA/dX (engine.loading), on each inner-surface particle's one point
        grad = np.empty((inner.size, 2))
        lumen_area_gradient(layout.X, inner, grad)
        loaded[point_at[inner, layout.layer[inner]]] = -grad
    mirror, w = np.ascontiguousarray(nb.mirror[entry]), np.ascontiguousarray(nb.w[entry])
    a = consistent_gradients(owner, volume, ptr, target, mirror, R, w, a, free, loaded)
    s = stencil_sums(ptr, a)
    first = first_points(owner)
    points = Layout(
        X=np.ascontiguousarray(layout.X[owner]),
        volume=volume,
        radius=layout.radius[owner],
        theta=layout.theta[owner],
        ring=layout.ring[owner],
        layer=layer,
        ring_radius=layout.ring_radius,
        ring_cell=layout.ring_cell,
        interfaces=layout.interfaces,
        layer_names=layout.layer_names,
        dx=layout.dx,
        pool_layers=layout.pool_layers,
        spacing=layout.spacing[owner],
    )
    return Quadrature(
        owner=owner,
        layer=layer,
        volume=volume,
        first=first,
        ptr=ptr,
        nbr=target,
        particle=owner[target],
        mirror=mirror,
        R=R,
        w=w,
        he=he,
        a=a,
        s=s,
        A=A,
        layout=points,
    )


def first_points(owner) -> np.ndarray:
    """Each particle's first integration point (``owner`` sorted, as :meth:`Layout.points` orders it)."""
    first = np.full(int(owner.max()) + 1, -1, dtype=np.int64)
    first[owner[::-1]] = np.arange(owner.size)[::-1]
    return first


def stencil_sums(ptr, a) -> np.ndarray:
    """``s_q = sum_e a_e`` over each point's entries (zero for an empty stencil)."""
    s = np.zeros((ptr.size - 1, 2))
    np.add.at(s, np.repeat(np.arange(ptr.size - 1), np.diff(ptr)), a)
    return s


def divergence(volume, ptr, nbr, mirror, a) -> np.ndarray:
    """``D_q = sum_p V_p sum_(e of p, nbr e = q) M_e a_e - V_q s_q`` (Q, 2): the discrete ``int_side grad N_q dV`` of
    each point's shape function over its side (mirror images folded back). A uniform stress ``P`` of a side puts the
    force ``-P D_q`` on point ``q``'s particle: the exact ``-P int grad N dV = -P int_boundary N n dA`` vanishes away
    from the side's boundary, so a consistent integration has ``D_q = 0`` there (the divergence constraint of
    Chen, Hillman & Rueter 2013)."""
    q_count = ptr.size - 1
    owner_of_entry = np.repeat(np.arange(q_count), np.diff(ptr))
    D = np.zeros((q_count, 2))
    np.add.at(D, nbr, volume[owner_of_entry, None] * mirror * a)
    D -= volume[:, None] * stencil_sums(ptr, a)
    return D


def consistent_gradients(owner, volume, ptr, nbr, mirror, R, w, a, free, loaded) -> np.ndarray:
    """The corrected gradients ``a`` made integration-consistent (variationally consistent integration, Chen, Hillman &
    Rueter 2013, IJNME 95:387-418, with linear exactness kept): the smallest kernel-weighted change ``delta a``
    (``sum_e |delta a_e|^2 / xi_e`` per point) such that every point still reproduces affine maps exactly
    (``sum_e R_e (x) delta a_e = 0``: eq. 2.9 stays exact) and its :func:`divergence` ``D_q`` is what the boundary
    integral ``int N n dA`` of the continuum makes it:

    * ``D_q = 0`` off the boundaries;
    * on a material interface, the points of a particle sum to zero and have no part along the interface (where its
      normal is defined; the normal part, the interface's own measure, is free): a piecewise-uniform stress whose
      traction is continuous across the interface (``P_1 n = P_2 n``) puts no force on an interface particle, nor on
      any particle inside a side (the bimaterial patch test);
    * on a traction-free surface (``free``), no part along the surface (``P n = 0`` there then puts no force);
    * on a loaded surface, ``D_q = loaded[q]`` (finite rows; the load's own ``-dA/dX``, so that a uniform stress in
      equilibrium with the load leaves no residual there).

    The multipliers solve one sparse symmetric system over the points (the pattern of points sharing a stencil),
    once per layout.
    """
    q_count = owner.size
    D = divergence(volume, ptr, nbr, mirror, a)
    T, target = _constraints(owner, ptr, nbr, R, free, loaded)
    indptr, indices, blockmap, map_ptr = block_pattern(ptr, nbr)
    data = np.zeros((indices.size, 2, 2))
    _consistency_blocks(volume, ptr, mirror, R, w, blockmap, map_ptr, data)
    S = sp.bsr_matrix((data, indices, indptr), shape=(2 * q_count, 2 * q_count)).tocsr()
    # symmetric positive definite: SuperLU in its symmetric mode (a minimum-degree ordering of K + K^T, no pivoting),
    # 20 times faster than its default here
    K = (T.T @ S @ T).tocsc()
    z = spla.splu(K, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options=dict(SymmetricMode=True)).solve(
        T.T @ (target - D).ravel()
    )
    out = a.copy()
    _apply_correction(volume, ptr, nbr, mirror, R, w, (T @ z).reshape(-1, 2), out)
    return out


def _constraints(owner, ptr, nbr, R, free, loaded) -> tuple[sp.csr_matrix, np.ndarray]:
    """``(T, target)`` of :func:`consistent_gradients`: the constraints ``T^T D = T^T target`` as the columns of ``T``
    over the points' components (the multipliers are ``lambda = T z``). A point inside a side, or on a loaded
    surface: its own two. The points of an interface particle: two on their sum and, where the interface has a
    normal (:func:`_normals`), one on the first's tangential part. A point on a traction-free surface: one on its
    tangential part (none at a corner)."""
    q_count = owner.size
    counts = np.bincount(owner)
    first = first_points(owner)
    shared = counts[owner] > 1
    normal = np.where(shared[:, None], _normals(shared[first], owner, ptr, nbr, R), _normals(free, owner, ptr, nbr, R))
    whole = ~free[owner] | shared  # every point with its two columns (on its particle's first point's)
    rows, cols, vals = [], [], []
    q = np.flatnonzero(whole)
    for c in range(2):
        rows.append(2 * q + c)
        cols.append(2 * first[owner[q]] + c)
        vals.append(np.ones(q.size))
    tangential = np.flatnonzero((free[owner] & ~shared) | (shared & (np.arange(q_count) == first[owner])))
    tangential = tangential[np.isfinite(normal[tangential, 0])]
    extra = 2 * q_count + np.arange(tangential.size)
    for c, t in enumerate((-normal[tangential, 1], normal[tangential, 0])):
        rows.append(2 * tangential + c)
        cols.append(extra)
        vals.append(t)
    rows, cols, vals = np.concatenate(rows), np.concatenate(cols), np.concatenate(vals)
    used, column = np.unique(cols, return_inverse=True)
    T = sp.csr_matrix((vals, (rows, column)), shape=(2 * q_count, used.size))
    target = np.where(np.isfinite(loaded), loaded, 0.0)
    return T, target


LINE_LIKE = 0.05  # boundary particles near one lie along a line where the smaller principal moment is below this


def _normals(on, owner, ptr, nbr, R) -> np.ndarray:
    """The unit normal of a boundary (the particles ``on``: an interface's or a surface's) at every point of its
    particles (NaN elsewhere, and at a corner): perpendicular to the principal direction of the separations ``R_e``
    to the boundary's other particles in the point's stencil (mirror images included), where they lie along a line
    (:data:`LINE_LIKE`)."""
    normal = np.full((owner.size, 2), np.nan)
    for q in np.flatnonzero(on[owner]):
        e = np.arange(ptr[q], ptr[q + 1])
        e = e[on[owner[nbr[e]]]]
        if e.size < 2:
            continue
        vals, vecs = np.linalg.eigh(R[e].T @ R[e])
        if vals[0] <= LINE_LIKE * vals[1]:
            normal[q] = vecs[:, 0]
    return normal


@njit(cache=True)
def _projector(ptr, R, w, q, Pi):
    """``Pi = W - W R (R^T W R)^-1 R^T W`` of point ``q`` (``W = diag(xi_e)``): the kernel-weighted projection onto
    the changes of its gradients that keep ``sum_e R_e (x) delta a_e = 0``."""
    e0, m = ptr[q], ptr[q + 1] - ptr[q]
    g00 = g01 = g11 = 0.0
    for k in range(m):
        e = e0 + k
        g00 += w[e] * R[e, 0] * R[e, 0]
        g01 += w[e] * R[e, 0] * R[e, 1]
        g11 += w[e] * R[e, 1] * R[e, 1]
    det = g00 * g11 - g01 * g01
    i00, i01, i11 = g11 / det, -g01 / det, g00 / det
    for k in range(m):
        ek = e0 + k
        for l in range(m):
            el = e0 + l
            quad = R[ek, 0] * (i00 * R[el, 0] + i01 * R[el, 1]) + R[ek, 1] * (i01 * R[el, 0] + i11 * R[el, 1])
            Pi[k, l] = -w[ek] * quad * w[el]
        Pi[k, k] += w[ek]


@njit(cache=True)
def _consistency_blocks(V, ptr, mir, R, w, blockmap, map_ptr, data):
    """The blocks of ``S = C Pi C^T`` (:func:`consistent_gradients`): per point ``q`` with nodes ``[q, nbr...]``
    and, per component, ``B[e, 0] = -1``, ``B[e, e + 1] = M_e``: ``V_q^2 B^T Pi B`` (the components decouple:
    diagonal blocks)."""
    q_count = ptr.shape[0] - 1
    Pi = np.empty((64, 64))
    for q in range(q_count):
        m = ptr[q + 1] - ptr[q]
        if m > Pi.shape[0]:
            Pi = np.empty((m, m))
        _projector(ptr, R, w, q, Pi)
        e0, base, n1 = ptr[q], map_ptr[q], m + 1
        v2 = V[q] * V[q]
        for c in range(2):
            total = 0.0
            for k in range(m):
                row = 0.0
                for l in range(m):
                    row += Pi[k, l]
                    data[blockmap[base + (k + 1) * n1 + l + 1], c, c] += v2 * mir[e0 + k, c] * Pi[k, l] * mir[e0 + l, c]
                total += row
                data[blockmap[base + k + 1], c, c] -= v2 * row * mir[e0 + k, c]  # (node 0, node k + 1)
                data[blockmap[base + (k + 1) * n1], c, c] -= v2 * row * mir[e0 + k, c]
            data[blockmap[base], c, c] += v2 * total


@njit(cache=True)
def _apply_correction(V, ptr, nbr, mir, R, w, lam, a):
    """``a_e += V_q (Pi Y)_e`` with ``Y_e = M_e lam_(nbr e) - lam_q`` (the stationary point of
    :func:`consistent_gradients`' Lagrangian)."""
    q_count = ptr.shape[0] - 1
    Pi = np.empty((64, 64))
    y = np.empty((64, 2))
    for q in range(q_count):
        m = ptr[q + 1] - ptr[q]
        if m > Pi.shape[0]:
            Pi = np.empty((m, m))
            y = np.empty((m, 2))
        _projector(ptr, R, w, q, Pi)
        e0 = ptr[q]
        for k in range(m):
            for c in range(2):
                y[k, c] = mir[e0 + k, c] * lam[nbr[e0 + k], c] - lam[q, c]
        for k in range(m):
            for c in range(2):
                acc = 0.0
                for l in range(m):
                    acc += Pi[k, l] * y[l, c]
                a[e0 + k, c] += V[q] * acc


@njit(cache=True, error_model="numpy", parallel=True)
def _gradients(x, owner, particle, ptr, mir, a, FP):
    """``FP[q, :4] = F_q`` (row-major): ``F_q = sum_e (M_e x_j - x_o) (x) a_e`` over the point's one-sided stencil
    (eq. 2.9), parallel over points."""
    for q in prange(owner.shape[0]):
        o = owner[q]
        xo0, xo1 = x[o, 0], x[o, 1]
        f00 = f01 = f10 = f11 = 0.0
        for e in range(ptr[q], ptr[q + 1]):
            j = particle[e]
            d0 = mir[e, 0] * x[j, 0] - xo0
            d1 = mir[e, 1] * x[j, 1] - xo1
            f00 += d0 * a[e, 0]
            f01 += d0 * a[e, 1]
            f10 += d1 * a[e, 0]
            f11 += d1 * a[e, 1]
        FP[q, 0], FP[q, 1], FP[q, 2], FP[q, 3] = f00, f01, f10, f11


@njit(cache=True, error_model="numpy")
def _scatter(owner, particle, ptr, mir, a, s, V, FP, f):
    """``f = -d/dx sum_q V_q W_q(F_q)``: ``f_o += V_q P_q s_q`` and ``f_j -= M_e V_q P_q a_e`` (eq. 2.11 per point)."""
    f[:, :] = 0.0
    for q in range(owner.shape[0]):
        o = owner[q]
        v = V[q]
        p00, p01, p10, p11 = v * FP[q, 4], v * FP[q, 5], v * FP[q, 6], v * FP[q, 7]
        f[o, 0] += p00 * s[q, 0] + p01 * s[q, 1]
        f[o, 1] += p10 * s[q, 0] + p11 * s[q, 1]
        for e in range(ptr[q], ptr[q + 1]):
            j = particle[e]
            f[j, 0] -= mir[e, 0] * (p00 * a[e, 0] + p01 * a[e, 1])
            f[j, 1] -= mir[e, 1] * (p10 * a[e, 0] + p11 * a[e, 1])


def forces_and_stresses(x, quad: Quadrature, lz, cth, sth, props, FP, f) -> float:
    """One force evaluation of a fitted model: ``FP`` (Q, 8) the points' F and P, ``f`` (N, 2) the internal forces;
    ``cth, sth, props``: per point. Returns the smallest det(F_2D) (a point with det <= 0 gets NaN stress)."""
    _gradients(x, quad.owner, quad.particle, quad.ptr, quad.mirror, quad.a, FP)
    dmin = piola_stresses(lz, cth, sth, props, NO_EXTRA_STRESS, FP, quad.n_points)  # P_q of its own row (eq. 2.10)
    _scatter(quad.owner, quad.particle, quad.ptr, quad.mirror, quad.a, quad.s, quad.volume, FP, f)
    return float(dmin)
