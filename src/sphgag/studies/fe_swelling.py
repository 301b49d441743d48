"""Finite-element reference solutions of a swelling GAG pool at large strain (verification of the SPH engine).

The SPH studies' boundary value problems on isoparametric quadratic triangles (scikit-fem: ``MeshTri2`` with its
vertices and edge midpoints on the exact geometry), total Lagrangian, plane strain at ``lz = 1``, with the laws of
:mod:`sphgag.physics.materials` (``pk2``): matrix ``W = mu/2 (I1 - 3) - mu ln J + lam/2 (ln J)^2`` (the elastin law,
eq. 2.21, without pre-stretch or fibres), ``I1 = tr C_2D + 1``, ``J = det F``; pool (GAG, eq. 2.27)
``mu_g/2 (I1 - 3) - mu_g ln J + U(J)``, ``U = lam_g u(J)`` the contents' volumetric form
(:mod:`sphgag.physics.volumetric`, the GAG's ``volumetric``), plus the prescribed Donnan term ``- Pi (J - 1)``.
First Piola stress ``P = mu F + g F^-T``, ``g = h - mu - Pi J`` with ``h = J U'(J)`` (``lam ln J`` for the matrix);
consistent tangent ``dP/dF = mu I (x) I + (k - Pi J) F^-T (x) F^-T - g F^-T_iL F^-T_kJ``, ``k = J dh/dJ``
(``lam`` for the matrix). Newton, ``Pi`` applied in steps (linear predictor from the last two states, step halved on
failure).
The discretisation (:class:`_Model`): P2 displacement; in the matrix a P1 pressure ``p = lam ln J`` (Taylor-Hood,
free of the locking of the nearly incompressible matrix, ``lam / mu = 111``).

Meshes are mapped tensor grids ``(q, t) -> (x, y)``, graded by :func:`_graded`: element size ``h (1 + d / ell)``
(at most ``cap h``), ``d`` the distance to the feature, so halving ``h`` refines one graded mesh uniformly.
:func:`elliptic_pool`: the quarter of the ellipse ``(a + extent, b + extent)`` around the pool ``(a, b)`` (the SPH
layout of :func:`sphgag.studies.inclusion.ellipse_layout`): scaled ellipses inside the pool (a fan at the centre),
offset ellipses ``((a + s) cos t, (b + s) sin t)`` outside, graded into the tip. :func:`sector_pool`: the quarter
annulus with an annular-sector pool (figure 4) on a polar grid graded into the pool's four corners, whose lines
include every edge of the SPH probe regions (:func:`sphgag.engine.measure.pool_probes`), so their averages are
integrals over whole elements. Mirror planes on the axes (``u_x = 0`` on ``x = 0``, ``u_y = 0`` on ``y = 0``),
traction-free outer (and inner) boundaries. Materials are dicts with ``shear_modulus_kPa`` and ``lame_lambda_kPa``,
and for the GAG its ``volumetric`` form.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from scipy.sparse import bmat
from scipy.sparse.linalg import splu
from skfem import Basis, BilinearForm, ElementTriP1, ElementTriP2, ElementVector, LinearForm, MeshTri1, MeshTri2

from ..engine.geometry import Sector
from ..engine.measure import pool_probes
from ..physics import volumetric

# Relative Newton residual (free dofs, against the pool pressure's forces) of an accepted state, and the bound under
# which a state is also accepted once Newton stops converging (round-off: lam eps / Pi ~ 1e-10 at Pi = 0.05 kPa)
TOLERANCE, ROUNDOFF = 1e-10, 1e-8


def _graded(breaks, foci, h, ell, cap, metric=1.0):
    """1D grid through every point of ``breaks`` (sorted), spaced ``h min(1 + d/ell, cap)`` with ``d = metric |x -
    nearest focus|`` (``metric``: physical length per unit of ``x``)."""
    nodes = [breaks[0]]
    for lo, hi in zip(breaks[:-1], breaks[1:]):
        x = np.linspace(lo, hi, 4001)
        d = metric * np.min(np.abs(x[:, None] - np.asarray(foci, dtype=float)[None, :]), axis=1)
        dens = metric / (h * np.minimum(1.0 + d / ell, cap))  # elements per unit of x
        c = np.concatenate([[0.0], np.cumsum(0.5 * (dens[1:] + dens[:-1]) * np.diff(x))])
        n = max(int(np.ceil(c[-1] - 1e-9)), 1)
        nodes.extend(np.interp(np.arange(1, n + 1) * c[-1] / n, c, x))
    return np.array(nodes)


def _breaks(values, lo, hi):
    """Sorted distinct values in ``[lo, hi]`` (with both ends; values closer than 1e-9 of the range merged)."""
    v = np.unique(np.clip(np.asarray([lo, hi, *values], dtype=float), lo, hi))
    return v[np.concatenate([[True], np.diff(v) > 1e-9 * (hi - lo)])]


def _curved(vx, vpar, tri, fan, phi):
    """``MeshTri2`` of the triangles ``tri`` with its edge midpoints at ``phi`` of the mean parameters of their ends
    (an edge from a ``fan`` centre runs along the ``t`` of its other end)."""
    m = MeshTri2.from_mesh(MeshTri1(np.ascontiguousarray(vx), np.ascontiguousarray(tri), sort_t=False))
    e0, e1 = m.facets
    mid = 0.5 * (vpar[:, e0] + vpar[:, e1])
    mid[1] = np.where(fan[e0], vpar[1, e1], np.where(fan[e1], vpar[1, e0], mid[1]))
    doflocs = m.doflocs.copy()
    doflocs[:, m.dofs.facet_dofs[0]] = np.vstack(phi(*mid))
    return MeshTri2(doflocs, m.t)


def _mapped_mesh(q, t, phi, inside):
    """Isoparametric meshes of the grid ``q x t`` mapped by ``phi(q, t) -> (x, y)`` (grid points that map together
    are merged: a fan; each cell is split along its shorter diagonal, alternating where they are equal). Returns the
    mesh of the displacement, the mesh of the pressure (the same triangles, the vertices on the pool boundary doubled:
    the pressure jumps there), the pool's elements (``inside(q, t)`` true at their parameter centroid) and the
    parameter centroids (2, elements)."""
    Q, T = np.meshgrid(q, t, indexing="ij")
    par = np.vstack([Q.ravel(), T.ravel()])
    X = np.vstack(phi(*par))
    key = np.round(X / np.abs(X).max(), 12)
    _, first, merged, count = np.unique(key, axis=1, return_index=True, return_inverse=True, return_counts=True)
    i = merged.ravel()[np.arange(Q.size).reshape(Q.shape)]
    a, b, c, d = i[:-1, :-1].ravel(), i[1:, :-1].ravel(), i[1:, 1:].ravel(), i[:-1, 1:].ravel()
    vpar, vx, fan = par[:, first], X[:, first], count > 1
    ac, bd = np.linalg.norm(vx[:, a] - vx[:, c], axis=0), np.linalg.norm(vx[:, b] - vx[:, d], axis=0)
    parity = (np.add.outer(np.arange(len(q) - 1), np.arange(len(t) - 1)) % 2 == 0).ravel()
    short = np.where(np.abs(ac - bd) < 1e-6 * bd, parity, ac < bd)  # equal diagonals (polar cells): alternating
    tri = np.hstack([np.where(short, [a, b, c], [a, b, d]), np.where(short, [a, c, d], [b, c, d])])
    tri = tri[:, (tri[0] != tri[1]) & (tri[1] != tri[2]) & (tri[0] != tri[2])]  # a cell with a merged side: one
    centre = vpar[:, tri].mean(1)
    pool = inside(*centre)
    edge = np.intersect1d(tri[:, pool], tri[:, ~pool])
    twin = np.arange(vx.shape[1])
    twin[edge] = vx.shape[1] + np.arange(edge.size)
    tri_p = np.where(pool, twin[tri], tri)
    k = np.concatenate([np.arange(vx.shape[1]), edge])
    return _curved(vx, vpar, tri, fan, phi), _curved(vx[:, k], vpar[:, k], tri_p, fan[k], phi), pool, centre


def _kinematics(grad_u, mu, p, pi, tangent, bulk=None):
    """``(F, J, ln J, P, A)`` at the quadrature points: first Piola stress ``P = mu F + g F^-T`` with ``g = p + h - mu
    - Pi J`` (``p``: the mixed form's pressure; ``bulk = (kappa, form)``: a displacement-only volumetric term
    ``kappa u(J)`` of a :class:`sphgag.physics.volumetric.VolumetricForm`, ``h = J U'``, none if None) and, if
    ``tangent``, ``A = dP/dF`` at fixed ``p``."""
    F = grad_u + np.eye(2)[:, :, None, None]
    dJ = _jacobian_change(grad_u)
    with np.errstate(invalid="ignore", divide="ignore"):  # an inverted trial state (J <= 0) is rejected by the caller
        J, lnJ = 1.0 + dJ, np.log1p(dJ)
        _, du, d2u = (0.0, 0.0, 0.0) if bulk is None else bulk[1].terms(J, 1.0)
    kappa = 0.0 if bulk is None else bulk[0]
    h, k = kappa * J * du, kappa * J * (du + J * d2u)  # J U' and J d(J U')/dJ
    FiT = _cofactor(F, J)
    g = p + h - mu - pi * J
    P = mu * F + g * FiT
    if not tangent:
        return F, J, lnJ, P, None
    eye = np.eye(2)[:, None, :, None, None, None] * np.eye(2)[None, :, None, :, None, None]
    A = mu * eye + (k - pi * J) * np.einsum("ij...,kl...->ijkl...", FiT, FiT)
    return F, J, lnJ, P, A - g * np.einsum("il...,kj...->ijkl...", FiT, FiT)


def _jacobian_change(grad_u):
    """``J - 1`` from the displacement gradient, without the cancellation of ``det F - 1``."""
    return grad_u[0, 0] + grad_u[1, 1] + grad_u[0, 0] * grad_u[1, 1] - grad_u[0, 1] * grad_u[1, 0]


def _cofactor(F, J):
    return np.array([[F[1, 1], -F[1, 0]], [-F[0, 1], F[0, 0]]]) / J


@LinearForm
def _internal(v, w):  # int P : grad v
    return np.einsum("ij...,ij...->...", w["P"], v.grad)


@LinearForm
def _weighted(q, w):  # int f q
    return w["f"] * q


@BilinearForm
def _stiffness(du, v, w):  # int grad v : A : grad du
    return np.sum(np.einsum("ijkl...,kl...->ij...", w["A"], du.grad) * v.grad, axis=(0, 1))


@BilinearForm
def _coupling(dp, v, w):  # int dp F^-T : grad v
    return np.einsum("ij...,ij...->...", w["FiT"], v.grad) * dp


@BilinearForm
def _mass(dp, q, w):  # int c dp q
    return w["c"] * dp * q


class _Model:
    """Displacement (P2) and, in the matrix, pressure (P1) of one problem. Matrix: the stationary points of
    ``int mu/2 (I1 - 3) - mu ln J + p ln J - p^2 / (2 lam)`` (eliminating ``p = lam ln J`` gives back ``W``). Pool
    (``pool``: its elements): displacement only (a mixed form is unstable where ``p`` exceeds ~2 mu_g). With
    ``U = lam_g/2 (ln J)^2`` the GAG law loses ellipticity where ``mu_g (J + 1) + lam_g < lam_g ln J`` (equi-biaxial;
    J > 2.82 for the configuration's GAG): with ``uniform_bulk`` its volumetric term ``U`` (any form) is taken at the
    pool's mean dilatation ``Jm`` (current / reference area), exact for a homogeneous pool and the one well-posed
    continuation beyond: forces of a uniform pressure ``-U'(Jm)``, tangent plus the rank one ``U''(Jm) / A f f^T``
    (Sherman-Morrison)."""

    def __init__(self, mesh, mesh_p, pool, matrix, gag, uniform_bulk):
        self.mesh, self.mesh_p, self.pool, self.uniform = mesh, mesh_p, pool, uniform_bulk
        self.basis = Basis(mesh, ElementVector(ElementTriP2()))
        self.pbasis = Basis(mesh_p, ElementTriP1(), quadrature=self.basis.quadrature)
        self.n = self.basis.N
        self.mu = np.where(pool, gag["shear_modulus_kPa"], matrix["shear_modulus_kPa"])[:, None]
        self.lam_g, self.form = gag["lame_lambda_kPa"], volumetric.VOLUMETRIC_FORMS.lookup(gag["volumetric"])
        # the displacement-only volumetric term of the pool's elements (none in the matrix, nor with uniform_bulk)
        self.contents = (np.where(pool & ~uniform_bulk, self.lam_g, 0.0)[:, None], self.form)
        self.mixed = (~pool).astype(float)[:, None]  # the pressure field's share (1 in the matrix)
        # the pressure equation int q (ln J - p / lam) in the matrix, int q (-p) (p = 0) on the pool's side
        self.inv_lam = np.where(pool, 1.0, 1.0 / matrix["lame_lambda_kPa"])[:, None]
        self.Kpp = _mass.assemble(self.pbasis, c=np.broadcast_to(-self.inv_lam, self.basis.dx.shape))
        self.area = float(np.sum(self.basis.dx[pool]))
        scale = np.abs(mesh.p).max()
        fixed = [self.basis.get_dofs(lambda x, k=k: np.abs(x[k]) < 1e-9 * scale).all(f"u^{k + 1}") for k in (0, 1)]
        self.free = np.setdiff1d(np.arange(self.n_dofs), np.concatenate(fixed))

    @property
    def n_dofs(self):
        return self.n + self.pbasis.N

    def bulk(self, grad_u):
        """``(Jm, U'(Jm), U''(Jm))`` of the pool's uniform volumetric term ``U = lam_g u(J)`` (zeros without it)."""
        J = 1.0 + _jacobian_change(grad_u[:, :, self.pool])
        Jm = float(np.sum(J * self.basis.dx[self.pool]) / self.area)
        if not self.uniform or Jm <= 0:
            return Jm, 0.0, 0.0
        _, dU, d2U = self.form.terms(Jm, self.lam_g)
        return Jm, float(dU), float(d2U)

    def fields(self, x, pi, tangent=False):
        grad_u, p = self.basis.interpolate(x[: self.n]).grad, np.asarray(self.pbasis.interpolate(x[self.n :]))
        pool_pressure = np.where(self.pool, pi - self.bulk(grad_u)[1], 0.0)[:, None]
        return _kinematics(grad_u, self.mu, self.mixed * p, pool_pressure, tangent, self.contents)

    def volume_gradient(self, F, J):
        """``f = int_pool J F^-T : grad v``: the gradient of the pool's current area (all dofs)."""
        f = _internal.assemble(self.basis, P=self.pool[:, None] * J * _cofactor(F, J))
        return np.concatenate([f, np.zeros(self.pbasis.N)])

    def residual(self, x, pi):
        """Free-dof residual and its relative norm: the forces' against the swelling pressure's (``Pi f``), and the
        pressure equation's ``int q (ln J - p / lam)`` against ``int q |p| / lam``, whichever is larger."""
        F, J, lnJ, P, _ = self.fields(x, pi)
        if not np.all(J > 0):
            return None, np.inf
        p_lam = np.asarray(self.pbasis.interpolate(x[self.n :])) * self.inv_lam
        r = np.concatenate(
            [_internal.assemble(self.basis, P=P), _weighted.assemble(self.pbasis, f=self.mixed * lnJ - p_lam)]
        )
        ref = np.concatenate([pi * self.volume_gradient(F, J)[: self.n], _weighted.assemble(self.pbasis, f=p_lam)])
        parts = np.split(self.free, [np.searchsorted(self.free, self.n)])  # displacements, pressures
        res = max(np.linalg.norm(r[k]) / max(np.linalg.norm(ref[k]), 1e-300) for k in parts)
        return r[self.free], float(res)

    def newton(self, x, pi, max_iterations=25):
        """Newton iterations from ``x``: ``(x, relative residual)`` or ``(None, residual)`` on failure."""
        x = x.copy()
        r, res = self.residual(x, pi)
        previous = np.inf
        for _ in range(max_iterations):
            if res < TOLERANCE or (res < ROUNDOFF and res > 0.1 * previous):
                return x, res
            if not np.isfinite(res) or res > 1e3 * previous:
                break
            F, J, _, _, A = self.fields(x, pi, tangent=True)
            Kup = _coupling.assemble(self.pbasis, self.basis, FiT=self.mixed * _cofactor(F, J))
            K = bmat([[_stiffness.assemble(self.basis, A=A), Kup], [Kup.T, self.Kpp]], format="csr")
            lu = splu(K[self.free][:, self.free].tocsc())
            d = lu.solve(r)
            if self.uniform:  # (K + c f f^T)^-1 r, c = U''(Jm) / A
                c = self.bulk(self.basis.interpolate(x[: self.n]).grad)[2] / self.area
                f = self.volume_gradient(F, J)[self.free]
                z = lu.solve(f)
                d -= z * (c * (f @ d) / (1.0 + c * (f @ z)))
            x[self.free] -= d
            previous, (r, res) = res, self.residual(x, pi)
        return None, res

    def cauchy(self, x, pi):
        """Cauchy stress ``P F^T / J`` (2, 2, elements, points), current positions of the points, pool volume ratio."""
        F, J, _, P, _ = self.fields(x, pi)
        pos = np.asarray(self.basis.global_coordinates()) + np.asarray(self.basis.interpolate(x[: self.n]))
        ratio = float(np.sum(J[self.pool] * self.basis.dx[self.pool]) / self.area)
        return np.einsum("ab...,cb...->ac...", P, F) / J, pos, ratio


def _ramp(model, pressures, measure, max_halvings=10):
    """The converged state at every pressure (in order): one row each of ``measure(x, pi)`` with ``pressure_kPa``,
    ``n_dofs``, ``residual`` (relative, :meth:`_Model.residual`) and ``increments`` (the load steps it took). Stops at
    a pressure not reached in ``max_halvings`` halvings of the step (``attrs['failed_at']``)."""
    u, pi, history, rows = np.zeros(model.n_dofs), 0.0, [], []
    failed = None
    for target in pressures:
        step, halvings, increments = target - pi, 0, 0
        while pi != target and failed is None:
            trial = target if abs(target - pi) <= abs(step) else pi + step
            guess = u if not history else u + (u - history[-1][1]) * (trial - pi) / (pi - history[-1][0])
            new, res = model.newton(guess, trial)
            if new is None:
                step, halvings = 0.5 * step, halvings + 1
                failed = target if halvings > max_halvings else None
                continue
            history, u, pi, increments = [(pi, u)], new, trial, increments + 1
        if failed is not None:
            break
        row = dict(pressure_kPa=target, **measure(u, pi))
        rows.append(dict(row, n_dofs=model.n_dofs, residual=model.residual(u, pi)[1], increments=increments))
    out = pd.DataFrame(rows)
    out.attrs["failed_at"] = failed
    return out


def _vertex_stress(model, x, point):
    """In-plane Cauchy stress (2, 2) at the mesh vertex nearest ``point``: the mean over the matrix elements at it."""
    m = model.mesh
    v = int(np.argmin(np.linalg.norm(m.p - np.asarray(point, dtype=float)[:, None], axis=0)))
    sig = []
    for e in np.flatnonzero((m.t == v).any(0) & ~model.pool):  # a few elements
        k = int(np.flatnonzero(m.t[:, e] == v)[0])
        ref = np.array([[0.0, 1.0, 0.0][k], [0.0, 0.0, 1.0][k]])[:, None]
        b = Basis(m, model.basis.elem, elements=np.array([e]), quadrature=(ref, np.ones(1)))
        p = x[model.n + model.mesh_p.t[k, e]]  # the pressure (P1) at the vertex
        F, J, _, P, _ = _kinematics(b.interpolate(x[: model.n]).grad, model.mu[e], p, 0.0, False)
        sig.append(np.einsum("ab...,cb...->ac...", P, F)[..., 0, 0] / J[0, 0])
    return np.mean(sig, axis=0)


def elliptic_pool(a, b, extent, matrix, gag, pressures, h, ell=None, cap=10.0, uniform_bulk=True):
    """The swelling elliptical pool (semi-axes ``a >= b``) in the quarter of the ellipse ``(a + extent, b +
    extent)``, at every swelling pressure ``pressures`` [kPa] (increasing). ``h`` [um]: the element size at the
    pool boundary next to the tip, growing like ``h (1 + d / ell)`` (at most ``cap h``); ``ell`` defaults to the
    tip's radius of curvature ``b^2 / a``. ``uniform_bulk``: the pool's bulk term at its mean dilatation
    (:class:`_Model`).

    Returns one row per converged pressure: ``pool_volume_ratio`` (current / reference pool area),
    ``tip_hoop_stress_kPa`` (Cauchy ``sigma_yy`` of the matrix at ``(a, 0)``), ``top_hoop_stress_kPa``
    (``sigma_xx`` of the matrix at ``(0, b)``), ``n_dofs``, ``residual``, ``increments``.
    """
    ell = b * b / a if ell is None else ell
    ts = np.linspace(0.0, 0.5 * np.pi, 4001)
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(a * np.sin(ts), b * np.cos(ts))[1:] * np.diff(ts))])
    t = np.interp(_graded([0.0, arc[-1]], [0.0], h, ell, cap), arc, ts)  # graded in arc length from the tip
    q = _graded([-b, 0.0, extent], [0.0], h, ell, np.inf)  # across the boundary: growing with the distance

    def phi(q, t):
        inside = np.minimum(q, 0.0) / b + 1.0  # scaled ellipses in the pool, offset ellipses in the matrix
        return np.where(q < 0, inside * a, a + q) * np.cos(t), np.where(q < 0, inside * b, b + q) * np.sin(t)

    model = _Model(*_mapped_mesh(q, t, phi, lambda q, t: q < 0.0)[:3], matrix, gag, uniform_bulk)

    def measure(u, pi):
        return dict(
            pool_volume_ratio=model.cauchy(u, pi)[2],
            tip_hoop_stress_kPa=float(_vertex_stress(model, u, (a, 0.0))[1, 1]),
            top_hoop_stress_kPa=float(_vertex_stress(model, u, (0.0, b))[0, 0]),
        )

    return _ramp(model, pressures, measure)


