"""A pressurised straight crack in a plane-strain block: the verification of the damage law with a fracture energy.

A pool that splits the media is a crack whose faces carry the swelling pressure, so the
fracture-energy law (:class:`sphgag.physics.damage.FractureEnergyLaw`) is verified on the
closed-form problem closest to it (:mod:`sphgag.physics.damage`): a straight crack of
half-length ``a`` in an infinite plane-strain block of the elastin matrix (the
neo-Hookean law of eq. 2.21 without pre-stretch or fibres, as :mod:`sphgag.studies.inclusion`),
its faces loaded by a pressure ``p``, in the linear regime:

* **before growth**, the opening area ``V = 2 pi a^2 p / E'`` (Sneddon);
* **onset of growth** at Griffith's ``p_c = sqrt(E' G_c / (pi a))``, for ``a >> ell_ch``;
* the **energy dissipated** per unit new crack area, ``G_c``.

**Layout.** A quarter block ``[0, L]^2`` of square cells of side ``dx`` (mirror planes on
both axes, :mod:`sphgag.engine.kernel`). The crack is a slit of GAG particles (eq. 2.27, the
prescribed Donnan law at the concentration whose Pi is ``p``): the first ``slit_rows`` rows
(half-thickness ``b = slit_rows dx``; one row, a sharp crack) for ``x < a`` (``a`` on a cell
edge). Ahead of it the first ``band_rows`` rows are the damage band, of width
``h = 2 band_rows dx``; each of its columns (its particles at one ``x``) is one crack-band
element: its onset measure and its energy density are the column's means, so that it
damages and ruptures as one (:meth:`SlitLayout.column_mean`). A band of one row is thinner
than the stencil a particle's deformation gradient is averaged over (2.5 dx): it ruptures
alone while the rows beside it unload, and the crack needs far more than Griffith's
pressure. The outer layer of cells is held on the exact displacement of the pressurised
elliptical hole with the slit's half-axes (:class:`sphgag.studies.inclusion.ExactBoundary`;
Sneddon's crack as ``b/a -> 0``).

**Growth** (as :mod:`sphgag.studies.delamination.growth`): the pressure is raised level by level; at each,
damage passes run until the band arrests: the onset measure is the opening stress ``sigma_yy``
(eq. 2.10) of the candidate's column, a ruptured particle (D = 1) becomes a GAG particle of the
slit along the conversion path, and every state is converged. Under pressure control
Griffith growth is unstable from its first step, so the onset of growth is the pressure
level of the first rupture; the run then follows the growth at that pressure. The
dissipated energy is that the damage releases at fixed deformation (``dD W_0 V``); its
slope against the crack's advance (its tip on the crack line) is the energy per unit crack
area.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..engine import kernel, measure, snap, solver
from ..engine.history import HistoryMaterial, ParticleHistory
from ..engine.loading import Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import Options
from ..physics import damage, donnan, materials
from ..physics.donnan import PAPER_LAW
from .delamination.front import intact_energy
from .inclusion import ExactBoundary, Materials

MAX_PASSES_PER_LEVEL = 400  # damage passes at one pressure level at most (growth under pressure control runs away)


@dataclass(frozen=True)
class CrackVerification(Options):
    """The ``verification.crack`` configuration: the pressurised straight crack of half-lengths ``half_lengths_um``
    at the spacings ``dx_um`` in a block ``extent_factor`` a wide, its slit and damage band ``slit_rows`` and
    ``band_rows`` rows thick, the fracture-energy damage law's sigma_cr and G_c, and the face pressure ramp in units of
    Griffith's p_c (``first_pressure`` to ``last_pressure`` in ``pressure_step``), growth followed ``growth_cells``
    cells beyond onset."""

    half_lengths_um: tuple
    dx_um: tuple
    extent_factor: float
    slit_rows: int
    band_rows: int
    critical_stress_kPa: float
    fracture_energy_J_m2: float
    first_pressure: float
    last_pressure: float
    pressure_step: float
    growth_cells: int


@dataclass(frozen=True)
class SlitLayout:
    """Square cells of a quarter block with a slit along ``y = 0`` (see the module docstring)."""

    X: np.ndarray
    volume: np.ndarray
    theta: np.ndarray
    slit: np.ndarray  # GAG particles of the initial crack: its rows behind the tip
    band: np.ndarray  # candidates: the band's rows ahead of the tip, off the held layer
    line: np.ndarray  # the row on the crack line (y = dx/2), ordered by x: its converted particles give the tip
    outer_surface: np.ndarray  # held on the exact far field
    a: float
    b: float  # the slit's half-thickness
    band_width: float  # h: the full width of the damage band (both sides of the crack line)
    dx: float
    size: float

    @property
    def n(self) -> int:
        return self.X.shape[0]

    @property
    def spacing(self) -> np.ndarray:
        """Every particle's spacing: ``dx`` (square cells, as :attr:`sphgag.engine.geometry.Layout.spacing`)."""
        return np.full(self.n, self.dx)

    @property
    def inner_surface(self) -> np.ndarray:  # no lumen
        return np.empty(0, dtype=np.int64)

    @property
    def outer_radius(self) -> float:
        return float(np.linalg.norm(self.X, axis=1).max())

    def column_mean(self, values: np.ndarray) -> np.ndarray:
        """``values`` with each band column (the band's particles at one ``x``: one crack-band element) replaced by
        its mean, so that a column damages, and ruptures, as one."""
        out = np.array(values, dtype=float)
        col = np.round(self.X[self.band, 0] / self.dx - 0.5).astype(np.int64)
        out[self.band] = (np.bincount(col, out[self.band]) / np.maximum(np.bincount(col), 1))[col]
        return out

    def tip(self, gag: np.ndarray) -> float:
        """The crack tip: the far edge of the last GAG particle of the crack line's unbroken run from x = 0."""
        on = gag[self.line]
        k = int(np.argmin(on)) if not on.all() else on.size
        return k * self.dx


