"""A swelling elliptical inclusion in a plane-strain block: the verification problem of the pool stress field.

The field around a GAG pool drives delamination (section 2.7), so it is
verified on the closed-form problem closest to it: a nearly incompressible
neo-Hookean matrix (the elastin-like law of eq. 2.21 without pre-stretch or
fibres) containing an elliptical GAG inclusion (eq. 2.27) swollen by a small
Gibbs-Donnan pressure ``Pi``. In the linear regime (``Pi`` << ``mu``) with a
negligible GAG stiffness, this is Inglis' pressurised elliptical hole: hoop
stress ``Pi (2a/b - 1)`` at the end of the major axis, and for a circle the
Lamé field ``sigma_rr = -Pi (R/r)^2``, ``sigma_tt = +Pi (R/r)^2``
(:mod:`sphgag.physics.inglis`).

**Layout.** Particles sit on rings that are offset ellipses
``P(s, t) = ((a + s) cos t, (b + s) sin t)``: ``s in (-b, 0)`` inside the
inclusion, ``s in (0, L)`` in the matrix. The inclusion boundary ``s = 0`` is a
cell boundary (as the pools' radial edges in the artery), every ring carries
particles at equal arc length about ``dx`` apart, and a particle's volume is the
exact area of its cell ``[s0, s1] x [t0, t1]``. Only the quarter ``x, y > 0`` is
discretised: the axes are mirror planes (:mod:`sphgag.engine.kernel`).

**Boundary.** The outermost ring is placed on the exact infinite-plate
displacement (:func:`sphgag.physics.inglis.field`), so the block's finite size does
not enter the reference at all.

**Tip value.** A particle's stress is a kernel average whose stencil straddles
the interface, and the hoop stress falls steeply ahead of the tip (over the
tip's radius of curvature ``rho = b^2/a``), so neither the first particle nor a
polynomial extrapolation in the distance ``s`` from the interface gives the
boundary value at a practical resolution. The tip stress is the least-squares
fit of the hoop stresses of the first ``TIP_PARTICLES`` matrix particles on the
major axis by ``c0 + c1 q + c2 q^2`` with ``q = rho / (rho + s)``, evaluated on
the interface (``q = 1``). The basis follows the tip's own length scale and
contains the Lamé field exactly; fitted to the exact Inglis field at the same
points, it reproduces the tip value to 2 % at ``b/dx = 16`` for ``a/b = 3``
(and exactly for a circle); docs/physics.md.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
import pandas as pd

from ..engine import kernel, measure, solver
from ..engine.loading import Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import FANS_OUT, Options, role
from ..physics import inglis, materials, volumetric


@dataclass(frozen=True)
class PoolVerification(Options):
    """The ``verification.pool`` configuration: the pressurised elliptical inclusion of minor semi-axis
    ``semi_axis_b_um`` at the ``aspect_ratios`` a / b and the ``resolutions`` b / dx, in a matrix reaching
    ``extent_factor`` a beyond it, under the swelling pressure ``swelling_pressure_kPa`` (Inglis; Lame for a circle)."""

    semi_axis_b_um: float
    aspect_ratios: tuple = role(FANS_OUT)
    resolutions: tuple
    extent_factor: float
    swelling_pressure_kPa: float


@dataclass(frozen=True)
class EllipseLayout:
    """Particles on offset-ellipse rings around an elliptical inclusion (quarter, mirror-symmetric).

    X, volume, theta : as :class:`sphgag.engine.geometry.Layout` (theta = 0: the local frame is global).
    s, t : ring offset and ellipse parameter of each particle.
    ring : ring index (0 = innermost); ``ring_offset[k]`` its ``s``.
    inclusion : True for particles inside the ellipse (``s < 0``).
    """

    X: np.ndarray
    volume: np.ndarray
    theta: np.ndarray
    s: np.ndarray
    t: np.ndarray
    ring: np.ndarray
    ring_offset: np.ndarray
    inclusion: np.ndarray
    a: float
    b: float
    dx: float
    _members: list = field(default_factory=list, repr=False, compare=False)

    @property
    def n(self) -> int:
        return self.X.shape[0]

    @property
    def spacing(self) -> np.ndarray:
        """Every particle's spacing: ``dx`` (a uniform layout, as :attr:`sphgag.engine.geometry.Layout.spacing`)."""
        return np.full(self.n, self.dx)

    def ring_members(self, k: int) -> np.ndarray:
        """Particles of ring ``k`` ordered by ``t`` (from the major axis)."""
        return self._members[k]

    @property
    def inner_surface(self) -> np.ndarray:  # no lumen
        return np.empty(0, dtype=np.int64)

    @property
    def outer_surface(self) -> np.ndarray:
        return self._members[-1]

    @property
    def outer_radius(self) -> float:
        return float(np.linalg.norm(self.X, axis=1).max())

    @property
    def first_matrix_ring(self) -> int:
        return int(np.searchsorted(self.ring_offset, 0.0))


