"""Large-strain swelling of a pool: the engine against the exact circular pool (and the finite-element references).

The pools of figure 4 swell many-fold under the paper's prescribed Donnan pressure (eqs. 2.25-2.27), far beyond
the linear regime of the Inglis/Lamé verification (:mod:`sphgag.studies.inclusion`). This verifies the engine where
the exact answer is known at any strain (and, in :func:`sector_study`, where a finite-element solution of the
same problem is the reference, :mod:`sphgag.studies.fe_swelling`): a circular GAG pool of radius ``A`` bonded in a
matrix annulus ``A < R < B`` (the elastin law of eq. 2.21 without pre-stretch or fibres), plane strain, the outer
surface free, swollen by a prescribed ``Pi`` to pool volume ratios ``J`` of 4 to 25 and more
(:func:`sphgag.physics.cavity.circular_pool`: the exact radially symmetric solution of the same laws).

**Layout**: the particles of :func:`sphgag.studies.inclusion.ellipse_layout` with ``a = b = A`` (rings of width
about ``dx``; the interface is a cell boundary) and ``extent = B - A``; mirror planes on both axes, no prescribed
particle. **Measures** (each at a converged state with its residual):

* ``volume_ratio``: the pool's area over its reference area, ``sum_pool V_i J_i / sum_pool V_i``, as the figure-4
  runs measure it (:func:`sphgag.studies.pool_swelling.swell_pool`);
* ``lining_radius_um``: the mean current radius of the first matrix ring (the pool's lining) against the exact
  ``r(R)`` at its reference radius;
* ``hoop_error``: the largest error of the matrix particles' hoop stress (eq. 2.10, current polar frame) against
  the exact field at their reference radius, over the particles one kernel support or more from the interface (the
  stencils that straddle it average across the kink of the exact field), relative to the exact interface hoop stress;
* ``lining_hoop_kPa``: the hoop stress at the hole, ``sigma_tt(A+)``: the ring means of the first
  :data:`sphgag.studies.inclusion.TIP_PARTICLES` matrix rings fitted by ``c0 + c1 q + c2 q^2``, ``q = A/R``, at
  ``R = A`` (:func:`sphgag.studies.inclusion.tip_fit`, the Lamé form; a particle's own stress near the free
  surface carries the truncated stencil's error), against the exact ``sigma_tt(A+)``;
* ``lining_hoop_traction_kPa``: the hoop stress at the hole recovered from its traction (a cavity's lining only,
  :func:`traction_hoop`);
* ``ring_crossing_um``: how far the pool's particles reach outside the lining (:func:`ring_crossing`; the paper's
  particles only);
* ``pool_jacobian_spread``: the largest over the smallest volume ratio ``J_i`` of the pool's particles (the paper's
  particles only; the exact pool's is 1, uniform): how far the contents are from the uniform state (a law that
  loses ellipticity, docs/physics.md "GAG bulk term (a deviation)", lets them take a non-uniform one);
* ``outer_radius_um``: the mean current radius of the outer ring against the exact ``r`` there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import geometry, kernel, measure, pool_cavity, solver
from ..engine.measure import normal_stress_state
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import FANS_OUT, Options, role
from ..physics import cavity
from . import artery, inclusion
from .pool_swelling import POOL_MODELS, pool_measurements


def two_rings_problems(where: str, radius: float, spacings) -> list[str]:
    """The spacings ``spacings`` (the key ``where.dx_um``) small enough to put two rings of particles in a hole or pool
    of radius ``radius`` (``where.radius_um``)."""
    return [
        f"{where}.dx_um[{k}] = {dx:g} must be at most half of {where}.radius_um = {radius:g}"
        for k, dx in enumerate(spacings)
        if dx > 0.5 * radius
    ]


@dataclass(frozen=True)
class CircularPoolVerification(Options):
    """The ``verification.circular_pool`` configuration: a circular pool of radius A (``radius_um``) in a free elastin
    annulus of outer radius B (``outer_radius_um``) at the volume ratios ``volume_ratios`` (each at the prescribed
    Pi that gives it exactly, :func:`sphgag.physics.cavity.circular_pool`), the spacings ``dx_um``, in ``steps``
    pressure increments, for each of ``pool_models``."""

    radius_um: float
    outer_radius_um: float
    volume_ratios: tuple
    dx_um: tuple
    steps: int
    pool_models: tuple = role(FANS_OUT)

    @classmethod
    def problems(cls, config) -> list[str]:
        """The annulus at least twice the pool's radius, and particles small enough to put two rings in the pool."""
        vc = config.get("verification", {}).get("circular_pool", {})
        problems = []
        where = "verification.circular_pool"
        A, B = vc.get("radius_um", 0.0), vc.get("outer_radius_um", 0.0)
        if B < 2.0 * A:
            problems.append(f"{where}.outer_radius_um = {B:g} must be at least twice {where}.radius_um = {A:g}")
        return problems + two_rings_problems(where, A, vc.get("dx_um", []))


