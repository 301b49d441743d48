"""Figure 4 under the authors' settings (target paper_settings): the configuration, its options and the study."""

import copy

import numpy as np
import pandas as pd
import pytest

from sphgag import config
from sphgag.engine import measure, solver
from sphgag.studies import artery, paper_settings
from sphgag.studies.pool_swelling import pool_table, swell_pool, tip_length, with_hourglass_factor
from sphgag.studies.wall_loading import homeostasis, homeostatic_load, pressurise

from .conftest import CI_NUMERICS, ROOT, law_gag

SCHEMA = ROOT / "config" / "schema.yaml"


@pytest.fixture(scope="module")
def script_config():
    return config.load_yaml(ROOT / "config" / "script.yaml")


@pytest.mark.parametrize("name", ["script.yaml", "config.yaml", "ci.yaml"])
def test_the_configurations_validate(name, monkeypatch):
    monkeypatch.chdir(ROOT)  # paper_settings.script_config is relative to the working directory
    config.validate(config.load_yaml(ROOT / "config" / name), SCHEMA)


def test_the_script_configuration_differs_from_ours_only_in_its_settings(script_config, full_config):
    """Every key where config/script.yaml and config/config.yaml differ is one of the study's settings (or a key the
    study does not switch: the ramp's top, the charge laws it runs, paper_procedure's temperature is already the
    script's, and which of paper_procedure's runs the authors' configuration makes)."""
    settings = {k for keys in full_config["paper_settings"]["settings"].values() for k in keys}
    unswitched = {"swelling.max_concentration_mEq_l", "swelling.concentration_points", "gag.charge_laws"}
    unswitched |= {"paper_procedure.cases", "paper_procedure.step_factors"}

    def leaves(node, path=()):
        if isinstance(node, dict):
            for k, v in node.items():
                yield from leaves(v, path + (k,))
        else:
            yield ".".join(path), node

    ours = dict(leaves(full_config))
    differ = {k for k, v in leaves(script_config) if ours.get(k) != v}
    covered = {k for k in differ if any(k == s or k.startswith(s + ".") for s in settings)}
    assert differ - covered == unswitched


@pytest.mark.parametrize(
    "key, value, message",
    [
        (("swelling", "lumen_control"), "volume", "swelling.lumen_control = 'volume' is invalid"),
        (("swelling", "tip_probe"), "peak", "swelling.tip_probe = 'peak' is invalid"),
        (("swelling", "hourglass_factor"), 0.0, "swelling.hourglass_factor = 0.0 is invalid"),
        (("paper_settings", "settings", "spacing"), ["bilayer.spacing"], "'bilayer.spacing' is not a key"),
        (("paper_settings", "cases"), ["V"], "paper_settings.cases[0] = 'V' is not a pool"),
        (("paper_settings", "concentrations_mEq_l"), [110.0], "paper_settings.concentrations_mEq_l[0] = 110"),
        (("paper_settings", "script_config"), "config/none.yaml", "paper_settings.script_config = 'config/none.yaml'"),
    ],
)
def test_a_bad_value_is_refused_naming_its_key(ci_config, monkeypatch, key, value, message):
    monkeypatch.chdir(ROOT)
    bad = copy.deepcopy(ci_config)
    node = bad
    for part in key[:-1]:
        node = node[part]
    node[key[-1]] = value
    with pytest.raises(config.ConfigError, match=message.replace("[", r"\[").replace("]", r"\]")):
        config.validate(bad, SCHEMA)


def test_a_run_switches_exactly_its_setting(script_config, full_config):
    ours, script = full_config, script_config
    run = paper_settings.configuration(ours, script, "ours", "gag_material")
    assert run["gag"]["shear_modulus_kPa"] == script["gag"]["shear_modulus_kPa"]
    assert run["gag"]["volumetric"] == "none" and run["gag"]["temperature_K"] == ours["gag"]["temperature_K"]
    assert run["bilayer"] == ours["bilayer"] and ours["gag"]["volumetric"] == "convex"  # ours untouched
    back = paper_settings.configuration(ours, script, "script", "spacing")
    assert back["bilayer"]["dx_um"] == ours["bilayer"]["dx_um"] and back["numerics"] == script["numerics"]
    assert paper_settings.configuration(ours, script, "script", paper_settings.NONE) == script
    p = paper_settings.run_params(ours, script, "script", paper_settings.NONE)
    assert list(p["cases"]) == ours["paper_settings"]["claim_cases"]
    assert p["swelling"]["concentration_points"] == 7 and p["swelling"]["max_concentration_mEq_l"] == 150.0
    assert p["gag"]["charge_law"] == "prescribed" and p["tip_probe"] == "adjacent"


