"""How the lumen pressure becomes particle forces: a registered numerical variant (``numerics.lumen_load``).

* ``surface``: the force ``P lz dA/dx`` on the inner-surface particles (:func:`sphgag.engine.loading.pressure_forces`,
  the exact gradient of the work ``P lz A`` of the quarter lumen's area), with its follower stiffness.
* ``operator``: the pressure through the internal-force operator's own boundary term, ``-P f_u(x)`` on the particles
  of the inner boundary layer (:func:`inner_layer`), with ``f_u`` the internal forces (eq. 2.11) of the uniform
  Cauchy stress ``-I`` (the Donnan term ``-Pi (J - 1)`` of eq. 2.26 at ``Pi = 1``, so its tangent is the engine's own
  Jacobian of that material on those rows).

Why: nodal integration spreads a boundary traction over the rings within the kernel's reach (at x = X: 0.78, 0.41,
-0.15, -0.03 of it on the first four rings). Under ``surface`` even an exact uniform state is out of balance there,
and the wall deforms to balance it, which puts the ring beside the lumen 25 % of P off at every spacing; under
``operator`` a uniform pressure state is an exact discrete equilibrium (docs/physics.md, "Stress recovery"). The paper
prescribes the inner radius instead (section 2.4.1) and has no pressure load of its own.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..physics import materials
from ..registry import Registry, Variant
from . import forces
from .loading import add_pressure_stiffness, pressure_forces


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