def slit_layout(a: float, dx: float, size: float, slit_rows: int = 1, band_rows: int = 3) -> SlitLayout:
    """The quarter block ``[0, size]^2`` at spacing ``dx``; ``a`` and ``size`` are rounded to whole cells."""
    n_a, n = int(round(a / dx)), int(round(size / dx))
    if not (1 <= slit_rows <= band_rows and n_a >= 2 and n >= n_a + band_rows + 3):  # two band cells ahead at least
        raise ValueError(
            f"need a >= 2 dx, 1 <= slit_rows <= band_rows and a block beyond the crack (a={a}, dx={dx}, size={size}, "
            f"slit_rows={slit_rows}, band_rows={band_rows})"
        )
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    i, j = i.ravel(), j.ravel()
    X = np.column_stack([(i + 0.5) * dx, (j + 0.5) * dx])
    held = (i == n - 1) | (j == n - 1)
    return SlitLayout(
        X=X,
        volume=np.full(i.size, dx * dx),
        theta=np.zeros(i.size),
        slit=np.flatnonzero((j < slit_rows) & (i < n_a)),
        band=np.flatnonzero((j < band_rows) & (i >= n_a) & (i < n - 1 - band_rows)),
        line=np.flatnonzero(j == 0),  # i-major order: by x
        outer_surface=np.flatnonzero(held),
        a=n_a * dx,
        b=slit_rows * dx,
        band_width=2.0 * band_rows * dx,
        dx=float(dx),
        size=n * dx,
    )


