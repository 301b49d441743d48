"""Loads and boundary conditions: axial stretch, lumen pressure, prescribed inner radius.

A :class:`Load` is one point on a loading path; the quasi-static driver
(:mod:`sphgag.engine.solver`) moves between loads by linear interpolation, so every
ramp in the paper (axial stretch, pressure, deposition pre-stretch, swelling)
is a path of loads.

**Pressure** acts on the inner surface as the exact gradient of the work
``P lz A``, where ``A`` is the area of the quarter lumen bounded by the
polygon through the inner-surface particles (closed on the symmetry planes)
and ``lz`` turns it into a volume per unit reference length. The load is
therefore conservative (its stiffness is symmetric) and follows the
deformed surface. The outer surface is traction free: that is the natural
boundary condition of the discrete energy, so no force is applied there (the
paper instead zeroes the normal component of P at outer particles, section
2.4.1; we check the resulting radial stress instead).

**How the pressure reaches the particles** is a registered numerical variant (``numerics.lumen_load``,
:data:`LUMEN_LOADS`):

* ``surface``: the force ``P lz dA/dx`` on the inner-surface particles (:func:`pressure_forces`, above), with its
  follower stiffness.
* ``operator``: the pressure through the internal-force operator's own boundary term, ``-P f_u(x)`` on the particles
  of the inner boundary layer (:func:`inner_layer`), with ``f_u`` the internal forces (eq. 2.11) of the uniform
  Cauchy stress ``-I`` (the Donnan term ``-Pi (J - 1)`` of eq. 2.26 at ``Pi = 1``, so its tangent is the engine's own
  Jacobian of that material on those rows).

Why: nodal integration spreads a boundary traction over the rings within the kernel's reach (at x = X: 0.78, 0.41,
-0.15, -0.03 of it on the first four rings). Under ``surface`` even an exact uniform state is out of balance there,
and the wall deforms to balance it, which puts the ring beside the lumen 25 % of P off at every spacing; under
``operator`` a uniform pressure state is an exact discrete equilibrium (docs/physics.md, "Stress recovery"). The paper
prescribes the inner radius instead (section 2.4.1) and has no pressure load of its own.

**Prescribed inner radius** (displacement control, as in the authors'
script) places the inner-surface particles at radius ``r_in`` on their
reference rays; the pressure the wall carries is read from the reactions.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
from numba import njit

from ..physics import materials
from ..registry import Registry, Variant
from . import forces

MMHG_TO_KPA = 0.133322387415

# the named scalars a load can carry (Load.material): what the model's material depends on besides the deformation
MATERIAL_NAMES = {
    "prestretch": "fraction of the constituents' deposition pre-stretches (section 2.5), 0 -> 1",
    "activation": "fraction of the active tone (eq. 2.24), 0 -> 1",
    "concentration": "fixed-charge concentration c of the GAG particles [mEq/l] (eqs. 2.25-2.27)",
    "transition": "fraction of the path between two particle histories (seeding, a damage pass), 0 -> 1",
    "swelling_pressure": "pressure of the verification inclusion [kPa] (sphgag.studies.inclusion)",
    "face_pressure": "pressure on the faces of the verification crack [kPa] (sphgag.studies.crack)",
}


def _known(name: str) -> str:
    if name not in MATERIAL_NAMES:
        raise KeyError(f"{name!r} is not a material value of a load: one of {', '.join(MATERIAL_NAMES)}")
    return name


@dataclass(frozen=True)
class Load:
    """One load state.

    axial_stretch : lambda_z of plane strain (relative to the reference).
    pressure_kPa : lumen pressure (pressure control), or None.
    inner_radius : prescribed inner radius in um (displacement control), or None.
    material : named scalars the model's material depends on (e.g. a
        pre-stretch ramp fraction or a GAG concentration), interpolated like
        the rest.
    """

    axial_stretch: float = 1.0
    pressure_kPa: float | None = 0.0
    inner_radius: float | None = None
    material: tuple = field(default_factory=tuple)

    def __post_init__(self):
        if (self.pressure_kPa is None) == (self.inner_radius is None):
            raise ValueError("a load prescribes exactly one of pressure_kPa and inner_radius")
        for name, _ in self.material:
            _known(name)

    @property
    def pressure_mmHg(self):
        return None if self.pressure_kPa is None else self.pressure_kPa / MMHG_TO_KPA

    def with_material(self, **values) -> Load:
        d = dict(self.material)
        d.update(values)
        return replace(self, material=tuple(sorted(d.items())))

    def material_value(self, name: str, default=None):
        """The load's value of the material scalar ``name`` (:data:`MATERIAL_NAMES`), ``default`` if the load does
        not carry it; a name that is not a material scalar raises ``KeyError``."""
        return dict(self.material).get(_known(name), default)

    def lerp(self, other: Load, t: float) -> Load:
        """The load a fraction ``t`` of the way from ``self`` to ``other``."""
        if (self.pressure_kPa is None) != (other.pressure_kPa is None):
            raise ValueError("cannot interpolate between pressure and radius control")

        def mix(a, b):
            return None if a is None else a + t * (b - a)

        mine, theirs = dict(self.material), dict(other.material)
        if set(mine) != set(theirs):
            raise ValueError("cannot interpolate loads with different material parameters")
        return Load(
            axial_stretch=mix(self.axial_stretch, other.axial_stretch),
            pressure_kPa=mix(self.pressure_kPa, other.pressure_kPa),
            inner_radius=mix(self.inner_radius, other.inner_radius),
            material=tuple(sorted((k, mix(mine[k], theirs[k])) for k in mine)),
        )


@njit(cache=True)
def lumen_area_gradient(x, idx, grad):
    """Quarter lumen area A and dA/dx of the inner-surface particles ``idx`` (ordered by theta).

    The polygon runs ``(x_0, 0) -> p_0 -> ... -> p_{n-1} -> (0, y_{n-1})``,
    i.e. it is closed by the mirror images across both symmetry planes.
    """
    n = idx.shape[0]
    area = 0.0
    for k in range(n - 1):
        a, b = idx[k], idx[k + 1]
        area += x[a, 0] * x[b, 1] - x[a, 1] * x[b, 0]
    first, last = idx[0], idx[n - 1]
    area += x[first, 0] * x[first, 1] + x[last, 0] * x[last, 1]
    for k in range(n):
        p = idx[k]
        if k == 0:
            y_prev, x_prev = -x[p, 1], x[p, 0]  # mirror across y = 0
        else:
            y_prev, x_prev = x[idx[k - 1], 1], x[idx[k - 1], 0]
        if k == n - 1:
            y_next, x_next = x[p, 1], -x[p, 0]  # mirror across x = 0
        else:
            y_next, x_next = x[idx[k + 1], 1], x[idx[k + 1], 0]
        grad[k, 0] = 0.5 * (y_next - y_prev)
        grad[k, 1] = 0.5 * (x_prev - x_next)
    return 0.5 * area


def pressure_forces(x, inner, pressure_kPa, lz):
    """External nodal forces of the lumen pressure, ``P lz dA/dx`` (all particles, zeros off the surface).

    No equation of the paper: the paper prescribes the inner radius (section 2.4.1)
    and reads the pressure back; this is the pressure-control alternative.
    """
    f = np.zeros_like(x)
    if pressure_kPa:
        g = np.empty((inner.size, 2))
        lumen_area_gradient(x, inner, g)
        f[inner] = pressure_kPa * lz * g
    return f


def pressure_stiffness_blocks(blocks_of, inner) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The Jacobian blocks that the follower pressure's stiffness fills (see :func:`add_pressure_stiffness`):
    ``(p, next)`` and ``(p, previous)`` for each inner-surface particle ``p``, and the diagonal blocks of the first and
    last (the mirror closures). ``blocks_of(p, q)`` gives a block index."""
    if inner.size == 0:  # no lumen (e.g. a free patch)
        return np.empty(0, np.int64), np.empty(0, np.int64), np.empty(0, np.int64)
    nxt = np.array([blocks_of(inner[k], inner[k + 1]) for k in range(inner.size - 1)], dtype=np.int64)
    prev = np.array([blocks_of(inner[k], inner[k - 1]) for k in range(1, inner.size)], dtype=np.int64)
    ends = np.array([blocks_of(inner[0], inner[0]), blocks_of(inner[-1], inner[-1])], dtype=np.int64)
    return nxt, prev, ends


