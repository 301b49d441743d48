"""Growth through snaps (sphgag.engine.snap) and the pool's volume as the control of a swelling path
(sphgag.engine.pool_volume)."""

import dataclasses

import numpy as np
import pytest

from sphgag.engine import geometry, pool_volume, snap, solver
from sphgag.engine.history import DAMAGED, HistoryMaterial, swelling_load
from sphgag.engine.numerics import Numerics
from sphgag.studies import artery
from sphgag.studies.delamination.growth import grow
from sphgag.studies.delamination.runs import load_snapshot, save_snapshots
from sphgag.studies.delamination.settings import Settings
from sphgag.studies.pool_swelling import state_model, swell_pool

from .conftest import CI_NUMERICS, law_gag
from .test_delamination import mirror_map


def prescribed(ci_config) -> dict:
    """The ``gag`` parameters of one run under the paper's law: Pi(c) prescribed (eqs. 2.25-2.27)."""
    return law_gag(ci_config, "prescribed")


# The single pool at 45 deg under the prescribed law, particle onset at 1 kPa, rupture after +0.5 % radial stretch,
# the authors' candidates (the whole window, whose islands are crushed against the pool), the log_squared contents
# (gag.volumetric): its third damage pass has no equilibrium on its path (the transition fails after bisecting it to
# depth 10 too, as measured; two levels keep the test short) and is followed as a snap. With the default convex
# contents, which stay elliptic, the same pass converges on its path (measured: no snap in four passes).
SNAP_PASS = 3


@pytest.fixture(scope="module")
def through_a_snap(ci_config, ci_wall, tmp_path_factory):
    """``(model, result, snapshot file)`` of that run, to one pass beyond the snap, with a snapshot at every pass."""
    base = Settings.from_config(ci_config["delamination"], 1.0, "particle")
    st = dataclasses.replace(
        base,
        max_passes=SNAP_PASS + 1,
        concentration_step_mEq_l=50.0,
        rupture_stretch_increment=0.005,
        candidates="window",
    )
    numerics = Numerics.of(dict(ci_config["numerics"], max_bisections=2))
    model = artery.bilayer_model(ci_config["bilayer"], numerics, name="test-snap")
    sectors = [geometry.Sector(663.0, 45.0, 15.0, 3.0)]
    gag = dict(prescribed(ci_config), volumetric="log_squared")
    args = (sectors, st, numerics, gag, model.props)
    result = grow(model, ci_wall, *args, snapshot_steps=range(SNAP_PASS + 2))
    path = tmp_path_factory.mktemp("snap") / "snapshots.npz"
    save_snapshots(path, model, result.snapshots, {"run": "test-snap"})

    def resume(step):
        k = next(i for i, s in enumerate(result.snapshots) if s[0] == step)
        again = artery.bilayer_model(ci_config["bilayer"], numerics, name="test-snap-resumed")
        snapshot = load_snapshot(path, k, {"run": "test-snap"})
        return grow(again, ci_wall, *args[:-1], again.props, resume=snapshot)

    return model, result, resume


def test_a_state_reached_through_a_snap_is_an_equilibrium_below_tolerance(ci_config, through_a_snap):
    model, result, _ = through_a_snap
    g, tol = result.growth, ci_config["numerics"]["tolerance"]
    snapped = g[g.snap]
    assert result.summary["snaps"] >= 1 and snapped.pseudo_time.iloc[0] == SNAP_PASS
    assert (g.residual < tol).all()
    # the snap ruptured particles (with the window they are islands ahead of the pool: snap_length_um, connected
    # length only, may stay 0)
    before = g[g.pseudo_time < SNAP_PASS].converted_particles.iloc[-1]
    assert snapped.converted_particles.iloc[0] > before and result.summary["snap_length_um"] >= 0
    # the saved state, re-evaluated with its own history, is an equilibrium
    step, state, hist = next(s for s in result.snapshots if s[0] == SNAP_PASS)
    model.set_props(HistoryMaterial(model.props.base, hist, dict(prescribed(ci_config), volumetric="log_squared")))
    assert solver.relative_residual(model, model.evaluate(state.x, state.load)) < tol