def swell_from_rest(model, pressures, steps: int, numerics: Numerics) -> tuple[dict, str]:
    """``({Pi: converged state}, end)`` on one path from rest in ``steps`` equal increments up to the largest of
    ``pressures`` [kPa] (with the requested pressures among them): the states reached, and ``complete`` or why the
    path ended (no state beyond its last equilibrium is returned)."""
    ramp = np.linspace(0.0, max(pressures), int(steps) + 1)[1:]
    loads = sorted(set(ramp.tolist()) | {float(p) for p in pressures})
    reached = {}
    try:
        numerics.solver(model).follow_path(
            model.layout.X,
            inclusion.pressure_load(0.0),
            [inclusion.pressure_load(p) for p in loads],
            run=model.name,
            on_state=lambda st: reached.update({st.load.material_value("swelling_pressure"): st}),
        )
    except solver.SimulationError as exc:
        return reached, str(exc)
    return reached, "complete"


def solids(mat: inclusion.Materials) -> tuple[cavity.Solid, cavity.Solid]:
    """The matrix and the pool's contents of ``mat`` as the exact solution's solids
    (:class:`sphgag.physics.cavity.Solid`)."""
    return cavity.Solid(mat.mu, mat.lam), cavity.Solid(mat.mu_gag, mat.lam_gag, volumetric=mat.volumetric)


def circle_model(A: float, B: float, dx: float, mat: inclusion.Materials, numerics: Numerics, pool_model: str):
    """The quarter annulus with its pool on offset-circle rings, mirror planes on both axes, the outer ring free;
    ``pool_model``: a name of :data:`sphgag.studies.pool_swelling.POOL_MODELS` (``particles``, the paper's GAG
    particles, or ``cavity``, :mod:`sphgag.engine.pool_cavity`), which holds the pool (:meth:`PoolModel.around`)."""
    pool = POOL_MODELS.lookup(pool_model)
    name = f"circular_{pool.noun}_dx{dx:g}"
    model = inclusion.inclusion_model(A, A, dx, B - A, mat, numerics, name=name, free=True)
    return pool.around(model, np.flatnonzero(model.layout.inclusion), mirrored=True)


def volume_ratio_of(model, ev, members: np.ndarray) -> float:
    """The pool's area over its reference area: ``sum_pool V_i J_i / sum_pool V_i`` (the paper's particles) or
    the area its lining encloses (a cavity, :meth:`sphgag.engine.pool_cavity.Cavity.volume_ratio`)."""
    if model.cavities:
        return model.cavities[0].volume_ratio(ev.x)
    V = model.layout.volume[members]
    return float(np.sum(V * measure.cauchy(ev)[1][members]) / V.sum())


def measure_circle(model, state: solver.State, exact: cavity.CircularPool, h: float) -> dict:
    """The measures of the module docstring at one converged state (``h``: the kernel support)."""
    lay = model.layout
    ev = state.evaluation
    pool = lay.inclusion
    volume = volume_ratio_of(model, ev, np.flatnonzero(pool))
    R0 = np.hypot(*lay.X.T)
    r = np.hypot(*state.x.T)
    lining = lay.ring_members(lay.first_matrix_ring)
    lining_exact = float(exact.field(np.array([R0[lining].mean()]))["r"][0])
    far = ~pool & (R0 >= lay.a + h)
    _, s_tt, _, J = measure.cauchy_polar(ev)
    ref = exact.field(R0[far])["sigma_tt"]
    edge = lay.ring_members(lay.ring_offset.size - 1)
    rings = range(lay.first_matrix_ring, lay.first_matrix_ring + inclusion.TIP_PARTICLES)
    ring_R = np.array([R0[lay.ring_members(k)].mean() for k in rings])
    ring_hoop = np.array([s_tt[lay.ring_members(k)].mean() for k in rings])
    lining_hoop = inclusion.tip_fit(ring_R - exact.A, ring_hoop, exact.A)
    recovered = traction_hoop(model, ev, exact.A)
    return dict(
        volume_ratio=volume,
        volume_ratio_exact=exact.volume_ratio,
        volume_error=volume / exact.volume_ratio - 1.0,
        lining_radius_um=float(r[lining].mean()),
        lining_radius_exact_um=lining_exact,
        lining_error=float(r[lining].mean()) / lining_exact - 1.0,
        hoop_error=float(np.abs(s_tt[far] - ref).max() / abs(exact.interface_hoop_kPa)),
        interface_hoop_exact_kPa=exact.interface_hoop_kPa,
        lining_hoop_kPa=lining_hoop,
        lining_hoop_exact_kPa=exact.interface_hoop_kPa,
        lining_hoop_error=lining_hoop / exact.interface_hoop_kPa - 1.0,
        lining_hoop_traction_kPa=recovered,
        lining_hoop_traction_error=recovered / exact.interface_hoop_kPa - 1.0,
        ring_crossing_um=np.nan if model.cavities else ring_crossing(state.x, np.flatnonzero(pool), lining),
        pool_jacobian_spread=np.nan if model.cavities else float(J[pool].max() / J[pool].min()),
        outer_radius_um=float(r[edge].mean()),
        outer_radius_exact_um=float(exact.field(np.array([R0[edge].mean()]))["r"][0]),
        residual=state.convergence.residual,
        particles=model.n,
    )


