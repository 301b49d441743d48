"""The exact circular swelling pool (sphgag.physics.cavity) against closed forms, its own equations and the engine."""

import numpy as np
import pytest
from scipy.integrate import quad

from sphgag.physics import cavity, donnan, materials, volumetric

A = 1.0


def test_infinite_cavity_pressure_is_the_incompressible_integral():
    # p = mu int_a^oo (lt^2 - lt^-2) dr/r with r^2 - R^2 = (l^2 - 1) A^2 (incompressible plane strain)
    for l in (1.1, 2.0, 5.0):
        c = (l * l - 1.0) * A * A
        p = quad(lambda r, c=c: (r * r / (r * r - c) - (r * r - c) / (r * r)) / r, l * A, np.inf, limit=200)[0]
        np.testing.assert_allclose(cavity.infinite_cavity_pressure(l, 2.5), 2.5 * p, rtol=1e-10)


@pytest.mark.parametrize("stretch", [2.0, 3.0, 5.0])
def test_large_pool_in_a_wide_nearly_incompressible_matrix_is_the_infinite_cavity(stretch):
    m, g = cavity.Solid(1.0, 1000.0), cavity.Solid(1e-6, 0.0)
    B = 400.0 * A
    p = cavity.pressure_for_volume_ratio(stretch**2, A, B, m, g)
    exact = cavity.infinite_cavity_pressure(stretch, 1.0)
    # the incompressible annulus's own correction: p(B) = mu (ln(lp/lB) + (lB^-2 - lp^-2)/2), lB = b/B
    lB = np.sqrt(1.0 + (stretch**2 - 1.0) * (A / B) ** 2)
    finite = np.log(stretch / lB) + 0.5 * (lB**-2 - stretch**-2)
    assert abs(p / exact - 1.0) < 5e-3
    assert abs(p / finite - 1.0) < 1e-4  # what remains is compressibility (lam = 1000 mu) and the pool's 1e-6 mu
    pool = cavity.circular_pool(A, B, m, g, p)
    np.testing.assert_allclose(pool.stretch, stretch, rtol=1e-10)


@pytest.mark.parametrize("form", [f for f in volumetric.VOLUMETRIC_FORMS if f != "none"])
def test_small_strain_is_the_lame_thick_cylinder_around_a_compliant_pool(form):
    """Every volumetric form of the contents has the small-strain bulk modulus lamg (its U''(1))."""
    mu, lam, mug, lamg, B, pi = 1.0, 2.0, 0.05, 0.3, 3.0 * A, 1e-4
    pool = cavity.circular_pool(A, B, cavity.Solid(mu, lam), cavity.Solid(mug, lamg, volumetric=form), pi)
    # annulus u = a R + b/R, sigma_rr = 2 (lam + mu) a - 2 mu b / R^2, sigma_rr(B) = 0: interface traction
    # -K u_A/A with K = 2 mu (lam + mu)(B^2 - A^2) / (mu A^2 + (lam + mu) B^2); the pool: 2 (lamg + mug) eps - Pi
    K = 2.0 * mu * (lam + mu) * (B * B - A * A) / (mu * A * A + (lam + mu) * B * B)
    eps = pi / (K + 2.0 * (lamg + mug))
    np.testing.assert_allclose(pool.stretch - 1.0, eps, rtol=1e-3)
    a = eps / (1.0 + (lam + mu) * B * B / (mu * A * A))
    b = (lam + mu) * a * B * B / mu
    R = np.linspace(A, B, 9)
    f = pool.field(R)
    np.testing.assert_allclose(f["r"] - R, a * R + b / R, rtol=1e-3)
    np.testing.assert_allclose(f["sigma_rr"], 2 * (lam + mu) * a - 2 * mu * b / R**2, rtol=1e-3, atol=1e-3 * pi)
    np.testing.assert_allclose(f["sigma_tt"], 2 * (lam + mu) * a + 2 * mu * b / R**2, rtol=1e-3)