def test_the_next_pass_starts_from_the_state_the_snap_reached(through_a_snap):
    """Resumed from the snapped state, the run takes the same next pass as the run that snapped."""
    _, result, resume = through_a_snap
    again = resume(SNAP_PASS)
    assert again.final[1].equals(result.final[1])
    assert np.array_equal(again.final[0].x, result.final[0].x)


def test_a_run_restarted_before_a_snap_reaches_the_same_end_state(through_a_snap):
    _, result, resume = through_a_snap
    again = resume(SNAP_PASS - 1)
    assert again.summary["snaps"] == 1
    assert again.final[1].equals(result.final[1])
    assert np.array_equal(again.final[0].x, result.final[0].x)


def test_a_single_pool_at_45_degrees_grows_symmetrically_through_a_snap(through_a_snap):
    model, result, _ = through_a_snap
    lay = model.layout
    for step, _, hist in result.snapshots:
        damaged = np.flatnonzero(hist.origin == DAMAGED)
        if step < SNAP_PASS:
            continue
        assert set(mirror_map(lay)[damaged]) == set(damaged)
        # both ends of the delaminated arc within one particle of each other
        arc = np.rad2deg(lay.theta[damaged])
        ends = np.array([arc.max() - 45.0, 45.0 - arc.min()]) * np.pi / 180.0 * 663.0
        assert abs(ends[0] - ends[1]) <= lay.dx


def test_a_snap_lands_on_the_equilibrium_the_quasi_static_path_reaches_where_that_is_unique(ci_config, ci_wall):
    """Swelling a seeded pool (conserved charge) from 0 to 150 mEq/l in one pseudo-dynamic snap gives the state the
    bisected quasi-static path gives."""
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=law_gag(ci_config))
    path_solver = CI_NUMERICS.solver(model)
    seeded = swelling_load(ci_wall.load, 1.0, 0.0)
    conv = path_solver.follow_path(ci_wall.x, swelling_load(ci_wall.load, 0.0, 0.0), [seeded])[-1]
    swollen = seeded.with_material(concentration=150.0)
    path = path_solver.follow_path(conv.x, seeded, [swollen])[-1]
    jumped = snap.follow(path_solver, conv.x, swollen)
    assert jumped.convergence.residual < CI_NUMERICS.tolerance
    u = path.x - conv.x
    assert np.abs(jumped.x - path.x).max() < 1e-3 * np.abs(u).max()


def test_no_stable_state_ends_a_snap_with_its_reason(ci_config, ci_wall):
    """A snap that cannot come to rest within its budget is reported, not returned as a state."""
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=law_gag(ci_config))
    load = swelling_load(ci_wall.load, 1.0, 150.0)
    with pytest.raises(snap.NoStableState, match="no equilibrium in 2 steps"):
        snap.follow(CI_NUMERICS.solver(model), ci_wall.x, load, max_steps=2)


# -- the pool's volume as the control --------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def swollen_pool(ci_config, ci_wall):
    """The CI pool of case I under the prescribed law at 50 mEq/l (concentration control), its equilibrium polished
    to a relative residual of 1e-8 (the volume control below solves to that)."""
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=prescribed(ci_config))
    sw = dict(ci_config["swelling"], max_concentration_mEq_l=50.0, concentration_points=3)
    last = swell_pool(model, ci_wall, CI_NUMERICS, sw)[-1]
    polished = solver.Solver(model, dict(tol=1e-8)).follow_path(last.x, last.load, [last.load])[-1]
    return model, solver.State(polished.load, polished.x, model.evaluate(polished.x, polished.load), None)


def test_the_pool_volume_gradient_is_exact(swollen_pool):
    model, state = swollen_pool
    pool = pool_volume.PoolVolume(model, model.props.converting)
    g = pool.gradient(state.x, state.load)
    rng = np.random.default_rng(3)
    d = rng.standard_normal(state.x.shape)
    h = 1e-4
    up = pool(model.evaluate(state.x + h * d, state.load))
    down = pool(model.evaluate(state.x - h * d, state.load))
    assert (up - down) / (2 * h) == pytest.approx(float(np.sum(g * d)), rel=1e-6)


