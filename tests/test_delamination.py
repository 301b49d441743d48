"""Delamination (section 2.7): particle history, the staggered growth protocol, symmetry, restarts."""

import dataclasses

import numpy as np
import pytest
from scipy.spatial import cKDTree

from sphgag.engine import geometry
from sphgag.engine.history import DAMAGED, SEEDED, HistoryMaterial, ParticleHistory
from sphgag.engine.loading import Load
from sphgag.records import state
from sphgag.studies import artery, delamination, protocols

from .conftest import law_gag


@pytest.fixture(scope="module")
def wall(ci_wall):
    """The passive CI wall pressurised to the delamination pressure."""
    return ci_wall


def settings(ci_config, **changes):
    """CI settings with a low sigma_cr, the particle measure and the authors' early rupture increment (0.5 %), so
    that the pools grow within a few passes."""
    base = delamination.Settings.from_config(ci_config["delamination"], 1.0, "particle")
    quick = dict(max_passes=3, concentration_step_mEq_l=50.0, rupture_stretch_increment=0.005)
    return dataclasses.replace(base, **dict(quick, **changes))


def grow(ci_config, wall, sectors, st, **kwargs):
    model = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"], name="test-grow")
    result = delamination.grow(
        model, wall, sectors, st, ci_config["numerics"], law_gag(ci_config), model.props, **kwargs
    )
    return model, result


def mirror_map(layout):
    """Index of every particle's mirror image about 45 deg (the layout is symmetric)."""
    mirrored = layout.X[:, ::-1]
    dist, idx = cKDTree(layout.X).query(mirrored)
    assert dist.max() < 1e-9 * layout.outer_radius
    return idx


def sector(angle, width=3.0):
    return geometry.Sector(663.0, angle, 15.0, width)


# -- particle history and the material it defines ---------------------------------------------------------------


def test_history_is_immutable_and_damage_never_decreases():
    h = ParticleHistory.intact(4).seed([[1]])
    with pytest.raises(ValueError):
        h.D[0] = 0.5
    h2 = h.with_damage([0.0, 0.0, 0.3, 0.0], h.onset_stretch)
    with pytest.raises(ValueError, match="never decreases"):
        h2.with_damage(np.zeros(4), h.onset_stretch)
    h3 = h2.rupture([2], [0], step=5)
    assert h3.origin.tolist() == [0, SEEDED, DAMAGED, 0] and h3.converted_step[2] == 5 and h3.pool[2] == 0
    with pytest.raises(ValueError):
        h3.rupture([1], [0], step=6)  # already GAG


def test_seeded_pool_material_is_the_swelling_material(ci_config):
    """The figure 4 runs are the special case 'pool seeded, no damage': conversion is the history transition."""
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"], pool=pool, gag=law_gag(ci_config))
    base = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"]).props
    load = Load(1.0, 10.0, material=(("concentration", 150.0), ("transition", 1.0)))
    table = model.props(load)
    members = pool.members(model.layout, layer="media")
    assert np.array_equal(np.flatnonzero(np.any(table != base(load), axis=1)), members)
    at_zero = model.props(load.with_material(transition=0.0))
    assert np.array_equal(at_zero, base(load))
    # a load that says nothing of the transition (homeostasis, pressurisation) sees the intact wall
    assert np.array_equal(model.props(Load(1.0, 10.0)), base(Load(1.0, 10.0)))


def test_a_material_path_of_damage_is_linear_in_d_and_ends_at_the_new_history(ci_config):
    base = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"]).props
    n = base(Load()).shape[0]
    before = ParticleHistory.intact(n)
    after = before.with_damage(np.where(np.arange(n) == 3, 0.8, 0.0), before.onset_stretch)
    path = HistoryMaterial(base, before, law_gag(ci_config), after)
    half = path(Load(material=(("transition", 0.5),)))
    intact = base(Load())
    assert np.isclose(half[3, 0], 0.6 * intact[3, 0])
    assert np.array_equal(path(Load(material=(("transition", 1.0),))), path.settled()(Load()))


def test_saved_states_carry_the_history_exactly(tmp_path):
    h = ParticleHistory.intact(5).seed([[0, 1]]).with_damage([0, 0, 0.25, 0, 0], [np.nan, np.nan, 1.01, np.nan, np.nan])
    h = h.rupture([4], [0], 3)
    path = tmp_path / "s.npz"
    state.save(path, np.zeros((5, 2)), Load(), {"a": 1}, history=h)
    back = state.load(path, {"a": 1})
    assert back.history.equals(h)
    assert state.load(path).history.D.flags.writeable is False


# -- the protocol ---------------------------------------------------------------------------------------------------