@pytest.fixture(scope="module")
def pressurised(ci_config):
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-ps-pressurised")
    h = homeostasis(model, CI_NUMERICS, ci_config["homeostasis"])
    start = pressurise(model, h.state, 103.0, CI_NUMERICS)
    return solver.State(start.load, start.x, None, None)


def test_the_radius_held_lumen_keeps_the_inner_radius_during_swelling(ci_config, pressurised):
    """lumen_control = radius: every state of the protocol has every inner particle at the start's mean inner radius;
    the lumen pressure is read back from the reactions, and moves as the pool swells."""
    sector = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(
        ci_config["bilayer"], CI_NUMERICS, "test-ps-radius", sector, law_gag(ci_config, "prescribed")
    )
    sw = dict(ci_config["swelling"], lumen_control="radius", max_concentration_mEq_l=100.0, concentration_points=3)
    states = swell_pool(model, pressurised, CI_NUMERICS, sw)
    r0 = measure.surface_radius(model, pressurised.x, "inner")
    assert [s.concentration for s in states if s.stage == "converted"] == [0.0, 50.0, 100.0]
    for s in states:
        assert s.load.pressure_kPa is None and s.load.inner_radius == pytest.approx(r0, rel=1e-12)
        radii = np.linalg.norm(s.x[model.layout.inner_surface], axis=1)
        assert np.allclose(radii, r0, rtol=1e-12)
    table = pool_table(model, states, sector, 10.0, law_gag(ci_config, "prescribed"))
    assert table.pressure_mmHg.iloc[0] == pytest.approx(103.0, rel=0.02)  # the start's pressure, read back
    assert table.pressure_mmHg.nunique() == len(table)


def test_the_hourglass_factor_scales_every_particles_penalty(ci_config):
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, "test-ps-hourglass")
    scaled = with_hourglass_factor(model, 0.1)
    assert scaled.hourglass_alpha == pytest.approx(0.1 * model.hourglass_alpha)
    assert with_hourglass_factor(model, 1.0) is model
    x = model.layout.X * 1.01 + 0.3 * np.sin(np.arange(model.n))[:, None]  # a non-affine deformation
    load = homeostatic_load(model.layout.inner_radius * 1.01, 0.0)
    f, g = model.hourglass_forces(x, load), scaled.hourglass_forces(x, load)
    assert np.allclose(g, 0.1 * f, rtol=1e-10, atol=1e-12 * np.abs(f).max())


def test_the_adjacent_tip_probe_selects_the_particles_just_beyond_the_pools_ends(ci_config):
    """tip_probe = adjacent: the pool layers' particles of the pool's radial band whose reference arc beyond an
    angular end of the pool is at most one spacing, at each end: none of the pool, none further out."""
    entry = ci_config["swelling"]["cases"]["IV"]
    sector = artery.pool_sector(entry)
    layout = artery.bilayer_layout(ci_config["bilayer"])
    dx = layout.dx
    assert tip_length("adjacent", 10.0, dx) == dx and tip_length("region", 10.0, dx) == 10.0
    probes = measure.pool_probes(sector, tip_length("adjacent", 10.0, dx))
    pool = sector.members(layout, layer=layout.pool_layers)
    (r0, r1), (t0, t1) = sector.r_range, sector.theta_range
    medial = layout.layer_mask(layout.pool_layers)
    band = medial & (layout.radius >= r0) & (layout.radius <= r1)
    for name, beyond in (("tip_low", t0 - layout.theta), ("tip_high", layout.theta - t1)):
        members = probes[name].members(layout, layer=layout.pool_layers)
        arc = beyond * layout.radius
        expected = np.flatnonzero(band & (arc >= 0.0) & (arc <= dx * layout.radius / sector.centre_radius))
        assert members.size and np.array_equal(np.sort(members), expected)
        assert not np.intersect1d(members, pool).size
        for radius in np.unique(np.round(layout.radius[band], 6)):  # on each ring of the band: its nearest particle
            ring = np.flatnonzero(band & (arc >= 0.0) & np.isclose(layout.radius, radius))
            on_ring = np.intersect1d(members, ring)
            assert on_ring.size == 1 and on_ring[0] == ring[np.argmin(arc[ring])]


