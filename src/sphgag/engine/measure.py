"""Measurements on converged states: diameters, Cauchy stresses in the current polar frame, profiles; and the stress
recovery they read.

Stresses are reported as Cauchy stress (eq. 2.10, as the run's stress recovery reads it, below) in the
local (r, theta) frame of the *current* configuration (the angle of the
particle's current position).

**Stress recovery**: the Cauchy stress every measurement reads, recovered from the particles' kernel stresses.
The equilibrium is that of the particles' own stresses ``sigma_i = P_i F_i^T / J_i`` (eq. 2.10), and it is never
changed here: a recovery only changes what is *read* as the stress (the transmural profiles, the pool's probes, the
damage criterion's radial stress, the exported fields), through :meth:`sphgag.engine.model.Evaluation.cauchy`.

A recovery is a :class:`StressRecovery` (a :class:`sphgag.registry.Variant`) of the registry :data:`RECOVERIES`, by
its name in the configuration (``numerics.stress_recovery``):

* ``paper``: the kernel stress itself, eq. (2.10) at each particle.
* ``volumetric``: the kernel stress with its volumetric part recovered (:class:`VolumetricAverage`). A nearly
  incompressible material (the elastin's ``lambda/mu`` is 110-1000) turns a tiny ring-to-ring scatter of ``J`` into a
  scatter of the pressure ``lambda ln J / J`` of the size of the lumen pressure; nodal integration does not control it
  (docs/physics.md, "Stress recovery"). ``J`` is averaged over each particle's kernel neighbourhood with weights that
  reproduce linear fields (the averaged nodal pressure of Bonet & Burton 1998, in the reading only), and the terms of
  the particle's strain energy that depend on ``J`` alone are evaluated at the average; the rest of the stress is
  the particle's own.
* ``traction``: ``volumetric`` inside the wall, and at the wall's loaded surfaces the stress recovered from the
  traction (:class:`SurfaceTraction`): a surface particle's stress is a kernel average over material on one side
  only, off by up to 0.7 P at the lumen, while its normal traction is known (``-P`` at the lumen, 0 at the outer
  surface) and its tangential stretches follow from the positions (patch recovery, as finite elements recover a
  surface's stress). Its ``J`` (the material's at that state) also enters its neighbours' averages.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from numba import njit

from ..physics import materials
from ..physics.materials import pk2
from ..registry import Registry, Variant
from .kernel import spiky
from .loading import lumen_area_gradient

if TYPE_CHECKING:  # the model computes its evaluations' stress with this module's recoveries
    from .model import Evaluation, Model


def cauchy(ev: Evaluation):
    """``(sigma, J)``: the in-plane Cauchy stress of every particle, ``(n, 2, 2)``, as the evaluation's stress
    recovery reads it (:data:`RECOVERIES`; the paper's: ``sigma = P F^T / J``, eq. 2.10), and
    ``J = det F lambda_z``."""
    return ev.cauchy()


def cauchy_polar(ev: Evaluation, kernel: bool = False):
    """``(sigma_rr, sigma_tt, sigma_rt, J)`` of every particle in its current polar frame, as recovered
    (:func:`cauchy`), or with ``kernel`` the particle's own kernel stress (eq. 2.10,
    :meth:`sphgag.engine.model.Evaluation.kernel_cauchy`) whatever the recovery."""
    sig, J = ev.kernel_cauchy() if kernel else cauchy(ev)
    return (*polar(sig, ev.x), J)


def kernel_stress(F: np.ndarray, P: np.ndarray, lz: float) -> tuple[np.ndarray, np.ndarray]:
    """``(sigma, J)``: the in-plane Cauchy stress ``sigma = P F^T / J`` (eq. 2.10) of the deformation gradients ``F``
    and first Piola stresses ``P`` (n, 2, 2), with ``J = det F lambda_z``."""
    J = (F[:, 0, 0] * F[:, 1, 1] - F[:, 0, 1] * F[:, 1, 0]) * lz
    return np.einsum("nab,ncb->nac", P, F) / J[:, None, None], J


def polar(sig: np.ndarray, x: np.ndarray):
    """``(sigma_rr, sigma_tt, sigma_rt)`` of the in-plane Cauchy stresses ``sig`` (n, 2, 2) at the positions ``x`` in
    their current polar frame."""
    phi = np.arctan2(x[:, 1], x[:, 0])
    c, s = np.cos(phi), np.sin(phi)
    srr = c * c * sig[:, 0, 0] + s * s * sig[:, 1, 1] + c * s * (sig[:, 0, 1] + sig[:, 1, 0])
    stt = s * s * sig[:, 0, 0] + c * c * sig[:, 1, 1] - c * s * (sig[:, 0, 1] + sig[:, 1, 0])
    srt = c * s * (sig[:, 1, 1] - sig[:, 0, 0]) + c * c * sig[:, 0, 1] - s * s * sig[:, 1, 0]
    return srr, stt, srt


def interface_stresses(model: Model, ev: Evaluation) -> pd.DataFrame:
    """Both sides of every material interface of an interface-fitted model (:mod:`sphgag.engine.quadrature`): per ring
    of shared particles and side, the mean current radius and the mean radial and hoop Cauchy stress of the side's
    integration points (eq. 2.10 with each side's own F and material). The radial (normal) stress is continuous
    across the interface in the continuum; the two sides' difference is the discretisation's. Empty for a model
    without integration points."""
    columns = ["ring", "reference_radius_um", "radius_um", "layer", "radial_stress_kPa", "circ_stress_kPa"]
    pts = model.points
    if pts is None or not pts.shared.size:
        return pd.DataFrame(columns=columns)
    shared = np.isin(pts.owner, pts.shared)
    q = np.flatnonzero(shared)
    F = np.ascontiguousarray(ev.FP_points[q, :4]).reshape(-1, 2, 2)
    P = np.ascontiguousarray(ev.FP_points[q, 4:]).reshape(-1, 2, 2)
    x = ev.x[pts.owner[q]]
    srr, stt, _ = polar(kernel_stress(F, P, ev.load.axial_stretch)[0], x)
    lay = model.layout
    table = pd.DataFrame(
        dict(
            ring=lay.ring[pts.owner[q]],
            reference_radius_um=lay.radius[pts.owner[q]],
            radius_um=np.linalg.norm(x, axis=1),
            layer=np.asarray(lay.layer_names)[pts.layer[q]],
            radial_stress_kPa=srr,
            circ_stress_kPa=stt,
        )
    )
    return table.groupby(["ring", "layer"], sort=True).mean().reset_index()[columns]


def surface_radius(model: Model, x: np.ndarray, which: str) -> float:
    """Mean current radius of the inner or outer surface particles."""
    idx = model.layout.inner_surface if which == "inner" else model.layout.outer_surface
    return float(np.linalg.norm(x[idx], axis=1).mean())


def diameters(model: Model, x: np.ndarray) -> tuple[float, float]:
    """(inner, outer) diameter of the deformed cross-section."""
    return 2.0 * surface_radius(model, x, "inner"), 2.0 * surface_radius(model, x, "outer")


def ring_profile(model: Model, ev: Evaluation) -> pd.DataFrame:
    """Transmural profile: per ring, the mean current radius and mean Cauchy stresses.

    Rings are averaged over all their particles (the state is axisymmetric
    for the intact wall); ``circ_stress_std_kPa`` shows how uniform a ring is. The stresses are the recovered ones
    (:func:`cauchy`); ``*_kernel_kPa`` are the particles' own kernel stresses (eq. 2.10), the same under the paper's
    recovery.
    """
    lay = model.layout
    srr, stt, _, J = cauchy_polar(ev)
    krr, ktt, _, _ = cauchy_polar(ev, kernel=True)
    rad = np.linalg.norm(ev.x, axis=1)
    rows = []
    for k in range(len(lay.ring_radius)):
        m = lay.ring_members(k)
        rows.append(
            dict(
                ring=k,
                reference_radius_um=lay.ring_radius[k],
                radius_um=rad[m].mean(),
                layer=lay.layer_names[lay.layer[m[0]]],
                radial_stress_kPa=srr[m].mean(),
                circ_stress_kPa=stt[m].mean(),
                circ_stress_std_kPa=stt[m].std(),
                jacobian=J[m].mean(),
                radial_stress_kernel_kPa=krr[m].mean(),
                circ_stress_kernel_kPa=ktt[m].mean(),
            )
        )
    return pd.DataFrame(rows)


def hoop_force(profile: pd.DataFrame) -> float:
    """``int sigma_tt dr`` across the wall (trapezoid over the rings; surfaces carry rings)."""
    r = profile["radius_um"].to_numpy()
    s = profile["circ_stress_kPa"].to_numpy()
    return float(np.sum(0.5 * (s[1:] + s[:-1]) * np.diff(r)))


def carried_pressure(model: Model, ev: Evaluation) -> float:
    """Lumen pressure [kPa] the state carries: applied pressure, or read from the reactions.

    Under radius control the reactions of the inner particles balance the wall;
    their outward radial sum divided by ``lz`` times the current inner arc length is
    the pressure that would hold the wall there.
    """
    if ev.load.pressure_kPa is not None:
        return float(ev.load.pressure_kPa)
    inner = model.layout.inner_surface
    x = ev.x[inner]
    er = x / np.linalg.norm(x, axis=1)[:, None]
    # the reactions push the wall outwards; the pressure would do the same
    push = np.sum(ev.reactions * er)
    g = np.empty_like(x)
    lumen_area_gradient(ev.x, inner, g)
    return float(push / (ev.load.axial_stretch * np.sum(np.linalg.norm(g, axis=1))))


def layer_stats(profile: pd.DataFrame) -> pd.DataFrame:
    """Per layer: mean circumferential stress over its rings and how uniform it is.

    ``circ_variation`` = (max - min) / mean of the ring-mean hoop stress within
    the layer; ``circ_cv`` = standard deviation / mean.
    """
    rows = []
    for layer, g in profile.groupby("layer", sort=False):
        s = g.circ_stress_kPa
        rows.append(
            dict(
                layer=layer,
                rings=len(g),
                circ_stress_mean_kPa=s.mean(),
                circ_stress_min_kPa=s.min(),
                circ_stress_max_kPa=s.max(),
                circ_variation=(s.max() - s.min()) / s.mean(),
                circ_cv=s.std(ddof=0) / s.mean(),
            )
        )
    return pd.DataFrame(rows)


def sector_average(ev: Evaluation, layout, sector, component: str, layer: str | tuple | None) -> float:
    """Volume-weighted mean Cauchy stress component (``rr`` or ``tt``, current polar frame) in a sector, over the
    particles of ``layer`` (a name, several names, or ``None``: every layer).

    Raises ``ValueError`` if no particle of ``layer`` lies in the sector (resolution too coarse).
    """
    idx = sector.members(layout, layer=layer)
    if idx.size == 0:
        names = ", ".join([layer] if isinstance(layer, str) else layer or ())
        raise ValueError(
            f"no {names} particle in the measurement region {sector} at dx = {layout.dx} um: "
            "the region must be at least about one particle spacing in size"
        )
    srr, stt, _, _ = cauchy_polar(ev)
    values = {"rr": srr, "tt": stt}[component][idx]
    w = layout.volume[idx]
    return float(np.sum(w * values) / np.sum(w))


def pool_probes(pool, length: float) -> dict:
    """Measurement regions around a pool sector (all of length ``length`` um, fixed in physical size).

    ``tip_low``/``tip_high``: the medial material just beyond each angular end, across
    the pool's radial extent; ``top``/``bottom``: just outside the pool radially
    (outer/inner side), centred on its mid-angle, ``length`` wide in arc.
    """
    from .geometry import Sector

    R, th, t, w = pool.centre_radius, pool.centre_angle_deg, pool.radial_extent, pool.angular_extent_deg
    arc = np.rad2deg(length / R)
    return {
        "tip_low": Sector(R, th - 0.5 * w - 0.5 * arc, t, arc),
        "tip_high": Sector(R, th + 0.5 * w + 0.5 * arc, t, arc),
        "top": Sector(R + 0.5 * t + 0.5 * length, th, length, arc),
        "bottom": Sector(R - 0.5 * t - 0.5 * length, th, length, arc),
    }


def averaging_matrix(layout, length: float, members: np.ndarray | None = None, rows: np.ndarray | None = None):
    """Sparse row-stochastic matrix ``W``: ``(W v)_i`` is the volume-weighted mean of ``v`` over the particles
    whose reference positions lie within ``length / 2`` of particle ``i`` (a disc of diameter ``length``).

    ``members`` restricts the particles averaged over (e.g. the media); rows of other particles average over
    the members near them. The averaging region has a fixed physical size, so an averaged stress means the
    same at every resolution (the "averaged" onset measure of section 2.7's damage law). ``rows``: compute only
    these particles' rows (the matrix is then ``len(rows) x N``).
    """
    import scipy.sparse as sp
    from scipy.spatial import cKDTree

    if length < layout.dx:
        raise ValueError(
            f"the averaging length ({length:g} um) must be at least the particle spacing "
            f"({layout.dx:g} um): below it the average is a single particle's value"
        )
    X = layout.X
    pool = np.arange(layout.n) if members is None else np.asarray(members)
    at = np.arange(layout.n) if rows is None else np.asarray(rows, dtype=np.int64)
    pairs = cKDTree(X[at]).query_ball_tree(cKDTree(X[pool]), 0.5 * length)
    r = np.repeat(np.arange(at.size), [len(p) for p in pairs])
    cols = pool[np.concatenate([np.asarray(p, dtype=np.int64) for p in pairs])] if r.size else r
    W = sp.csr_matrix((layout.volume[cols], (r, cols)), shape=(at.size, layout.n))
    total = np.asarray(W.sum(axis=1)).ravel()
    if np.any(total == 0.0):
        raise ValueError(f"no member particle within {0.5 * length:g} um of some particles")
    return sp.diags(1.0 / total) @ W


@dataclass(frozen=True)
class StressRecovery(Variant):
    """A way to read the Cauchy stress of a converged configuration (it owns the key ``numerics.stress_recovery``)."""

    name: str
    title: str
    paper: bool = False

    def cauchy(self, model, ev) -> tuple[np.ndarray, np.ndarray]:
        """``(sigma, J)``: the in-plane Cauchy stress ``(n, 2, 2)`` of every particle of ``model`` at the evaluation
        ``ev`` (global x-y), and ``J = det F lambda_z``."""
        raise NotImplementedError

    def bind(self, model):
        """This recovery on ``model``: ``ev -> (sigma, J)`` (an evaluation's ``recovery``)."""
        return partial(self.cauchy, model)


@dataclass(frozen=True)
class KernelStress(StressRecovery):
    """The particle's own stress, eq. (2.10): ``sigma_i = P_i F_i^T / J_i`` with ``F_i`` of eq. (2.9)."""

    def cauchy(self, model, ev):
        return ev.kernel_cauchy()


@dataclass(frozen=True)
class VolumetricAverage(StressRecovery):
    """The kernel stress (eq. 2.10) with its volumetric part averaged: ``sigma_i + (U_i'(J~_i) - U_i'(J_i)) I``, where
    ``U_i'`` is the stress of the terms of the strain energy (eqs. 2.18, 2.21, 2.26-2.27) that depend on ``J`` alone
    (:func:`sphgag.physics.materials.volumetric_stress`) and ``J~_i = sum_j w_ij J_j`` the average of :func:`averaged`.
    A homogeneous deformation keeps its stress (the weights sum to one)."""

    def cauchy(self, model, ev):
        sig, J = ev.kernel_cauchy()
        return self.averaged_stress(model, model.material(ev.load)[0], sig, J), J

    @staticmethod
    def averaged_stress(model, props, sig, J):
        """``sig + (U'(J~) - U'(J)) I`` with ``J~`` the average of ``J`` (:func:`averaged`)."""
        own, mean = np.empty_like(J), np.empty_like(J)
        materials.volumetric_stress(props, J, own)
        materials.volumetric_stress(props, averaged(model, props, J), mean)
        return sig + (mean - own)[:, None, None] * np.eye(2)


def averaged(model, props, values: np.ndarray) -> np.ndarray:
    """``sum_j w_ij v_j``: ``values`` averaged over each particle's kernel neighbourhood (itself and its stencil of
    eq. 2.1, mirror images included) within its own volumetric law (the neighbours whose rows share ``LAM``, ``KAPPA``,
    its form and ``TISSUE``: a layer border or a pool's lining is not averaged across), with the kernel weights of
    eq. (2.4) corrected to reproduce linear fields (:func:`linear_average`)."""
    nb = model.nb
    law = np.ascontiguousarray(props[:, [materials.LAM, materials.KAPPA, materials.VOLUMETRIC, materials.TISSUE]])
    out = np.empty(model.n)
    linear_average(nb.ptr, nb.nbr, nb.R, nb.w, nb.hp, model.layout.volume, law, np.ascontiguousarray(values), out)
    return out


@njit(cache=True, error_model="numpy")
def linear_average(ptr, nbr, R, xi, hp, V, law, values, out):
    """``out_i = w_ii v_i + sum_j w_ij v_j`` over particle i and its neighbours j of the same ``law`` row, with the
    weights ``V_j xi_ij (alpha_i + beta_i . R_ij)`` (``xi`` of eq. 2.4, ``xi(0)`` for the particle itself) whose
    ``alpha_i, beta_i`` make them sum to one with no first moment ``sum_j w_ij R_ij``: a linear field is averaged
    exactly, beside a surface too. A particle whose moment matrix is singular (too few neighbours of its own law)
    falls back to the normalised kernel weights (constants only)."""
    n = ptr.shape[0] - 1
    for i in range(n):
        s0 = V[i] * spiky(0.0, hp[i])
        m0, m1x, m1y, mxx, mxy, myy = s0, 0.0, 0.0, 0.0, 0.0, 0.0
        v0, v1x, v1y = s0 * values[i], 0.0, 0.0  # the moments of the values
        for e in range(ptr[i], ptr[i + 1]):
            j = nbr[e]
            same = True
            for k in range(law.shape[1]):
                same = same and law[i, k] == law[j, k]
            if not same:
                continue
            c = V[j] * xi[e]
            r0, r1 = R[e, 0], R[e, 1]
            m0 += c
            m1x += c * r0
            m1y += c * r1
            mxx += c * r0 * r0
            mxy += c * r0 * r1
            myy += c * r1 * r1
            v0 += c * values[j]
            v1x += c * r0 * values[j]
            v1y += c * r1 * values[j]
        det = mxx * myy - mxy * mxy
        if det > 1e-8 * (mxx + myy) ** 2:
            # w = c (alpha + beta . R), beta = -alpha M2^-1 m1, alpha = 1 / (m0 - m1 . M2^-1 m1)
            ux = (myy * m1x - mxy * m1y) / det
            uy = (mxx * m1y - mxy * m1x) / det
            alpha = 1.0 / (m0 - (m1x * ux + m1y * uy))
            out[i] = alpha * (v0 - ux * v1x - uy * v1y)
        else:
            out[i] = v0 / m0


@dataclass(frozen=True)
class SurfaceTraction(VolumetricAverage):
    """At the wall's two surfaces (``layout.inner_surface``, ``layout.outer_surface``), the Cauchy stress from the
    known traction; inside, :class:`VolumetricAverage` (the kernel ``J`` of the surface particles enters their
    neighbours' averages: their recovered ``J`` doubles the error of the ring beside the lumen, docs/physics.md).

    A surface particle's normal stress is the traction: ``sigma_rr = -P`` at the lumen (the load's pressure, or the
    pressure a held inner surface carries, :func:`sphgag.engine.measure.carried_pressure`), ``0`` at the free outer
    surface (section 2.4.1), ``sigma_rt = 0`` at both. Its circumferential stretch ``lambda_t`` is the surface's
    (:func:`surface_stretch`), its axial stretch ``lambda_z`` the load's, and its radial stretch ``lambda_r`` solves
    the normal-stress condition ``sigma_rr(lambda_r, lambda_t, lambda_z) = t_n`` of the particle's own material
    (eqs. 2.10, 2.18-2.24 through :func:`sphgag.physics.materials.pk2`); its hoop stress is then
    ``sigma_tt = lambda_t^2 S_tt / J`` and its ``J = lambda_r lambda_t lambda_z``. The stress is the exact one of a
    surface element with those stretches: its error is the stretch's, of the displacements' order."""

    def cauchy(self, model, ev):
        lay, props, lz = model.layout, model.material(ev.load)[0], ev.load.axial_stretch
        sig, J = ev.kernel_cauchy()
        rings = ((lay.inner_surface, -carried_pressure(model, ev)), (lay.outer_surface, 0.0))
        surface = np.concatenate([ring for ring, _ in rings])
        traction = np.concatenate([np.full(ring.size, t) for ring, t in rings])
        lt = np.concatenate([surface_stretch(lay, ev.x, ring) for ring, _ in rings])
        srr, stt, Js = np.empty(surface.size), np.empty(surface.size), np.empty(surface.size)
        normal_stress_state(props, surface, lt, lz, traction, srr, stt, Js)
        sig = self.averaged_stress(model, props, sig, J)
        phi = np.arctan2(ev.x[surface, 1], ev.x[surface, 0])
        c, s = np.cos(phi), np.sin(phi)
        sig[surface, 0, 0] = c * c * srr + s * s * stt
        sig[surface, 1, 1] = s * s * srr + c * c * stt
        sig[surface, 0, 1] = sig[surface, 1, 0] = c * s * (srr - stt)
        return sig, J


def surface_stretch(layout, x: np.ndarray, surface: np.ndarray) -> np.ndarray:
    """The tangential stretch of each particle of a surface ring ``surface`` (ordered by angle): the central
    difference ``|x_(k+1) - x_(k-1)| / |X_(k+1) - X_(k-1)|`` of the positions along the ring, with the mirror images of
    its end particles beyond the symmetry planes (kernel.py: ``theta = 0`` and ``pi/2``). Second order in the
    spacing for a smooth deformation."""
    X = layout.X[surface]
    y0, x0 = np.array([1.0, -1.0]), np.array([-1.0, 1.0])  # mirrors across y = 0 and x = 0

    def chords(p):
        ext = np.vstack([p[:1] * y0, p, p[-1:] * x0])
        return np.linalg.norm(ext[2:] - ext[:-2], axis=1)

    return chords(x[surface]) / chords(X)


@njit(cache=True, error_model="numpy")
def normal_stress_state(props, rows, lt, lz, t, srr, stt, J):
    """For each particle ``rows[k]`` with circumferential stretch ``lt[k]`` and axial stretch ``lz``: the radial
    stretch ``lr`` at which its radial Cauchy stress ``lr^2 S_rr / J`` (eq. 2.10 with ``C = diag(lr^2, lt^2)`` in its
    polar frame, ``S`` of :func:`sphgag.physics.materials.pk2`) equals ``t[k]``, by bisection (the radial stress
    rises with ``lr``); ``srr``, ``stt`` and ``J`` of that state."""
    for k in range(rows.shape[0]):
        i, c_tt = rows[k], lt[k] * lt[k]
        lo, hi = 1e-3, 1e3
        for _ in range(200):
            lr = np.sqrt(lo * hi)
            s_rr = pk2(lr * lr, c_tt, 0.0, lz, props, i)[0]
            if lr * s_rr / (lt[k] * lz) > t[k]:
                hi = lr
            else:
                lo = lr
            if hi - lo < 1e-14 * hi:
                break
        lr = np.sqrt(lo * hi)
        s_rr, s_tt, _ = pk2(lr * lr, c_tt, 0.0, lz, props, i)
        J[k] = lr * lt[k] * lz
        srr[k] = lr * lr * s_rr / J[k]
        stt[k] = c_tt * s_tt / J[k]


#: the registry of stress recoveries, by name (``numerics.stress_recovery``; the paper's first)
RECOVERIES: Registry[StressRecovery] = Registry(
    "stress recovery",
    (
        KernelStress("paper", "the particle's kernel stress, eq. (2.10)", paper=True),
        VolumetricAverage("volumetric", "the kernel stress with its volumetric part averaged over the neighbourhood"),
        SurfaceTraction("traction", "volumetric inside, and at the wall's surfaces the stress of the known traction"),
    ),
)


def recovered(model, ev, name: str):
    """The evaluation ``ev`` of ``model`` read through the recovery ``name`` (a copy: the forces are shared)."""
    return replace(ev, recovery=RECOVERIES.lookup(name).bind(model), recovered=None)