def test_a_huge_critical_stress_gives_no_growth_and_the_swelling_state(ci_config, wall):
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    st = settings(ci_config, critical_stress_kPa=1e6, criterion="averaged")
    model, result = grow(ci_config, wall, [pool], st)
    assert result.summary["final_length_um"] == 0.0 and np.isnan(result.summary["onset_concentration_mEq_l"])
    assert (result.growth.converted_particles == 0).all() and result.summary["passes"] == 0
    # the same equilibrium as the figure 4 protocol at the highest concentration
    sw = dict(ci_config["swelling"], concentration_points=4, max_concentration_mEq_l=st.max_concentration_mEq_l)
    seeded = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"], pool=pool, gag=law_gag(ci_config))
    table = protocols.pool_table(
        seeded,
        protocols.swell_pool(seeded, wall, ci_config["numerics"], sw),
        pool,
        sw["probe_length_um"],
        law_gag(ci_config),
    )
    final, hist = result.final
    members = np.flatnonzero(hist.gag)
    ours = protocols.pool_measurements(model, final.evaluation, pool, members, sw["probe_length_um"])
    theirs = table.iloc[-1]
    for key in ("tip_radial_stress_kPa", "top_circ_stress_kPa", "pool_volume_change"):
        assert ours[key] == pytest.approx(theirs[key], rel=2e-3, abs=0.05), key


def test_a_run_that_ends_where_its_pools_are_seeded_is_a_row_and_a_summary(ci_config, wall):
    """A matched G_c without growth to match (the paper's law dissipated nothing) ends at the seeded wall: one row at
    c = 0, a summary that says why, no growth."""
    model = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"], name="test-seeded")
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    result = delamination.seeded_only(
        model, wall, [pool], settings(ci_config), ci_config["numerics"], law_gag(ci_config), model.props, "no G_c"
    )
    assert len(result.growth) == 1 and result.growth.concentration_mEq_l.iloc[0] == 0.0
    assert result.summary["stop"] == "no G_c" and result.summary["final_length_um"] == 0.0
    assert result.summary["passes"] == 0 and len(result.snapshots) == 1


def test_every_state_is_below_tolerance_and_damage_grows_the_pool(ci_config, wall):
    st = settings(ci_config)
    _, result = grow(ci_config, wall, [sector(51.5)], st)
    g = result.growth
    assert (g.residual < ci_config["numerics"]["tolerance"]).all()
    assert result.summary["max_residual"] < ci_config["numerics"]["tolerance"]
    assert g.converted_particles.iloc[-1] > 0 and result.summary["dissipated_energy_J_m2"] > 0
    assert np.all(np.diff(g.converted_particles) >= 0) and np.all(np.diff(g.pseudo_time) >= 0)


def test_a_single_pool_at_45_degrees_grows_symmetrically(ci_config, wall):
    model, result = grow(ci_config, wall, [sector(45.0)], settings(ci_config))
    hist = result.final[1]
    damaged = np.flatnonzero(hist.origin == DAMAGED)
    assert damaged.size > 0
    assert set(mirror_map(model.layout)[damaged]) == set(damaged)


def test_two_mirrored_pools_have_mirrored_interior_and_exterior_growth(ci_config, wall):
    # edges off the particle angles, so that the seeded pools are exact mirror images
    model, result = grow(ci_config, wall, [sector(42.1), sector(47.9)], settings(ci_config))
    hist = result.final[1]
    mirror = mirror_map(model.layout)
    seeded = [np.flatnonzero((hist.origin == SEEDED) & (hist.pool == k)) for k in (0, 1)]
    assert set(mirror[seeded[0]]) == set(seeded[1])
    damaged = hist.origin == DAMAGED
    assert damaged.sum() > 0 and set(mirror[np.flatnonzero(damaged)]) == set(np.flatnonzero(damaged))
    off_axis = mirror != np.arange(model.n)  # a particle on 45 deg is its own mirror and joins one pool
    for k, other in ((0, 1), (1, 0)):
        mine = np.flatnonzero(damaged & (hist.pool == k) & off_axis)
        assert set(mirror[mine]) == set(np.flatnonzero(damaged & (hist.pool == other) & off_axis))
    last = result.growth.iloc[-1]
    assert last.converted_interior + last.converted_exterior == last.converted_particles
    assert last.converted_interior > 0 and last.converted_exterior > 0


def test_a_run_restarted_from_a_snapshot_reaches_the_same_end_state(ci_config, wall, tmp_path):
    st = settings(ci_config)
    model, full = grow(ci_config, wall, [sector(51.5)], st)
    path = tmp_path / "snapshots.npz"
    delamination.save_snapshots(path, model, full.snapshots, {"run": "test"})
    steps = [s[0] for s in full.snapshots]
    k = next(i for i, s in enumerate(full.snapshots) if 0 < s[0] < steps[-1])
    resumed_state, resumed_hist, step = delamination.load_snapshot(path, k, {"run": "test"})
    assert resumed_hist.equals(full.snapshots[k][2]) and np.array_equal(resumed_state.x, full.snapshots[k][1].x)
    _, again = grow(ci_config, wall, [sector(51.5)], st, resume=(resumed_state, resumed_hist, step))
    assert again.final[1].equals(full.final[1])
    assert np.array_equal(again.final[0].x, full.final[0].x)
    last = ["pseudo_time", "converted_particles", "delaminated_length_um", "tip_radial_stress_kPa"]
    assert again.growth[last].iloc[-1].equals(full.growth[last].iloc[-1])