def sector_pool(
    r_in, r_out, pool, matrix, gag, pressures, h, arc=10.0, media=None, ell=1.0, cap=50.0, uniform_bulk=True
):
    """The swelling annular-sector pool ``pool = (centre_radius, centre_angle_deg, radial_extent,
    angular_extent_deg)`` in the quarter annulus ``r_in < R < r_out`` (matrix law everywhere else), at every
    swelling pressure (increasing). ``h`` [um]: the element size at the pool's corners, ``h (1 + d / ell)`` away
    from them (at most ``cap h``; ``d`` in um, arc length at the pool's centre radius for angles).
    ``media``: the radii ``(lo, hi)`` of the layer the probes measure in (SPH: the media), ``None`` the whole wall.

    Returns one row per converged pressure: ``pool_volume_ratio``; the SPH probes of
    :func:`sphgag.engine.measure.pool_probes` with length ``arc`` [um], as area-weighted means over their reference
    regions of the Cauchy stress in the current polar frame (as :func:`sphgag.engine.measure.cauchy_polar`):
    ``tip_radial_stress_kPa`` (mean of ``tip_low`` and ``tip_high``, each also given), ``top_hoop_stress_kPa``,
    ``bottom_hoop_stress_kPa``; ``corner_peak_radial_stress_kPa``, the largest ``sigma_rr`` at a quadrature point
    of the tip regions (next to the corners: singular, it grows without bound under refinement); ``n_dofs``,
    ``residual``, ``increments``.
    """
    sector = Sector(*pool)
    probes = pool_probes(sector, arc)
    rc = sector.centre_radius
    regions = [sector, *probes.values()]
    media = (r_in, r_out) if media is None else media
    R = _graded(_breaks([*media, *(r for s in regions for r in s.r_range)], r_in, r_out), sector.r_range, h, ell, cap)
    th = _breaks([t for s in regions for t in s.theta_range], 0.0, 0.5 * np.pi)
    th = _graded(th, sector.theta_range, h, ell, cap, metric=rc)
    *meshes, centre = _mapped_mesh(R, th, lambda r, t: (r * np.cos(t), r * np.sin(t)), sector.contains)
    model = _Model(*meshes, matrix, gag, uniform_bulk)
    dx = model.basis.dx
    layer = (centre[0] > media[0]) & (centre[0] < media[1])
    masks = {k: p.contains(*centre) & layer for k, p in probes.items()}  # region edges are grid lines

    def mean(f, probe):  # area-weighted mean over a probe's reference region
        m = masks[probe]
        return float(np.sum(f[m] * dx[m]) / np.sum(dx[m]))

    def measure(u, pi):
        sig, x, ratio = model.cauchy(u, pi)
        c, s = np.cos(np.arctan2(x[1], x[0])), np.sin(np.arctan2(x[1], x[0]))
        srr = c * c * sig[0, 0] + s * s * sig[1, 1] + c * s * (sig[0, 1] + sig[1, 0])
        stt = s * s * sig[0, 0] + c * c * sig[1, 1] - c * s * (sig[0, 1] + sig[1, 0])
        lo, hi = mean(srr, "tip_low"), mean(srr, "tip_high")
        return dict(
            pool_volume_ratio=ratio,
            tip_radial_stress_kPa=0.5 * (lo + hi),
            tip_low_radial_stress_kPa=lo,
            tip_high_radial_stress_kPa=hi,
            top_hoop_stress_kPa=mean(stt, "top"),
            bottom_hoop_stress_kPa=mean(stt, "bottom"),
            corner_peak_radial_stress_kPa=float(srr[masks["tip_low"] | masks["tip_high"]].max()),
        )

    return _ramp(model, pressures, measure)