@dataclass(frozen=True)
class Problem:
    """The crack problem of one ``(a, dx)``: the ``verification.crack`` configuration, the matrix and the GAG."""

    a: float
    dx: float
    size_factor: float
    slit_rows: int
    band_rows: int
    mat: Materials
    gag: materials.Gag  # HistoryMaterial's GAG parameters (prescribed Donnan law)
    critical_stress_kPa: float
    fracture_energy_J_m2: float

    def __post_init__(self):
        object.__setattr__(self, "gag", materials.Gag.of(self.gag))

    @property
    def modulus(self) -> float:
        """``E' = 2 mu / (1 - nu)`` of the linearised matrix (:func:`sphgag.physics.damage.plane_strain_modulus`)."""
        return float(damage.plane_strain_modulus(self.mat.mu, self.mat.poisson_ratio))

    @property
    def law(self) -> damage.FractureEnergyLaw:
        return damage.FractureEnergyLaw(self.critical_stress_kPa, self.fracture_energy_J_m2)

    @property
    def cohesive_length(self) -> float:
        gc = self.fracture_energy_J_m2 * damage.J_M2
        return float(damage.cohesive_length(self.modulus, gc, self.critical_stress_kPa))

    def griffith(self, a: float) -> float:
        return float(damage.griffith_pressure(a, self.fracture_energy_J_m2 * damage.J_M2, self.modulus))


def gag_settings(gag: Mapping) -> dict:
    """What the crack verification reads of the ``gag`` section ``gag``: the GAG's moduli
    (:meth:`sphgag.studies.inclusion.Materials.gag_settings`), and the bath and temperature of the Donnan law that turns
    a face pressure into a concentration (:func:`load_at`)."""
    return Materials.gag_settings(gag, also=("bath_concentration_mEq_l", "temperature_K"))


def load_at(problem: Problem, pressure: float, transition: float | None = None) -> Load:
    """The load with face pressure ``p``: the concentration whose Pi (eqs. 2.25-2.26) is ``p``, and the far field."""
    g = problem.gag
    c = donnan.concentration_for_pressure(pressure, g.bath_concentration_mEq_l, g.temperature_K)
    values = dict(concentration=float(c), face_pressure=float(pressure))
    if transition is not None:
        values["transition"] = float(transition)
    return Load(1.0, 0.0).with_material(**values)


def crack_model(problem: Problem, numerics: Numerics, name: str = "crack") -> tuple[Model, HistoryMaterial]:
    """The block with its slit (seeded GAG), mirror planes on both axes and the exact far field on its outer layer."""
    lay = slit_layout(problem.a, problem.dx, problem.size_factor * problem.a, problem.slit_rows, problem.band_rows)
    nb = kernel.build_neighbours(lay.X, lay.volume, numerics.kernel_support_factor * lay.dx, mirrors=(1, 2))
    table = materials.empty_props(lay.n)
    table[:, materials.MU], table[:, materials.LAM] = problem.mat.mu, problem.mat.lam
    table[:, materials.HG_E] = problem.mat.hourglass_modulus
    table.setflags(write=False)
    material = HistoryMaterial(lambda load: table.copy(), ParticleHistory.intact(lay.n).seed([lay.slit]), problem.gag)
    boundary = ExactBoundary(lay, problem.mat, pressure="face_pressure")
    model = Model(name, lay, nb, material, boundary=boundary, **numerics.model_options())
    return model, material


def opening_stress(ev) -> np.ndarray:
    """``sigma_yy`` of every particle (Cauchy, eq. 2.10): the stress that opens the crack."""
    return measure.cauchy(ev)[0][:, 1, 1]


def opening_area(model: Model, ev, material: HistoryMaterial) -> float:
    """The crack's opening area per unit depth: the volume change of its GAG particles, whole crack (4 quarters)."""
    J = measure.cauchy(ev)[1]
    gag = material.history.gag
    return 4.0 * float(np.sum((J[gag] - 1.0) * model.layout.volume[gag]))


@dataclass
class Growth:
    """The result of one run: onset of growth, the opening area before growth and the growth itself."""

    sneddon_pressure: float
    opening_area: float
    critical_pressure: float
    passes: list  # (pressure, new crack length [um], dissipated energy of the quarter [kPa um^2], residual)
    max_residual: float
    onset_pressure: float  # the level of the first damage onset
    history: ParticleHistory  # at the end


