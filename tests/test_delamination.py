"""Delamination (section 2.7): particle history, the staggered growth protocol, symmetry, restarts."""

import dataclasses
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.spatial import cKDTree

from sphgag.engine import geometry, solver
from sphgag.engine.history import DAMAGED, SEEDED, HistoryMaterial, ParticleHistory
from sphgag.engine.loading import Load
from sphgag.physics import donnan
from sphgag.records import state
from sphgag.studies import artery
from sphgag.studies.delamination import growth
from sphgag.studies.delamination.front import Front
from sphgag.studies.delamination.growth import DamageUpdate, GrowthRun, seeded_only
from sphgag.studies.delamination.runs import load_snapshot, save_snapshots
from sphgag.studies.delamination.settings import Settings
from sphgag.studies.delamination.tables import GROWTH_COLUMNS, Stop, labelled
from sphgag.studies.pool_swelling import pool_measurements, pool_table, swell_pool
from sphgag.studies.wall_loading import homeostasis, pressurise

from .conftest import CI_NUMERICS, law_gag


@pytest.fixture(scope="module")
def wall(ci_wall):
    """The passive CI wall pressurised to the delamination pressure."""
    return ci_wall


def settings(ci_config, **changes):
    """CI settings (the particles touching a pool are the candidates, the particle measure) in which every candidate
    starts damage at once (sigma_cr = -100 kPa: at the CI spacing, 6 um, the particles touching a case I pool are in
    radial compression up to 300 mEq/l under the conserved law) and ruptures after the authors' early increment of
    radial stretch (0.5 %), so that the pools grow a column at each end per level of the ramp (50, 100, 150 mEq/l)."""
    base = Settings.from_config(ci_config["delamination"], -100.0, "particle")
    quick = dict(max_passes=3, concentration_step_mEq_l=50.0, rupture_stretch_increment=0.005, candidates="contact")
    return dataclasses.replace(base, **dict(quick, **changes))


def grow(ci_config, wall, sectors, st, **kwargs):
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-grow")
    result = growth.grow(model, wall, sectors, st, CI_NUMERICS, law_gag(ci_config), model.props, **kwargs)
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
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=law_gag(ci_config))
    base = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS).props
    load = Load(1.0, 10.0, material=(("concentration", 150.0), ("transition", 1.0)))
    table = model.props(load)
    members = pool.members(model.layout, layer="media")
    assert np.array_equal(np.flatnonzero(np.any(table != base(load), axis=1)), members)
    at_zero = model.props(load.with_material(transition=0.0))
    assert np.array_equal(at_zero, base(load))
    # a load that says nothing of the transition (homeostasis, pressurisation) sees the intact wall
    assert np.array_equal(model.props(Load(1.0, 10.0)), base(Load(1.0, 10.0)))


def test_a_material_path_of_damage_is_linear_in_d_and_ends_at_the_new_history(ci_config):
    base = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS).props
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
    seeded = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=law_gag(ci_config))
    table = pool_table(
        seeded, swell_pool(seeded, wall, CI_NUMERICS, sw), pool, sw["probe_length_um"], law_gag(ci_config)
    )
    final, hist = result.final
    members = np.flatnonzero(hist.gag)
    ours = pool_measurements(model, final.evaluation, pool, members, sw["probe_length_um"])
    theirs = table.iloc[-1]
    for key in ("tip_radial_stress_kPa", "top_circ_stress_kPa", "pool_volume_change"):
        assert ours[key] == pytest.approx(theirs[key], rel=2e-3, abs=0.05), key


