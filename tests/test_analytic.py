"""Closed-form references: thin-walled means and the exact incompressible thick-walled tube."""

import dataclasses

import numpy as np
import pytest
from scipy.integrate import quad

from sphgag.physics import analytic
from sphgag.studies import artery
from sphgag.studies.pressure_diameter import mean_thick_wall


def test_thin_wall_means():
    assert analytic.thin_wall_stress(13.0, 650.0, 40.0) == pytest.approx(13.0 * 650.0 / 40.0)
    assert analytic.thin_wall_stretch(650.0, 40.0, 332.0, 112.0) == pytest.approx(670.0 / 388.0)


def test_neo_hookean_tube_matches_the_stretch_integral():
    """For W = mu/2 (I1 - 3), P = int_{l_b}^{l_a} W'(l) / (l^2 lz - 1) dl (Ogden's form, independent route)."""
    mu, lz, Ri, Ro = 20.0, 1.4, 300.0, 420.0
    tube = analytic.ThickWallTube.single(analytic.Mixture(mu), Ri, Ro, lz)
    for r_in in (260.0, 350.0, 500.0):
        la, lb = r_in / Ri, tube.radius(Ro, r_in) / Ro

        def dW(l):  # d/dl of W(l) = mu/2 (l^2 + lz^2 + 1/(l lz)^2 - 3)
            return mu * (l - 1.0 / (l**3 * lz**2))

        P = quad(lambda l: dW(l) / (l * l * lz - 1.0), lb, la, epsabs=1e-13, epsrel=1e-13)[0]
        assert tube.pressure(r_in) == pytest.approx(P, rel=1e-10)


def test_transmural_state_satisfies_the_boundary_conditions_and_equilibrium(full_config):
    tube = mean_thick_wall(full_config["mean"])
    P = 103 * 0.133322387415
    s = tube.state(P)
    assert s.pressure_kPa == pytest.approx(P, rel=1e-12)
    assert s.radial_stress[0] == pytest.approx(-P, rel=1e-12)
    assert abs(s.radial_stress[-1]) < 1e-10 * P
    # equilibrium of half the tube: int sigma_tt dr = P r_in
    assert np.trapezoid(s.circ_stress, s.radius) == pytest.approx(P * s.r_in, rel=1e-4)
    # incompressibility: the wall area per unit length is conserved
    lz = full_config["mean"]["axial_stretch"]
    area = (s.r_out**2 - s.r_in**2) * lz
    assert area == pytest.approx(tube.R_out**2 - tube.R_in**2, rel=1e-12)


def test_pressure_inverts(full_config):
    tube = mean_thick_wall(full_config["mean"])
    for P in (0.0, 5.0, 26.66):
        assert tube.pressure(tube.inner_radius(P)) == pytest.approx(P, abs=1e-10)


def test_the_walls_fibre_families_are_the_exact_tubes_fields_in_their_order():
    """The SPH wall's families (artery.FibreFamily) reach the exact tube positionally (analytic.Family(*f)), so both
    declare the same fields, with the same defaults, in the same order."""
    fields = dataclasses.fields(analytic.Family)
    assert artery.FibreFamily._fields == tuple(f.name for f in fields)
    defaults = {f.name: f.default for f in fields if f.default is not dataclasses.MISSING}
    assert artery.FibreFamily._field_defaults == defaults
