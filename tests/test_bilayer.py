"""Bi-layered constrained-mixture model: homeostasis, activation, pressure-diameter, saved states."""

import copy

import numpy as np
import pytest

from sphgag import config
from sphgag.engine.loading import MMHG_TO_KPA, Load
from sphgag.engine.numerics import Numerics
from sphgag.physics import materials
from sphgag.records import state
from sphgag.records.state import StateMismatch
from sphgag.studies import artery
from sphgag.studies.pressure_diameter import bilayer_law, bilayer_pressure_diameter, bilayer_tube
from sphgag.studies.wall_loading import homeostasis

from .conftest import CI_NUMERICS, ROOT

# Bounds at the CI resolution (dx = 6 um, 1222 particles), from measured values (dx = 8 um, alpha = 50):
# carried pressure 104.7 mmHg (semi-analytical 104.6, target 103); hoop stress (max - min)/mean
# 6.0 % in the media and 0.03 % in the adventitia; OD within 0.07 % of the semi-analytical tube over
# 60-200 mmHg. The full resolution (README) is as good or better.


@pytest.fixture(scope="module")
def ci(ci_config):
    p, numerics = ci_config["bilayer"], CI_NUMERICS
    model = artery.bilayer_model(p, numerics, name="test-bilayer")
    return ci_config, model, homeostasis(model, numerics, ci_config["homeostasis"])


def test_layers_and_composition(ci):
    cfg, model, _ = ci
    lay = model.layout
    assert set(lay.layer_names) == {"media", "adventitia"}
    props = model.props(Load(1.0, 0.0, material=(("activation", 1.0), ("prestretch", 1.0))))
    media = lay.layer_mask("media")
    mu = cfg["bilayer"]["elastin_shear_modulus_kPa"]
    assert np.allclose(props[media, materials.MU], 0.47 * mu)
    assert np.allclose(props[~media, materials.MU], 0.04 * mu)
    assert np.allclose(props[media, materials.TACT], cfg["bilayer"]["active"]["max_stress_kPa"])
    assert np.all(props[~media, materials.TACT] == 0.0)
    # G_r = 1 / (G_theta G_z), det G = 1
    assert np.allclose(props[:, materials.GR] * props[:, materials.GT] * props[:, materials.GZ], 1.0)


@pytest.mark.parametrize("layer", ["media", "adventitia"])
@pytest.mark.parametrize("active", [False, True])
def test_sph_material_and_semi_analytical_law_agree(ci, layer, active):
    """The particle law (materials) and the independently written incompressible law (analytic) give the
    same sigma_tt - sigma_rr for isochoric axisymmetric states (the volumetric part is a pressure)."""
    cfg, model, _ = ci
    p = cfg["bilayer"]
    lay = model.layout
    i = int(np.flatnonzero(lay.layer_mask(layer))[0])
    props = model.props(Load(1.0, 0.0, material=(("activation", float(active)), ("prestretch", 1.0))))
    law = bilayer_law(p, layer, active)
    c, s = np.cos(lay.theta[i]), np.sin(lay.theta[i])
    Q = np.array([[c, -s], [s, c]])
    for lt in (0.7, 0.95, 1.0, 1.1, 1.3):
        F = Q @ np.diag([1.0 / lt, lt]) @ Q.T
        P = np.array(materials.first_piola(*F.ravel(), 1.0, c, s, props, i)).reshape(2, 2)
        sigma = Q.T @ (P @ F.T) @ Q  # local (r, theta), J = 1
        assert sigma[1, 1] - sigma[0, 0] == pytest.approx(float(law.hoop_minus_radial(lt, 1.0)), rel=1e-10)


def test_homeostatic_state_carries_the_homeostatic_pressure(ci):
    cfg, model, h = ci
    assert h.state.convergence.residual < cfg["numerics"]["tolerance"]
    target = cfg["homeostasis"]["target_pressure_mmHg"]
    carried = h.pressures_kPa["reactions"] / MMHG_TO_KPA
    assert carried == pytest.approx(target, rel=0.05)
    assert h.pressures_kPa["hoop_equilibrium"] / MMHG_TO_KPA == pytest.approx(carried, rel=0.01)
    semi = bilayer_tube(cfg["bilayer"], active=False).pressure(model.layout.inner_radius) / MMHG_TO_KPA
    assert carried == pytest.approx(semi, rel=0.005)


def test_homeostatic_hoop_stress_is_near_uniform_per_layer(ci):
    """(max - min)/mean of the ring hoop stress per layer: measured 10.1 % (media) and 0.07 % (adventitia) at the
    CI resolution with alpha = 5 (6.9 % and 0.5 % at full resolution, claim C3's bar is 10 %). Bound: 12 %."""
    _, _, h = ci
    stats = h.layers.set_index("layer")
    assert (stats.circ_variation < 0.12).all()
    assert stats.loc["media", "circ_stress_mean_kPa"] > stats.loc["adventitia", "circ_stress_mean_kPa"]


@pytest.fixture(scope="module")
def sweeps(ci):
    cfg, model, h = ci
    cal = dict(cfg["bilayer_calibration"], pressure_points=5)
    out = {}
    for label in ("passive", "active"):
        tube = bilayer_tube(cfg["bilayer"], active=label == "active")
        out[label] = bilayer_pressure_diameter(
            model, tube, h.state, Numerics.of(cfg["numerics"]), cal, active=label == "active", label=label
        )
    return out


