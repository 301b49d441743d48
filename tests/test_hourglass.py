"""The energy form of the hourglass control (sphgag.engine.forces): the gradient of its energy, symmetric and
positive semi-definite, silent for affine maps and rigid rotations, and an exact Jacobian with a GAG interface."""

import dataclasses

import numpy as np
import pytest

from sphgag.engine import kernel, loading
from sphgag.engine.loading import Load
from sphgag.engine.model import Model

from .conftest import Lattice, assert_jacobian_matches_fd, isotropic_props
from .test_interface import with_gag

rng = np.random.default_rng(5)


def energy_form(model: Model) -> Model:
    return dataclasses.replace(model, hourglass="energy")


@pytest.fixture
def patch():
    lay = Lattice(n=10)
    nb = kernel.build_neighbours(lay.X, lay.volume, 2.5, mirrors=())
    return Model("patch", lay, nb, isotropic_props(lay.n), 1.0, hourglass="energy")


def direct_energy(model: Model, x: np.ndarray, load: Load) -> float:
    """``sum_e c_e/2 |F~_i R_e - r_e|^2`` entry by entry, with F~ of the hourglass stencil."""
    paper = dataclasses.replace(model, hourglass="paper")
    ev = paper.evaluate(x, load)
    _, hgc, _ = paper.material(load)
    nb = model.nb
    owner = np.repeat(np.arange(model.n), nb.counts())
    r = nb.mirror * x[nb.nbr] - x[owner]
    d = np.einsum("eab,eb->ea", ev.F_hourglass[owner], nb.R) - r
    return 0.5 * float(np.sum(hgc * np.sum(d * d, axis=1)))


def test_forces_are_the_gradient_of_the_pair_energy(patch):
    load = Load(1.0, 0.0)
    x = patch.layout.X * 1.1 + 0.05 * rng.standard_normal(patch.layout.X.shape)
    f = patch.hourglass_forces(x, load)
    eps = 1e-6
    for k in rng.choice(2 * patch.n, 8, replace=False):
        xp, xm = x.copy().ravel(), x.copy().ravel()
        xp[k] += eps
        xm[k] -= eps
        up, um = direct_energy(patch, xp.reshape(-1, 2), load), direct_energy(patch, xm.reshape(-1, 2), load)
        fd = -(up - um) / (2 * eps)
        assert f.ravel()[k] == pytest.approx(fd, rel=1e-6, abs=1e-9 * np.abs(f).max())
    u = (x - patch.layout.X).ravel()
    assert -0.5 * u @ f.ravel() == pytest.approx(direct_energy(patch, x, load), rel=1e-10)


def test_stiffness_is_symmetric_positive_semidefinite_and_silent_for_affine_maps(patch):
    load = Load(1.0, 0.0)
    patch.material(load)
    K = patch.hourglass_matrix(load).toarray()
    assert np.abs(K - K.T).max() <= 1e-12 * np.abs(K).max()
    assert np.linalg.eigvalsh(K).min() >= -1e-10 * np.abs(K).max()
    X = patch.layout.X
    c, s = np.cos(0.7), np.sin(0.7)
    for A in (np.array([[1.3, 0.2], [-0.1, 0.8]]), np.array([[c, -s], [s, c]])):
        assert np.abs(patch.hourglass_forces(X @ A.T + [3.0, -2.0], load)).max() <= 1e-10 * np.abs(K).max()


def test_jacobian_with_an_interface_matches_finite_differences(coarse_mean_model):
    """Elastic + energy hourglass across a GAG band + Donnan + pressure: exact Jacobian vs central differences."""
    m = energy_form(coarse_mean_model)
    r = np.linalg.norm(m.layout.X, axis=1)
    band = np.flatnonzero((r > 370) & (r < 400) & (m.layout.theta < 0.6))
    m.set_props(with_gag(m, band, fixed_charge=(120.0, 300.0, 310.0)))
    x = m.layout.X * 1.2 + 0.3 * rng.standard_normal(m.layout.X.shape)
    cols = np.concatenate([2 * band[:4], rng.choice(2 * m.n, 6, replace=False)])
    assert_jacobian_matches_fd(m, Load(1.3, 40 * loading.MMHG_TO_KPA), x, cols)
    assert m.material(Load(1.0, 0.0))[1].max() == 0.0  # no eq. (2.14) pair forces under the energy form


def test_unknown_form_is_rejected(patch):
    with pytest.raises(ValueError, match="hourglass form 'pairs'"):
        dataclasses.replace(patch, hourglass="pairs")
