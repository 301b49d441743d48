"""The closed forms of the pressurised crack (sphgag.physics.damage) against each other and the literature."""

import numpy as np
import pytest
from scipy import integrate

from sphgag.physics import damage

E = damage.plane_strain_modulus(42.0)  # the media's elastin matrix, incompressible: 168 kPa


def test_the_plane_strain_modulus_of_an_incompressible_solid_is_four_shear_moduli():
    assert E == pytest.approx(168.0)
    assert damage.plane_strain_modulus(42.0, 0.0) == pytest.approx(84.0)  # E / (1 - 0) with E = 2 mu


@pytest.mark.parametrize("a", [5.0, 60.0, 330.0])
def test_griffith_pressure_releases_exactly_the_fracture_energy(a):
    gc = 51.0 * damage.J_M2
    p = damage.griffith_pressure(a, gc, E)
    assert damage.energy_release_rate(a, p, E) == pytest.approx(gc, rel=1e-12)
    assert damage.griffith_half_length(p, gc, E) == pytest.approx(a, rel=1e-12)


def test_sneddon_area_is_the_integral_of_the_opening_profile():
    a, p = 40.0, 91.0
    area, _ = integrate.quad(lambda x: damage.opening(x, a, p, E), -a, a)
    assert area == pytest.approx(damage.opening_area(a, p, E), rel=1e-8)
    assert damage.opening(a * 1.5, a, p, E) == 0.0


def test_dugdale_tends_to_griffith_for_long_cracks_and_lies_below_for_short_ones():
    """About 1 % below Griffith at a = 5 ell_ch and 6 % below at a = ell_ch; never above the strength."""
    gc, sigma = 51.0 * damage.J_M2, 40.0
    ell = damage.cohesive_length(E, gc, sigma)
    for ratio, below in ((1.0, 0.064), (5.0, 0.014)):
        a = ratio * ell
        rel = damage.dugdale_pressure(a, gc, E, sigma) / damage.griffith_pressure(a, gc, E)
        assert 1.0 - rel == pytest.approx(below, abs=0.002)
    a = 1e4 * ell
    assert damage.dugdale_pressure(a, gc, E, sigma) == pytest.approx(damage.griffith_pressure(a, gc, E), rel=1e-4)
    assert damage.dugdale_pressure(1e-3 * ell, gc, E, sigma) == pytest.approx(sigma)  # short: the strength


def test_a_linear_softening_band_dissipates_the_fracture_energy_at_any_width():
    gc, sigma = 51.0 * damage.J_M2, 40.0
    for h in (2.0, 3.0, 4.0):
        strain = damage.band_softening_strain(gc, sigma, h)
        assert 0.5 * sigma * strain * h == pytest.approx(gc, rel=1e-12)


def test_the_half_length_a_swelling_pool_needs_at_measured_toughness():
    """At Pi(150 mEq/l) = 91 kPa in the media (E' = 4 x 42 kPa), G_c = 51 J/m^2 needs a half-length of ~0.33 mm."""
    a = damage.griffith_half_length(91.0, 51.0 * damage.J_M2, E)
    assert a == pytest.approx(330.0, rel=0.01)
    assert np.all(np.diff(damage.griffith_half_length(91.0, np.array([51.0, 76.0, 159.0]) * damage.J_M2, E)) > 0)


def test_a_swelling_pool_at_its_griffith_concentration_needs_exactly_its_own_half_length():
    """Griffith's criterion for a pool (eqs. 2.25-2.26): Pi at the critical concentration is p_c, so the half-length
    that concentration makes critical is the pool's."""
    gc, a = 51.0 * damage.J_M2, 17.4
    pool = damage.griffith_pool(a, gc, E, 150.0, 300.0, 310.0)
    assert pool.pressure == pytest.approx(damage.griffith_pressure(a, gc, E))
    assert damage.griffith_pool(a, gc, E, pool.concentration, 300.0, 310.0).half_length == pytest.approx(a)
