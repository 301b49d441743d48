"""A pool as a pressurised cavity (sphgag.engine.pool_cavity): the lining's forces are the gradient of the work
of the pressure, the Jacobian with the contents' rank-one term is exact, and a swollen circular cavity
follows the exact large-strain solution (sphgag.physics.cavity)."""

import dataclasses

import numpy as np
import pytest

from sphgag.engine import loading, pool_cavity, solver
from sphgag.engine.loading import Load
from sphgag.engine.numerics import Numerics
from sphgag.physics import materials
from sphgag.studies import swollen_pool

rng = np.random.default_rng(11)


# the contents' stiffness w''(J) per reference area of each volumetric form (kappa, lz), in closed form
CONTENTS_STIFFNESS = {
    "none": lambda J, mu, kappa, lz: mu / J**2,
    "log_squared": lambda J, mu, kappa, lz: (mu + kappa * (1.0 - np.log(J * lz))) / J**2,
    "convex": lambda J, mu, kappa, lz: (mu + kappa) / J**2,
    "hartmann_neff": lambda J, mu, kappa, lz: mu / J**2 + kappa * lz**2 * (1.0 + 3.0 / (J * lz) ** 4) / 4.0,
}


def band(m, form="log_squared"):
    """The coarse mean model ``m`` with a medial band of GAG (prescribed Pi = 30 kPa, the contents' volumetric term
    ``form`` with kappa = 1 kPa) as a cavity."""
    r = np.linalg.norm(m.layout.X, axis=1)
    th = m.layout.theta
    members = np.flatnonzero((r > 375) & (r < 400) & (th > 0.5) & (th < 0.8))
    p = np.array(m.props, dtype=float)
    materials.convert_to_gag(p, members, 1.0, 0.1, 18.53, kappa=1.0, volumetric=form)
    p[members, materials.PI] = 30.0
    cav = pool_cavity.Cavity.around(m.layout, members, m.layout.X)
    return dataclasses.replace(m, props=p, cavities=(cav,)), cav


@pytest.fixture
def band_cavity(coarse_mean_model):
    """:func:`band` of the coarse mean model."""
    return band(coarse_mean_model)


def test_the_lining_is_a_simple_loop_around_the_pool(band_cavity):
    model, cav = band_cavity
    X = model.layout.X
    assert cav.loop_area0 > cav.pool_area > 0.0  # the loop runs through the lining's centres, outside the pool
    q = X[cav.loop]
    steps = np.linalg.norm(np.roll(q, -1, axis=0) - q, axis=1)
    assert steps.max() <= 1.5 * model.layout.dx * 1.01  # neighbours along the loop, no jump across the pool
    assert cav.volume_ratio(X) == pytest.approx(1.0)


def test_area_gradient_matches_differences(band_cavity):
    _, cav = band_cavity
    x = band_cavity[0].layout.X * 1.1 + 0.2 * rng.standard_normal(band_cavity[0].layout.X.shape)
    g = cav.area_gradient(x)
    eps = 1e-6
    for k in rng.choice(cav.loop.size, 5, replace=False):
        for c in range(2):
            xp, xm = x.copy(), x.copy()
            xp[cav.loop[k], c] += eps
            xm[cav.loop[k], c] -= eps
            assert g[k, c] == pytest.approx((cav.area(xp) - cav.area(xm)) / (2 * eps), rel=1e-6)


@pytest.mark.parametrize("form", list(CONTENTS_STIFFNESS))
def test_jacobian_with_the_contents_rank_one_term_is_exact(coarse_mean_model, form):
    """Central differences of the residual equal the model's sparse Jacobian plus its rank-one terms
    (``-w''(J)/V_pool dA/dx dA/dx^T``, in closed form for each volumetric form of the contents), and the solver's
    factorisation solves that full matrix (Sherman-Morrison)."""
    model, cav = band(coarse_mean_model, form)
    load = Load(1.3, 40 * loading.MMHG_TO_KPA)
    x = model.layout.X * 1.05 + 0.1 * rng.standard_normal(model.layout.X.shape)
    x[cav.loop] *= 1.02  # a swollen pool
    ev = model.evaluate(x, load)
    data = model.jacobian(ev)
    Jm = model.block_matrix(data).toarray()
    ((c, g),) = model.rank_one_terms(ev)
    J = cav.volume_ratio(x)
    stiffness = CONTENTS_STIFFNESS[form](J, 0.1, 1.0, load.axial_stretch)
    assert c == pytest.approx(-stiffness / cav.pool_area, rel=1e-12)
    Jm += c * np.outer(g, g)
    eps = 1e-6
    cols = np.concatenate([2 * cav.loop[:3], 2 * cav.loop[3:6] + 1, rng.choice(2 * model.n, 4, replace=False)])
    free = np.ones(2 * model.n, dtype=bool)
    free[np.concatenate([2 * cav.members, 2 * cav.members + 1])] = False
    for k in cols:
        xp, xm = x.copy().ravel(), x.copy().ravel()
        xp[k] += eps
        xm[k] -= eps
        ep, em = model.evaluate(xp.reshape(-1, 2), load), model.evaluate(xm.reshape(-1, 2), load)
        fd = (ep.residual_vector - em.residual_vector).ravel() / (2 * eps)
        assert np.abs(fd[free] - Jm[free, k]).max() <= 1e-6 * np.abs(fd).max()
    # the factorisation solves the full matrix (constrained rows: scale * identity)
    fac = solver.factorise(model, ev, data.copy(), 0.0, "test")
    full = Jm.copy()
    fixed = np.flatnonzero(~free)
    full[fixed] = 0.0
    full[fixed, fixed] = fac.scale
    rhs = rng.standard_normal(2 * model.n)
    assert np.allclose(full @ fac.solve(rhs), rhs, atol=1e-9 * np.abs(rhs).max())


def test_a_cavity_with_a_conserved_charge_is_rejected(band_cavity):
    model, cav = band_cavity
    p = np.array(model.props)
    p[cav.members, materials.FCD] = 100.0
    bad = dataclasses.replace(model, props=p)
    with pytest.raises(ValueError, match="prescribed"):
        bad.evaluate(model.layout.X, Load(1.0, 0.0))


def test_circular_cavity_converges_to_the_exact_large_strain_solution(ci_config):
    """A circular cavity (radius 15 um, annulus to 60 um, the elastin matrix) swollen to J = 4 and 10: the errors of
    the volume ratio and of the lining's radius fall from dx = 3 to 2 um, to within 4 % at 2 um (measured: volume
    +4.1 / +1.9 % at J = 4, +7.3 / +3.3 % at J = 10)."""
    b = ci_config["bilayer"]
    matrix = dict(
        shear_modulus_kPa=b["elastin_shear_modulus_kPa"],
        lame_lambda_kPa=b["lame_lambda_kPa"],
        hourglass_modulus_kPa=b["hourglass_modulus_kPa"],
    )
    vc = dict(radius_um=15.0, outer_radius_um=60.0, dx_um=[3.0, 2.0], volume_ratios=[4.0, 10.0], steps=10)
    numerics = Numerics.of(dict(ci_config["numerics"], hourglass="energy"))
    table = swollen_pool.circle_study(vc, matrix, ci_config["gag"], numerics, pool_model="cavity")
    for column in ("volume_error", "lining_error"):
        err = np.abs(table.pivot(index="target_volume_ratio", columns="dx_um", values=column))
        assert np.all(err[2.0] < err[3.0]) and np.all(err[2.0] < 0.04)
    assert np.all(table.residual < ci_config["numerics"]["tolerance"])
