"""The pressurised annulus at large strain: the prescribed law's limit of existence, verified.

Under the paper's charge law (eq. 2.27, ``prescribed``) a pool's swelling pressure Pi does not fall as the pool
swells. A hole of reference radius ``A`` in a plane-strain neo-Hookean annulus ``A < R < B`` with a free outer
surface then has an equilibrium only below the largest pressure the annulus holds: for the incompressible law the
pressure rises monotonically to the saturation pressure ``mu ln(B/A)`` and never reaches it
(:func:`sphgag.physics.cavity.annulus_pressure_incompressible`); for the engine's compressible law (eq. 2.21
without pre-stretch or fibres) and a pool with contents of its own (eq. 2.27 with the volumetric term of
``gag.volumetric``, :mod:`sphgag.physics.volumetric`, the same in the exact solution) the curve is
:func:`sphgag.physics.cavity.pressure_for_volume_ratio`, and its largest pressure
:func:`sphgag.physics.cavity.limit_pressure` (a saturation for the hole and for a pool of particles whose contents'
stress saturates, ``convex``, at ``mu ln(B/A) + mu_GAG + kappa``; a limit point for ``log_squared`` contents, whose
bulk term adds a little pressure that falls again as they swell; none for ``hartmann_neff``'s, which hold any
pressure: the study refuses them).

**Cases** (``verification.annulus``): two pool models (:data:`ANNULUS_POOL_MODELS`, each a pool model of the engine's
registry :data:`sphgag.studies.pool_swelling.POOL_MODELS` with its contents),

* ``hole``: an empty hole, its lining loaded by the pressure (the cavity of :mod:`sphgag.engine.pool_cavity` with
  contents of zero stiffness);
* ``particles``: the paper's pool of GAG particles carrying Pi as their own stress (eq. 2.27 with the volumetric
  term),

each in annuli of ``outer_ratios`` B/A, at every spacing of ``dx_um``, swollen from rest with the pool's volume as
the control (:func:`swell_by_volume`) through ``fractions`` (below 1) of the largest pressure, every state measured
against the exact solution (:func:`sphgag.studies.swollen_pool.measure_circle`: the volume ratio, the hoop stress at
the hole, how far the pool's particles reach outside its lining). Then ``beyond`` (above 1) times the largest pressure
(:func:`beyond_limit`): the engine must report that no equilibrium exists there, or the limit point its path
reaches, never a state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import pool_volume, solver
from ..engine.numerics import Numerics
from ..options import FANS_OUT, Options, role
from ..physics import cavity
from ..registry import Registry, Variant
from . import inclusion, swollen_pool


@dataclass(frozen=True)
class AnnulusPool(Variant):
    """A pool of the annulus verification (``verification.annulus.pool_models``, column ``pool_model``): the engine's
    pool model ``engine`` (:data:`sphgag.studies.pool_swelling.POOL_MODELS`) that holds it and whether its contents are
    ``empty`` (zero stiffness: a hole, its lining loaded by the pressure)."""

    name: str
    title: str
    engine: str
    empty: bool = False
    paper: bool = False

    def materials(self, matrix: dict, gag: dict) -> inclusion.Materials:
        """The annulus' matrix around the pool and its contents (those of ``gag``, with its volumetric term, as in the
        artery; none for an empty pool)."""
        if self.empty:
            gag = dict(gag, shear_modulus_kPa=0.0, lame_lambda_kPa=0.0)
        return inclusion.Materials.of(matrix, gag, bulk=True)


#: the annulus' pool models, by name (the paper's last, as the verification lists them)
ANNULUS_POOL_MODELS: Registry[AnnulusPool] = Registry(
    "pool model of the annulus",
    (
        AnnulusPool("hole", "an empty hole, its lining loaded by the pressure", "cavity", empty=True),
        AnnulusPool("particles", "the paper's GAG particles carrying the pressure", "particles", paper=True),
    ),
)
MEASURES = {  # measure -> its exact
    "volume_ratio": "volume_ratio_exact",
    "lining_hoop_kPa": "lining_hoop_exact_kPa",
    "lining_hoop_traction_kPa": "lining_hoop_exact_kPa",
}


@dataclass(frozen=True)
class AnnulusVerification(Options):
    """The ``verification.annulus`` configuration: a hole or pool of radius A (``radius_um``) in free elastin annuli
    of the ``outer_ratios`` B/A, loaded to the ``fractions`` of the prescribed law's largest pressure and to
    ``beyond`` times it, at the spacings ``dx_um``, the volume-controlled path stopped at ``max_volume_ratio``, for
    each of ``pool_models`` (:data:`ANNULUS_POOL_MODELS`)."""

    radius_um: float
    outer_ratios: tuple
    fractions: tuple
    beyond: float
    dx_um: tuple
    max_volume_ratio: float
    pool_models: tuple = role(FANS_OUT)

    @classmethod
    def problems(cls, config) -> list[str]:
        """Particles small enough to put two rings in the hole."""
        va = config.get("verification", {}).get("annulus", {})
        return swollen_pool.two_rings_problems("verification.annulus", va.get("radius_um", 0.0), va.get("dx_um", []))


def materials(pool_model: str, matrix: dict, gag: dict) -> inclusion.Materials:
    """The annulus' matrix around the pool ``pool_model`` (:data:`ANNULUS_POOL_MODELS`): the GAG contents of ``gag``
    (with its volumetric term, as in the artery) or, for the ``hole``, contents of zero stiffness
    (:meth:`AnnulusPool.materials`)."""
    return ANNULUS_POOL_MODELS.lookup(pool_model).materials(matrix, gag)


def limit(A: float, B: float, mat: inclusion.Materials) -> cavity.LimitPressure:
    """The largest pressure the exact solution of these laws holds (:func:`sphgag.physics.cavity.limit_pressure`);
    ValueError where there is none (contents whose volumetric form's stress grows without bound hold any pressure:
    no limit of existence to verify)."""
    top = cavity.limit_pressure(A, B, *swollen_pool.solids(mat))
    if not np.isfinite(top.pressure_kPa):
        raise ValueError(
            f"the pool with the volumetric form {mat.volumetric!r} holds any pressure (its contents' stress grows "
            "without bound): the annulus verification has no limit of existence to check (gag.volumetric)"
        )
    return top


def swell_by_volume(path_solver: solver.Solver, pressures, max_ratio: float) -> tuple[dict, str]:
    """``({Pi: converged state}, end)``: the pool swollen from rest with its volume as the control (steps of at most
    5 %, the pressure the unknown: :func:`sphgag.engine.pool_volume.continue_path`), each of ``pressures`` solved by
    load control from the state before it; ``end`` is ``complete`` or why the path stopped. Near the limit the
    volume at a given pressure is ill-conditioned and load control creeps through ever smaller increments; a
    prescribed volume is not, and every step converges in a few iterations. ``path_solver``: the solver of the
    annulus' model."""
    model = path_solver.model
    rest = inclusion.pressure_load(0.0)
    start = path_solver.follow_path(model.layout.X, rest, [rest], run=model.name)[-1]
    members = np.flatnonzero(model.layout.inclusion)
    path, reached = pool_volume.continue_path(
        path_solver, start, members, list(pressures), run=model.name, max_ratio=max_ratio, parameter="swelling_pressure"
    )
    at = {s.load.material_value("swelling_pressure"): s for s in reached}
    return at, "complete" if path.end == "complete" else f"{path.end}: {path.reason}"


