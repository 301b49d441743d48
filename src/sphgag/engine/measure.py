"""Measurements on converged states: diameters, Cauchy stresses in the current polar frame, profiles.

Stresses are reported as Cauchy stress ``sigma = P F^T / J`` (eq. 2.10) in the
local (r, theta) frame of the *current* configuration (the angle of the
particle's current position).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .loading import lumen_area_gradient
from .model import Evaluation, Model


def cauchy(ev: Evaluation):
    """``(sigma, J)``: the in-plane Cauchy stress of every particle, ``(n, 2, 2)``, as the evaluation's stress
    recovery reads it (:mod:`sphgag.engine.recovery`; the paper's: ``sigma = P F^T / J``, eq. 2.10), and
    ``J = det F lambda_z``."""
    return ev.cauchy()


def cauchy_polar(ev: Evaluation, kernel: bool = False):
    """``(sigma_rr, sigma_tt, sigma_rt, J)`` of every particle in its current polar frame, as recovered
    (:func:`cauchy`), or with ``kernel`` the particle's own kernel stress (eq. 2.10,
    :meth:`sphgag.engine.model.Evaluation.kernel_cauchy`) whatever the recovery."""
    sig, J = ev.kernel_cauchy() if kernel else cauchy(ev)
    x = ev.x
    phi = np.arctan2(x[:, 1], x[:, 0])
    c, s = np.cos(phi), np.sin(phi)
    srr = c * c * sig[:, 0, 0] + s * s * sig[:, 1, 1] + c * s * (sig[:, 0, 1] + sig[:, 1, 0])
    stt = s * s * sig[:, 0, 0] + c * c * sig[:, 1, 1] - c * s * (sig[:, 0, 1] + sig[:, 1, 0])
    srt = c * s * (sig[:, 1, 1] - sig[:, 0, 0]) + c * c * sig[:, 0, 1] - s * s * sig[:, 1, 0]
    return srr, stt, srt, J


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
