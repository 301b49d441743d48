"""Particle layout of the quarter-annulus arterial cross-section (paper section 2.4, figure 1a): uniform, or graded
around GAG pools.

The paper discretises the quarter annulus with the nodes of an unstructured
triangle mesh. We generate the layout instead, from one resolution parameter
``dx_um``, so that refining the resolution means the same thing everywhere. **The uniform layout**:

* **Rings in r.** Every layer ``[r_a, r_b]`` of the wall is split into cells of
  equal radial width. The inner and outer surfaces carry a ring of particles
  (surface particles own a half cell, so boundary conditions act exactly at the
  surfaces) and every interface between layers is a cell boundary (no particle
  straddles two layers).
* **Equal arc spacing.** Each ring carries ``n = round(arc / dx)`` particles at
  equal angular spacing, offset by half a spacing from the symmetry edges
  ``theta = 0`` and ``theta = pi/2``. The edges are mirror planes (see
  :mod:`sphgag.engine.kernel`), so no particle sits on them.
* **Volumes.** A particle's volume is the exact area of its annular cell,
  ``(r_hi^2 - r_lo^2) / 2 * dtheta`` (reference area per unit reference axial
  length; the axial stretch enters through the constitutive law). The volumes
  sum to the exact area of the quarter annulus.

**Graded particle spacing around GAG pools** (:class:`Grading`, the ``grading`` section): finest at their corners,
coarsest away from them.

A sector pool (figure 4) is a rectangle in (r, theta) whose four corners are re-entrant corners of the media around
it; there the field of a swelling pool is singular. Measured against a finite-element reference of the pool in an
all-elastin wall, the particles' error sits at the pools' angular ends; in the artery's wall it is set by the
spacing over the pool, its interface (docs/physics.md, "Where figure 4's first-order error comes from"). Spacing
graded towards the pool and its corners (Babuska et al.) reaches either at less cost than uniform refinement;
SPHinXsys blends the spacing smoothly between a finest and a coarsest value with a per-particle kernel support, as
here.

**The field** (um), for a coarse spacing ``dx`` and the options :class:`Grading`::

    s(r, theta) = dx min(1, pool + d_pool / reach, corners + d_corner / reach)

``d_pool`` is the distance to the nearest pool (0 inside it) and ``d_corner`` to the nearest pool corner, measured
in (radius, arc length at the pool's centre radius). The spacing grows by ``dx / reach`` per um away from the pools:
the graded zones keep their size and every spacing scales with ``dx``, so halving ``dx`` refines the graded layout
uniformly (the resolution study's spacings keep their meaning).

**The graded layout** (:func:`columns`, :func:`quarter_annulus`): the quarter is cut into angular
columns whose edges include every pool's angular ends (cell boundaries in every ring, so a pool is exactly its sector
at every spacing); a column is ``column_cells`` of its finest spacing wide where the finest spacing varies with the
angle, one column where it does not. Each column's rings are graded radially by the field over the column (from its
finest spacing up to its width: cells stay about square), every layer interface a cell boundary, a ring on each wall
surface; each ring is cut into equal arc cells of about its radial width. Every particle's kernel support is
``kernel_support_factor`` times its cell's width, and a pair's the mean of its two (:mod:`sphgag.engine.kernel`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..options import Options

QUARTER = 0.5 * np.pi


@dataclass(frozen=True)
class Layout:
    """Reference configuration of the particles (flat arrays, SI-free units: um).

    Attributes
    ----------
    X : (N, 2) reference positions.
    volume : (N,) reference areas of the particles' annular cells [um^2].
    radius, theta : (N,) reference polar coordinates of the particles.
    ring : (N,) index of the particle's ring (0 = inner surface).
    layer : (N,) index into ``layer_names``.
    ring_radius : (n_rings,) reference radius of each ring.
    ring_cell : (n_rings, 2) radial extent [r_lo, r_hi] of each ring's cells.
    interfaces : radii of the wall surfaces and layer interfaces, inner to outer.
    layer_names : name of each layer, inner to outer.
    dx : requested particle spacing [um] (graded layouts: the coarsest).
    pool_layers : names of the layers whose particles GAG pools convert and damage delaminates (the paper's media).
    spacing : (N,) the spacing each particle was laid out at [um] (``dx`` everywhere on a uniform layout); its kernel
        support is a multiple of it.
    second_layer, second_volume : (N,) of a fitted layout (None otherwise): the second layer of a particle on a
        material interface (``-1``: none) and the part of its volume in that layer; ``volume - second_volume`` lies
        in ``layer``. Such a particle carries one integration point per layer (:meth:`points`).
    """

    X: np.ndarray
    volume: np.ndarray
    radius: np.ndarray
    theta: np.ndarray
    ring: np.ndarray
    layer: np.ndarray
    ring_radius: np.ndarray
    ring_cell: np.ndarray
    interfaces: tuple
    layer_names: tuple
    dx: float
    pool_layers: tuple = ()
    spacing: np.ndarray | None = None
    second_layer: np.ndarray | None = None
    second_volume: np.ndarray | None = None
    _ring_members: list = field(default_factory=list, repr=False, compare=False)

    def __post_init__(self):
        if self.spacing is None:
            object.__setattr__(self, "spacing", np.full(self.X.shape[0], self.dx))

    @property
    def n(self) -> int:
        return self.X.shape[0]

    @property
    def inner_radius(self) -> float:
        return float(self.interfaces[0])

    @property
    def outer_radius(self) -> float:
        return float(self.interfaces[-1])

    def ring_members(self, k: int) -> np.ndarray:
        """Indices of the particles of ring ``k``, ordered by increasing theta."""
        return self._ring_members[k]

    @property
    def inner_surface(self) -> np.ndarray:
        return self.ring_members(0)

    @property
    def outer_surface(self) -> np.ndarray:
        return self.ring_members(len(self.ring_radius) - 1)

    def layer_mask(self, name: str | tuple | list) -> np.ndarray:
        """Which particles belong to the layer ``name`` (or to any of several names; a name the wall lacks has none)."""
        if isinstance(name, str):
            return self.layer == self.layer_names.index(name)
        return np.isin(self.layer, [k for k, n in enumerate(self.layer_names) if n in name])

    @property
    def fitted(self) -> bool:
        """Whether particles sit on the material interfaces, shared by both sides (:func:`quarter_annulus`)."""
        return self.second_layer is not None

    def points(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(owner, layer, volume)`` of the integration points: one per particle and layer it belongs to (two on a
        material interface of a fitted layout), ordered by owner, then the particle's own layer first; each layer's
        volumes sum to its exact area."""
        own = self.volume - (0.0 if self.second_volume is None else self.second_volume)
        owner, layer, volume = [np.arange(self.n)], [self.layer], [own]
        if self.fitted:
            shared = np.flatnonzero(self.second_layer >= 0)
            owner.append(shared)
            layer.append(self.second_layer[shared])
            volume.append(self.second_volume[shared])
        owner = np.concatenate(owner)
        order = np.argsort(owner, kind="stable")
        return owner[order], np.concatenate(layer)[order], np.concatenate(volume)[order]

    @property
    def pool_mask(self) -> np.ndarray:
        """Which particles belong to a pool layer (``pool_layers``)."""
        return self.layer_mask(self.pool_layers)


def _ring_radii(interfaces, dx, fitted=()):
    """Ring radii, cell bounds, layer and radial width of every ring, such that surfaces carry rings and interfaces are
    cell bounds; ``dx`` is the spacing, a number or a function of the radius (a graded column,
    :class:`Grading`). ``fitted``: the indices ``l`` of the interfaces (``interfaces[l]``, between layers ``l - 1`` and
    ``l``) that carry a ring of their own, like a surface on both sides (a material interface, :func:`quarter_annulus`);
    its particles' cells straddle the interface, and its ring is listed once, in layer ``l - 1``, with the part of
    its cell in layer ``l`` as the fifth array (``upper``: the cell's radial extent above the interface; 0 elsewhere).

    With ``L`` layers and ``n_l`` rings in layer ``l`` (radial widths ``d_l``):
    a single layer spans ``(n - 1) d`` (half cells at both surfaces); with several
    layers the first spans ``(n_1 - 1/2) d_1``, inner ones ``n_l d_l`` and the last
    ``(n_L - 1/2) d_L``. A graded spacing places the rings at equal steps of ``int dr / dx(r)`` (scaled to the same
    count of cells), so their widths follow ``dx(r)``.
    """
    interfaces = np.asarray(interfaces, dtype=float)
    n_layers = len(interfaces) - 1
    radii, cells, layer_of_ring, widths = [], [], [], []
    for l in range(n_layers):
        a, b = interfaces[l], interfaces[l + 1]
        first, last = l == 0 or l in fitted, l == n_layers - 1 or l + 1 in fitted
        half_cells = int(first) + int(last)  # surfaces own half cells
        if callable(dx):  # u(r): cells from a, scaled to end at the layer's count
            r_s = np.linspace(a, b, 2001)
            rho = 1.0 / dx(r_s)
            u_s = np.concatenate([[0.0], np.cumsum(0.5 * (rho[1:] + rho[:-1]) * np.diff(r_s))])
            cells_in = u_s[-1]
        else:
            cells_in = (b - a) / dx
        n = max(int(round(cells_in + 0.5 * half_cells)), 1 + int(first and last))
        top = n - 0.5 * half_cells
        if callable(dx):
            u_s *= top / u_s[-1]
            at = np.arange(n) + (0.0 if first else 0.5)
            r_k = np.interp(at, u_s, r_s)
            lo_k = np.interp(np.maximum(at - 0.5, 0.0), u_s, r_s)
            hi_k = np.interp(np.minimum(at + 0.5, top), u_s, r_s)
            full = hi_k - lo_k
            if first:  # a surface's half cell: twice its width
                full[0] *= 2.0
            if last:
                full[-1] *= 2.0
            for r, lo, hi, w in zip(r_k, lo_k, hi_k, full):
                radii.append(r)
                cells.append((lo, hi))
                layer_of_ring.append(l)
                widths.append(w)
            continue
        d = (b - a) / top
        start = a if first else a + 0.5 * d
        for k in range(n):
            r = b if (k == n - 1 and l + 1 in fitted) else start + k * d  # an interface's ring: exactly on it
            if k == 0 and l in fitted:  # the interface's ring, listed in the layer below: its cell reaches up
                cells[-1] = (cells[-1][0], r + 0.5 * d)
                continue
            lo = max(r - 0.5 * d, a)
            hi = min(r + 0.5 * d, b)
            radii.append(r)
            cells.append((lo, hi))
            layer_of_ring.append(l)
            widths.append(d)
    radii, cells = np.array(radii), np.array(cells)
    upper = np.where(np.isin(radii, interfaces[list(fitted)]), cells[:, 1] - radii, 0.0)
    return radii, cells, np.array(layer_of_ring), np.array(widths), upper


def _ring_cells(r, dx, lo, hi, at_least):
    """Angular cells of the ring at radius ``r`` in the column ``lo < theta < hi`` (radians): ``round(arc / dx)``
    equal cells (at least ``at_least``). Returns their centres and widths (radians)."""
    n = max(int(round((hi - lo) * r / dx)), at_least)
    w = (hi - lo) / n
    return lo + (np.arange(n) + 0.5) * w, np.full(n, w)


def quarter_annulus(interfaces, dx, layer_names=("wall",), pool_layers=(), columns=None, fitted=False) -> Layout:
    """Generate the particle layout of a (possibly layered) quarter annulus.

    Parameters
    ----------
    interfaces : radii ``[R_in, (interfaces...), R_out]`` in um; every one is a cell boundary.
    dx : target particle spacing in um (the resolution parameter ``dx_um``).
    layer_names : one name per interval, inner to outer; repeating a name splits a layer
        into sub-layers (e.g. to align cell boundaries with the radial edges of a GAG pool).
    pool_layers : the names of the layers GAG pools may occupy (``Layout.pool_layers``).
    columns : ``(edges, spacings)``: angular columns ``edges[k] < theta < edges[k + 1]`` (radians, from 0 to pi/2),
        each laid out at its own spacing ``spacings[k]`` [um], a number or a function of the radius (rings of that
        width, each cut into equal arc cells of about its width: :class:`Grading`); the edges are cell
        boundaries in every ring (e.g. the angular ends of GAG pools). Default: one column at ``dx``.
    fitted : a ring of particles on every material interface (between layers of different names), shared by both
        materials (``Layout.second_layer``; :mod:`sphgag.engine.quadrature`), in place of a cell boundary; uniform
        spacing only.
    """
    interfaces = tuple(float(r) for r in interfaces)
    if len(layer_names) != len(interfaces) - 1:
        raise ValueError("need one layer name per layer (len(interfaces) - 1)")
    # consecutive intervals may share a name: sub-layers of one material whose bounds are cell bounds
    names = tuple(dict.fromkeys(layer_names))
    if any(b <= a for a, b in zip(interfaces, interfaces[1:])):
        raise ValueError(f"interfaces must increase strictly, got {interfaces}")
    if dx <= 0:
        raise ValueError("dx must be positive")
    edges, spacings = ((0.0, QUARTER), (float(dx),)) if columns is None else columns
    edges = np.asarray(edges, dtype=float)
    if edges[0] != 0.0 or abs(edges[-1] - QUARTER) > 1e-12 or np.any(np.diff(edges) <= 0):
        raise ValueError("column edges must rise strictly from 0 to pi/2")
    at_least = 2 if len(spacings) == 1 else 1
    borders = [k for k in range(1, len(layer_names)) if layer_names[k] != layer_names[k - 1]] if fitted else []
    if borders and any(callable(s) for s in spacings):
        raise ValueError("a fitted layout needs uniform spacing (no graded columns)")
    X, vol, rad, th, ring_r, ring_lohi, layer, spacing, second, above = [], [], [], [], [], [], [], [], [], []
    grids = {}
    for lo, hi, s in zip(edges[:-1], edges[1:], spacings):
        if callable(s):
            grid = _ring_radii(interfaces, s)
        else:
            if s <= 0:
                raise ValueError("column spacings must be positive")
            grid = grids[s] = grids[s] if s in grids else _ring_radii(interfaces, s, borders)
        radii, cells, layer_of_ring, widths, upper = grid
        for r, (a, b), lr, w, up in zip(radii, cells, layer_of_ring, widths, upper):
            w = w if callable(s) else s  # a uniform column's particles are laid out at its spacing
            t, dth = _ring_cells(r, w, lo, hi, at_least)
            X.append(np.column_stack([r * np.cos(t), r * np.sin(t)]))
            vol.append(0.5 * (b * b - a * a) * dth)
            second.append(np.full(t.size, names.index(layer_names[lr + 1]) if up > 0.0 else -1))
            above.append(0.5 * (b * b - r * r) * dth if up > 0.0 else np.zeros(t.size))
            rad.append(np.full(t.size, r))
            th.append(t)
            ring_r.append(np.full(t.size, r))
            ring_lohi.append(np.tile([a, b], (t.size, 1)))
            layer.append(np.full(t.size, names.index(layer_names[lr])))
            spacing.append(np.full(t.size, float(w)))
    # rings: the distinct radii over all columns (the surfaces' rings are shared by every column)
    ring_r = np.concatenate(ring_r)
    ring_radius, first, ring = np.unique(ring_r, return_index=True, return_inverse=True)
    ring_cell = np.concatenate(ring_lohi)[first]
    # number the particles by angle (then radius): neighbours get nearby indices, which keeps
    # the Jacobian banded for the sparse direct solver and the force loops cache friendly
    theta_all = np.concatenate(th)
    order = np.lexsort((ring, theta_all))
    rank = np.empty_like(order)
    rank[order] = np.arange(order.size)
    members = [np.sort(rank[ring == k]) for k in range(ring_radius.size)]
    return Layout(
        X=np.ascontiguousarray(np.vstack(X)[order]),
        volume=np.concatenate(vol)[order],
        radius=np.concatenate(rad)[order],
        theta=theta_all[order],
        ring=ring.astype(np.int64)[order],
        layer=np.concatenate(layer).astype(np.int64)[order],
        ring_radius=ring_radius,
        ring_cell=ring_cell,
        interfaces=interfaces,
        layer_names=names,
        dx=float(dx),
        pool_layers=tuple(pool_layers),
        spacing=np.concatenate(spacing)[order],
        second_layer=np.concatenate(second).astype(np.int64)[order] if borders else None,
        second_volume=np.concatenate(above)[order] if borders else None,
        _ring_members=members,
    )


def quarter_annulus_area(r_in: float, r_out: float) -> float:
    """Exact area of the quarter annulus, the sum the particle volumes must reproduce."""
    return 0.25 * np.pi * (r_out**2 - r_in**2)


@dataclass(frozen=True)
class Sector:
    """An annular sector of the reference configuration (a GAG pool, a measurement box).

    Defined geometrically (um and degrees), so it means the same region at any
    resolution: a particle belongs to it when its reference position does.
    """

    centre_radius: float
    centre_angle_deg: float
    radial_extent: float
    angular_extent_deg: float

    @property
    def r_range(self):
        return self.centre_radius - 0.5 * self.radial_extent, self.centre_radius + 0.5 * self.radial_extent

    @property
    def theta_range(self):
        half = 0.5 * np.deg2rad(self.angular_extent_deg)
        c = np.deg2rad(self.centre_angle_deg)
        return c - half, c + half

    def contains(self, radius, theta):
        (r0, r1), (t0, t1) = self.r_range, self.theta_range
        return (radius >= r0) & (radius <= r1) & (theta >= t0) & (theta <= t1)

    def members(self, layout: Layout, layer: str | tuple | None = None) -> np.ndarray:
        """The particles of ``layout`` in the sector (of the layer ``layer``, or of any of several names)."""
        mask = self.contains(layout.radius, layout.theta)
        if layer is not None:
            mask &= layout.layer_mask(layer)
        return np.flatnonzero(mask)


def axisymmetric_positions(source: Layout, x: np.ndarray, target: Layout) -> np.ndarray:
    """Positions of ``target``'s particles in the axisymmetric state ``x`` of ``source`` (the same wall laid out
    differently, e.g. graded around a pool: :class:`Grading`): each particle keeps its angle and takes the
    current radius ``r(R)`` of its reference radius, interpolated between ``source``'s ring means. A guess for the
    equilibrium on ``target``, which its solver then converges."""
    radius = np.hypot(x[:, 0], x[:, 1])
    current = np.array([radius[source.ring_members(k)].mean() for k in range(len(source.ring_radius))])
    r = np.interp(target.radius, source.ring_radius, current)
    return np.column_stack([r * np.cos(target.theta), r * np.sin(target.theta)])


SAMPLES = 401  # points at which the field's minimum over an interval is sampled


@dataclass(frozen=True)
class Grading(Options):
    """The graded spacing around GAG pools (the ``grading`` section): ``pool`` and ``corners`` are the spacings over the
    pools and at their corners as fractions of the coarse ``dx``; ``reach_um`` the distance [um] at the coarse
    spacing over which the spacing grows by ``dx`` (growth ``dx / reach_um`` per um, scaled with ``dx``);
    ``column_cells``: the width of a graded column in its finest cells. ``pool = corners = 1`` (the default) is no
    grading: the wall's own uniform layout (:func:`sphgag.studies.artery.bilayer_layout`)."""

    SECTION = "grading"

    pool: float = 1.0
    corners: float = 1.0
    reach_um: float = 30.0
    column_cells: float = 3.0

    @classmethod
    def problems(cls, config) -> list[str]:
        """The corners no coarser than the pool."""
        g = config.get("grading", {})
        if g.get("corners", 0.0) > g.get("pool", 1.0):
            return [f"grading.corners = {g['corners']:g} must be at most grading.pool = {g['pool']:g}"]
        return []

    @property
    def uniform(self) -> bool:
        return self.pool >= 1.0 and self.corners >= 1.0


@dataclass(frozen=True)
class Field:
    """The spacing field of :class:`Grading` around ``pools`` (:class:`Sector`) at the coarse
    spacing ``dx`` [um]."""

    pools: tuple
    dx: float
    grading: Grading

    def __call__(self, r, t):
        """The spacing [um] at radii ``r`` [um] and angles ``t`` (radians; broadcast)."""
        g = self.grading
        r, t = np.asarray(r, dtype=float), np.asarray(t, dtype=float)
        s = np.ones(np.broadcast(r, t).shape)
        for p in self.pools:
            (r0, r1), (t0, t1), rc = p.r_range, p.theta_range, p.centre_radius
            outside_r = np.maximum(np.maximum(r0 - r, r - r1), 0.0)
            outside_t = np.maximum(np.maximum(t0 - t, t - t1), 0.0)
            d_pool = np.hypot(outside_r, rc * outside_t)
            d_corner = np.hypot(np.minimum(abs(r - r0), abs(r - r1)), rc * np.minimum(abs(t - t0), abs(t - t1)))
            s = np.minimum(s, np.minimum(g.pool + d_pool / g.reach_um, g.corners + d_corner / g.reach_um))
        return self.dx * s

    def angular(self, t):
        """The finest spacing over the wall at angles ``t``: at a pool's radius (its corners' or inside it)."""
        radii = [r for p in self.pools for r in (*p.r_range, p.centre_radius)]
        return np.min([self(r, t) for r in radii], axis=0)


def _interval_min(f, lo: float, hi: float) -> float:
    return float(np.min(f(np.linspace(lo, hi, SAMPLES))))


def columns(graded: Field) -> tuple[np.ndarray, list]:
    """The angular columns of the graded layout: ``(edges, spacings)``, ``edges`` rising from 0 to pi/2 (every pool's
    angular ends among them) and per column a radial spacing profile (a function of the radius, constant where the
    column is uniform)."""
    m = graded.grading.column_cells
    rc = float(np.mean([p.centre_radius for p in graded.pools]))
    breaks = sorted({float(t) for p in graded.pools for t in p.theta_range} | {QUARTER})
    edges, finest = [0.0], []
    t = 0.0
    while t < QUARTER - 1e-12:
        stop = min(b for b in breaks if b > t + 1e-12)
        s = float(graded.angular(t))
        for _ in range(60):  # the column's finest spacing: the minimum over its own width
            s_new = _interval_min(graded.angular, t, min(t + m * s / rc, stop))
            if abs(s_new - s) <= 1e-12 * s:
                break
            s = s_new
        ts = np.linspace(t, stop, 4 * SAMPLES)
        changes = np.flatnonzero(np.abs(graded.angular(ts) - s) > 1e-9 * s)
        if changes.size == 0 or changes[0] > SAMPLES // 4:  # constant: one column up to where it changes (or a break)
            end = stop if changes.size == 0 else float(ts[changes[0] - 1])
        else:
            end = t + m * s / rc
            if end > stop - 0.5 * m * s / rc:  # no sliver before a break
                end = stop
        edges.append(end)
        finest.append(s)
        t = end
    edges[-1] = QUARTER
    edges = np.array(edges)
    return edges, [_profile(graded, lo, hi, s, rc) for lo, hi, s in zip(edges[:-1], edges[1:], finest)]


def _profile(graded: Field, lo: float, hi: float, finest: float, rc: float):
    """The radial spacing of the column ``lo < theta < hi``: the field's minimum over the column at each radius,
    between the column's finest spacing and its width; a number where that is constant."""
    if finest >= graded.dx * (1.0 - 1e-12):  # a coarse column: uniform
        return float(graded.dx)
    width = max((hi - lo) * rc, finest)
    ts = np.linspace(lo, hi, 41)

    def spacing(r):
        r = np.atleast_1d(np.asarray(r, dtype=float))
        s = np.min(graded(r[:, None], ts[None, :]), axis=1)
        return np.clip(s, finest, width)

    return spacing