def beyond_limit(path_solver: solver.Solver, last, pressure_kPa: float, members: np.ndarray, max_ratio: float) -> dict:
    """What the engine does above the exact limit: from the converged state ``last``, load control to
    ``pressure_kPa`` (with the options of a transition, :meth:`sphgag.engine.solver.PathOptions.for_transition`);
    where it fails, as it must, volume control with the pressure as the unknown
    (:func:`sphgag.engine.pool_volume.continue_path`, up to ``max_ratio`` times the pool's reference volume) finds the
    discrete path's limit point or shows the pressure still rising (a saturation). ``state_beyond``: a state was
    reached at ``pressure_kPa`` (a defect: the exact solution has none). ``path_solver``: the solver of the path
    that reached ``last``."""
    model = path_solver.model
    try:
        transition = path_solver.using(path_solver.options.for_transition())
        transition.follow_path(last.x, last.load, [inclusion.pressure_load(pressure_kPa)], run=model.name)
        return dict(beyond_end="state", beyond_reason=f"a state at Pi = {pressure_kPa:.4g} kPa", state_beyond=True)
    except solver.SimulationError as exc:
        load_control = exc.reason
    path, reached = pool_volume.continue_path(
        path_solver, last, members, [pressure_kPa], run=model.name, max_ratio=max_ratio, parameter="swelling_pressure"
    )
    held = [s.concentration for s in path.states]
    return dict(
        beyond_end=path.end,
        beyond_reason=f"load control: {load_control}; volume control: {path.reason or path.end}",
        state_beyond=bool(reached),
        discrete_limit_kPa=path.limit_concentration,
        largest_held_kPa=max(held, default=np.nan),
    )


