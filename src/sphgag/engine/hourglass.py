"""The hourglass control of a run (``numerics.hourglass``): eq. (2.14) as printed, or its energy form.

TLSPH's deformation gradient (eq. 2.9) does not see zero-energy particle
modes, so both forms penalise the part of a pair's current separation
``r_ij = x_j - x_i`` that the particle's deformation gradient does not predict,
``d_ij = F~_i R_ij - r_ij``, with the same pair coefficient
``c_ij = alpha E_ij V_i V_j xi_ij / (2 |R_ij|^2)`` (eq. 2.14;
:func:`sphgag.engine.forces.hourglass_coefficients`) and the same stencil
``F~_i`` (:func:`sphgag.engine.kernel.hourglass_gradients`: within each
material):

* ``paper``: eq. (2.14) as printed (Ganzenmueller's form): the pair force
  ``-c_ij (delta_i + delta_j) n_ij`` along the current pair direction, with
  ``delta_i = d_ij . n_ij``. It is not the gradient of an energy: its
  stiffness is not symmetric and, where a kernel's deformation is far from
  affine and pairs are squeezed, its geometric part (``delta (I - n n)/|r|``)
  is negative (docs/physics.md, "What fails near the artery's pools").
  Computed with the elastic forces (:mod:`sphgag.engine.forces`).
* ``energy``: the energy ``E_hg = sum_(i, j) c_ij / 2 |d_ij|^2`` over every
  neighbour entry. ``F~_i`` and ``r_ij`` are linear in the positions and
  ``d_ij`` vanishes for every affine map (the stencil is corrected), so
  ``E_hg = 1/2 u^T K u`` with ``u = x - X`` and a constant, symmetric, positive
  semi-definite ``K``: the force is ``-K u`` and the stiffness ``-K``. Its
  force along a pair is eq. (2.14)'s with ``d_ij`` in place of its projection
  on ``n_ij``, plus the reaction through ``F~`` that makes it conservative. It
  is invariant under rigid rotations (``|Q d| = |d|``).

A form is a :class:`HourglassForm` (a :class:`sphgag.registry.Variant`) of the registry :data:`HOURGLASS_FORMS`, by its
name in the configuration (``numerics.hourglass``, whose schema enumeration is the registry's) and the pipeline's
wildcard ``{form}``; the model asks it for its part of the forces and the stiffness (:meth:`HourglassForm.contribute`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ..registry import Registry, Variant


@dataclass(frozen=True)
class HourglassForm(Variant):
    """A form of the hourglass control of eq. (2.14): what it adds to a model's forces and stiffness, given the pair
    coefficients ``c_ij`` and the stencil ``F~`` the forms share. It owns the key ``numerics.hourglass`` (with
    ``numerics.hourglass_alpha``, every form's alpha). ``short``: its label in a figure's legend (its name if
    empty)."""

    name: str
    title: str
    paper: bool = False
    short: str = ""

    def contribute(self, model, ah, sh, hgc) -> tuple[np.ndarray, np.ndarray | None]:
        """``(hgc, K)``: the coefficients of eq. (2.14)'s pair forces, which the elastic kernels compute with the
        elastic forces (:mod:`sphgag.engine.forces`), and the 2 x 2 blocks of a constant stiffness ``K`` whose forces
        are ``-K (x - X)`` (None: no such part). ``model`` gives the neighbour lists and the blocks' pattern
        (:func:`sphgag.engine.forces.block_pattern`); ``ah, sh`` the stencil of ``F~``."""
        raise NotImplementedError


@dataclass(frozen=True)
class PairForm(HourglassForm):
    """Eq. (2.14) as printed: the pair forces along the current pair direction, computed with the elastic forces."""

    def contribute(self, model, ah, sh, hgc):
        return hgc, None


@dataclass(frozen=True)
class EnergyForm(HourglassForm):
    """The energy ``E_hg = sum c_ij / 2 |d_ij|^2``: a constant stiffness ``K`` (:func:`energy_stiffness_blocks`), no
    pair forces in the elastic kernels (their coefficients are zero)."""

    def contribute(self, model, ah, sh, hgc):
        nb = model.nb
        stiffness = np.zeros((model.block_indices.size, 2, 2))
        energy_stiffness_blocks(nb.ptr, nb.nbr, nb.mirror, nb.R, ah, sh, hgc, model.blockmap, model.map_ptr, stiffness)
        return np.zeros_like(hgc), stiffness


#: the registry of hourglass forms, by name (``numerics.hourglass``, wildcard ``{form}``; the paper's first)
HOURGLASS_FORMS: Registry[HourglassForm] = Registry(
    "hourglass form",
    (
        PairForm(
            "paper",
            "eq. (2.14) as printed: pair forces along the current pair direction",
            paper=True,
            short="eq. (2.14) as printed",
        ),
        EnergyForm(
            "energy",
            "the energy form of eq. (2.14): a symmetric, positive semi-definite stiffness",
            short="energy form of eq. (2.14)",
        ),
    ),
)


@njit(cache=True)
def energy_stiffness_blocks(ptr, nbr, mir, R, ah, sh, hgc, blockmap, map_ptr, data):
    """Add ``K`` of ``E_hg = sum_e c_e/2 |d_e|^2`` to the 2 x 2 blocks ``data`` (pattern of
    :func:`sphgag.engine.forces.block_pattern`).

    For entry ``e = (i, j)`` of particle i's stencil (node 0 = i, node k = entry k, mirror signs ``M``):
    ``d_e = sum_p g_p M_p x_p`` with ``g_0 = 1 - sh_i . R_e``, ``g_k = ah_k . R_e`` and ``-1`` added at
    the node of j (``r_e = M_j x_j - x_i``); each component separately, so the blocks are diagonal.
    """
    n = ptr.shape[0] - 1
    for i in range(n):
        e0 = ptr[i]
        m = ptr[i + 1] - e0 + 1
        base = map_ptr[i]
        M = np.ones((m, 2))
        for k in range(1, m):
            M[k, 0], M[k, 1] = mir[e0 + k - 1, 0], mir[e0 + k - 1, 1]
        g = np.empty(m)
        for k in range(1, m):
            e = e0 + k - 1
            c = hgc[e]
            if c == 0.0:
                continue
            g[0] = 1.0 - (sh[i, 0] * R[e, 0] + sh[i, 1] * R[e, 1])
            for p in range(1, m):
                g[p] = ah[e0 + p - 1, 0] * R[e, 0] + ah[e0 + p - 1, 1] * R[e, 1]
            g[k] -= 1.0
            for p in range(m):
                cp = c * g[p]
                for q in range(m):
                    blk = blockmap[base + p * m + q]
                    v = cp * g[q]
                    data[blk, 0, 0] += v * M[p, 0] * M[q, 0]
                    data[blk, 1, 1] += v * M[p, 1] * M[q, 1]
