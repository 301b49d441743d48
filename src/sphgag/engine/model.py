"""The discrete arterial cross-section: particles, neighbours, materials and loads.

:class:`Model` bundles the static data of a simulation (layout, neighbour
lists, property table, hourglass parameter) and evaluates, for positions
``x`` and a :class:`~sphgag.engine.loading.Load`, everything the solver and the
measurements need (:class:`Evaluation`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np
import scipy.sparse as sp

from ..physics import materials
from . import forces, kernel, measure, quadrature
from .geometry import Layout
from .kernel import Neighbours
from .loading import LUMEN_LOADS, Load, prescribed_inner_positions, pressure_stiffness_blocks


@dataclass
class Evaluation:
    """Forces and stresses of one configuration under one load."""

    x: np.ndarray
    load: Load
    F: np.ndarray
    P: np.ndarray
    f_int: np.ndarray
    f_ext: np.ndarray
    min_det: float
    constrained: np.ndarray  # particle indices with prescribed positions
    target: np.ndarray  # their prescribed positions
    F_hourglass: np.ndarray | None = None  # F~ of the hourglass penalty (kernel.hourglass_gradients)
    # (Q, 8): F and P of every integration point of a fitted model (engine.quadrature; F, P above: each particle's
    # first point), None otherwise
    FP_points: np.ndarray | None = None
    # ev -> (sigma, J): the stress every measurement reads (engine.measure), bound to the model; None: eq. 2.10
    recovery: Callable | None = field(default=None, repr=False, compare=False)
    recovered: tuple | None = field(default=None, repr=False, compare=False)  # its value, once computed

    def kernel_cauchy(self) -> tuple[np.ndarray, np.ndarray]:
        """``(sigma, J)``: each particle's own in-plane Cauchy stress ``sigma = P F^T / J`` (eq. 2.10), ``(n, 2, 2)``
        in global x-y, and ``J = det F lambda_z``: the stress the equilibrium balances."""
        return measure.kernel_stress(self.F, self.P, self.load.axial_stretch)

    def cauchy(self) -> tuple[np.ndarray, np.ndarray]:
        """``(sigma, J)`` as the measurements read them: the stress recovered by the model's recovery
        (:mod:`sphgag.engine.measure`, computed once), or the kernel stress (eq. 2.10) without one."""
        if self.recovery is None:
            return self.kernel_cauchy()
        if self.recovered is None:
            self.recovered = self.recovery(self)
        return self.recovered

    @property
    def residual_vector(self) -> np.ndarray:
        """Out-of-balance force on the free particles (zeros on constrained ones)."""
        r = self.f_int + self.f_ext
        r[self.constrained] = 0.0
        return r

    @property
    def reactions(self) -> np.ndarray:
        """Forces the prescribed particles receive from their supports."""
        return -(self.f_int + self.f_ext)[self.constrained]

    @property
    def finite(self) -> bool:
        return bool(np.isfinite(self.f_int).all() and np.isfinite(self.P).all())

    def force_scale(self, model: Model) -> float:
        """Reference force of the relative residual (see :func:`sphgag.engine.solver.relative_residual`)."""
        loaded = np.linalg.norm(self.f_ext) + np.linalg.norm(self.reactions)
        q = np.empty(model.n)
        forces.pair_force_scale(model.layout.volume, model.nb.ptr, model.nb.a, self.P, q)
        # floor for stress-free states: the force a stress of 1e-9 of the stiffest modulus exerts on a cell face
        props = model.material(self.load)[0]
        floor = 1e-9 * float(props[:, [0, 1]].sum(axis=1).max()) * model.layout.dx * np.sqrt(model.n)
        return float(max(loaded, 1e-3 * np.linalg.norm(q), floor)) or 1.0

    @property
    def constraint_error(self) -> float:
        return float(np.abs(self.x[self.constrained] - self.target).max()) if self.constrained.size else 0.0


@dataclass
class Model:
    """Static description of one simulation.

    name : run name used in logs and error messages.
    layout, nb : reference particles and neighbour lists.
    props : (N, NPROP) property table (:mod:`sphgag.physics.materials`), or a callable
        ``props(load) -> table`` for materials that change along a path.
    hourglass_alpha : alpha of eq. (2.14); E comes from the property table.
    hourglass : the name of the hourglass control's form (the registry :data:`sphgag.engine.forces.HOURGLASS_FORMS`):
        ``paper`` (eq. 2.14 as printed) or ``energy`` (its energy form, :mod:`sphgag.engine.forces`).
    stress_recovery : the name of the stress its evaluations are read with (the registry
        :data:`sphgag.engine.measure.RECOVERIES`; ``paper``: the kernel stress of eq. 2.10). The forces do not
        depend on it.
    cavities : pools modelled as pressurised cavities (:class:`sphgag.engine.pool_cavity.Cavity`): the swelling pressure
        their particles' rows carry acts on their linings, their particles are held and carry nothing, and every
        deformation gradient sees its own material only. The model calls each one's hooks (``loading``,
        ``hollow_rows``, ``add_forces``, ``stiffness_blocks``, ``add_stiffness``, ``rank_one``, ``lining_pressure``,
        ``members``, ``held``) and knows nothing else of it.
    boundary : optional ``boundary(load) -> (indices, positions)`` of particles with
        prescribed positions; by default the inner surface is held at
        ``load.inner_radius`` when the load prescribes one.
    points : the integration points of an interface-fitted layout (:class:`sphgag.engine.quadrature.Quadrature`:
        each side of a material interface computes its F from its own side), or None: one point per particle over
        its full stencil (eq. 2.9 as printed). With points, ``props`` has one row per point, and the hourglass
        control is its energy form over each point's stencil.
    """

    name: str
    layout: Layout
    nb: Neighbours
    props: np.ndarray | Callable[[Load], np.ndarray]
    hourglass_alpha: float
    boundary: Callable[[Load], tuple] | None = None
    hourglass: str = "paper"
    cavities: tuple = ()
    stress_recovery: str = "paper"
    lumen_load: str = "surface"  # loading.LUMEN_LOADS: how the lumen pressure becomes particle forces
    points: quadrature.Quadrature | None = None
    # derived data of the fields above (material tables, hourglass stencil): every model object, a replaced one too,
    # starts with its own, empty
    _cache: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self):
        forces.HOURGLASS_FORMS.lookup(self.hourglass)
        measure.RECOVERIES.lookup(self.stress_recovery)
        self._lumen = LUMEN_LOADS.lookup(self.lumen_load)
        self.cth = np.cos(self.layout.theta)
        self.sth = np.sin(self.layout.theta)
        if self.points is None:
            indptr, indices, blockmap, map_ptr = forces.block_pattern(self.nb.ptr, self.nb.nbr)
        else:
            fitted = dict(hourglass="energy", stress_recovery="paper", lumen_load="surface")
            wrong = [f"{k} = {getattr(self, k)}" for k, v in fitted.items() if getattr(self, k) != v]
            if wrong or self.cavities:
                raise ValueError(
                    f"[{self.name}] interface-fitted points need the energy hourglass form, the paper's stress "
                    f"reading, the surface lumen load and no cavity pool; got {', '.join(wrong) or 'cavities'}"
                )
            pts = self.points
            self.cth_points, self.sth_points = self.cth[pts.owner], self.sth[pts.owner]
            indptr, indices, blockmap, map_ptr = forces.block_pattern(pts.ptr, pts.particle, pts.owner)
        self.block_indptr, self.block_indices = indptr, indices
        self.blockmap, self.map_ptr = blockmap, map_ptr
        n_ext = self.n + self.nb.ghost_owner.size
        self._xe, self._fe = np.empty((n_ext, 2)), np.empty((n_ext, 2))
        self.block_diagonal = np.array([self.block_index(i, i) for i in range(self.n)], dtype=np.int64)
        self.pressure_blocks = pressure_stiffness_blocks(self.block_index, self.layout.inner_surface)
        self.cavity_blocks = [c.stiffness_blocks(self.block_index) for c in self.cavities]

    @property
    def n(self) -> int:
        return self.layout.n

    @property
    def stencil(self):
        """The stencils the stresses are integrated over: the particles' (:attr:`nb`) or the integration points'
        (:attr:`points`); both give ``ptr``, ``nbr``, ``mirror``, ``R``, ``w``, ``a``, ``s`` per stencil."""
        return self.nb if self.points is None else self.points

    # -- material -----------------------------------------------------------
    def material(self, load: Load):
        """Property table, hourglass coefficients (eq. 2.14) and packed pair data for ``load``, cached.

        The hourglass coefficient of a pair is scaled by its stencil weight
        (zero across a GAG/tissue interface, :func:`kernel.hourglass_gradients`). Under the ``energy`` form the
        coefficients returned (those of eq. 2.14's pair forces) are zero: its forces are :meth:`hourglass_forces`.
        """
        key = (load.material if callable(self.props) else None, self.hourglass_alpha)
        if "props" not in self._cache or self._cache["key"] != key:
            props = np.ascontiguousarray(self.props(load) if callable(self.props) else self.props)
            loadings = [c.loading(props, self.name) for c in self.cavities]
            if self.cavities:
                props = props.copy()
                for c in self.cavities:
                    c.hollow_rows(props)
            self._cache.update(key=key, props=props, cavity_loadings=loadings)
            self._stencil(props)
        return self._cache["props"], self._cache["hgc"], self._cache["pairs"]

    #: what :meth:`_stencil` caches (a function of the hourglass form, alpha and the stencil's columns alone)
    STENCIL = ("nb_elastic", "stencil_of", "hgc", "pairs", "hg", "hg_stiffness", "hg_matrix")

    def _stencil(self, props) -> None:
        """Hourglass coefficients, hourglass stencil and packed pair data of ``props``: rebuilt only where what they
        read (alpha, each particle's hourglass modulus and tissue fraction) changed, not for a new swelling pressure
        (the unknown of volume control, a new value every iteration)."""
        cols = props[:, [materials.HG_E, materials.TISSUE]]
        old = self._cache.get("stencil_of")
        if old is not None and old[0] == (self.hourglass, self.hourglass_alpha) and np.array_equal(old[1], cols):
            return
        st = self.stencil
        V = self.layout.volume if self.points is None else self.points.volume
        hgc = np.empty(st.n_entries)
        forces.hourglass_coefficients(V, st.ptr, st.nbr, st.R, st.w, props, self.hourglass_alpha, hgc)
        if self.points is None:
            beta, ah, sh = kernel.hourglass_gradients(self.nb, V, props[:, materials.TISSUE])
            hgc *= beta
        else:  # each point's stencil is its own side's: no pair crosses an interface
            ah, sh = st.a, st.s
        nb_elastic = self.nb
        if self.cavities:  # a free surface at every cavity: each material's own stencil for F too
            nb_elastic = replace(self.nb, a=ah, s=sh)
        hgc, stiffness = forces.HOURGLASS_FORMS[self.hourglass].contribute(self, ah, sh, hgc)
        pairs = forces.PairData.pack(nb_elastic, V, hgc, ah) if self.points is None else None
        self._cache.update(
            nb_elastic=nb_elastic,
            stencil_of=((self.hourglass, self.hourglass_alpha), cols),
            hgc=hgc,
            pairs=pairs,
            hg=(ah, sh),
            hg_stiffness=stiffness,
            hg_matrix=None if stiffness is None else self._sparse(stiffness),
        )

    def _sparse(self, blocks) -> sp.csr_matrix:
        """The CSR matrix of 2 x 2 ``blocks`` without their stored zeros (the energy hourglass form's blocks are
        diagonal: half the entries, and the same products, in the same order, as with them)."""
        K = self.block_matrix(blocks).tocsr()
        K.eliminate_zeros()
        return K

    def hourglass_forces(self, x: np.ndarray, load: Load) -> np.ndarray | None:
        """``-K (x - X)``: the forces of the ``energy`` hourglass form (:mod:`sphgag.engine.forces`); None under
        eq. (2.14), whose forces are part of the elastic kernel's."""
        self.material(load)
        K = self._cache["hg_matrix"]
        if K is None:
            return None
        return -(K @ (x - self.layout.X).ravel()).reshape(-1, 2)

    def hourglass_matrix(self, load: Load) -> sp.csr_matrix | None:
        """``K``, the stiffness of the ``energy`` hourglass form for ``load`` (:mod:`sphgag.engine.forces`; its
        forces are ``-K (x - X)``, its energy ``1/2 u K u``), None under eq. (2.14)."""
        self.material(load)
        return self._cache["hg_matrix"]

    def hourglass_stencil(self, load: Load):
        """``(ah, sh)``: the hourglass stencil's corrected gradients for ``load`` (see :meth:`material`)."""
        self.material(load)
        return self._cache["hg"]

    def set_props(self, props) -> None:
        """Replace the property table (a copy is kept: edit tables through this method, not in place). The hourglass
        stencil is kept: :meth:`material` rebuilds it only if the columns it reads changed (:meth:`_stencil`)."""
        self.props = props if callable(props) else np.array(props, dtype=float)
        stencil = {k: self._cache[k] for k in self.STENCIL if k in self._cache}
        self._cache.clear()
        self._cache.update(stencil)

    # -- boundary conditions --------------------------------------------------
    def constraints(self, load: Load):
        """``(indices, positions)`` of the prescribed particles: the boundary's (by default the inner surface under
        a prescribed radius) and the particles of every cavity, held."""
        if self.boundary is not None:
            idx, pos = self.boundary(load)
        elif load.inner_radius is None:
            idx, pos = np.empty(0, dtype=np.int64), np.empty((0, 2))
        else:
            idx = self.layout.inner_surface
            pos = prescribed_inner_positions(self.layout.X[idx], load.inner_radius)
        if not self.cavities:
            return idx, pos
        idx = np.concatenate([idx] + [c.members for c in self.cavities])
        return idx, np.vstack([pos] + [c.held for c in self.cavities])

    # -- evaluation -----------------------------------------------------------
    def evaluate(self, x: np.ndarray, load: Load, extra_stress: np.ndarray | None = None) -> Evaluation:
        """Forces and stresses at positions ``x`` under ``load`` (``extra_stress``: (N, 4) added to P)."""
        n = self.n
        FP = np.empty((n, 12))
        f = np.empty((n, 2))
        props, hgc, pairs = self.material(load)
        FPq = None
        if self.points is None:
            extra = forces.NO_EXTRA_STRESS if extra_stress is None else extra_stress
            min_det = forces.evaluate_forces(
                x, pairs, load.axial_stretch, self.cth, self.sth, props, self._xe, self._fe, FP, f, extra
            )
        else:
            if extra_stress is not None:
                raise ValueError(f"[{self.name}] no extra stress on interface-fitted points")
            FPq = np.empty((self.points.n_points, 8))
            min_det = quadrature.forces_and_stresses(
                x, self.points, load.axial_stretch, self.cth_points, self.sth_points, props, FPq, f
            )
            FP[:, :8] = FPq[self.points.first]
            FP[:, 8:] = FP[:, :4]
        hg = self.hourglass_forces(x, load)
        if hg is not None:
            f += hg
        F, P = FP[:, :4].reshape(n, 2, 2), FP[:, 4:8].reshape(n, 2, 2)
        Fh = FP[:, 8:].reshape(n, 2, 2)
        p = load.pressure_kPa or 0.0
        f_ext = self._lumen.forces(self, x, pairs, load.axial_stretch, p)
        for c, loading in zip(self.cavities, self._cache["cavity_loadings"]):
            c.add_forces(f_ext, x, loading, load.axial_stretch)
        cons, target = self.constraints(load)
        return Evaluation(
            x=x,
            load=load,
            F=F,
            P=P,
            f_int=f,
            f_ext=f_ext,
            min_det=float(min_det),
            constrained=cons,
            target=target,
            F_hourglass=Fh,
            FP_points=FPq,
            recovery=measure.RECOVERIES[self.stress_recovery].bind(self),
        )

    def jacobian(self, ev: Evaluation) -> np.ndarray:
        """``d(f_int + f_ext)/dx`` (exact) as the 2 x 2 blocks of the pattern :meth:`block_matrix` uses."""
        nb, lay, load = self.nb, self.layout, ev.load
        props, hgc, _ = self.material(load)
        ah, sh = self.hourglass_stencil(load)
        elastic = self._cache["nb_elastic"]
        data = np.zeros((self.block_indices.size, 2, 2))
        if self.points is not None:
            self._point_jacobian(ev, props, data)
        else:
            forces.jacobian_blocks(
                ev.x,
                lay.volume,
                nb.ptr,
                nb.nbr,
                nb.mirror,
                elastic.a,
                elastic.s,
                ah,
                sh,
                nb.R,
                hgc,
                ev.F,
                ev.F_hourglass,
                load.axial_stretch,
                self.cth,
                self.sth,
                props,
                self.blockmap,
                self.map_ptr,
                data,
            )
        if self._cache["hg_stiffness"] is not None:
            data -= self._cache["hg_stiffness"]
        for c, blocks, loading in zip(self.cavities, self.cavity_blocks, self._cache["cavity_loadings"]):
            c.add_stiffness(data, blocks, ev.x, loading, load.axial_stretch)
        self._lumen.add_stiffness(self, data, ev, load.pressure_kPa or 0.0)
        return data

    def _point_jacobian(self, ev: Evaluation, props, data) -> None:
        """The elastic part of the Jacobian of a fitted model, ``-sum_q V_q B_q^T A_q B_q`` over its integration
        points (:func:`sphgag.engine.forces.jacobian_blocks` on the points' stencils, no pair forces of eq. 2.14)."""
        pts, FPq = self.points, ev.FP_points
        Fq = np.ascontiguousarray(FPq[:, :4]).reshape(-1, 2, 2)
        stencil = (pts.ptr, pts.particle, pts.mirror, pts.a, pts.s, pts.a, pts.s, pts.R)
        frame = (ev.load.axial_stretch, self.cth_points, self.sth_points, props, self.blockmap, self.map_ptr)
        forces.jacobian_blocks(ev.x, pts.volume, *stencil, np.zeros(pts.n_entries), Fq, Fq, *frame, data)

    def lining_pressures(self, ev: Evaluation) -> list[float]:
        """The pressure [kPa] on each cavity's lining at ``ev``: the normal Cauchy traction the prescribed Pi and the
        contents exert, its :meth:`sphgag.engine.pool_cavity.Cavity.lining_pressure` (per reference length) over the
        axial stretch (a hole's: Pi)."""
        self.material(ev.load)
        lz = ev.load.axial_stretch
        pairs = zip(self.cavities, self._cache["cavity_loadings"])
        return [c.lining_pressure(ev.x, loading, lz) / lz for c, loading in pairs]

    def rank_one_terms(self, ev: Evaluation) -> list[tuple[float, np.ndarray]]:
        """The Jacobian's dense rank-one parts, ``(c, g)`` with ``d(f_int + f_ext)/dx += c g g^T`` (``g`` flat over
        the dofs): each cavity's contents (:meth:`sphgag.engine.pool_cavity.Cavity.rank_one`). The solver applies them
        by Sherman-Morrison (:func:`sphgag.engine.solver.factorise`)."""
        self.material(ev.load)
        pairs = zip(self.cavities, self._cache["cavity_loadings"])
        return [c.rank_one(ev.x, loading, ev.load.axial_stretch) for c, loading in pairs]

    def block_index(self, p: int, q: int) -> int:
        lo, hi = self.block_indptr[p], self.block_indptr[p + 1]
        k = lo + np.searchsorted(self.block_indices[lo:hi], q)
        if k >= hi or self.block_indices[k] != q:
            raise KeyError(f"no Jacobian block ({p}, {q})")
        return int(k)

    def row_blocks(self, rows) -> np.ndarray:
        """Indices of all blocks in the given block rows."""
        return np.concatenate([np.arange(self.block_indptr[r], self.block_indptr[r + 1]) for r in rows])

    def block_matrix(self, data) -> sp.bsr_matrix:
        n2 = 2 * self.n
        return sp.bsr_matrix((data, self.block_indices, self.block_indptr), shape=(n2, n2))

    @cached_property
    def band(self) -> tuple[int, int, np.ndarray]:
        """``(kl, ku, index)``: lower and upper bandwidth of the Jacobian (in dofs, fixed by the neighbour lists)
        and the position of every block entry ``data[b, c, d]`` in LAPACK's band storage
        ``ab[kl + ku + row - col, col]`` (shape ``(2 kl + ku + 1, 2 N)``), counted in column-major order: the
        order LAPACK reads it in, so that the matrix is scattered straight into the array it factorises (no copy);
        computed once."""
        rows = np.repeat(np.arange(self.n), np.diff(self.block_indptr))
        r = 2 * rows[:, None, None] + np.arange(2)[None, :, None] + np.zeros(2, dtype=np.int64)[None, None, :]
        c = (
            2 * self.block_indices[:, None, None]
            + np.arange(2)[None, None, :]
            + np.zeros(2, dtype=np.int64)[None, :, None]
        )
        kl, ku = int((r - c).max()), int((c - r).max())
        return kl, ku, (c * (2 * kl + ku + 1) + kl + ku + r - c).ravel()