def grow(problem: Problem, numerics: Numerics, levels, growth_cells: int, log=None, name="crack") -> Growth:
    """Raise the face pressure through ``levels`` [kPa], with damage passes at each, until the crack has grown by
    ``growth_cells`` cells or the band is used up (module docstring)."""
    model, material = crack_model(problem, numerics, name)
    lay: SlitLayout = model.layout
    law, h = problem.law, lay.band_width
    path_solver = numerics.solver(model)
    state = solver.State(load_at(problem, 0.0), lay.X.copy(), None, None)
    dmg = damage.DamageState.intact(lay.n)
    passes, dissipated = [], 0.0
    p_crit, p_onset, area, max_res = np.nan, np.nan, np.nan, 0.0
    tol = 1e-3

    for p in levels:
        model.set_props(material)
        state = path_solver.follow_path(state.x, state.load, [load_at(problem, p)], run=name)[-1]
        max_res = max(max_res, state.convergence.residual)
        if np.isnan(area):
            area = opening_area(model, state.evaluation, material)
        for _ in range(MAX_PASSES_PER_LEVEL):
            ev = state.evaluation
            hist = material.history
            cand = lay.band[~hist.gag[lay.band]]
            before = dmg.D.copy()
            W0 = lay.column_mean(intact_energy(model, ev, material.base(ev.load)))
            sigma = np.full(lay.n, -np.inf)
            sigma[cand] = lay.column_mean(opening_stress(ev))[cand]
            dmg.update(law, cand, sigma, np.ones(lay.n), W0, h)
            if np.isnan(p_onset) and np.any(~np.isnan(dmg.onset_stretch)):
                p_onset = p
            ruptured = np.flatnonzero(dmg.ruptured & ~hist.gag)
            if float(np.max(dmg.D - before)) <= tol and not ruptured.size:
                dmg.D[:] = before  # changes below the tolerance are not applied
                break
            dissipated += float(np.sum((dmg.D - before) * W0 * lay.volume))
            new = hist.with_damage(dmg.D.copy(), dmg.onset_stretch.copy(), dmg.onset_energy.copy())
            if ruptured.size:
                new = new.rupture(ruptured, np.zeros(ruptured.size, dtype=np.int64), len(passes) + 1)
                if np.isnan(p_crit):
                    p_crit = p
            at = load_at(problem, p)
            try:
                state, material, _ = snap.transition(path_solver, state.x, material, new, at, run=name)
            except snap.NoStableState as exc:  # the growth snapped to no equilibrium: end at the last one
                if log is not None:
                    log.warning("[%s] p = %.4g kPa: no stable state after a snap (%s)", name, p, exc.reason)
                model.set_props(material)
                return Growth(levels[0], area, p_crit, passes, max_res, p_onset, material.history)
            max_res = max(max_res, state.convergence.residual)
            grown = lay.tip(material.history.gag) - lay.a
            passes.append((p, grown, dissipated, state.convergence.residual))
            if log is not None and ruptured.size:
                log.info("[%s] p = %.4g kPa, pass %d: crack grown by %.3g um", name, p, len(passes), grown)
            if grown >= growth_cells * lay.dx or not cand.size:
                return Growth(levels[0], area, p_crit, passes, max_res, p_onset, material.history)
        if log is not None:
            log.info(
                "[%s] p = %.4g kPa: %d damage passes so far, %d particles past onset, crack grown by %.3g um",
                name,
                p,
                len(passes),
                int(np.sum(~np.isnan(dmg.onset_stretch))),
                passes[-1][1] if passes else 0.0,
            )
        if len(passes) and passes[-1][1] >= growth_cells * lay.dx:
            break
    return Growth(levels[0], area, p_crit, passes, max_res, p_onset, material.history)


def energy_per_area(growth: Growth) -> float:
    """The energy dissipated per unit new crack area [J/m^2]: the slope of the quarter's dissipated energy against the
    new crack length over the growth (so that the damage ahead of the tip, which no length measures, drops out),
    doubled for the two halves of the crack (the quarter holds one face of one tip); NaN without two grown states."""
    P = np.array([row for row in growth.passes if row[1] > 0.0])
    if len(P) < 2 or np.ptp(P[:, 1]) <= 0.0:
        return np.nan
    return 2.0 * float(np.polyfit(P[:, 1], P[:, 2], 1)[0]) / damage.J_M2