def test_a_run_that_ends_where_its_pools_are_seeded_is_a_row_and_a_summary(ci_config, wall):
    """A matched G_c without growth to match (the paper's law dissipated nothing) ends at the seeded wall: one row at
    c = 0, a summary that says why, no growth."""
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-seeded")
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    result = seeded_only(
        model, wall, [pool], settings(ci_config), CI_NUMERICS, law_gag(ci_config), model.props, "no G_c"
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
    save_snapshots(path, model, full.snapshots, {"run": "test"})
    steps = [s[0] for s in full.snapshots]
    k = next(i for i, s in enumerate(full.snapshots) if 0 < s[0] < steps[-1])
    resumed_state, resumed_hist, step = load_snapshot(path, k, {"run": "test"})
    assert resumed_hist.equals(full.snapshots[k][2]) and np.array_equal(resumed_state.x, full.snapshots[k][1].x)
    _, again = grow(ci_config, wall, [sector(51.5)], st, resume=(resumed_state, resumed_hist, step))
    assert again.final[1].equals(full.final[1])
    assert np.array_equal(again.final[0].x, full.final[0].x)
    last = ["pseudo_time", "converted_particles", "delaminated_length_um", "tip_radial_stress_kPa"]
    assert again.growth[last].iloc[-1].equals(full.growth[last].iloc[-1])


# -- damage candidates and islands ---------------------------------------------------------------------


@pytest.fixture(scope="module")
def layout(ci_config):
    """The CI bi-layered wall's particles (dx = 6 um)."""
    return artery.bilayer_layout(ci_config["bilayer"])


def front(layout, sectors, rule, window_deg=5.0):
    return Front(SimpleNamespace(layout=layout), sectors, window_deg, rule)


def seeded(layout, sectors):
    return ParticleHistory.intact(layout.n).seed([s.members(layout, layer="media") for s in sectors])


def ahead(layout, band, hist, pool, lo, hi):
    """The particles of ``band`` whose arc beyond the upper angular edge of ``pool`` lies in (lo, hi] spacings."""
    arc = (layout.theta - layout.theta[hist.members(pool)].max()) * layout.radius / layout.dx
    return np.flatnonzero(band & (arc > lo) & (arc <= hi))


def distance(layout, a, b):
    """The smallest reference distance between the particles ``a`` and ``b`` (every pair)."""
    return float(np.linalg.norm(layout.X[a][:, None] - layout.X[b][None], axis=-1).min())


def window_candidates(layout, sectors, hist, window_deg):
    """The candidates of the authors' script (Front.candidates before the candidate rules), copied: ``window``'s
    reference."""
    surface = np.zeros(layout.n, dtype=bool)
    surface[layout.inner_surface] = surface[layout.outer_surface] = True
    interior = layout.layer_mask("media") & ~surface
    bands = [(layout.radius >= s.r_range[0]) & (layout.radius <= s.r_range[1]) for s in sectors]
    th, w = layout.theta, np.deg2rad(window_deg)
    best, pool = np.full(hist.n, np.inf), np.full(hist.n, -1)
    for k, band in enumerate(bands):
        members = hist.members(k)
        lo, hi = th[members].min(), th[members].max()
        dist = np.maximum(lo - th, th - hi)
        ok = band & interior & ~hist.gag & (dist <= w) & (dist < best)
        best[ok], pool[ok] = dist[ok], k
    idx = np.flatnonzero(pool >= 0)
    return idx, pool[idx]


@pytest.fixture(scope="module")
def island_history(layout):
    """A case I pool at 51.5 deg, the column of its band touching its upper end converted (connected), and two
    columns 3.5-5.5 spacings beyond its end converted (an island): ``(sector, history, connected, island)``."""
    pool = sector(51.5)
    hist = seeded(layout, [pool])
    band = front(layout, [pool], "window").bands[0] & layout.layer_mask("media")
    connected = ahead(layout, band, hist, 0, 0.0, 1.2)
    island = ahead(layout, band, hist, 0, 3.5, 5.5)
    assert connected.size and island.size
    converted = np.concatenate([connected, island])
    return pool, hist.rupture(converted, np.zeros(converted.size), 1), (connected, island)


def test_the_delaminated_length_counts_the_damage_connected_to_its_pool_and_islands_apart(layout, island_history):
    pool, hist, (connected, island) = island_history
    f = front(layout, [pool], "window")
    V = layout.volume
    assert f.converted(hist)[0] == connected.size + island.size  # converted_particles counts both
    assert f.delaminated_length(hist) == pytest.approx(V[connected].sum() / 15.0, rel=1e-12)
    found = f.islands(hist)
    pool_now = np.concatenate([hist.members(0)[hist.origin[hist.members(0)] == SEEDED], connected])
    assert (found.count, found.particles) == (1, island.size)
    assert found.distance_um == pytest.approx(distance(layout, island, pool_now), rel=1e-12)
    assert found.distance_um > 1.5 * layout.dx
    # the particles between them converted: one pool, every converted particle counts
    band = f.bands[0] & layout.layer_mask("media")
    bridge = ahead(layout, band, seeded(layout, [pool]), 0, 1.2, 3.5)
    joined = hist.rupture(bridge, np.zeros(bridge.size), 2)
    none = f.islands(joined)
    assert none.count == 0 and none.particles == 0 and np.isnan(none.distance_um)
    damaged = joined.origin == DAMAGED
    assert f.delaminated_length(joined) == pytest.approx(V[damaged].sum() / 15.0, rel=1e-12)
    assert f.delaminated_length(joined) > f.delaminated_length(hist) + V[island].sum() / 15.0


@pytest.mark.parametrize("pools", [[51.5], [42.1, 47.9]])
def test_contact_candidates_touch_their_pool_and_window_candidates_are_the_authors(layout, island_history, pools):
    """``contact``: every candidate has a GAG particle of its pool within 1.5 dx (reference positions), and lies in
    the window; ``window``: the candidates of the code before the candidate rules (the authors' script), unchanged."""
    sectors = [sector(a) for a in pools]
    histories = [seeded(layout, sectors)]
    if len(pools) == 1:
        histories.append(island_history[1])  # the window follows the island; contact touches it, too
    for hist in histories:
        old = window_candidates(layout, sectors, hist, 5.0)
        idx, owner = front(layout, sectors, "window").candidates(hist)
        assert np.array_equal(idx, old[0]) and np.array_equal(owner, old[1])
        near, near_owner = front(layout, sectors, "contact").candidates(hist)
        assert 0 < near.size < idx.size and set(near) <= set(idx)
        for i, k in zip(near, near_owner):
            assert distance(layout, [i], hist.members(k)) <= 1.5 * layout.dx * (1 + 1e-12)
        far = np.setdiff1d(idx, near)
        assert all(
            distance(layout, [i], hist.members(k)) > 1.5 * layout.dx for i, k in zip(far, owner[np.isin(idx, far)])
        )
    # the window bounds contact: a window of about one spacing (0.5 deg) keeps the touching particles within it
    hist = histories[0]
    near = front(layout, sectors, "contact").candidates(hist)[0]
    narrow, narrow_owner = front(layout, sectors, "contact", window_deg=0.5).candidates(hist)
    assert 0 < narrow.size < near.size and set(narrow) <= set(near)
    for i, k in zip(narrow, narrow_owner):
        th = layout.theta[hist.members(k)]
        assert max(th.min() - layout.theta[i], layout.theta[i] - th.max()) <= np.deg2rad(0.5)


def test_a_settings_candidate_rule_must_be_a_registered_one(ci_config):
    assert "candidates" in Settings.config_keys()  # a run-level setting in the rules' params
    with pytest.raises(ValueError, match="candidates must be one of contact, window, got 'foo'"):
        settings(ci_config, candidates="foo")


def test_growth_by_contact_leaves_no_island_and_the_window_does(ci_config, wall):
    """A real growth run at the CI spacing: with the paper's candidates (contact) the pool grows (by 5 particles in
    its 3 passes, from 300 mEq/l on) and never leaves an island; with the authors' window (the same settings: its
    pass limit comes at 150 mEq/l) the damage converts particles ahead of the pool that are not connected to it, and
    those are not delaminated length."""
    st = settings(ci_config, critical_stress_kPa=1.0, max_concentration_mEq_l=500.0)
    model, result = grow(ci_config, wall, [sector(51.5)], st)
    g = result.growth
    assert (g.islands == 0).all() and (g.island_particles == 0).all() and g.island_distance_um.isna().all()
    assert g.converted_particles.iloc[-1] >= 4 and result.summary["islands"] == 0
    damaged = result.final[1].origin == DAMAGED
    assert g.delaminated_length_um.iloc[-1] == pytest.approx(model.layout.volume[damaged].sum() / 15.0)
    growth, summary = labelled(result, "single", st, model.layout.dx)
    assert list(growth.columns) == GROWTH_COLUMNS and (growth.candidates == "contact").all()
    assert {"islands", "island_particles", "island_distance_um", "candidates"} <= set(summary.columns)

    _, window = grow(ci_config, wall, [sector(51.5)], dataclasses.replace(st, candidates="window"))
    w, hist = window.growth, window.final[1]
    assert (w.islands > 0).any() and (w.island_distance_um[w.islands > 0] > 1.5 * model.layout.dx).all()
    assert window.summary["islands"] > 0 and window.summary["island_particles"] > 0
    damaged = hist.origin == DAMAGED
    assert window.summary["final_length_um"] < model.layout.volume[damaged].sum() / 15.0


# -- how a run ends, and the concentrations of its events -----------------------------------------------------------


def runaway_settings(ci_config, **changes):
    """Growth that does not arrest at a fixed concentration at the CI spacing: the paper's contact candidates, a low
    sigma_cr (1 kPa) and the authors' early rupture increment (0.5 %), a ramp of 50 mEq/l steps to 500 mEq/l, a
    pass budget that is never the limit and a cap of 15 deg on a pool's extent (a wall that looks unbounded to the
    pool: it runs away long before a symmetry edge)."""
    quick = dict(critical_stress_kPa=1.0, max_concentration_mEq_l=500.0, max_passes=400, max_extent_deg=15.0)
    return settings(ci_config, **dict(quick, **changes))


def test_a_pool_that_grows_without_arrest_is_unstable_with_its_runaway_concentration_bisected(ci_config, wall):
    st = runaway_settings(ci_config)
    _, result = grow(ci_config, wall, [sector(51.5)], st)
    s, g = result.summary, result.growth
    assert s["stop_kind"] == "unstable" and s["stop"].startswith("growth at a fixed concentration did not arrest")
    level = s["stop_level_mEq_l"]
    assert f"c = {level:g} mEq/l, {s['passes']} passes" in s["stop"]  # the stop names the level and the pass
    # the runaway concentration lies between the last level that arrested and the first that did not, to the
    # bisection's bracket, and the onset lies at or below it
    step = st.concentration_step_mEq_l
    assert level - step < s["runaway_concentration_mEq_l"] <= level
    assert s["onset_concentration_mEq_l"] <= s["runaway_concentration_mEq_l"] + st.bisection_tolerance_mEq_l / 2
    # growth at the last level carried the pool to the cap, from the length at which the level before came to rest
    before = g[g.concentration_mEq_l < level - 1e-9]
    assert s["arrested_length_um"] == pytest.approx(before.delaminated_length_um.iloc[-1])
    assert s["final_length_um"] > s["arrested_length_um"] and np.isfinite(s["dissipated_energy_J_m2"])
    assert (g.residual < ci_config["numerics"]["tolerance"]).all()


def test_the_bisected_onset_lies_within_half_the_bracket_of_where_the_measure_crosses_sigma_cr(ci_config, wall):
    """Runs of the seeded pool at the bisected onset concentration -+ half the bracket: below it no candidate
    reaches sigma_cr, above it one does."""
    st = runaway_settings(ci_config, critical_stress_kPa=20.0, max_concentration_mEq_l=350.0)
    _, result = grow(ci_config, wall, [sector(51.5)], st)
    onset = result.summary["onset_concentration_mEq_l"]
    assert np.isfinite(onset) and result.summary["onset_level_mEq_l"] - st.concentration_step_mEq_l < onset
    half = st.bisection_tolerance_mEq_l / 2
    for c, reached in ((onset - half, False), (onset + half, True)):
        probe = dataclasses.replace(st, max_concentration_mEq_l=c, concentration_step_mEq_l=c)
        _, at = grow(ci_config, wall, [sector(51.5)], probe)
        assert at.growth.concentration_mEq_l.iloc[-1] == pytest.approx(c)
        assert (at.growth.tip_radial_stress_kPa.iloc[-1] >= st.critical_stress_kPa) == reached, c


def test_a_pair_that_merges_is_merged_with_its_merge_concentration(ci_config, wall):
    st = runaway_settings(ci_config)
    _, result = grow(ci_config, wall, [sector(42.5), sector(47.5)], st)
    s = result.summary
    assert s["stop_kind"] == "merged" and s["merged"] and s["outcome"] == "merges"
    assert s["merge_concentration_mEq_l"] == s["runaway_concentration_mEq_l"]
    assert s["stop_level_mEq_l"] - st.concentration_step_mEq_l < s["merge_concentration_mEq_l"] <= s["stop_level_mEq_l"]


def test_a_stop_kind_must_be_a_known_one():
    assert Stop("edge", "x", 1.0).kind == "edge"
    with pytest.raises(ValueError, match="stop kind must be one of arrested, merged"):
        Stop("no stable state", "x", 1.0)


def test_a_pool_that_grows_into_a_symmetry_edge_stops_there(ci_config, wall):
    """The same unstable growth started 15 deg from the symmetry edge at 0 deg reaches the edge's candidate window
    before the cap: the stop is ``edge``, and its level has a runaway concentration too."""
    st = runaway_settings(ci_config, max_extent_deg=60.0)
    _, result = grow(ci_config, wall, [sector(15.0)], st)
    s = result.summary
    assert s["stop_kind"] == "edge" and "symmetry edge" in s["stop"]
    assert (
        s["stop_level_mEq_l"] - st.concentration_step_mEq_l < s["runaway_concentration_mEq_l"] <= s["stop_level_mEq_l"]
    )


def soft_wall(ci_config, mu):
    """``(model, start, gag)``: a wall of elastin alone (shear modulus ``mu`` kPa, its Lame parameter 100 ``mu`` and
    hourglass modulus ``mu``; no pre-stretch, no smooth muscle, no collagen) at 0.05 mmHg in the lumen, and the
    prescribed law's GAG (hourglass modulus 1 kPa; the contents' volumetric term ``log_squared``, whose pressure has a
    largest value): a wall so soft that the pool's contents are what holds a pool."""
    bl = dict(ci_config["bilayer"], elastin_shear_modulus_kPa=mu, lame_lambda_kPa=100.0 * mu, hourglass_modulus_kPa=mu)
    bl["prestretch"] = dict(bl["prestretch"], elastin_circumferential=1.0, elastin_axial=1.0, smc=1.0, collagen=1.0)
    bl["mass_fractions"] = {
        "media": {"elastin": 1.0, "smc": 0.0, "collagen": 0.0},
        "adventitia": {"elastin": 1.0, "collagen": 0.0},
    }
    gag = dict(law_gag(ci_config, "prescribed"), hourglass_modulus_kPa=1.0, volumetric="log_squared")
    model = artery.bilayer_model(bl, CI_NUMERICS, name=f"test-soft-wall-{mu:g}")
    home = homeostasis(model, CI_NUMERICS, ci_config["homeostasis"])
    start = pressurise(model, home.state, 0.05, CI_NUMERICS)
    return model, solver.State(start.load, start.x, None, None), gag


def contents_limit(gag):
    """The largest concentration the pool's contents hold on their own (mEq/l): eq. (2.27) under a prescribed Donnan
    pressure has a largest pressure, where ``mu_g (1 - 1/J) + lam_g ln J / J`` peaks (ln J = 1 + mu_g/lam_g); a wall
    around them can only raise it."""
    mu, lam = gag["shear_modulus_kPa"], gag["lame_lambda_kPa"]
    J = np.exp(1.0 + mu / lam)
    return donnan.concentration_for_pressure(
        mu * (1 - 1 / J) + lam * np.log(J) / J, gag["bath_concentration_mEq_l"], gag["temperature_K"]
    )


def test_a_pool_past_the_limit_point_of_its_frozen_state_ends_at_that_limit_point(ci_config):
    """A long pool (12 deg) in a wall 90 times softer than the artery's (:func:`soft_wall`, mu = 1 kPa), no damage: the
    pool's contents are what holds it (:func:`contents_limit`). Raising the concentration past it, volume control
    finds the maximum concentration the pool holds, and the run ends at that ``limit point``: between the contents'
    own limit and 2 mEq/l above it (what the soft wall adds), between the last level reached and the first that was
    not."""
    model, start, gag = soft_wall(ci_config, 1.0)
    st = settings(ci_config, critical_stress_kPa=1e6, max_concentration_mEq_l=40.0, concentration_step_mEq_l=10.0)
    result = growth.grow(model, start, [sector(45.0, 12.0)], st, CI_NUMERICS, gag, model.props)
    s = result.summary
    assert s["stop_kind"] == "limit point" and s["stop_level_mEq_l"] == 40.0, s["stop"]
    own = contents_limit(gag)
    assert own < s["limit_concentration_mEq_l"] < own + 2.0 and 30.0 <= s["limit_concentration_mEq_l"] < 40.0
    assert result.growth.concentration_mEq_l.max() == 30.0 and s["final_length_um"] == 0.0


def test_a_damage_pass_past_the_limit_point_of_its_history_ends_at_that_limit_point(ci_config):
    """The same pool in a wall 10 times stiffer (mu = 10 kPa) is held at 30.6 mEq/l. A damage pass that weakens every
    tissue particle to D = 0.9 (the wall of the test above, whose pool's limit point lies below that) has no
    equilibrium there: its transition fails, and its snap comes to rest at no equilibrium. Followed from the state
    before the pass (the new history reached with the pool's volume held, then its volume as the control), the
    concentration the pool holds passes a maximum: the run ends at that ``limit point``, between the contents' own
    limit and the level, at its state before the pass (no state beyond the last equilibrium)."""
    level = 30.6
    model, start, gag = soft_wall(ci_config, 10.0)
    st = settings(ci_config, critical_stress_kPa=1e6, max_concentration_mEq_l=level, concentration_step_mEq_l=level)
    run = GrowthRun.seed(model, start, [sector(45.0, 12.0)], st, CI_NUMERICS, gag, model.props)
    hist = run.hist
    weakened = hist.with_damage(np.where(hist.gag, hist.D, 0.9), hist.onset_stretch, hist.onset_energy)
    updates = iter([DamageUpdate(weakened)])
    run.next_history = lambda: next(updates, DamageUpdate(None))  # the one pass, then no change
    kind, what = run.settle_level(level)
    assert kind == "limit point" and "pass 1, whose snap came to rest at no equilibrium" in what, what
    assert contents_limit(gag) < run.limit_c < level
    assert run.concentration == level and run.step == 0 and run.hist is hist and run.snaps == 0
    assert [(r.step, r.concentration) for r in run.rows] == [(0, level)]  # the level's first state, and no other
    assert run.state.convergence.residual < ci_config["numerics"]["tolerance"]
    assert model.props is run.material  # the model is left at the run's material
