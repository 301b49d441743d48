"""What researchers look at: ParaView series read back against the states they came from, and the animations."""

import dataclasses

import numpy as np
import pytest

from sphgag.engine import geometry, measure
from sphgag.engine.history import HistoryMaterial
from sphgag.records import state
from sphgag.studies import artery, delamination
from sphgag.views import paraview

from .conftest import law_gag
from .test_delamination import settings


@pytest.fixture(scope="module")
def grown(ci_config, ci_wall, tmp_path_factory):
    """A short delamination run of the CI wall (damage at once, so that the pool grows in a few passes:
    :func:`tests.test_delamination.settings`), its snapshots saved as the pipeline saves them."""
    st = settings(ci_config)
    model = artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"], name="test-views")
    gag = law_gag(ci_config)
    result = delamination.grow(
        model, ci_wall, [geometry.Sector(663.0, 45.0, 15.0, 3.0)], st, ci_config["numerics"], gag, model.props
    )
    path = tmp_path_factory.mktemp("views") / "snapshots.npz"
    delamination.save_snapshots(path, model, result.snapshots, {"run": "test"})
    return gag, path, result


def intact_wall(ci_config):
    return artery.bilayer_model(ci_config["bilayer"], ci_config["numerics"], name="test-views-export")


def test_a_paraview_series_reads_back_as_the_states_it_came_from(ci_config, grown, tmp_path):
    gag, path, result = grown
    model = intact_wall(ci_config)
    base = model.props
    frames = paraview.delamination_frames(model, path, gag, {"run": "test"})
    pvd = paraview.write_series(tmp_path / "run.pvd", frames)
    series = paraview.read_series(pvd)
    saved = state.load_series(path, {"run": "test"})
    assert len(series) == len(saved) == len(result.snapshots) > 1
    with np.load(path) as npz:
        stored_radial = [npz[f"s{k}_radial_stress_kPa"] for k in range(len(saved))]
    assert [f.time for f in series] == list(range(len(saved)))  # distinct times: ParaView's slider steps every state
    assert [f.data["pseudo_time"][0] for f in series] == [float(s.info["pseudo_time"]) for s in saved]
    for k, (frame, s) in enumerate(zip(series, saved)):
        d = frame.data
        assert set(paraview.FIELDS) <= set(d)
        np.testing.assert_array_equal(frame.x, s.x)
        np.testing.assert_array_equal(d["reference_position"][:, :2], model.layout.X)
        np.testing.assert_array_equal(d["displacement"][:, :2], s.x - model.layout.X)
        # the radial stress the run measured on its own converged state, recomputed from the saved one
        np.testing.assert_allclose(d["cauchy_rr_kPa"], stored_radial[k], rtol=1e-10, atol=1e-9)
        model.set_props(HistoryMaterial(base, s.history, gag))
        srr, stt, srt, J = measure.cauchy_polar(model.evaluate(s.x, s.load))
        model.set_props(base)
        np.testing.assert_array_equal(d["cauchy_tt_kPa"], stt)
        np.testing.assert_array_equal(d["cauchy_rt_kPa"], srt)
        np.testing.assert_array_equal(d["J"], J)
        np.testing.assert_array_equal(d["damage"], s.history.D)
        np.testing.assert_array_equal(d["origin"], s.history.origin)
        np.testing.assert_array_equal(d["pool"], s.history.pool)
        np.testing.assert_array_equal(d["layer"], model.layout.layer)
        c = s.load.material_value("concentration")
        np.testing.assert_array_equal(d["concentration_mEq_l"], np.where(s.history.gag, c, 0.0))
    assert series[-1].data["damage"].max() > 0.0  # the run grew: damage is in the series


def test_a_series_written_twice_is_the_same_bytes(ci_config, grown, tmp_path):
    gag, path, _ = grown
    frames = paraview.delamination_frames(intact_wall(ci_config), path, gag, {"run": "test"})
    a = paraview.write_series(tmp_path / "a" / "run.pvd", frames)
    b = paraview.write_series(tmp_path / "b" / "run.pvd", frames)
    for fa in sorted(a.parent.iterdir()):
        assert fa.read_bytes() == (b.parent / fa.name).read_bytes(), fa.name


def test_an_animation_shows_every_frames_stresses_and_partial_damage(ci_config, grown, tmp_path):
    """Each frame has its own colour range (a wall at 1/100 of the last frame's stresses is not drawn white), and
    tissue with 0 < D < 1 has a colour of its own."""
    from PIL import Image

    from sphgag.views import animation

    gag, path, _ = grown
    last = paraview.delamination_frames(intact_wall(ci_config), path, gag, {"run": "test"})[-1]
    quiet = dict(last.data, cauchy_rr_kPa=last.data["cauchy_rr_kPa"] / 100.0, damage=np.zeros_like(last.data["damage"]))
    tissue = np.flatnonzero(last.data["origin"] == 0)
    damaged = dict(last.data, damage=last.data["damage"].copy())
    box = animation.view([last])
    inside = (last.x[tissue, 0] > box[0]) & (last.x[tissue, 0] < box[1])
    inside &= (last.x[tissue, 1] > box[2]) & (last.x[tissue, 1] < box[3])
    damaged["damage"][tissue[inside][:20]] = 0.5
    frames = [paraview.Frame(0.0, last.x, quiet), paraview.Frame(1.0, last.x, damaged)]
    assert animation.stress_range(frames[0], box) == pytest.approx(
        animation.stress_range(dataclasses.replace(frames[1], data=dict(damaged, damage=quiet["damage"])), box) / 100
    )
    gif = animation.write(tmp_path / "run.gif", frames, "test")
    with Image.open(gif) as im:
        pixels = []
        for k in range(im.n_frames):
            im.seek(k)
            pixels.append(np.asarray(im.convert("RGB"), dtype=int).reshape(-1, 3))

    def saturated(rgb):  # strong reds or blues of the stress map
        return int(np.sum((np.abs(rgb[:, 0] - rgb[:, 2]) > 120) & (rgb.max(axis=1) - rgb.min(axis=1) > 120)))

    orange = np.array([0xD9, 0x5F, 0x02])
    for k, rgb in enumerate(pixels):
        assert saturated(rgb) > 200, k  # the quiet frame's stresses are visible too
    assert np.sum(np.all(np.abs(pixels[1] - orange) < 12, axis=1)) > 50  # partial damage, in its colour
    assert np.sum(np.all(np.abs(pixels[0] - orange) < 12, axis=1)) < 5  # and not where there is none