def test_volume_control_holds_the_concentration_path(swollen_pool):
    """At the volume of a concentration-controlled state, volume control finds that state; a larger volume needs a
    higher concentration, and concentration control from there agrees."""
    model, state = swollen_pool
    pool = pool_volume.PoolVolume(model, model.props.converting)
    v0 = pool(state.evaluation)
    same = pool_volume.solve_at_volume(model, pool, state.x, state.load, v0, 1e-8, 20, "test")
    assert same.concentration == pytest.approx(50.0, abs=1e-3)
    bigger = pool_volume.solve_at_volume(model, pool, state.x, state.load, 1.05 * v0, 1e-8, 20, "test")
    assert bigger.concentration > 50.0
    check = solver.Solver(model, dict(tol=1e-8)).follow_path(state.x, state.load, [bigger.load])[-1]
    assert pool(check.evaluation) == pytest.approx(1.05 * v0, rel=1e-6)


def test_volume_control_reaches_a_requested_concentration(ci_config, swollen_pool):
    """From a converged state, the volume-controlled path reaches a requested concentration, and the state it returns
    there is the one concentration control reaches."""
    model, state = swollen_pool
    path_solver = CI_NUMERICS.solver(model).using(tol=1e-8)
    path, reached = pool_volume.continue_path(path_solver, state, model.props.converting, [60.0])
    assert path.end == "complete" and len(reached) == 1
    assert reached[0].load.material_value("concentration") == 60.0
    direct = path_solver.follow_path(state.x, state.load, [reached[0].load])[-1]
    assert np.abs(direct.x - reached[0].x).max() < 1e-4 * np.abs(direct.x - state.x).max()


@pytest.fixture(scope="module")
def swollen_cavity(ci_config, ci_wall):
    """The CI pool of case I as a cavity (swelling.pool_models: cavity) at 50 mEq/l, with the model it is in."""
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=prescribed(ci_config))
    sw = dict(ci_config["swelling"], max_concentration_mEq_l=50.0, concentration_points=3, pool_model="cavity")
    last = swell_pool(model, ci_wall, CI_NUMERICS, sw)[-1]
    assert last.cavity
    hollow = state_model(model, True, last.x)
    return hollow, solver.State(last.load, last.x, hollow.evaluate(last.x, last.load), None)


def test_the_cavitys_volume_is_the_area_its_lining_encloses_with_its_exact_gradient(swollen_cavity):
    model, state = swollen_cavity
    pool = pool_volume.PoolVolume.of(model, model.props.converting)
    assert isinstance(pool, pool_volume.CavityVolume)
    (cavity,) = model.cavities
    assert pool(state.evaluation) == pytest.approx(cavity.pool_area * cavity.volume_ratio(state.x), rel=1e-12)
    g = pool.gradient(state.x, state.load)
    d = np.random.default_rng(5).standard_normal(state.x.shape)
    h = 1e-4
    up, down = pool(model.evaluate(state.x + h * d, state.load)), pool(model.evaluate(state.x - h * d, state.load))
    assert (up - down) / (2 * h) == pytest.approx(float(np.sum(g * d)), rel=1e-6)


def test_volume_control_of_a_cavity_holds_its_concentration_path(swollen_cavity):
    """As for the pool of particles: the cavity's own volume as the control returns the state's concentration, and a
    larger volume a higher one that concentration control confirms."""
    model, state = swollen_cavity
    pool = pool_volume.PoolVolume.of(model, model.props.converting)
    v0 = pool(state.evaluation)
    same = pool_volume.solve_at_volume(model, pool, state.x, state.load, v0, 1e-8, 20, "test")
    assert same.concentration == pytest.approx(50.0, abs=1e-3)
    bigger = pool_volume.solve_at_volume(model, pool, state.x, state.load, 1.05 * v0, 1e-8, 20, "test")
    assert bigger.concentration > 50.0
    check = solver.Solver(model, dict(tol=1e-8)).follow_path(state.x, state.load, [bigger.load])[-1]
    assert pool(check.evaluation) == pytest.approx(1.05 * v0, rel=1e-6)


def test_a_limit_point_is_the_top_of_the_parabola_through_the_largest_concentration():
    points = [(v, 100.0 - (v - 3.0) ** 2) for v in (1.0, 2.0, 2.5, 3.5, 4.0)]
    assert pool_volume._limit(points) == pytest.approx(100.0)