def _ring_particles(a, b, s, dx, samples=4001):
    """Ellipse parameters of particles at equal arc length on ring ``s``, and of their cell bounds."""
    t = np.linspace(0.0, 0.5 * np.pi, samples)
    speed = np.hypot((a + s) * np.sin(t), (b + s) * np.cos(t))
    arc = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(t))])
    n = max(int(round(arc[-1] / dx)), 1)
    at = lambda frac: np.interp(frac * arc[-1], arc, t)  # noqa: E731
    return at((np.arange(n) + 0.5) / n), at(np.arange(n + 1) / n)


def _cell_area(a, b, s0, s1, t0, t1):
    """Exact area of the cell ``[s0, s1] x [t0, t1]``: the integral of ``(b+s) cos^2 t + (a+s) sin^2 t``."""
    cos2 = 0.5 * (t1 - t0) + 0.25 * (np.sin(2 * t1) - np.sin(2 * t0))
    sin2 = 0.5 * (t1 - t0) - 0.25 * (np.sin(2 * t1) - np.sin(2 * t0))
    return 0.5 * ((b + s1) ** 2 - (b + s0) ** 2) * cos2 + 0.5 * ((a + s1) ** 2 - (a + s0) ** 2) * sin2


def ellipse_layout(a: float, b: float, dx: float, extent: float) -> EllipseLayout:
    """Rings of width ~dx: ``round(b/dx)`` inside the inclusion, ``round(extent/dx)`` in the matrix."""
    if not (a >= b > 0 and dx > 0 and extent > 0):
        raise ValueError(f"need a >= b > 0, dx > 0, extent > 0 (got a={a}, b={b}, dx={dx}, extent={extent})")
    n_in, n_out = max(int(round(b / dx)), 1), max(int(round(extent / dx)), 2)
    bounds = np.concatenate([np.linspace(-b, 0.0, n_in + 1), np.linspace(0.0, extent, n_out + 1)[1:]])
    X, vol, S, T, ring, members, start = [], [], [], [], [], [], 0
    for k, (s0, s1) in enumerate(zip(bounds[:-1], bounds[1:])):
        s = 0.5 * (s0 + s1)
        tc, tb = _ring_particles(a, b, s, dx)
        X.append(np.column_stack([(a + s) * np.cos(tc), (b + s) * np.sin(tc)]))
        vol.append(_cell_area(a, b, s0, s1, tb[:-1], tb[1:]))
        S.append(np.full(tc.size, s))
        T.append(tc)
        ring.append(np.full(tc.size, k))
        members.append(np.arange(start, start + tc.size))
        start += tc.size
    S = np.concatenate(S)
    return EllipseLayout(
        X=np.vstack(X),
        volume=np.concatenate(vol),
        theta=np.zeros(start),
        s=S,
        t=np.concatenate(T),
        ring=np.concatenate(ring),
        ring_offset=0.5 * (bounds[1:] + bounds[:-1]),
        inclusion=S < 0.0,
        a=float(a),
        b=float(b),
        dx=float(dx),
        _members=members,
    )


def quarter_ellipse_area(a, b, extent):
    """Area the particle volumes must sum to: the quarter of the outer ring's ellipse."""
    return 0.25 * np.pi * (a + extent) * (b + extent)


