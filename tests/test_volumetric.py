"""The GAG contents' volumetric term (sphgag.physics.volumetric, ``gag.volumetric``) and the ellipticity of the
swollen contents' law (sphgag.physics.ellipticity)."""

import numpy as np
import pytest

from sphgag import config
from sphgag.physics import ellipticity, volumetric

from .conftest import ROOT

FORMS = list(volumetric.VOLUMETRIC_FORMS)
BULK = [f for f in FORMS if f != volumetric.VOLUMETRIC_FORMS.paper.name]  # the forms with a term


def test_the_registry_holds_the_paper_form_first():
    assert volumetric.VOLUMETRIC_FORMS.paper.name == "none" == FORMS[0]
    assert {"log_squared", "convex"} <= set(FORMS)
    with pytest.raises(ValueError, match="convex"):
        volumetric.form("convext")


@pytest.mark.parametrize("name", FORMS)
def test_the_configuration_names_each_form(ci_config, name):
    cfg = dict(ci_config, gag=dict(ci_config["gag"], volumetric=name))
    config.validate(cfg, ROOT / "config" / "schema.yaml")


def test_the_configuration_refuses_an_unknown_form(ci_config):
    cfg = dict(ci_config, gag=dict(ci_config["gag"], volumetric="cubic"))
    with pytest.raises(config.ConfigError, match="gag.volumetric"):
        config.validate(cfg, ROOT / "config" / "schema.yaml")


@pytest.mark.parametrize("name", BULK)
def test_every_form_has_the_same_small_strain_bulk_modulus(name):
    """u(1) = u'(1) = 0 (stress free at J = 1) and u''(1) = 1: kappa is the bulk modulus U''(1) of every form."""
    u, du, d2u = volumetric.VOLUMETRIC_FORMS[name].terms(1.0)
    assert u == 0.0 and abs(du) < 1e-15 and d2u == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize("name", FORMS)
def test_the_derivatives_are_those_of_the_energy(name):
    """U' and U'' against central differences of U and U', from a compressed to a 50-fold swollen state."""
    form = volumetric.VOLUMETRIC_FORMS[name]
    for J in (0.3, 0.9, 1.7, 2.8, 12.0, 50.0):
        h = 1e-5 * J
        (up, dp, _), (um, dm, _) = form.terms(J + h, 10.0), form.terms(J - h, 10.0)
        _, du, d2u = form.terms(J, 10.0)
        assert du == pytest.approx((up - um) / (2 * h), rel=1e-7, abs=1e-9)
        assert d2u == pytest.approx((dp - dm) / (2 * h), rel=1e-7, abs=1e-9)


@pytest.mark.parametrize("name", FORMS)
def test_the_kernels_acoustic_tensor_is_the_closed_form(name):
    """The smallest eigenvalue of the engine's acoustic tensor at F = sqrt(J) I is min(mu, mu + mu/J + J U'')."""
    for J in (0.5, 1.0, 2.0, 2.8, 7.0, 60.0):
        numeric = ellipticity.swollen_contents(J, name, 0.1, 10.0, directions=36)
        exact = float(ellipticity.equibiaxial_eigenvalue(J, name, 0.1, 10.0))
        assert numeric == pytest.approx(exact, rel=1e-9, abs=1e-12)


@pytest.mark.parametrize("name", FORMS)
def test_the_swollen_contents_stay_elliptic_unless_log_squared(ci_config, name):
    """With the configured mu_GAG = 0.1 and kappa = 10 kPa: the contents of every form but ``log_squared`` stay
    elliptic up to J = 100; ``log_squared`` loses ellipticity where mu (J + 1) + kappa (1 - ln J) = 0, J = 2.82."""
    g = ci_config["gag"]
    mu, kappa = g["shear_modulus_kPa"], g["lame_lambda_kPa"]
    assert (mu, kappa) == (0.1, 10.0)
    J = np.geomspace(1.0, 100.0, 60)
    lowest = np.array([ellipticity.swollen_contents(j, name, mu, kappa) for j in J])
    lost = ellipticity.loss_of_ellipticity(name, mu, kappa)
    assert volumetric.VOLUMETRIC_FORMS[name].elliptic == bool(np.all(lowest > 0.0)) == (lost == np.inf)
    if name == "log_squared":
        root = float(np.exp(1.0 + mu * (lost + 1.0) / kappa))  # mu (J + 1) + kappa (1 - ln J) = 0 at the loss
        assert lost == pytest.approx(root, rel=1e-9)
        assert 2.8 < lost < 2.85
        assert lowest[J < 2.7].min() > 0.0 and lowest[J > 2.9].max() < 0.0


@pytest.mark.parametrize("name", FORMS)
def test_a_prescribed_swelling_pressure_does_not_change_ellipticity(name):
    """-Pi (J - 1) is affine in det F: the acoustic tensor is the same at Pi = 0 and Pi(150 mEq/l) = 91 kPa."""
    for J in (1.0, 2.5, 3.5, 20.0):
        F = np.sqrt(J) * np.eye(2) + np.array([[0.0, 0.3], [-0.1, 0.2]])  # not only the equibiaxial state
        free, swollen = (ellipticity.contents_props(name, 0.1, 10.0, pi) for pi in (0.0, 91.0))
        a = ellipticity.smallest_acoustic_eigenvalue(F, 1.0, free)
        b = ellipticity.smallest_acoustic_eigenvalue(F, 1.0, swollen)
        assert b == pytest.approx(a, rel=1e-9, abs=1e-9 * 91.0)
    lost = [ellipticity.loss_of_ellipticity(name, 0.1, 10.0, pi=pi) for pi in (0.0, 91.0)]
    assert lost[1] == pytest.approx(lost[0], rel=1e-12)  # inf for the elliptic forms