def add_pressure_stiffness(data, blocks, pressure_kPa, lz):
    """Add d(P lz dA/dx)/dx to Jacobian blocks ``blocks`` (:func:`pressure_stiffness_blocks`; no paper equation).

    d(dA/dx_k)/dy_{k+1} = 1/2, d(dA/dx_k)/dy_{k-1} = -1/2, d(dA/dy_k)/dx_{k-1} = 1/2,
    d(dA/dy_k)/dx_{k+1} = -1/2; the mirror closures add d(dA/dx)/dy = 1/2 at the
    first and d(dA/dy)/dx = 1/2 at the last particle (the Hessian is symmetric).
    """
    if not pressure_kPa:
        return
    c = 0.5 * pressure_kPa * lz
    nxt, prev, ends = blocks
    data[nxt, 0, 1] += c
    data[nxt, 1, 0] -= c
    data[prev, 0, 1] -= c
    data[prev, 1, 0] += c
    np.add.at(data, (ends, 0, 1), c)
    np.add.at(data, (ends, 1, 0), c)


def prescribed_inner_positions(X_inner, r_in):
    """Inner-surface particles at radius ``r_in`` on their reference rays."""
    R = np.linalg.norm(X_inner, axis=1)
    return X_inner * (r_in / R)[:, None]