CASES = [  # matrix, gag, B, pressure, law
    (cavity.Solid(1.0, 1000.0), cavity.Solid(0.01, 0.5), 6.0, 1.5, "prescribed"),
    (cavity.Solid(89.71, 10000.0), cavity.Solid(0.1, 10.0), 4.0, 91.0, "prescribed"),  # the engine's, Pi(150 mEq/l)
    (cavity.Solid(89.71, 10000.0), cavity.Solid(0.1, 10.0), 4.0, 91.0, "conserved"),
    (cavity.Solid(1.0, 1.0), cavity.Solid(0.1, 0.0), 10.0, 1.5, "prescribed"),  # compressible matrix
    (cavity.Solid(89.71, 10000.0), cavity.Solid(0.1, 10.0, volumetric="convex"), 4.0, 91.0, "prescribed"),
    (cavity.Solid(89.71, 10000.0), cavity.Solid(0.1, 10.0, volumetric="hartmann_neff"), 4.0, 91.0, "conserved"),
]


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"lam{c[0].lam / c[0].mu:g}-{c[1].volumetric}-{c[4]}")
def test_field_is_in_equilibrium_with_free_outer_surface_and_continuous_traction(case):
    m, g, B, pi, law = case
    pool = cavity.circular_pool(A, B, m, g, pi, law=law)
    assert pool.volume_ratio > 1.5
    R = np.geomspace(A, B, 4001)
    f = pool.field(R)
    r, srr, stt = f["r"], f["sigma_rr"], f["sigma_tt"]
    residual = np.gradient(srr, r, edge_order=2) + (srr - stt) / r
    scale = np.abs(stt).max() / (A * pool.stretch)
    assert np.abs(residual).max() < 1e-5 * scale
    assert abs(srr[-1]) < 1e-9 * scale
    assert np.all(np.diff(r) > 0.0)
    inner = pool.field([0.5 * A, A * (1.0 - 1e-12), A])
    np.testing.assert_allclose(inner["r"], np.array([0.5, 1.0, 1.0]) * pool.stretch * A, rtol=1e-10)
    np.testing.assert_allclose(inner["sigma_rr"], pool.pool_stress_kPa, rtol=1e-9)
    assert pool.interface_hoop_kPa == pytest.approx(stt[0], rel=1e-12)
    if law == "conserved":
        c0 = cavity.fixed_charge(pi, g)
        assert pool.swelling_kPa == pytest.approx(cavity.donnan_pressure(pool.volume_ratio, c0, g), rel=1e-12)
        assert pool.swelling_kPa < pi


@pytest.mark.parametrize("ratio", [2.0, 4.0])
def test_hole_in_a_nearly_incompressible_annulus_is_the_closed_form(ratio):
    # an empty hole (no contents) in lam = 1e4 mu: the incompressible closed form to the compressibility's O(mu/lam)
    m, hole, B = cavity.Solid(1.0, 1e4), cavity.Solid(0.0), ratio * A
    for J in (2.0, 5.0, 20.0, 100.0):
        p = cavity.pressure_for_volume_ratio(J, A, B, m, hole)
        np.testing.assert_allclose(p, cavity.annulus_pressure_incompressible(np.sqrt(J), A, B, 1.0), rtol=2e-3)


def test_incompressible_annulus_saturates_at_mu_ln_B_over_A():
    la = np.geomspace(1.01, 1e4, 200)
    p = cavity.annulus_pressure_incompressible(la, A, 3.0 * A, 2.0)
    assert np.all(np.diff(p) > 0) and np.all(p < 2.0 * np.log(3.0))
    assert p[-1] == pytest.approx(2.0 * np.log(3.0), rel=1e-7)


@pytest.mark.parametrize("ratio", [2.0, 4.0])
def test_limit_pressure_of_a_hole_is_the_saturation_and_of_a_pool_a_maximum(ratio):
    m, B = cavity.Solid(1.0, 100.0), ratio * A
    hole = cavity.limit_pressure(A, B, m, cavity.Solid(0.0))
    assert hole.kind == "saturation"
    assert hole.pressure_kPa == pytest.approx(np.log(ratio), rel=1e-6)  # compressibility leaves mu ln(B/A) in place
    g = cavity.Solid(1e-3, 0.1)  # contents with a bulk term: the curve has a maximum
    pool = cavity.limit_pressure(A, B, m, g)
    assert pool.kind == "limit point"
    for J in (0.9 * pool.volume_ratio, 1.1 * pool.volume_ratio):
        assert cavity.pressure_for_volume_ratio(J, A, B, m, g) < pool.pressure_kPa
    cavity.circular_pool(A, B, m, g, (1.0 - 1e-6) * pool.pressure_kPa)
    with pytest.raises(ValueError, match="limit pressure"):
        cavity.circular_pool(A, B, m, g, (1.0 + 1e-6) * pool.pressure_kPa)


@pytest.mark.parametrize("ratio", [2.0, 4.0])
def test_limit_pressure_of_each_volumetric_form(ratio):
    """The contents' stress U'(J) decides the kind of limit: ``convex``'s saturates at kappa, so the pool saturates
    at the hole's mu ln(B/A) plus mu_g + kappa; ``none`` at mu ln(B/A) + mu_g; ``hartmann_neff``'s grows without
    bound, so the pool holds any pressure."""
    m, B = cavity.Solid(1.0, 100.0), ratio * A
    for form, contents in (("convex", 0.05 + 0.2), ("none", 0.05)):
        top = cavity.limit_pressure(A, B, m, cavity.Solid(0.05, 0.2, volumetric=form))
        assert top.kind == "saturation"
        assert top.pressure_kPa == pytest.approx(np.log(ratio) + contents, rel=1e-6)
    top = cavity.limit_pressure(A, B, m, cavity.Solid(0.05, 0.2, volumetric="hartmann_neff"))
    assert top.kind == "unbounded" and top.pressure_kPa == np.inf