@dataclass(frozen=True)
class Materials:
    """Matrix (neo-Hookean, eq. 2.21 without pre-stretch) and GAG inclusion (eq. 2.27) constants [kPa]; ``lam_gag``
    the modulus of the GAG contents' volumetric term of the form ``volumetric``
    (:data:`sphgag.physics.volumetric.VOLUMETRIC_FORMS`)."""

    mu: float
    lam: float
    mu_gag: float
    lam_gag: float
    hourglass_modulus: float
    gag_hourglass_modulus: float
    volumetric: str

    #: the keys of the ``gag`` section that :meth:`of` reads: the GAG's moduli, and with ``bulk`` its volumetric term's
    GAG_KEYS: ClassVar[tuple] = ("shear_modulus_kPa", "hourglass_modulus_kPa")
    BULK_GAG_KEYS: ClassVar[tuple] = ("shear_modulus_kPa", "lame_lambda_kPa", "volumetric", "hourglass_modulus_kPa")

    @classmethod
    def gag_settings(cls, gag: Mapping, bulk: bool = False, also: tuple = ()) -> dict:
        """What a verification job reads of the ``gag`` section ``gag``: the keys :meth:`of` reads (with ``bulk`` or
        without), then those of ``also``."""
        return {k: gag[k] for k in (cls.BULK_GAG_KEYS if bulk else cls.GAG_KEYS) + also}

    @classmethod
    def of(cls, matrix: dict, gag: dict, bulk: bool = False) -> Materials:
        """The elastin matrix (``matrix``: shear modulus, Lame parameter, hourglass modulus) around GAG of ``gag``'s
        shear and hourglass moduli, without a volumetric term (eq. 2.27 as printed) or, with ``bulk``, with ``gag``'s
        (``volumetric``, ``lame_lambda_kPa``: as in the artery's pools)."""
        return cls(
            mu=matrix["shear_modulus_kPa"],
            lam=matrix["lame_lambda_kPa"],
            mu_gag=gag["shear_modulus_kPa"],
            lam_gag=gag["lame_lambda_kPa"] if bulk else 0.0,
            hourglass_modulus=matrix["hourglass_modulus_kPa"],
            gag_hourglass_modulus=gag["hourglass_modulus_kPa"],
            volumetric=gag["volumetric"] if bulk else volumetric.VOLUMETRIC_FORMS.paper.name,
        )

    @property
    def poisson_ratio(self) -> float:
        """Plane-strain Poisson's ratio of the linearised matrix law, lambda / (2 (lambda + mu))."""
        return self.lam / (2.0 * (self.lam + self.mu))


class InclusionMaterial:
    """Property table as a function of the load's ``swelling_pressure`` [kPa] (eqs. 2.21, 2.27): the matrix, and GAG
    at ``members`` (default the layout's inclusion)."""

    def __init__(self, layout: EllipseLayout, mat: Materials, members: np.ndarray | None = None):
        self.table = materials.empty_props(layout.n)
        self.gag = np.flatnonzero(layout.inclusion) if members is None else np.asarray(members, dtype=np.int64)
        self.table[:, materials.MU], self.table[:, materials.LAM] = mat.mu, mat.lam
        self.table[:, materials.HG_E] = mat.hourglass_modulus
        materials.convert_to_gag(
            self.table,
            self.gag,
            1.0,
            mat.mu_gag,
            mat.gag_hourglass_modulus,
            kappa=mat.lam_gag,
            volumetric=mat.volumetric,
        )

    def __call__(self, load: Load) -> np.ndarray:
        out = self.table.copy()
        out[self.gag, materials.PI] = load.material_value("swelling_pressure", 0.0)
        return out


class ExactBoundary:
    """The outer surface of a layout with a hole of half-axes ``layout.a``, ``layout.b`` held on the exact
    infinite-plate displacement of the hole under the pressure the load names ``pressure`` (Inglis)."""

    def __init__(self, layout, mat: Materials, pressure: str = "swelling_pressure"):
        self.idx, self.pressure = layout.outer_surface, pressure
        X = layout.X[self.idx]
        u = inglis.field(X[:, 0], X[:, 1], layout.a, layout.b, 1.0, mat.mu, mat.poisson_ratio)
        self.X, self.u = X, np.column_stack([u["ux"], u["uy"]])

    def __call__(self, load: Load):
        return self.idx, self.X + load.material_value(self.pressure, 0.0) * self.u


def inclusion_model(
    a, b, dx, extent, mat: Materials, numerics: Numerics, name: str = "inclusion", free: bool = False
) -> Model:
    """The block with its inclusion, mirror planes on both axes and the exact far field (Inglis) on the outer ring,
    or, ``free``, the outer ring traction free."""
    lay = ellipse_layout(a, b, dx, extent)
    nb = kernel.build_neighbours(lay.X, lay.volume, numerics.kernel_support_factor * dx, mirrors=(1, 2))
    return Model(
        name,
        lay,
        nb,
        InclusionMaterial(lay, mat),
        boundary=None if free else ExactBoundary(lay, mat),
        **numerics.model_options(),
    )


def pressure_load(pressure_kPa: float) -> Load:
    """The load of an inclusion at swelling pressure ``pressure_kPa`` [kPa] (no lumen, plane strain at ``lz = 1``)."""
    return Load(1.0, 0.0, material=(("swelling_pressure", float(pressure_kPa)),))