@dataclass(frozen=True)
class SurfaceLoad(Variant):
    """``P lz dA/dx`` on the inner-surface particles, with its follower stiffness."""

    name: str
    title: str
    paper: bool = False

    def forces(self, model, x: np.ndarray, pairs, lz: float, pressure_kPa: float) -> np.ndarray:
        """The external forces of the lumen pressure at ``x`` (``pairs``: the model's packed pair data)."""
        return pressure_forces(x, model.layout.inner_surface, pressure_kPa, lz)

    def add_stiffness(self, model, data: np.ndarray, ev, pressure_kPa: float) -> None:
        """Add ``d(f_ext)/dx`` of the lumen pressure to the Jacobian blocks ``data``."""
        add_pressure_stiffness(data, model.pressure_blocks, pressure_kPa, ev.load.axial_stretch)


@dataclass(frozen=True)
class OperatorLoad(SurfaceLoad):
    """``-P f_u(x)`` on the inner boundary layer, ``f_u`` the internal forces of the stress ``-I``."""

    def forces(self, model, x, pairs, lz, pressure_kPa):
        f_ext = np.zeros((model.n, 2))
        if not pressure_kPa:
            return f_ext
        props, rows, _ = unit_pressure(model)
        FP, f_u = np.empty((model.n, 12)), np.empty((model.n, 2))
        forces.evaluate_forces(x, pairs, lz, model.cth, model.sth, props, model._xe, model._fe, FP, f_u)
        f_ext[rows] = -pressure_kPa * f_u[rows]
        return f_ext

    def add_stiffness(self, model, data, ev, pressure_kPa):
        if not pressure_kPa:
            return
        props, _, row_blocks = unit_pressure(model)
        nb, elastic = model.nb, model._cache["nb_elastic"]
        ah, sh = model.hourglass_stencil(ev.load)
        hgc = np.zeros_like(model.material(ev.load)[1])  # no hourglass penalty: its forces are the wall's
        unit = np.zeros_like(data)
        stencil = (nb.ptr, nb.nbr, nb.mirror, elastic.a, elastic.s, ah, sh, nb.R, hgc, ev.F, ev.F_hourglass)
        frame = (ev.load.axial_stretch, model.cth, model.sth, props, model.blockmap, model.map_ptr)
        forces.jacobian_blocks(ev.x, model.layout.volume, *stencil, *frame, unit)
        data[row_blocks] -= pressure_kPa * unit[row_blocks]


def unit_pressure(model) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(props, rows, row_blocks)`` of ``model`` (cached on it): a material table whose only stress is the uniform
    Cauchy stress ``-I`` (the Donnan term of eq. 2.26 at ``Pi = 1``), the particles of its inner boundary layer, and
    which of the Jacobian's blocks are theirs (the blocks of those rows)."""
    if "unit_pressure" not in model._cache:
        props = np.zeros((model.n, materials.NPROP))
        props[:, materials.PI] = 1.0
        lay = model.layout
        rows = inner_layer(lay.X, lay.inner_surface, lay.outer_surface)
        in_layer = np.zeros(model.n, dtype=bool)
        in_layer[rows] = True
        row_blocks = in_layer[np.repeat(np.arange(model.n), np.diff(model.block_indptr))]
        model._cache["unit_pressure"] = (props, rows, row_blocks)
    return model._cache["unit_pressure"]


def inner_layer(X: np.ndarray, inner: np.ndarray, outer: np.ndarray) -> np.ndarray:
    """The particles of the inner boundary layer: those nearer, in the reference configuration, to the inner surface
    than to the outer one (a wall's inner half; the operator's boundary term of a uniform stress vanishes away from
    the surfaces)."""
    R = np.hypot(X[:, 0], X[:, 1])
    r_in, r_out = np.hypot(*X[inner].T).mean(), np.hypot(*X[outer].T).mean()
    return np.flatnonzero(R - r_in < r_out - R)


#: the registry of lumen loads, by name (``numerics.lumen_load``)
LUMEN_LOADS: Registry[SurfaceLoad] = Registry(
    "lumen load",
    (
        SurfaceLoad("surface", "the pressure on the polygon through the inner-surface particles, P lz dA/dx"),
        OperatorLoad("operator", "the pressure through the force operator's boundary term (exact for a uniform one)"),
    ),
)