def study(half_length: float, vc: dict, matrix: dict, gag: dict, numerics: Numerics, log=None) -> pd.DataFrame:
    """Rows of ``pressurised_crack.csv`` for one crack half-length at every spacing of ``vc['dx_um']``.

    ``vc``: the ``verification.crack`` configuration; ``matrix`` and ``gag`` as :func:`sphgag.studies.inclusion.study`.
    """
    mat = Materials.of(matrix, gag)
    gag_law = materials.Gag(
        charge_law=PAPER_LAW,  # the prescribed Donnan law: the slit carries the fixed Pi of the load
        bath_concentration_mEq_l=gag["bath_concentration_mEq_l"],
        temperature_K=gag["temperature_K"],
        shear_modulus_kPa=gag["shear_modulus_kPa"],
        hourglass_modulus_kPa=gag["hourglass_modulus_kPa"],
        lame_lambda_kPa=0.0,
        volumetric=mat.volumetric,  # eq. 2.27 as printed: no volumetric term
    )
    rows = []
    for dx in vc["dx_um"]:
        problem = Problem(
            float(half_length),
            float(dx),
            vc["extent_factor"],
            vc["slit_rows"],
            vc["band_rows"],
            mat,
            gag_law,
            vc["critical_stress_kPa"],
            vc["fracture_energy_J_m2"],
        )
        lay = slit_layout(problem.a, problem.dx, problem.size_factor * problem.a, problem.slit_rows, problem.band_rows)
        a = lay.a
        pc = problem.griffith(a)
        steps = np.arange(vc["first_pressure"], vc["last_pressure"] + 1e-9, vc["pressure_step"])
        name = f"crack_a{half_length:g}_dx{dx:g}"
        g = grow(problem, numerics, pc * steps, vc["growth_cells"], log=log, name=name)
        sneddon = float(damage.opening_area(a, g.sneddon_pressure, problem.modulus))
        energy = energy_per_area(g)
        row = dict(
            dx_um=float(dx),
            nominal_half_length_um=float(half_length),
            half_length_um=a,
            half_thickness_um=lay.b,
            band_width_um=lay.band_width,
            plane_strain_modulus_kPa=problem.modulus,
            critical_stress_kPa=problem.critical_stress_kPa,
            fracture_energy_J_m2=problem.fracture_energy_J_m2,
            cohesive_length_um=problem.cohesive_length,
            length_over_cohesive=a / problem.cohesive_length,
            critical_pressure_kPa=g.critical_pressure,
            griffith_kPa=pc,
            rel_error=g.critical_pressure / pc - 1.0,
            onset_pressure_kPa=g.onset_pressure,
            pressure_kPa=g.sneddon_pressure,
            opening_area_um2=g.opening_area,
            sneddon_um2=sneddon,
            area_rel_error=g.opening_area / sneddon - 1.0,
            dissipated_J_m2=energy,
            energy_rel_error=energy / problem.fracture_energy_J_m2 - 1.0,
            grown_um=g.passes[-1][1] if g.passes else 0.0,
            residual=g.max_residual,
            particles=int(round(problem.size_factor * a / dx)) ** 2,
        )
        rows.append(row)
        if log is not None:
            log.info(
                "[%s] growth at %.4g kPa (Griffith %.4g, %+.1f %%), opening area %+.2f %% of Sneddon, %.3g J/m^2 per "
                "area (G_c %.3g, %+.1f %%), residual %.1e",
                name,
                row["critical_pressure_kPa"],
                pc,
                100 * row["rel_error"],
                100 * row["area_rel_error"],
                energy,
                problem.fracture_energy_J_m2,
                100 * row["energy_rel_error"],
                row["residual"],
            )
    return pd.DataFrame(rows)
