"""TLSPH forces: patch tests, zero force at rest, conservation, energy consistency, exact Jacobian."""

import numpy as np
import pytest

from sphgag.engine import forces, loading
from sphgag.engine.loading import Load, lumen_area_gradient

from .conftest import assert_jacobian_matches_fd, direct_pair_sum

rng = np.random.default_rng(2018)


def random_affine(scale=0.3):
    while True:
        A = np.eye(2) + scale * rng.standard_normal((2, 2))
        if np.linalg.det(A) > 0.3:
            return A, 50.0 * rng.standard_normal(2)


def rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s], [s, c]])


def total_energy(model, x, load):
    ev = model.evaluate(x, load)
    props, _, _ = model.material(load)
    W = np.empty(model.n)
    forces.energy_densities(ev.F, load.axial_stretch, model.cth, model.sth, props, W)
    return float((model.layout.volume * W).sum())


# --- patch tests --------------------------------------------------------------------------


@pytest.mark.parametrize("trial", range(5))
def test_deformation_gradient_is_exact_for_affine_maps(coarse_mean_model, trial):
    """F_i (eq. 2.9) reproduces any affine map at every particle whose stencil has no ghost."""
    m = coarse_mean_model
    A, c = random_affine()
    ev = m.evaluate(m.layout.X @ A.T + c, Load(1.0, 0.0))
    owner = np.repeat(np.arange(m.n), m.nb.counts())
    has_ghost = np.zeros(m.n, bool)
    has_ghost[owner[m.nb.mirror.min(axis=1) < 0]] = True
    assert (~has_ghost).sum() > m.n // 2
    assert np.abs(ev.F[~has_ghost] - A).max() <= 1e-10


def test_deformation_gradient_is_exact_everywhere_for_symmetric_maps(coarse_mean_model):
    """Maps that respect both mirror planes (diagonal, no translation) are exact at every particle."""
    m = coarse_mean_model
    A = np.diag([1.3, 0.8])
    ev = m.evaluate(m.layout.X @ A.T, Load(1.0, 0.0))
    assert np.abs(ev.F - A).max() <= 1e-10


def test_zero_force_at_rest(coarse_mean_model):
    m = coarse_mean_model
    ev = m.evaluate(m.layout.X.copy(), Load(1.0, 0.0))
    stiffness = m.props[:, 1].max()  # the bulk penalty amplifies round-off in J
    assert np.abs(ev.P).max() < 1e-14 * stiffness
    assert np.abs(ev.f_int).max() < 1e-14 * stiffness * m.layout.volume.max() / m.layout.dx


def test_zero_interior_force_for_an_affine_map(free_lattice_model):
    """A homogeneous deformation of a stressed material leaves interior particles in equilibrium."""
    m = free_lattice_model
    A, c = random_affine(0.2)
    ev = m.evaluate(m.layout.X @ A.T + c, Load(1.0, 0.0))
    assert np.abs(ev.P).max() > 1.0  # the material is stressed
    h = m.nb.h
    X = m.layout.X
    interior = np.all((X >= X.min(0) + 2 * h) & (X <= X.max(0) - 2 * h), axis=1)
    assert interior.sum() >= 9
    scale = np.abs(ev.P).max() * m.layout.volume.max() / m.layout.dx
    assert np.abs(ev.f_int[interior]).max() <= 1e-10 * scale
    # the boundary carries the tractions, and they balance
    assert np.abs(ev.f_int.sum(axis=0)).max() <= 1e-9 * scale


def test_zero_force_for_a_rigid_rotation(free_lattice_model):
    m = free_lattice_model
    Q = rotation(0.7)
    ev = m.evaluate(m.layout.X @ Q.T + np.array([3.0, -2.0]), Load(1.0, 0.0))
    assert np.abs(ev.f_int).max() < 1e-10


def test_forces_are_objective(free_lattice_model):
    """Rotating a deformed state rotates its forces."""
    m = free_lattice_model
    x = m.layout.X * 1.1 + 0.05 * rng.standard_normal(m.layout.X.shape)
    Q = rotation(-1.1)
    f = m.evaluate(x, Load(1.0, 0.0)).f_int
    fq = m.evaluate(x @ Q.T, Load(1.0, 0.0)).f_int
    assert np.abs(fq - f @ Q.T).max() <= 1e-10 * np.abs(f).max()