def test_the_ablation_gives_no_number_without_an_equilibrium():
    base = dict(
        base="script",
        model="passive",
        case="I",
        charge_law="prescribed",
        particles=100,
        stage="converted",
        top_circ_stress_kPa=1.0,
        pool_volume_change=0.5,
        pressure_mmHg=103.0,
        end_reason="",
    )
    runs = pd.DataFrame(
        [
            dict(
                base,
                setting="none",
                concentration_mEq_l=100.0,
                tip_radial_stress_kPa=40.0,
                residual=1e-6,
                path_end="limit point",
            ),
            dict(
                base,
                setting="tip_probe",
                concentration_mEq_l=100.0,
                tip_radial_stress_kPa=50.0,
                residual=1e-3,
                path_end="complete",
            ),
        ]
    )
    table = paper_settings.ablation([runs], [100.0, 150.0], 1e-4)
    none = table[table.setting == "none"].set_index("concentration_mEq_l")
    assert none.loc[100.0, "tip_radial_stress_kPa"] == 40.0 and none.loc[100.0, "equilibrium"] == "converged"
    assert np.isnan(none.loc[150.0, "tip_radial_stress_kPa"])
    assert none.loc[150.0, "equilibrium"] == "no equilibrium at 150 mEq/l (the path ends below it: limit point)"
    switched = table[(table.setting == "tip_probe") & (table.concentration_mEq_l == 100.0)].iloc[0]
    assert np.isnan(switched.tip_radial_stress_kPa) and switched.equilibrium.startswith("not converged")
    assert switched.direction == "from_script"
    assert list(table.columns[:10]) == [
        "setting",
        "direction",
        "case",
        "model",
        "charge_law",
        "concentration_mEq_l",
        "tip_radial_stress_kPa",
        "top_hoop_stress_kPa",
        "volume_ratio",
        "residual",
    ]


def _ablation(tips: dict) -> pd.DataFrame:
    """An ablation table at 150 mEq/l: ``tips[(setting, direction, case)]`` = tip radial stress."""
    rows = [
        dict(
            setting=s,
            direction=d,
            case=c,
            model="passive",
            charge_law="prescribed",
            concentration_mEq_l=150.0,
            tip_radial_stress_kPa=v,
            top_hoop_stress_kPa=1.0,
            volume_ratio=2.0,
            residual=1e-6,
            equilibrium="converged",
            pressure_mmHg=103.0,
            particles=100,
        )
        for (s, d, c), v in tips.items()
    ]
    return pd.DataFrame(rows, columns=paper_settings.COLUMNS)


def test_claim_p5_judges_the_authors_configuration_and_names_the_largest_steps():
    from sphgag.studies.claims.evidence import Evidence
    from sphgag.studies.claims.procedure import p5_authors_settings

    tips = {
        ("none", "script", "I"): 120.0,
        ("none", "script", "IV"): 60.0,
        ("none", "ours", "I"): 400.0,
        ("none", "ours", "IV"): 1200.0,
        ("lumen_control", "from_script", "I"): 300.0,
        ("lumen_control", "from_script", "IV"): 900.0,
        ("lumen_control", "from_ours", "I"): 150.0,
        ("lumen_control", "from_ours", "IV"): 100.0,
        ("temperature", "from_script", "I"): 121.0,
        ("temperature", "from_script", "IV"): 61.0,
        ("temperature", "from_ours", "I"): 399.0,
        ("temperature", "from_ours", "IV"): 1199.0,
    }
    claim = p5_authors_settings(Evidence(paper_settings=_ablation(tips)))
    assert claim.claim_id == "P5" and claim.holds == "yes" and claim.margin == pytest.approx(10.0)
    assert claim.our_value.index("lumen_control") < claim.our_value.index("temperature")
    assert "|" not in claim.our_value  # the report reads the table as reStructuredText: |x| is a substitution
    tips[("none", "script", "IV")] = 200.0
    assert p5_authors_settings(Evidence(paper_settings=_ablation(tips))).holds == "no"
    tips[("none", "script", "IV")] = np.nan  # no equilibrium: never a pass
    assert p5_authors_settings(Evidence(paper_settings=_ablation(tips))).holds == "no"
    assert p5_authors_settings(Evidence()).holds == "not run"
