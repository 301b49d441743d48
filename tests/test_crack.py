"""The pressurised-crack verification problem (sphgag.studies.crack): its layout, load and opening before growth."""

import numpy as np
import pytest

from sphgag.engine.numerics import Numerics
from sphgag.physics import damage, donnan
from sphgag.studies import crack, inclusion

NUMERICS = Numerics(
    kernel_support_factor=2.5,
    hourglass_alpha=5.0,
    hourglass="paper",
    tolerance=1e-4,
    max_newton_iterations=30,
    max_bisections=10,
    reuse_factorisation=True,
)
MAT = inclusion.Materials(
    mu=89.71,
    lam=10000.0,
    mu_gag=0.1,
    lam_gag=0.0,
    hourglass_modulus=89.71,
    gag_hourglass_modulus=89.71,
    volumetric="none",
)
GAG = dict(
    charge_law="prescribed",
    bath_concentration_mEq_l=300.0,
    temperature_K=310.0,
    shear_modulus_kPa=0.1,
    hourglass_modulus_kPa=89.71,
    lame_lambda_kPa=0.0,
    volumetric="none",
)


def problem(a=20.0, dx=2.0, rows=3):
    return crack.Problem(a, dx, 2.0, rows, rows, MAT, GAG, 4.0, 3.6e-4)


def test_the_concentration_for_a_pressure_inverts_the_donnan_law():
    c = np.array([0.0, 10.0, 150.0, 400.0])
    pi = donnan.swelling_pressure(c, 300.0, 310.0)
    assert donnan.concentration_for_pressure(pi, 300.0, 310.0) == pytest.approx(c, abs=1e-9)


def test_the_slit_layout_fills_the_quarter_block_with_the_slit_and_its_band_on_the_crack_line():
    lay = crack.slit_layout(22.6, 2.0, 33.4, slit_rows=3, band_rows=3)  # rounded to whole cells
    assert (lay.a, lay.b, lay.band_width, lay.size) == (22.0, 6.0, 12.0, 34.0)
    assert lay.volume.sum() == pytest.approx(lay.size**2)
    assert np.all(lay.X[lay.slit, 0] < lay.a) and np.all(lay.X[lay.slit, 1] < lay.b)
    assert np.all(lay.X[lay.band, 0] > lay.a) and np.all(lay.X[lay.band, 1] < lay.b)
    assert lay.slit.size == 11 * 3 and not np.intersect1d(lay.band, lay.outer_surface).size
    with pytest.raises(ValueError, match="block beyond the crack"):
        crack.slit_layout(20.0, 2.0, 30.0, slit_rows=3, band_rows=3)
    with pytest.raises(ValueError, match="slit_rows <= band_rows"):
        crack.slit_layout(20.0, 2.0, 40.0, slit_rows=3, band_rows=2)


def test_a_band_column_damages_as_one_element_and_the_tip_is_the_end_of_the_broken_crack_line():
    lay = crack.slit_layout(10.0, 1.0, 20.0, slit_rows=1, band_rows=3)
    values = np.arange(lay.n, dtype=float)
    mean = lay.column_mean(values)
    col = lay.band[np.isclose(lay.X[lay.band, 0], 12.5)]
    assert col.size == 3 and np.all(mean[col] == values[col].mean())
    outside = np.setdiff1d(np.arange(lay.n), lay.band)
    assert np.array_equal(mean[outside], values[outside])
    gag = np.zeros(lay.n, dtype=bool)
    gag[lay.slit] = True
    assert lay.tip(gag) == 10.0
    gag[lay.line[[10, 11, 13]]] = True  # 10, 11 extend the crack; 13 is beyond an unbroken particle
    assert lay.tip(gag) == 12.0


def test_the_cohesive_length_and_griffith_pressure_of_the_problem():
    pr = problem()
    assert pr.modulus == pytest.approx(damage.plane_strain_modulus(MAT.mu, MAT.poisson_ratio))
    assert pr.cohesive_length == pytest.approx(pr.modulus * 0.36 / 16.0)
    assert pr.griffith(20.0) == pytest.approx(np.sqrt(pr.modulus * 0.36 / (np.pi * 20.0)))
    load = crack.load_at(pr, 0.8)
    pi = donnan.swelling_pressure(load.material_value("concentration"), 300.0, 310.0)
    assert pi == pytest.approx(0.8) and load.material_value("face_pressure") == 0.8


def test_a_coarse_slit_opens_as_sneddons_crack_before_it_grows():
    """One level, no damage pass needed to compare: the opening area of a 20 um crack at dx = 2 um within 5 %."""
    pr = problem(rows=1)  # a slit 2 dx = 4 um thick: b / a = 0.1
    p = 0.5 * pr.griffith(20.0)
    g = crack.grow(pr, NUMERICS, [p], growth_cells=2)
    assert g.opening_area == pytest.approx(damage.opening_area(20.0, p, pr.modulus), rel=0.05)
    assert g.max_residual < 1e-4 and np.isnan(g.critical_pressure)  # no growth at half Griffith's pressure
