"""A GAG pool as a pressurised cavity (``gag.pool_model: cavity``; our deviation, docs/physics.md).

In the paper's model (``particles``) the pool's GAG particles carry the Donnan pressure as their own stress
(``W -= Pi (J - 1)``, eq. 2.27) and their deformation gradients (eq. 2.9) follow the pool's deformation. The pool's
contents carry almost no shear (mu_GAG = 0.1 kPa against Pi(150 mEq/l) = 91 kPa), so what holds a GAG particle's
neighbourhood together is the hourglass penalty (eq. 2.14) with the elastin's modulus: a stiffness of the
discretisation that resists the pool's non-affine swelling and fades as the particles get finer, so the swollen
volume grows with refinement (docs/physics.md, "What fails near the artery's pools").

Here, as finite-element codes model fluid-filled cavities, the pool is a hole in the tissue whose boundary carries
the Donnan pressure as a follower load:

* the **lining** is the closed polygon through the tissue particles within 1.5 of their spacing (reference) of the
  pool's particles, ordered by angle about the pool's centroid (star-shaped pools: sectors, ellipses); a pool centred on
  the corner of a quarter layout's mirror planes (the verification's circle and ellipse) is closed as the lumen is,
  on the mirror planes (:func:`sphgag.engine.loading.lumen_area_gradient`);
* the pressure does the work ``Pi lz A`` of the polygon's area ``A`` (``lz``: plane strain per reference length, as
  the lumen pressure, :mod:`sphgag.engine.loading`), so its nodal forces are the exact gradient ``Pi lz dA/dx`` and
  its stiffness ``Pi lz d2A/dx2`` is symmetric; ``Pi`` is the prescribed Pi(c) of eqs. (2.25-2.26) that the pool's
  particles would carry;
* the pool's contents keep their own law (eq. 2.27 with the GAG's volumetric term ``U = kappa u``,
  :mod:`sphgag.physics.volumetric`) as a uniform swelling of the whole pool:
  ``w(J) = mu_g/2 (2 J + lz^2 - 3) - mu_g ln(J lz) + U(J lz)`` per reference area, ``J`` the pool's volume ratio
  (:func:`pool_pressure`; the contents' state is uniform, as the pool's particles cannot resolve it where the law
  is not elliptic: with ``U = kappa/2 (ln J)^2`` and the Donnan pressure it loses ellipticity at ``J`` of about 2.8,
  ``mu_g (J + 1) + kappa < kappa ln J``, and a non-uniform state of the contents is not unique). Its stiffness,
  ``w''/V_pool`` times the outer product of
  ``dA/dx`` with itself, couples the whole lining: it stays out of the sparse Jacobian and enters the solves as a
  rank-one update (:meth:`Cavity.rank_one`, Sherman-Morrison in :func:`sphgag.engine.solver.factorise`);
* the pool's volume ratio is ``1 + (A - A_0) / V_pool`` (``V_pool``: the pool's reference area, the sum of its
  particles' volumes; ``A_0``: the polygon's reference area), the exact area the lining encloses in place of
  ``sum V_i J_i``;
* the tissue sees a free surface at the pool: its deformation gradients come from tissue neighbours only (the
  material-split stencil of :func:`sphgag.engine.kernel.hourglass_gradients`, used for the elastic forces too);
* the pool's particles (the filler) no longer touch the tissue and are held where the pool's conversion left them
  (their positions carry no meaning).

A :class:`Cavity` is one of a :class:`sphgag.engine.model.Model`'s ``cavities``: the model asks it for its hooks, the
property rows it empties (:meth:`Cavity.hollow_rows`), its loading read from them (:meth:`Cavity.loading`), its
lining's forces, stiffness blocks and rank-one term at that loading, and the particles it holds.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy.spatial import cKDTree

from ..physics import materials
from ..physics.volumetric import NONE, unit_terms
from .loading import add_pressure_stiffness, lumen_area_gradient, pressure_stiffness_blocks

CONTACT = 1.5  # lining: tissue particles within this many of their spacings of a pool particle (reference)


@dataclass(frozen=True)
class Cavity:
    """One pool as a cavity: ``members`` (its particles), ``loop`` (the lining, a closed counter-clockwise polygon),
    ``pool_area`` (reference area of the pool), ``loop_area0`` (reference area of the polygon) and ``held`` (the
    positions its particles are held at); ``mirrored``: closed on the mirror planes of a quarter layout."""

    members: np.ndarray
    loop: np.ndarray
    pool_area: float
    loop_area0: float
    held: np.ndarray
    mirrored: bool = False

    @classmethod
    def around(cls, layout, members: np.ndarray, x: np.ndarray, mirrored: bool = False) -> Cavity:
        """The cavity of the pool ``members`` of ``layout``, its particles held at their positions in ``x``;
        ``mirrored``: a pool about the origin of a quarter layout, closed on its mirror planes."""
        X = layout.X
        members = np.asarray(members, dtype=np.int64)
        if members.size == 0:
            raise ValueError("a cavity needs at least one pool particle")
        tissue = np.ones(layout.n, dtype=bool)
        tissue[members] = False
        dist = cKDTree(X[members]).query(X)[0]
        lining = np.flatnonzero((dist <= CONTACT * layout.spacing) & tissue)
        centre = np.zeros(2) if mirrored else X[members].mean(axis=0)
        loop = lining[np.argsort(np.arctan2(X[lining, 1] - centre[1], X[lining, 0] - centre[0]))]
        cav = cls(members, loop, float(layout.volume[members].sum()), 0.0, x[members].copy(), mirrored)
        return replace(cav, loop_area0=cav.area(X))

    def area(self, x: np.ndarray) -> float:
        """The area the lining encloses (a quarter layout's: the quarter)."""
        if self.mirrored:
            return float(lumen_area_gradient(x, self.loop, np.empty((self.loop.size, 2))))
        return polygon_area(x[self.loop])

    def volume_ratio(self, x: np.ndarray) -> float:
        """The pool's current area over its reference area, ``1 + (A - A_0) / V_pool``."""
        return 1.0 + (self.area(x) - self.loop_area0) / self.pool_area

    def area_gradient(self, x: np.ndarray) -> np.ndarray:
        """``dA/dx`` of the lining's particles (rows in the order of ``loop``)."""
        if self.mirrored:
            grad = np.empty((self.loop.size, 2))
            lumen_area_gradient(x, self.loop, grad)
            return grad
        q = x[self.loop]
        nxt, prv = np.roll(q, -1, axis=0), np.roll(q, 1, axis=0)
        return 0.5 * np.column_stack([nxt[:, 1] - prv[:, 1], prv[:, 0] - nxt[:, 0]])

    def loading(self, props: np.ndarray, run: str) -> tuple[float, tuple]:
        """``(Pi, contents)``: the prescribed swelling pressure (eqs. 2.25-2.27) its particles' rows of ``props`` carry,
        its lining's load, and their shear modulus and volumetric term (``contents = (mu_g, kappa, form code)``,
        :mod:`sphgag.physics.volumetric`; a cavity's contents are GAG, no tissue's ``LAM`` left). ValueError, naming
        the run ``run``, where the rows carry no one prescribed pressure."""
        rows = props[self.members]
        if np.any(rows[:, materials.FCD] > 0.0) or np.ptp(rows[:, materials.PI]) > 0.0:
            raise ValueError(f"{run}: a cavity carries one prescribed pressure (the law 'prescribed')")
        row = rows[0]
        contents = (float(row[materials.MU]), float(row[materials.KAPPA]), int(row[materials.VOLUMETRIC]))
        return float(row[materials.PI]), contents

    def hollow_rows(self, props: np.ndarray) -> None:
        """Empty its particles' rows of ``props`` (in place): they carry no stress, their pressure is the lining's."""
        props[self.members, materials.PI] = 0.0
        props[self.members, materials.MU] = props[self.members, materials.LAM] = 0.0
        props[self.members, materials.KAPPA] = 0.0
        props[self.members, materials.HG_E] = 0.0

    def lining_pressure(self, x: np.ndarray, loading: tuple, lz: float) -> float:
        """The net pressure ``Pi lz - w'(J)`` on the lining per reference length at ``x`` (:func:`pool_pressure`;
        ``loading``: :meth:`loading`)."""
        pressure_kPa, contents = loading
        return pool_pressure(self.volume_ratio(x), pressure_kPa, lz, *contents)

    def add_forces(self, f: np.ndarray, x: np.ndarray, loading: tuple, lz: float) -> None:
        """Add the nodal forces ``(Pi lz - w'(J)) dA/dx`` to ``f`` (``loading``: :meth:`loading`)."""
        f[self.loop] += self.lining_pressure(x, loading, lz) * self.area_gradient(x)

    def rank_one(self, x: np.ndarray, loading: tuple, lz: float) -> tuple[float, np.ndarray]:
        """The part of the Jacobian the blocks leave out: ``(c, g)`` with ``d(f)/dx += c g g^T``, ``g = dA/dx`` on
        the lining (a flat vector over all particles) and ``c = p'(J) / V_pool``, ``p'(J) = -w''(J)`` the contents'
        stiffness (:func:`pool_pressure`; the prescribed Pi does not depend on J): it couples every lining particle to
        every other."""
        J = self.volume_ratio(x)
        g = np.zeros_like(x)
        g[self.loop] = self.area_gradient(x)
        return -contents_stiffness(J, lz, *loading[1]) / self.pool_area, g.ravel()

    def stiffness_blocks(self, block_index) -> tuple:
        """The Jacobian blocks ``(p, next)`` and ``(p, previous)`` of each lining particle (``block_index(p, q)``;
        mirrored: those of :func:`sphgag.engine.loading.pressure_stiffness_blocks`)."""
        if self.mirrored:
            return pressure_stiffness_blocks(block_index, self.loop)
        k = self.loop
        try:
            nxt = np.array([block_index(k[i], k[(i + 1) % k.size]) for i in range(k.size)], dtype=np.int64)
            prv = np.array([block_index(k[i], k[i - 1]) for i in range(k.size)], dtype=np.int64)
        except KeyError as e:  # the Jacobian's pattern is the kernel's pairs
            raise ValueError(
                f"the cavity's lining has consecutive particles that are not kernel neighbours ({e.args[0]}): its "
                "loop, ordered by angle about the pool's centre, is not a chain of neighbours on this layout (a "
                "graded layout around a long pool can do this; use the particles pool model there)"
            ) from None
        return nxt, prv

    def add_stiffness(self, data: np.ndarray, blocks: tuple, x: np.ndarray, loading: tuple, lz: float) -> None:
        """Add ``d(p dA/dx)/dx`` at the lining's net pressure ``p`` (:meth:`lining_pressure`) to the Jacobian blocks
        ``data`` (``blocks``: :meth:`stiffness_blocks`):
        ``d(dA/dx_k)/dy_(k+1) = 1/2``, ``d(dA/dx_k)/dy_(k-1) = -1/2``, ``d(dA/dy_k)/dx_(k-1) = 1/2``,
        ``d(dA/dy_k)/dx_(k+1) = -1/2`` (mirrored: :func:`sphgag.engine.loading.add_pressure_stiffness`)."""
        pressure_kPa = self.lining_pressure(x, loading, lz)
        if self.mirrored:
            add_pressure_stiffness(data, blocks, pressure_kPa, 1.0)
            return
        c = 0.5 * pressure_kPa
        nxt, prv = blocks
        np.add.at(data, (nxt, 0, 1), c)
        np.add.at(data, (nxt, 1, 0), -c)
        np.add.at(data, (prv, 0, 1), -c)
        np.add.at(data, (prv, 1, 0), c)


def hollow(model, members: np.ndarray, x: np.ndarray):
    """``model`` with the pool ``members`` as a cavity (:class:`Cavity`), its particles held at their positions in
    ``x``: a new model, with its own derived data, solved by a :class:`sphgag.engine.solver.Solver` of its own (its
    Jacobian's pattern of loads changes, so no factorisation of ``model`` carries over)."""
    return replace(model, cavities=(Cavity.around(model.layout, members, x),))


def pool_pressure(J: float, pressure_kPa: float, lz: float, mu: float, kappa: float = 0.0, form: int = NONE) -> float:
    """``Pi lz - w'(J)``: the net pressure on the lining per unit reference length (module docstring), with
    ``w'(J) = mu (1 - 1/J) + lz U'(J lz)``, ``U = kappa u`` the volumetric form of code ``form``
    (:func:`sphgag.physics.volumetric.unit_terms`)."""
    return pressure_kPa * lz - (mu * (1.0 - 1.0 / J) + kappa * lz * unit_terms(int(form), J * lz)[1])


def contents_stiffness(J: float, lz: float, mu: float, kappa: float = 0.0, form: int = NONE) -> float:
    """``w''(J) = mu / J^2 + lz^2 U''(J lz)``: the contents' stiffness per reference area (for
    ``U = kappa/2 (ln J)^2``: ``(mu + kappa (1 - ln(J lz))) / J^2``, negative beyond ``J = e / lz`` with ``mu = 0``:
    the loss of ellipticity of the module docstring)."""
    return mu / (J * J) + kappa * lz * lz * unit_terms(int(form), J * lz)[2]


def polygon_area(q: np.ndarray) -> float:
    """Signed area of the closed polygon through the rows of ``q`` (counter-clockwise positive)."""
    return 0.5 * float(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - q[:, 1] * np.roll(q[:, 0], -1)))
