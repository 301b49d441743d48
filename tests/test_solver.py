"""Factorisation reuse (chord steps with a stale LU): same equilibria as fresh Newton, never a state above tolerance."""

import dataclasses

import numpy as np
import pytest

from sphgag.engine import solver
from sphgag.engine.history import swelling_load
from sphgag.engine.loading import MMHG_TO_KPA, Load
from sphgag.engine.solver import PathOptions
from sphgag.studies import artery
from sphgag.studies.wall_loading import homeostasis, pressurise

from .conftest import CI_NUMERICS, law_gag


@pytest.fixture(scope="module")
def wall(ci_config):
    """The passive CI wall with a pool of case I, pressurised to 103 mmHg (pool still intact)."""
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(
        ci_config["bilayer"], CI_NUMERICS, name="test-solver", pool=pool, gag=law_gag(ci_config)
    )
    path_solver = CI_NUMERICS.solver(model)
    h = homeostasis(model, CI_NUMERICS, ci_config["homeostasis"], path_solver=path_solver)
    return model, pressurise(model, h.state, 103.0, CI_NUMERICS, path_solver=path_solver)


def both_ways(model, x, start, targets, tol):
    """The path solved without and with chord steps, each by a solver of its own (an empty cache)."""
    return {
        reuse: solver.Solver(model, PathOptions(tol=tol, reuse=reuse)).follow_path(x, start, targets)
        for reuse in (False, True)
    }


@pytest.mark.parametrize("path", ["pressure", "swelling"])
def test_reuse_reaches_the_same_equilibria_as_fresh_newton(wall, path):
    """A pressure ramp (103 -> 110 mmHg) and a conversion + swelling path (0 -> 150 mEq/l), solved to a tight
    tolerance (1e-8) both ways: every state is below it and the two agree to 1e-6 of the displacement. (At the
    working tolerance 1e-4 two states may differ by ~0.2 % of the displacement, whichever solver made them.)"""
    model, start = wall
    base = start.load
    if path == "pressure":
        targets = [Load(1.0, base.pressure_kPa + k * MMHG_TO_KPA, material=base.material) for k in range(1, 8)]
        begin = base
    else:
        begin = swelling_load(base, 0.0, 0.0)
        targets = [swelling_load(base, f, 0.0) for f in (0.25, 0.5, 0.75, 1.0)]
        targets += [swelling_load(base, 1.0, c) for c in (50.0, 100.0, 150.0)]
    tol = 1e-8
    runs = both_ways(model, start.x, begin, targets, tol)
    fresh, reused = runs[False], runs[True]
    assert all(s.convergence.residual < tol for s in fresh + reused)
    scale = np.abs(fresh[-1].x - start.x).max()
    for a, b in zip(fresh, reused):
        assert np.abs(a.x - b.x).max() <= 1e-6 * scale
    assert sum(s.convergence.jacobians for s in reused) < sum(s.convergence.jacobians for s in fresh)


def test_a_stale_factorisation_never_lets_a_state_through_above_tolerance(wall):
    """A factorisation of another state (the unloaded reference, with its constraint rows) or a wrong one
    (the Jacobian scaled by 50) only shapes the steps: the accepted state meets the tolerance."""
    model, start = wall
    target = Load(1.0, start.load.pressure_kPa + 5 * MMHG_TO_KPA, material=start.load.material)
    ref = model.evaluate(model.layout.X, start.load)
    wrong = [
        solver.factorise(model, ref, model.jacobian(ref), 0.0, "test"),
        solver.factorise(model, ref, 50.0 * model.jacobian(ref), 0.0, "test"),
    ]
    for fac in wrong:
        for tol in (1e-4, 1e-7):
            stale = solver.Solver(model, PathOptions(tol=tol, reuse=True))
            stale.cache.keep(fac)
            x, ev, conv = stale.newton(start.x, target)
            assert conv.residual < tol
            assert solver.relative_residual(model, ev) < tol


def test_a_misspelt_material_name_raises():
    load = Load(1.0, 0.0, material=(("concentration", 50.0),))
    assert load.material_value("concentration") == 50.0
    assert load.material_value("activation", 0.0) == 0.0  # a known name the load does not carry
    with pytest.raises(KeyError, match="'concentraton' is not a material value"):
        load.material_value("concentraton", 0.0)
    with pytest.raises(KeyError, match="'activaton'"):
        load.with_material(activaton=1.0)
    with pytest.raises(KeyError, match="'prestrech'"):
        Load(1.0, 0.0, material=(("prestrech", 1.0),))


def test_every_solver_keeps_a_factorisation_cache_of_its_own(ci_config):
    """A solver's cache is its own (a second solver of the same model starts empty) and is shared with the solvers
    :meth:`Solver.using` makes (other options, the same paths); a damped factorisation is not kept, and ``reset``
    forgets an undamped one."""
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-cache")
    first = CI_NUMERICS.solver(model)
    second = solver.Solver(model, first.options)
    assert first.cache is not second.cache and first.cache.factorisation is None
    fac = solver.Factorisation(lambda rhs: rhs, 1.0, np.empty(0, dtype=np.int64), 0.0)
    first.cache.keep(fac)
    assert first.cache.factorisation is fac and second.cache.factorisation is None
    transition = first.using(first.options.for_transition())
    assert transition.cache is first.cache and transition.model is model
    assert transition.options.stall == solver.STALL_ITERATIONS and first.options.stall is None
    first.cache.keep(dataclasses.replace(fac, damping=1e-4))
    assert first.cache.factorisation is None
    first.cache.keep(fac)
    transition.reset()
    assert first.cache.factorisation is None


def test_a_replaced_model_starts_with_empty_derived_data(ci_config):
    """``dataclasses.replace`` gives a model its own derived-data cache (material tables, hourglass stencil), empty,
    whatever the model it was made from holds; the cache is no field of its constructor, its repr or its equality."""
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-replace")
    load = Load(1.0, 0.0)
    model.material(load)
    assert model._cache
    copy = dataclasses.replace(model, name="test-replace-copy")
    assert copy._cache == {} and copy._cache is not model._cache
    assert np.array_equal(copy.material(load)[0], model.material(load)[0])
    with pytest.raises(ValueError, match="_cache"):
        dataclasses.replace(model, _cache={})
    assert "_cache" not in repr(copy)