def swell(model: Model, pressure_kPa: float, numerics: Numerics) -> solver.State:
    """The converged state with the inclusion at swelling pressure ``pressure_kPa`` (one load step from rest)."""
    load, rest = pressure_load(pressure_kPa), pressure_load(0.0)
    return numerics.solver(model).follow_path(model.layout.X, rest, [load], run=model.name)[-1]


def normal_stress(lay: EllipseLayout, ev) -> tuple[np.ndarray, np.ndarray]:
    """Cauchy stress normal and tangential to each particle's ring, ``(sigma_nn, sigma_tt)``
    (current frame ~ reference)."""
    sig = measure.cauchy(ev)[0]
    n = np.column_stack([(lay.b + lay.s) * np.cos(lay.t), (lay.a + lay.s) * np.sin(lay.t)])
    n /= np.linalg.norm(n, axis=1)[:, None]
    tvec = np.column_stack([-n[:, 1], n[:, 0]])
    snn = np.einsum("ni,nij,nj->n", n, sig, n)
    stt = np.einsum("ni,nij,nj->n", tvec, sig, tvec)
    return snn, stt


TIP_PARTICLES = 6


def _extrapolate(s, v, order=2):
    """Value at s = 0 of the least-squares polynomial of degree ``order`` through the points (s, v)."""
    return float(np.polyval(np.polyfit(s, v, order), 0.0))


def tip_fit(s, v, rho):
    """Value on the interface (s = 0) of the least-squares fit ``c0 + c1 q + c2 q^2``, ``q = rho/(rho + s)``."""
    q = rho / (rho + np.asarray(s, dtype=float))
    c = np.linalg.lstsq(np.column_stack([np.ones_like(q), q, q * q]), v, rcond=None)[0]
    return float(c.sum())


def measure_state(model: Model, state: solver.State, pressure_kPa: float, mat: Materials) -> dict:
    """Tip hoop stress against Inglis, traction continuity and the field error (see the module docstring)."""
    lay: EllipseLayout = model.layout
    ev = state.evaluation
    snn, stt = normal_stress(lay, ev)
    k0 = lay.first_matrix_ring
    axis = np.array([lay.ring_members(k)[0] for k in range(lay.ring_offset.size)])  # closest to the major axis
    out_axis = axis[k0 : k0 + TIP_PARTICLES]
    tip = tip_fit(lay.s[out_axis], stt[out_axis], lay.b**2 / lay.a)
    ref = inglis.tip_hoop_stress(lay.a, lay.b, pressure_kPa)
    # traction continuity: ring-mean normal stress extrapolated linearly to s = 0 from each side
    ring_mean = np.array(
        [
            np.average(snn[lay.ring_members(k)], weights=lay.volume[lay.ring_members(k)])
            for k in range(lay.ring_offset.size)
        ]
    )
    inside = _extrapolate(lay.ring_offset[k0 - 2 : k0], ring_mean[k0 - 2 : k0], 1) if k0 >= 2 else ring_mean[0]
    outside = _extrapolate(lay.ring_offset[k0 : k0 + 2], ring_mean[k0 : k0 + 2], 1)
    # pointwise field error on the matrix (particles off the prescribed ring)
    free = ~lay.inclusion & (lay.ring < lay.ring_offset.size - 1)
    X = lay.X[free]
    ex = inglis.field(X[:, 0], X[:, 1], lay.a, lay.b, pressure_kPa, mat.mu, mat.poisson_ratio)
    srr, sth, _, _ = measure.cauchy_polar(ev)
    err = np.concatenate([srr[free] - ex["srr"], sth[free] - ex["stt"]])
    first = out_axis[0]
    first_ref = float(
        inglis.field(lay.X[first, 0], lay.X[first, 1], lay.a, lay.b, pressure_kPa, mat.mu, mat.poisson_ratio)["syy"]
    )
    return dict(
        tip_stress_kPa=tip,
        reference_kPa=ref,
        rel_error=tip / ref - 1.0,
        traction_jump_kPa=abs(outside - inside),
        traction_inside_kPa=inside,
        traction_outside_kPa=outside,
        first_particle_stress_kPa=float(stt[first]),
        first_particle_reference_kPa=first_ref,
        first_particle_rel_error=float(stt[first]) / first_ref - 1.0,
        field_rms_error_kPa=float(np.sqrt(np.mean(err**2))),
        field_max_error_kPa=float(np.abs(err).max()),
        residual=state.convergence.residual,
        particles=lay.n,
    )


