"""The finite-element reference of a swelling pool (sphgag.studies.fe_swelling) against closed forms and itself.

Mesh sizes (``h``: the element size at the pool tip; measured on 2 shared cores, one thread):
Inglis h = 0.5 um (15 k dofs, 2 s); circle h = 1 um (3 k dofs, 5 s); ellipse study h = 1, 0.5, 0.25 um
(2.3 k, 8.7 k, 33 k dofs, about 1 min).
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from sphgag.physics import cavity, ellipticity, inglis, volumetric
from sphgag.physics.materials import first_piola, tangent_modulus
from sphgag.studies import fe_swelling


@pytest.fixture(scope="module")
def materials(full_config):
    """The verification's matrix (the bilayer's elastin, unweighted) and the configuration's GAG."""
    bl, gag = full_config["bilayer"], full_config["gag"]
    matrix = dict(shear_modulus_kPa=bl["elastin_shear_modulus_kPa"], lame_lambda_kPa=bl["lame_lambda_kPa"])
    return matrix, {k: gag[k] for k in ("shear_modulus_kPa", "lame_lambda_kPa", "volumetric")}


@pytest.fixture(scope="module")
def inglis_run(materials):
    """A nearly stress-free pool (mu_g = 0.01 kPa, no bulk term) at Pi = 0.05 kPa in a plate 20 a wide."""
    matrix, _ = materials
    gag = dict(shear_modulus_kPa=0.01, lame_lambda_kPa=0.0, volumetric="none")
    return fe_swelling.elliptic_pool(45.0, 15.0, 900.0, matrix, gag, [0.05], h=0.5)


def exact_circle(pi, radius, outer, matrix, gag):
    """Pool volume ratio ``lp^2`` of the swollen circular pool (homogeneous, ``r = lp R``) in a ring ``radius < R <
    outer`` (plane strain, ``lz = 1``): radial equilibrium ``d(R P_r)/dR = P_theta`` integrated outwards from the
    interface traction, shooting on ``lp`` until ``P_r(outer) = 0``."""
    mu, lam = matrix["shear_modulus_kPa"], matrix["lame_lambda_kPa"]
    mu_g, lam_g = gag["shear_modulus_kPa"], gag["lame_lambda_kPa"]

    def piola(lr, lt):  # principal first Piola stresses of W = mu/2 (I1 - 3) - mu ln J + lam/2 (ln J)^2
        lnJ = np.log(lr * lt)
        return mu * lr + (lam * lnJ - mu) / lr, mu * lt + (lam * lnJ - mu) / lt

    def rhs(R, y):
        r, Pr = y
        lt = r / R
        lr = brentq(lambda s: piola(s, lt)[0] - Pr, 1e-3, 1e3, xtol=1e-14)
        return [lr, (piola(lr, lt)[1] - Pr) / R]

    def outer_traction(lp):
        J = lp * lp
        bulk = volumetric.VOLUMETRIC_FORMS[gag["volumetric"]].stress(J, lam_g)  # U'(J) of the contents' volumetric term
        sigma = mu_g * (1.0 - 1.0 / J) + bulk - pi  # the pool's Cauchy stress (isotropic)
        sol = solve_ivp(rhs, (radius, outer), [lp * radius, sigma * lp], rtol=1e-11, atol=1e-11)
        return sol.y[1, -1]

    return brentq(outer_traction, 1.0 + 1e-9, 10.0, xtol=1e-13) ** 2


def test_small_pressure_tip_hoop_stress_is_inglis(inglis_run):
    """Linear regime, a/b = 3: hoop stress Pi (2a/b - 1) at the tip, Pi (2b/a - 1) at the top (3 %)."""
    row = inglis_run.iloc[0]
    assert row.tip_hoop_stress_kPa == pytest.approx(inglis.tip_hoop_stress(45.0, 15.0, 0.05), rel=0.03)
    assert row.top_hoop_stress_kPa == pytest.approx(0.05 * (2.0 * 15.0 / 45.0 - 1.0), rel=0.03)


@pytest.fixture(scope="module")
def circle_run(materials):
    """The circular pool (b = 15 um in a ring to 30 um) at the pressure whose exact pool volume ratio is 10 (the
    exact solution of :mod:`sphgag.physics.cavity`; the test's own shooting checks it)."""
    matrix, gag = materials
    pi = cavity.pressure_for_volume_ratio(10.0, 15.0, 30.0, matrix, gag)
    return pi, fe_swelling.elliptic_pool(15.0, 15.0, 15.0, matrix, gag, [40.0, pi], h=1.0)