def traction_hoop(model, ev, A: float) -> float:
    """The hoop stress [kPa] at the hole's surface ``R = A`` recovered from its traction (as the wall's surfaces,
    :class:`sphgag.engine.measure.SurfaceTraction`): the normal stress is the pressure on the lining
    (:meth:`sphgag.engine.model.Model.lining_pressures`), the hoop stretch that of the first two matrix rings (each
    ring's mean current radius over its reference one) extrapolated linearly to ``R = A``, the axial stretch the
    load's, and the radial stretch solves the normal-stress condition of the lining's material
    (:func:`sphgag.engine.measure.normal_stress_state`). Second order in the spacing (docs/physics.md). NaN for a
    pool of particles: its lining's traction is the contents' own stress, not a known load."""
    if not model.cavities:
        return np.nan
    lay = model.layout
    rings = [lay.ring_members(k) for k in (lay.first_matrix_ring, lay.first_matrix_ring + 1)]
    R = np.array([np.hypot(*lay.X[m].T).mean() for m in rings])
    stretch = np.array([np.hypot(*ev.x[m].T).mean() for m in rings]) / R
    lt = stretch[0] + (A - R[0]) * (stretch[1] - stretch[0]) / (R[1] - R[0])
    srr, stt, J = np.empty(1), np.empty(1), np.empty(1)
    props = model.material(ev.load)[0]
    pressure = np.array([-model.lining_pressures(ev)[0]])
    normal_stress_state(props, rings[0][:1], np.array([lt]), ev.load.axial_stretch, pressure, srr, stt, J)
    return float(stt[0])


def ring_crossing(x: np.ndarray, pool: np.ndarray, lining: np.ndarray) -> float:
    """How far [um] the pool's particles ``pool`` reach outside the pool's lining ``lining`` (the first matrix
    ring), each against the lining's current radius at its own polar angle (interpolated between the lining's
    particles): the largest ``r_i - r_lining(theta_i)``. Positive: a GAG particle has passed the lining, which the
    exact solution never allows (the pool's rings stay inside, in order)."""
    r, theta = np.hypot(*x.T), np.arctan2(x[:, 1], x[:, 0])
    order = lining[np.argsort(theta[lining])]
    return float(np.max(r[pool] - np.interp(theta[pool], theta[order], r[order])))


def circle_study(
    vc: dict, matrix: dict, gag: dict, numerics: Numerics, pool_model: str = "particles", log=None
) -> pd.DataFrame:
    """The circular pool at every spacing of ``vc['dx_um']`` and volume ratio of ``vc['volume_ratios']``.

    ``vc``: ``radius_um`` (A), ``outer_radius_um`` (B), ``dx_um``, ``volume_ratios``, ``steps`` (pressure
    increments from rest to the largest); ``matrix``, ``gag``: as the pool verification's
    (:meth:`sphgag.studies.inclusion.Materials.of`; the GAG's volumetric term of ``gag`` is kept, as in the
    artery).
    One row per (spacing, volume ratio): the prescribed pressure that gives that exact volume ratio, the engine's
    measures and the exact ones, and ``path_end`` (``complete``, or why the spacing's path ended: its rows beyond
    the last equilibrium carry no measures).
    """
    A, B = float(vc["radius_um"]), float(vc["outer_radius_um"])
    mat = inclusion.Materials.of(matrix, gag, bulk=True)
    m_solid, g_solid = solids(mat)
    targets = sorted(float(j) for j in vc["volume_ratios"])
    pressures = [cavity.pressure_for_volume_ratio(j, A, B, m_solid, g_solid) for j in targets]
    rows = []
    for dx in vc["dx_um"]:
        model = circle_model(A, B, float(dx), mat, numerics, pool_model)
        h = numerics.kernel_support_factor * float(dx)
        at, end = swell_from_rest(model, pressures, vc["steps"], numerics)
        if end != "complete" and log is not None:
            log.warning("[%s] the path ends before the last pressure: %s", model.name, end)
        for j, p in zip(targets, pressures):
            row = dict(
                pool_model=pool_model,
                dx_um=float(dx),
                radius_um=A,
                outer_radius_um=B,
                target_volume_ratio=j,
                pressure_kPa=p,
                path_end=end,
            )
            if p not in at:  # beyond the path's last equilibrium: no state, no numbers
                rows.append(row)
                continue
            row.update(measure_circle(model, at[p], cavity.circular_pool(A, B, m_solid, g_solid, p), h))
            rows.append(row)
            if log is not None:
                log.info(
                    "[%s] Pi %.3f kPa: pool volume ratio %.3f (exact %.3f, %+.2f %%), lining radius %+.2f %%, "
                    "hoop error %.2f %% of the interface hoop stress, residual %.1e",
                    model.name,
                    p,
                    row["volume_ratio"],
                    j,
                    100 * row["volume_error"],
                    100 * row["lining_error"],
                    100 * row["hoop_error"],
                    row["residual"],
                )
    return pd.DataFrame(rows)