@pytest.mark.parametrize("law", donnan.CHARGE_LAWS)
@pytest.mark.parametrize("J", [4.0, 25.0, 100.0])
@pytest.mark.parametrize("ratio", [10.0, 1000.0])
def test_pressure_for_volume_ratio_inverts_the_pool(law, J, ratio):
    m, g, B = cavity.Solid(1.0, ratio), cavity.Solid(0.05, 1.0), 20.0 * A  # stable up to J ~ 1000
    p = cavity.pressure_for_volume_ratio(J, A, B, m, g, law=law)
    pool = cavity.circular_pool(A, B, m, g, p, law=law)
    np.testing.assert_allclose(pool.volume_ratio, J, rtol=1e-9)
    assert pool.field(B)["sigma_rr"] == pytest.approx(0.0, abs=1e-9 * p)


def test_thick_annulus_has_a_limit_pressure_and_two_pools_below_it():
    # B = 4 A: the pressure-volume curve peaks near J = 25 (about 1.504 mu)
    m, g, B = cavity.Solid(1.0, 10.0), cavity.Solid(0.05, 1.0), 4.0 * A
    p = [cavity.pressure_for_volume_ratio(J, A, B, m, g) for J in (16.0, 25.0, 100.0)]
    assert p[1] > p[0] and p[1] > p[2]
    with pytest.raises(ValueError, match="limit pressure"):
        cavity.circular_pool(A, B, m, g, 1.001 * p[1])
    stable = cavity.circular_pool(A, B, m, g, p[2])  # the unstable J = 100 has a stable twin at the same pressure
    assert stable.volume_ratio < 25.0
    np.testing.assert_allclose(cavity.pressure_for_volume_ratio(stable.volume_ratio, A, B, m, g), p[2], rtol=1e-9)


@pytest.mark.parametrize("form", volumetric.VOLUMETRIC_FORMS)
@pytest.mark.parametrize("law", donnan.CHARGE_LAWS)
def test_cauchy_stress_is_the_engines(law, form):
    """The exact solution's stresses of the GAG contents (each volumetric form) are the engine's kernels'."""
    rng = np.random.default_rng(7)
    g = cavity.Solid(3.0, 40.0, bath_mEq_l=250.0, temperature_K=300.0, volumetric=form)
    props = materials.empty_props(1)
    materials.convert_to_gag(props, [0], 1.0, g.mu, 0.0, 5.0, kappa=g.lam, volumetric=form)
    c0 = 120.0 if law == "conserved" else 0.0
    props[0, materials.FCD], props[0, materials.CBATH], props[0, materials.RT] = c0, g.bath_mEq_l, g.rt
    for lr, lt in rng.uniform(0.3, 6.0, size=(20, 2)):
        s_rr, s_tt, s_rt = materials.pk2(lr * lr, lt * lt, 0.0, 1.0, props, 0)
        J = lr * lt
        pi = 5.0 + (cavity.donnan_pressure(J, c0, g) if c0 else 0.0)
        srr, stt = cavity.cauchy(lr, lt, g, pi)
        np.testing.assert_allclose([srr, stt], [lr * lr * s_rr / J, lt * lt * s_tt / J], rtol=1e-12, atol=1e-12 * g.lam)
        assert s_rt == 0.0


def test_donnan_pressure_and_fixed_charge_are_the_engines():
    g = cavity.Solid(1.0, bath_mEq_l=300.0, temperature_K=310.0)
    for J in (0.5, 1.0, 3.0, 40.0):
        pd = materials.donnan(J, 150.0, g.bath_mEq_l, g.rt)[0]
        assert cavity.donnan_pressure(J, 150.0, g) == pytest.approx(pd, rel=1e-13)
    c = donnan.concentration_for_pressure(np.array([1.0, 91.0, 500.0]), 300.0, 310.0)
    np.testing.assert_allclose(cavity.fixed_charge(np.array([1.0, 91.0, 500.0]), g), c, rtol=1e-13)
    cfg = cavity.Solid.of({"shear_modulus_kPa": 0.1, "lame_lambda_kPa": 10.0, "hourglass_modulus_kPa": 89.71})
    assert cfg == cavity.Solid(0.1, 10.0)