def test_circle_at_large_strain_matches_the_radial_solution(circle_run, materials):
    """J_pool = 10 (a ring compressed to less than half its thickness): the pool volume within 0.5 %."""
    pi, run = circle_run
    matrix, gag = materials
    assert run.pressure_kPa.iloc[-1] == pi
    for p, ratio in zip(run.pressure_kPa, run.pool_volume_ratio):
        assert ratio == pytest.approx(exact_circle(p, 15.0, 30.0, matrix, gag), rel=0.005)
    assert run.pool_volume_ratio.iloc[-1] == pytest.approx(10.0, rel=0.005)
    assert exact_circle(pi, 15.0, 30.0, matrix, gag) == pytest.approx(10.0, rel=1e-8)


@pytest.fixture(scope="module")
def ellipse_study(materials):
    """a/b = 3, b = 15 um, extent = a, at Pi = 81 kPa (pool volume ratio 10.4 with the configured convex contents;
    with log_squared contents 74 kPa gave 10.1), at h = 1, 0.5, 0.25 um."""
    matrix, gag = materials
    return fe_swelling.mesh_study(
        lambda h: fe_swelling.elliptic_pool(45.0, 15.0, 45.0, matrix, gag, [81.0], h), [1.0, 0.5, 0.25]
    )


def test_ellipse_converges_at_large_strain(ellipse_study):
    runs, changes = ellipse_study
    assert len(runs) == 3 and (runs.groupby("h").n_dofs.first().diff().dropna() < 0).all()  # finer: more dofs
    row = changes.iloc[0]
    assert row.pool_volume_ratio >= 10.0
    assert row.pool_volume_ratio_change < 0.01
    assert row.tip_hoop_stress_kPa_change < 0.01


def test_every_state_is_converged(inglis_run, circle_run, ellipse_study):
    for run in (inglis_run, circle_run[1], ellipse_study[0]):
        assert (run.residual < 1e-8).all()


def test_uniform_bulk_is_the_local_law_where_that_is_elliptic(materials):
    """Below J ~ 2.9 the GAG law is elliptic: its bulk term taken at the pool's mean dilatation changes nothing
    (a/b = 3 at Pi = 40 kPa, pool volume ratio 2.55: 1e-4)."""
    matrix, gag = materials
    runs = [fe_swelling.elliptic_pool(45.0, 15.0, 45.0, matrix, gag, [40.0], 1.0, uniform_bulk=u) for u in (1, 0)]
    for key in ("pool_volume_ratio", "tip_hoop_stress_kPa"):
        assert runs[0][key].iloc[0] == pytest.approx(runs[1][key].iloc[0], rel=1e-4)


def test_sector_pool_measures_and_swells(materials):
    """Case I of figure 4 in the elastin wall (coarse): the pool swells, the probes are finite, the tip is in
    radial tension and the corner's peak exceeds the tip's mean."""
    matrix, gag = materials
    pool = (663.0, 51.5, 15.0, 3.0)
    run = fe_swelling.sector_pool(646.8, 687.0, pool, matrix, gag, [20.0], h=1.0, media=(646.8, 675.2))
    row = run.iloc[0]
    assert row.pool_volume_ratio > 1.0 and row.residual < 1e-8
    assert row.tip_radial_stress_kPa > 0.0
    assert row.corner_peak_radial_stress_kPa > row.tip_radial_stress_kPa
    assert np.isfinite(run[["top_hoop_stress_kPa", "bottom_hoop_stress_kPa"]].to_numpy()).all()


@pytest.mark.parametrize("form", volumetric.VOLUMETRIC_FORMS)
def test_the_pools_law_is_the_engines(form):
    """The displacement-only pool law of the reference (each volumetric form of the contents, Pi = 30 kPa): its first
    Piola stress and tangent are the engine's kernels' (sphgag.physics.materials) at random F, J of 0.6 to 20."""
    rng = np.random.default_rng(3)
    props = ellipticity.contents_props(form, 0.1, 10.0, 30.0)
    C, A = np.empty((3, 3)), np.empty((4, 4))
    for scale in (0.8, 1.0, 2.0, 4.0):
        F = scale * (np.eye(2) + 0.15 * rng.standard_normal((2, 2)))
        bulk = (10.0, volumetric.VOLUMETRIC_FORMS[form])
        _, _, _, P, T = fe_swelling._kinematics((F - np.eye(2))[:, :, None, None], 0.1, 0.0, 30.0, True, bulk)
        engine = first_piola(F[0, 0], F[0, 1], F[1, 0], F[1, 1], 1.0, 1.0, 0.0, props, 0)
        tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], 1.0, 1.0, 0.0, props, 0, C, A)
        np.testing.assert_allclose(P[:, :, 0, 0].ravel(), engine, rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(T[..., 0, 0].reshape(4, 4), A, rtol=1e-10, atol=1e-10)