def axis_profile(model: Model, state: solver.State, pressure_kPa: float, mat: Materials) -> pd.DataFrame:
    """Hoop and normal stress of the particles nearest the major axis, SPH and exact (matrix side)."""
    lay: EllipseLayout = model.layout
    snn, stt = normal_stress(lay, state.evaluation)
    k0 = lay.first_matrix_ring
    idx = np.array([lay.ring_members(k)[0] for k in range(k0, lay.ring_offset.size - 1)])
    ex = inglis.field(lay.X[idx, 0], lay.X[idx, 1], lay.a, lay.b, pressure_kPa, mat.mu, mat.poisson_ratio)
    return pd.DataFrame(
        dict(
            s_um=lay.s[idx],
            hoop_sph_kPa=stt[idx],
            hoop_exact_kPa=ex["syy"],
            normal_sph_kPa=snn[idx],
            normal_exact_kPa=ex["sxx"],
        )
    )


def ring_profile(model: Model, state: solver.State, pressure_kPa: float, mat: Materials) -> pd.DataFrame:
    """Ring means of the polar Cauchy stresses, SPH and Lamé (circular inclusion: rings are circles)."""
    lay: EllipseLayout = model.layout
    srr, stt, _, _ = measure.cauchy_polar(state.evaluation)
    rows = []
    for k, s in enumerate(lay.ring_offset[:-1]):
        m = lay.ring_members(k)
        r = lay.a + s
        lame = pressure_kPa * (lay.a / r) ** 2 if s > 0 else pressure_kPa
        rows.append(
            dict(
                radius_um=r,
                radial_sph_kPa=np.average(srr[m], weights=lay.volume[m]),
                circ_sph_kPa=np.average(stt[m], weights=lay.volume[m]),
                radial_exact_kPa=-lame,
                circ_exact_kPa=lame if s > 0 else -pressure_kPa,
            )
        )
    return pd.DataFrame(rows)


def study(aspect_ratio: float, vp: dict, matrix: dict, gag: dict, numerics: Numerics, log=None):
    """The pool verification for one aspect ratio ``a/b`` at every resolution of ``vp['resolutions']``.

    ``vp``: the ``verification.pool`` configuration; ``matrix``: shear modulus,
    Lame parameter and hourglass modulus of the matrix (the elastin law of the
    bi-layered model, unweighted); ``gag``: the GAG section (``mu_GAG``,
    hourglass modulus; the bulk term is 0 here, as eq. 2.27). Returns the rows
    of ``elliptic_pool.csv`` and the axis (and, for a circle, ring) profiles.
    """
    b = float(vp["semi_axis_b_um"])
    a = float(aspect_ratio) * b
    Pi = float(vp["swelling_pressure_kPa"])
    mat = Materials.of(matrix, gag)
    extent = max(vp["extent_factor"] * a, 3.0 * b)
    rows, profiles = [], []
    for res in vp["resolutions"]:
        dx = b / res
        model = inclusion_model(a, b, dx, extent, mat, numerics, name=f"inclusion_ab{aspect_ratio:g}_b{res:g}dx")
        state = swell(model, Pi, numerics)
        row = dict(dx_um=dx, semi_axis_a_um=a, semi_axis_b_um=b, pressure_kPa=Pi)
        row.update(measure_state(model, state, Pi, mat))
        row.update(aspect_ratio=float(aspect_ratio), b_over_dx=float(res))
        rows.append(row)
        common = dict(aspect_ratio=float(aspect_ratio), dx_um=dx, b_over_dx=float(res))
        profiles.append(axis_profile(model, state, Pi, mat).assign(profile="axis", **common))
        if a == b:
            profiles.append(ring_profile(model, state, Pi, mat).assign(profile="rings", **common))
        if log is not None:
            log.info(
                "[%s] %d particles: tip %.4f kPa (Inglis %.4f, error %+.2f %%), traction jump %.3f Pi, "
                "field rms error %.3f Pi, residual %.1e",
                model.name,
                model.n,
                row["tip_stress_kPa"],
                row["reference_kPa"],
                100 * row["rel_error"],
                row["traction_jump_kPa"] / Pi,
                row["field_rms_error_kPa"] / Pi,
                row["residual"],
            )
    return pd.DataFrame(rows), pd.concat(profiles, ignore_index=True)


def observed_order(dx, error) -> float:
    """Slope of log|error| against log dx (least squares) over the finite, nonzero errors: the observed order of
    convergence (NaN with fewer than two)."""
    dx, error = np.asarray(dx, float), np.abs(np.asarray(error, float))
    ok = np.isfinite(error) & (error > 0.0)
    if ok.sum() < 2:
        return float("nan")
    return float(np.polyfit(np.log(dx[ok]), np.log(error[ok]), 1)[0])