def test_forces_conserve_linear_and_angular_momentum(free_lattice_model):
    """Internal + hourglass forces of a random deformed free body sum to zero, and so do their moments."""
    m = free_lattice_model
    x = m.layout.X @ random_affine(0.15)[0].T + 0.08 * rng.standard_normal(m.layout.X.shape)
    f = m.evaluate(x, Load(1.3, 0.0)).f_int
    scale = np.abs(f).sum()
    assert np.abs(f.sum(axis=0)).max() <= 1e-12 * scale
    moment = np.sum(x[:, 0] * f[:, 1] - x[:, 1] * f[:, 0])
    assert abs(moment) <= 1e-11 * scale * np.abs(x).max()


def test_internal_force_is_minus_the_energy_gradient(coarse_mean_model):
    """Eq. (2.11) is the exact gradient of sum_i V_i W(F_i) (hourglass off: it has no energy)."""
    m = coarse_mean_model
    saved = m.hourglass_alpha
    m.hourglass_alpha = 0.0
    m.set_props(m.props)
    try:
        load = Load(1.4, 0.0)
        x = m.layout.X * 1.05 + 0.3 * rng.standard_normal(m.layout.X.shape)
        f = m.evaluate(x, load).f_int
        eps = 1e-5
        for k in rng.choice(2 * m.n, 12, replace=False):
            xp, xm = x.copy().ravel(), x.copy().ravel()
            xp[k] += eps
            xm[k] -= eps
            dE = (total_energy(m, xp.reshape(-1, 2), load) - total_energy(m, xm.reshape(-1, 2), load)) / (2 * eps)
            assert -dE == pytest.approx(f.ravel()[k], rel=1e-6, abs=1e-6 * np.abs(f).max())
    finally:
        m.hourglass_alpha = saved
        m.set_props(m.props)


def test_pressure_load_is_the_gradient_of_the_lumen_work(coarse_mean_model):
    m = coarse_mean_model
    inner = m.layout.inner_surface
    x = m.layout.X * 1.2 + 0.5 * rng.standard_normal(m.layout.X.shape)
    g = np.empty((inner.size, 2))
    A0 = lumen_area_gradient(x, inner, g)
    # the polygon closed on the mirror planes encloses the quarter lumen
    r = np.linalg.norm(x[inner], axis=1).mean()
    assert A0 == pytest.approx(np.pi * r * r / 4, rel=0.02)
    eps = 1.0  # the area is linear in each coordinate: central differences are exact
    for k in range(0, inner.size, 3):
        for d in range(2):
            xp, xm = x.copy(), x.copy()
            xp[inner[k], d] += eps
            xm[inner[k], d] -= eps
            fd = (lumen_area_gradient(xp, inner, g.copy()) - lumen_area_gradient(xm, inner, g.copy())) / (2 * eps)
            assert fd == pytest.approx(g[k, d], rel=1e-7, abs=1e-9)
    f = loading.pressure_forces(x, inner, 13.0, 1.5)
    assert np.allclose(f[inner], 13.0 * 1.5 * g)


def test_jacobian_matches_finite_differences(coarse_mean_model):
    """The exact Jacobian (elastic + hourglass + follower pressure) equals central differences."""
    m = coarse_mean_model
    load = Load(1.5, 60 * loading.MMHG_TO_KPA)
    x = m.layout.X * 1.3 + 0.4 * rng.standard_normal(m.layout.X.shape)
    cols = np.concatenate([rng.choice(2 * m.n, 10, replace=False), 2 * m.layout.inner_surface[:2]])
    assert_jacobian_matches_fd(m, load, x, cols)


def test_mirror_ghosts_and_half_list_match_a_direct_sum(printed_mean_model):
    """The fused half-list kernel equals the directed per-entry formula of eqs. (2.11), (2.14) as printed."""
    m = printed_mean_model
    x = m.layout.X * 1.1 + 0.3 * rng.standard_normal(m.layout.X.shape)
    f, f_kernel = direct_pair_sum(m, x, Load(1.2, 0.0))
    assert np.abs(f - f_kernel).max() <= 1e-10 * np.abs(f).max()