@pytest.mark.parametrize("label", ["passive", "active"])
def test_pressure_diameter_matches_the_semi_analytical_tube(sweeps, label, ci_config):
    res = sweeps[label]
    assert res.max_od_error(60.0, 200.0) < 0.015
    assert (res.states.residual < ci_config["numerics"]["tolerance"]).all()


def test_activation_narrows_the_artery_by_about_a_fifth(sweeps):
    od = {k: float(np.interp(103.0, r.states.pressure_mmHg, r.states.outer_diameter_um)) for k, r in sweeps.items()}
    reduction = 1 - od["active"] / od["passive"]
    assert 0.15 < reduction < 0.30  # paper: about 20 %; measured 22.2 %


def test_adventitia_shields_the_media_and_activation_shifts_load_to_it(sweeps):
    """Figure 3c: at high pressure the adventitia takes over load; activation moves load into the media."""
    t = {k: r.transmural[r.transmural.source == "sph"] for k, r in sweeps.items()}

    def hoop(label, P, layer):
        d = t[label]
        return d[(d.pressure_mmHg == P) & (d.layer == layer)].circ_stress_kPa.mean()

    ratio = {P: hoop("passive", P, "adventitia") / hoop("passive", P, "media") for P in (103.0, 200.0)}
    assert ratio[200.0] > 1.5 * ratio[103.0]
    for P in (103.0, 145.0, 200.0):
        share = {k: hoop(k, P, "media") / hoop(k, P, "adventitia") for k in t}
        assert share["active"] > share["passive"]
        assert hoop("active", P, "adventitia") < hoop("passive", P, "adventitia")


def test_state_files_round_trip_exactly(tmp_path, ci):
    cfg, _, h = ci
    path = tmp_path / "s.npz"
    slice_ = {k: cfg[k] for k in ("bilayer", "numerics", "homeostasis")}
    state.save(path, h.state.x, h.state.load, slice_, info={"note": "test"})
    back = state.load(path, expected_params=slice_)
    assert np.array_equal(back.x, h.state.x)
    assert back.load == h.state.load
    assert back.info == {"note": "test"}
    assert len(back.code["source_sha256"]) == 64


def test_a_state_from_another_configuration_is_refused(tmp_path, ci):
    cfg, _, h = ci
    path = tmp_path / "s.npz"
    slice_ = {k: cfg[k] for k in ("bilayer", "numerics", "homeostasis")}
    state.save(path, h.state.x, h.state.load, slice_)
    other = {**slice_, "bilayer": dict(slice_["bilayer"], dx_um=4.0)}
    with pytest.raises(StateMismatch, match=r"bilayer.dx_um: expected 4.0, file has 6.0"):
        state.load(path, expected_params=other)


# the CI wall with an external elastic lamina between media and adventitia, one particle thick (1 um at dx = 6 um)
LAMELLAR = dict(
    layers=[
        dict(name="media", thickness_um=27.4),
        dict(name="lamina", thickness_um=1.0),
        dict(name="adventitia", thickness_um=11.8),
    ],
    lamina_fractions=dict(elastin=1.0, collagen=0.0),
    lamina_orientations=dict(axial=0.0, diagonal=0.0, circumferential=1.0),
)


def test_a_three_layer_wall_built_from_config_alone_carries_its_exact_tube_pressure(ci_config):
    """docs/contributing.md's steps for a lamellar wall, from the configuration alone: a third layer (an elastin
    lamina one particle thick, thinner than half the spacing) gets its ring, its composition and no active tone, and
    the homeostatic wall carries the pressure of the exact three-layer tube. Measured: 105.40 mmHg against the exact
    105.45 (0.04 %); the two-layer tube carries 104.62, 0.8 % less, so a lamina the model ignored would fail."""
    cfg = copy.deepcopy(ci_config)
    b = cfg["bilayer"]
    b["layers"] = LAMELLAR["layers"]
    b["mass_fractions"]["lamina"] = LAMELLAR["lamina_fractions"]
    b["orientations"]["lamina"] = LAMELLAR["lamina_orientations"]
    config.validate(cfg, ROOT / "config" / "schema.yaml")

    model = artery.bilayer_model(b, Numerics.of(cfg["numerics"]), name="test-lamellar")
    lay = model.layout
    assert lay.layer_names == ("media", "lamina", "adventitia")
    lamina = lay.layer_mask("lamina")
    assert np.unique(lay.ring[lamina]).size == 1  # one ring, its cell the lamina's 1 um
    assert np.ptp(lay.ring_cell[lay.ring[lamina][0]]) == pytest.approx(1.0)
    props = model.props(Load(1.0, 0.0, material=(("activation", 1.0), ("prestretch", 1.0))))
    assert np.allclose(props[lamina, materials.MU], b["elastin_shear_modulus_kPa"])
    assert np.all(props[lamina, materials.TACT] == 0.0)  # no smc: no active tone
    assert np.all(props[lay.layer_mask("media"), materials.TACT] > 0.0)

    h = homeostasis(model, Numerics.of(cfg["numerics"]), cfg["homeostasis"])
    assert h.state.convergence.residual < cfg["numerics"]["tolerance"]
    carried = h.pressures_kPa["reactions"] / MMHG_TO_KPA
    exact = bilayer_tube(b, active=False).pressure(lay.inner_radius) / MMHG_TO_KPA
    two_layer = bilayer_tube(ci_config["bilayer"], active=False).pressure(lay.inner_radius) / MMHG_TO_KPA
    assert carried == pytest.approx(exact, rel=0.002)
    assert abs(two_layer / exact - 1.0) > 0.005
