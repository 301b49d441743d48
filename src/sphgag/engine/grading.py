"""Graded particle spacing around GAG pools: finest at their corners, coarsest away from them.

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

**The layout** (:func:`columns`, :func:`sphgag.engine.geometry.quarter_annulus`): the quarter is cut into angular
columns whose edges include every pool's angular ends (cell boundaries in every ring, so a pool is exactly its sector
at every spacing); a column is ``column_cells`` of its finest spacing wide where the finest spacing varies with the
angle, one column where it does not. Each column's rings are graded radially by the field over the column (from its
finest spacing up to its width: cells stay about square), every layer interface a cell boundary, a ring on each wall
surface; each ring is cut into equal arc cells of about its radial width. Every particle's kernel support is
``kernel_support_factor`` times its cell's width, and a pair's the mean of its two (:mod:`sphgag.engine.kernel`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..options import Options
from .geometry import QUARTER

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
    """The spacing field of :class:`Grading` around ``pools`` (:class:`sphgag.engine.geometry.Sector`) at the coarse
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


def columns(field: Field) -> tuple[np.ndarray, list]:
    """The angular columns of the graded layout: ``(edges, spacings)``, ``edges`` rising from 0 to pi/2 (every pool's
    angular ends among them) and per column a radial spacing profile (a function of the radius, constant where the
    column is uniform)."""
    m = field.grading.column_cells
    rc = float(np.mean([p.centre_radius for p in field.pools]))
    breaks = sorted({float(t) for p in field.pools for t in p.theta_range} | {QUARTER})
    edges, finest = [0.0], []
    t = 0.0
    while t < QUARTER - 1e-12:
        stop = min(b for b in breaks if b > t + 1e-12)
        s = float(field.angular(t))
        for _ in range(60):  # the column's finest spacing: the minimum over its own width
            s_new = _interval_min(field.angular, t, min(t + m * s / rc, stop))
            if abs(s_new - s) <= 1e-12 * s:
                break
            s = s_new
        ts = np.linspace(t, stop, 4 * SAMPLES)
        changes = np.flatnonzero(np.abs(field.angular(ts) - s) > 1e-9 * s)
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
    return edges, [_profile(field, lo, hi, s, rc) for lo, hi, s in zip(edges[:-1], edges[1:], finest)]


def _profile(field: Field, lo: float, hi: float, finest: float, rc: float):
    """The radial spacing of the column ``lo < theta < hi``: the field's minimum over the column at each radius,
    between the column's finest spacing and its width; a number where that is constant."""
    if finest >= field.dx * (1.0 - 1e-12):  # a coarse column: uniform
        return float(field.dx)
    width = max((hi - lo) * rc, finest)
    ts = np.linspace(lo, hi, 41)

    def spacing(r):
        r = np.atleast_1d(np.asarray(r, dtype=float))
        s = np.min(field(r[:, None], ts[None, :]), axis=1)
        return np.clip(s, finest, width)

    return spacing