def mesh_study(problem, sizes):
    """Run ``problem(h)`` (a function of the mesh size returning a table like :func:`elliptic_pool`'s) at every
    size in ``sizes`` (coarse to fine, 3 or more). Returns ``(runs, changes)``: all rows with their ``h``, and per
    pressure converged at every size, each output at the finest mesh, its relative change from the second finest
    (``<output>_change``) and the observed order ``log(e2/e1) / log(h2/h1)`` of the last two changes
    (``<output>_order``)."""
    if len(sizes) < 3:
        raise ValueError("a mesh study needs 3 or more sizes")
    runs = pd.concat([problem(h).assign(h=h) for h in sizes], ignore_index=True)
    outputs = [c for c in runs.columns if c.endswith(("_ratio", "_kPa")) and c != "pressure_kPa"]
    wide = runs.pivot(index="pressure_kPa", columns="h", values=outputs).dropna()
    rows = []
    for p, v in wide.iterrows():
        row = dict(pressure_kPa=p)
        for k in outputs:
            f = [v[(k, h)] for h in sizes[::-1]]  # finest first
            row[k] = f[0]
            row[f"{k}_change"] = abs(f[0] - f[1]) / abs(f[0])
            with np.errstate(divide="ignore"):
                row[f"{k}_order"] = np.log(abs(f[1] - f[2]) / abs(f[0] - f[1])) / np.log(sizes[-2] / sizes[-1])
        rows.append(row)
    return runs, pd.DataFrame(rows)