def sector_model(
    walls, pool: geometry.Sector, dx: float, mat: inclusion.Materials, numerics: Numerics, pool_model, graded=None
):
    """The paper's sector pool (figure 4) in a quarter annulus of the matrix law alone: ``walls`` = (inner radius,
    media/adventitia border, outer radius) [um], the pool's edges cell boundaries (the layout graded around it by
    ``graded``, :mod:`sphgag.engine.geometry`), mirror planes at 0 and 90 deg, inner and outer surfaces free;
    ``pool_model`` as :func:`circle_model`."""
    r_in, r_media, r_out = (float(r) for r in walls)
    edges = (pool.centre_radius - 0.5 * pool.radial_extent, pool.centre_radius + 0.5 * pool.radial_extent)
    lay = geometry.quarter_annulus(
        (r_in, *edges, r_media, r_out),
        dx,
        layer_names=("media", "media", "media", "adventitia"),
        pool_layers=("media",),
        columns=geometry.columns(geometry.Field((pool,), dx, geometry.Grading.of(graded or {}))),
    )
    members = pool.members(lay, layer=lay.pool_layers)
    nb = kernel.for_layout(lay, numerics.kernel_support_factor)
    material = inclusion.InclusionMaterial(lay, mat, members)
    model = Model(f"sector_pool_{pool_model}_dx{dx:g}", lay, nb, material, **numerics.model_options())
    return POOL_MODELS.lookup(pool_model).around(model, members), members


def sector_study(
    vs: dict, matrix: dict, gag: dict, numerics: Numerics, pool_model: str, log=None, graded=None
) -> pd.DataFrame:
    """The sector pool in the matrix at every spacing of ``vs['dx_um']`` and pressure of ``vs['pressures_kPa']``
    (``vs``: ``walls_um``, ``pool`` (a figure-4 case), ``probe_length_um``, ``steps``), the layout graded by
    ``graded``: figure 4's measures (:func:`sphgag.studies.pool_swelling.pool_measurements`), the pool's volume ratio
    and the area its lining encloses (``lining_volume_ratio``, :class:`sphgag.engine.pool_cavity.Cavity`), to compare
    with :func:`sphgag.studies.fe_swelling.sector_pool` on the same geometry and laws."""
    mat = inclusion.Materials.of(matrix, gag, bulk=True)
    pool = artery.pool_sector(vs["pool"])
    pressures = sorted(float(p) for p in vs["pressures_kPa"])
    rows = []
    for dx in vs["dx_um"]:
        model, members = sector_model(vs["walls_um"], pool, float(dx), mat, numerics, pool_model, graded)
        lining = pool_cavity.Cavity.around(model.layout, members, model.layout.X)
        at, end = swell_from_rest(model, pressures, vs["steps"], numerics)
        if end != "complete" and log is not None:
            log.warning("[%s] the path ends before the last pressure: %s", model.name, end)
        for p in filter(at.__contains__, pressures):
            ev = at[p].evaluation
            row = dict(pool_model=pool_model, dx_um=float(dx), pressure_kPa=p, particles=model.n)
            row.update(pool_measurements(model, ev, pool, members, float(vs["probe_length_um"])))
            row.update(
                pool_volume_ratio=volume_ratio_of(model, ev, members),
                lining_volume_ratio=lining.volume_ratio(ev.x),
                residual=at[p].convergence.residual,
            )
            rows.append(row)
            if log is not None:
                log.info(
                    "[%s] Pi %.1f kPa: pool volume ratio %.3f, tip radial %.2f kPa, top hoop %.2f kPa",
                    model.name,
                    p,
                    row["pool_volume_ratio"],
                    row["tip_radial_stress_kPa"],
                    row["top_circ_stress_kPa"],
                )
    return pd.DataFrame(rows)