def annulus_study(va: dict, matrix: dict, gag: dict, numerics: Numerics, pool_model: str, log=None) -> pd.DataFrame:
    """One row per (outer ratio, spacing, pressure fraction) of ``va`` (``radius_um``, ``outer_ratios``, ``dx_um``,
    ``fractions``, ``beyond``, ``max_volume_ratio``): the pressure, the exact limit
    (``limit_pressure_kPa``, ``limit_kind``, ``limit_volume_ratio``), ``path_end`` and, below the limit, the measures
    of :func:`sphgag.studies.swollen_pool.measure_circle` against the exact state; at ``beyond`` times the limit,
    what :func:`beyond_limit` found (no measures: there is no exact state)."""
    mat = materials(pool_model, matrix, gag)
    m_solid, g_solid = swollen_pool.solids(mat)
    A = float(va["radius_um"])
    fractions = sorted(float(f) for f in va["fractions"])
    rows = []
    for ratio in va["outer_ratios"]:
        B = float(ratio) * A
        top = limit(A, B, mat)
        pressures = [f * top.pressure_kPa for f in fractions]
        for dx in va["dx_um"]:
            model = swollen_pool.circle_model(A, B, float(dx), mat, numerics, ANNULUS_POOL_MODELS[pool_model].engine)
            path_solver = numerics.solver(model)  # one solver for the model's paths, beyond the limit too
            at, end = swell_by_volume(path_solver, pressures, float(va["max_volume_ratio"]))
            case = dict(
                pool_model=pool_model,
                outer_ratio=float(ratio),
                dx_um=float(dx),
                limit_pressure_kPa=top.pressure_kPa,
                limit_kind=top.kind,
                limit_volume_ratio=top.volume_ratio,
                path_end=end,
            )
            h = numerics.kernel_support_factor * float(dx)
            for f, p in zip(fractions, pressures):
                row = dict(case, fraction=f, pressure_kPa=p, state=p in at)
                if p in at:
                    row.update(
                        swollen_pool.measure_circle(model, at[p], cavity.circular_pool(A, B, m_solid, g_solid, p), h)
                    )
                    if log is not None:
                        log.info(
                            "[%s B/A=%g] %.2f of the limit (%.2f kPa): volume ratio %.3f (exact %.3f, %+.2f %%), "
                            "hoop at the hole %+.2f %%, GAG outside the lining by %.2f um, residual %.1e",
                            model.name,
                            ratio,
                            f,
                            p,
                            row["volume_ratio"],
                            row["volume_ratio_exact"],
                            100 * row["volume_error"],
                            100 * row["lining_hoop_error"],
                            row["ring_crossing_um"],
                            row["residual"],
                        )
                rows.append(row)
            if end != "complete" or not pressures:
                continue
            p = float(va["beyond"]) * top.pressure_kPa
            members = np.flatnonzero(model.layout.inclusion)
            found = beyond_limit(path_solver, at[pressures[-1]], p, members, float(va["max_volume_ratio"]))
            rows.append(dict(case, fraction=float(va["beyond"]), pressure_kPa=p, state=found["state_beyond"], **found))
            if log is not None:
                log.info("[%s B/A=%g] %.2f of the limit: %s", model.name, ratio, va["beyond"], found["beyond_reason"])
    return pd.DataFrame(rows)


def exact_curves(table: pd.DataFrame, radius_um: float, matrix: dict, gag: dict, points: int = 60) -> pd.DataFrame:
    """The exact pressure-volume curve of every (pool model, B/A) of ``table``, up to its limit (or to 1.5 times the
    largest volume ratio the runs reached, for a saturation): ``volume_ratio``, ``pressure_kPa`` (the engine's
    compressible laws, :func:`sphgag.physics.cavity.pressure_for_volume_ratio`) and ``incompressible_kPa`` (the
    closed form of the hole, :func:`sphgag.physics.cavity.annulus_pressure_incompressible`)."""
    rows = []
    A = float(radius_um)
    for (model, ratio), case in table.groupby(["pool_model", "outer_ratio"], sort=True):
        mat = materials(model, matrix, gag)
        m, g = swollen_pool.solids(mat)
        B = float(ratio) * A
        top = case.limit_volume_ratio.iloc[0]
        if case.limit_kind.iloc[0] == "saturation":
            top = 1.5 * float(case.volume_ratio.max())
        for J in np.geomspace(1.0, top, points):
            rows.append(
                dict(
                    pool_model=model,
                    outer_ratio=float(ratio),
                    volume_ratio=J,
                    pressure_kPa=cavity.pressure_for_volume_ratio(J, A, B, m, g),
                    incompressible_kPa=float(cavity.annulus_pressure_incompressible(np.sqrt(J), A, B, mat.mu)),
                )
            )
    return pd.DataFrame(rows)
