"""Configuration validation: every key typed and ranged, messages that name the bad key."""

import copy

import pytest

from sphgag import config

from .conftest import ROOT

SCHEMA = ROOT / "config" / "schema.yaml"


@pytest.mark.parametrize("name", ["config.yaml", "ci.yaml"])
def test_shipped_configs_are_valid(name):
    config.validate(config.load_yaml(ROOT / "config" / name), SCHEMA)


def bad(cfg, path, value):
    cfg = copy.deepcopy(cfg)
    node = cfg
    for key in path[:-1]:
        node = node[key]
    if value is KeyError:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    with pytest.raises(config.ConfigError) as info:
        config.validate(cfg, SCHEMA)
    return str(info.value)


def test_out_of_range_value_names_the_key_and_the_range(full_config):
    msg = bad(full_config, ["mean", "dx_um"], -3.0)
    assert "mean.dx_um = -3.0" in msg
    assert ">= 0.5" in msg and "<= 100" in msg
    assert "particle spacing" in msg


def test_wrong_type_is_rejected(full_config):
    msg = bad(full_config, ["numerics", "max_newton_iterations"], 2.5)
    assert "numerics.max_newton_iterations = 2.5" in msg and "integer" in msg


def test_unknown_key_is_rejected(full_config):
    cfg = copy.deepcopy(full_config)
    cfg["mean"]["dx"] = 5.0
    with pytest.raises(config.ConfigError, match=r"unknown key 'mean.dx'.*allowed here:.*dx_um"):
        config.validate(cfg, SCHEMA)


def test_missing_key_is_rejected(full_config):
    assert "missing key 'calibration.pressure_points'" in bad(full_config, ["calibration", "pressure_points"], KeyError)


def test_nested_items_are_checked(full_config):
    msg = bad(full_config, ["calibration", "transmural_pressures_mmHg"], [103.0, -5.0])
    assert "calibration.transmural_pressures_mmHg[1] = -5.0" in msg


def test_fibre_angle_range(full_config):
    msg = bad(full_config, ["mean", "fibres", "diagonal", "angle_deg"], 95.0)
    assert "mean.fibres.diagonal.angle_deg = 95.0" in msg and "< 90" in msg


def test_relations_between_keys(full_config):
    assert "must exceed mean.inner_radius_um" in bad(full_config, ["mean", "outer_radius_um"], 300.0)
    msg = bad(full_config, ["calibration", "transmural_pressures_mmHg"], [103.0, 250.0])
    assert "exceeds calibration.max_pressure_mmHg" in msg


def test_all_problems_are_reported_at_once(full_config):
    cfg = copy.deepcopy(full_config)
    cfg["mean"]["dx_um"] = 0.0
    cfg["numerics"]["tolerance"] = 1.0
    with pytest.raises(config.ConfigError) as info:
        config.validate(cfg, SCHEMA)
    assert "mean.dx_um" in str(info.value) and "numerics.tolerance" in str(info.value)


# -- inputs a schema alone lets through ----------------------------------------------------------------


@pytest.mark.parametrize(
    "path, value, expected",
    [
        (("bilayer", "inner_radius_um"), float("nan"), "bilayer.inner_radius_um = nan is not a finite number"),
        (("mean", "shear_modulus_kPa"), float("inf"), "mean.shear_modulus_kPa = inf is not a finite number"),
        (("numerics", "tolerance"), float("nan"), "numerics.tolerance = nan is not a finite number"),
        (("numerics", "max_newton_iterations"), 30.0, "numerics.max_newton_iterations = 30.0 is invalid"),
        (("numerics", "reuse_factorisation"), 1, "numerics.reuse_factorisation = 1 is invalid"),
        (("numerics", "hourglass"), "pairs", "numerics.hourglass = 'pairs' is invalid"),
        (
            ("verification", "circular_pool", "outer_radius_um"),
            20.0,
            "verification.circular_pool.outer_radius_um = 20 must be at least twice",
        ),
        (
            ("verification", "circular_pool", "pool_models"),
            ["particles", "bubble"],
            "verification.circular_pool.pool_models[1] = 'bubble' is invalid",
        ),
        (("numerics", "tolerance"), "1e-4", "write 1.0e-4"),
        (("swelling", "pressures_mmHg"), [103.0, 103.0], "swelling.pressures_mmHg = [103.0, 103.0] is invalid"),
        (("swelling", "cases", "I", "angular_extent_deg"), 0, "swelling.cases.I.angular_extent_deg = 0 is invalid"),
        (("bilayer_calibration", "state_pressures_mmHg"), [103.0, 103.0000001, 200.0], "all give the file name '103'"),
        # found by the fuzz test: below round-off the layer's outer radius equals its inner one
        (("bilayer", "layers", 1, "thickness_um"), 3.9e-56, "bilayer.layers[1].thickness_um (adventitia) = 3.9e-56 um"),
        (("bilayer", "pool_layers"), ["intima"], "bilayer.pool_layers.intima is not a layer of bilayer.layers"),
        (
            ("bilayer", "mass_fractions", "lamina"),
            dict(elastin=1.0, collagen=0.0),
            "mass_fractions.lamina is not a layer",
        ),
        (("bilayer", "orientations", "media", "circumferential"), 0.0, "a layer carries at most 4 fibre families"),
        (
            ("bilayer", "layers"),
            [dict(name="media", thickness_um=28.4), dict(name="lamina", thickness_um=1.0)],
            "missing key 'bilayer.mass_fractions.lamina'",
        ),
        (("delamination", "averaging_length_um"), 1.0, "the average of averaged would be a single particle's value"),
        (("bilayer", "aligned_radii_um"), [700.0], "bilayer.aligned_radii_um[0] = 700.0 is not inside the wall"),
        (("bilayer", "aligned_radii_um"), [646.9, 670.5], "the media sub-layer 646.8-646.9 um = 0.1 um is thinner"),
        (("mean", "outer_radius_um"), 333.0, "must be at least half the particle spacing mean.dx_um"),
    ],
)
def test_inputs_the_schema_alone_misses_are_rejected_by_name(ci_config, path, value, expected):
    assert expected in bad(ci_config, path, value)


def test_a_pool_named_by_a_number_is_rejected(ci_config):
    cfg = copy.deepcopy(ci_config)
    cfg["swelling"]["cases"][1] = cfg["swelling"]["cases"]["I"]
    with pytest.raises(config.ConfigError, match="key 'swelling.cases.1' must be a name"):
        config.validate(cfg, SCHEMA)


def test_a_corrupt_state_file_names_the_file_and_the_remedy(tmp_path):
    from sphgag.records import state

    path = tmp_path / "homeostatic.npz"
    path.write_bytes(b"PK\x03\x04 truncated")
    with pytest.raises(state.CorruptState, match="homeostatic.npz is not a readable state file.*rerun snakemake"):
        state.load(path)


# -- charge laws and pool-set roles ------------------------------------------------------------------


@pytest.mark.parametrize(
    "value, expected",
    [
        (["literal"], "gag.charge_laws[0] = 'literal' is invalid"),
        (["conserved", "conserved"], "gag.charge_laws = ['conserved', 'conserved'] is invalid"),
        ([], "gag.charge_laws = [] is invalid"),
        (True, "gag.charge_laws = True is invalid"),
    ],
)
def test_a_bad_charge_law_list_is_rejected_by_name(ci_config, value, expected):
    assert expected in bad(ci_config, ["gag", "charge_laws"], value)


@pytest.mark.parametrize(
    "value, expected",
    [
        (["particles", "bubble"], "swelling.pool_models[1] = 'bubble' is invalid"),
        ([], "swelling.pool_models = [] is invalid"),
    ],
)
def test_a_bad_pool_model_list_is_rejected_by_name(ci_config, value, expected):
    assert expected in bad(ci_config, ["swelling", "pool_models"], value)


def test_a_pool_model_without_any_of_its_charge_laws_is_rejected(ci_config):
    """The cavity carries the prescribed law only: with the conserved law alone it would run nothing."""
    cfg = copy.deepcopy(ci_config)
    cfg["gag"]["charge_laws"] = ["conserved"]
    expected = "swelling.pool_models[1] = 'cavity' carries the charge laws prescribed, none of gag.charge_laws"
    assert expected in bad(cfg, ["swelling", "pool_models"], ["particles", "cavity"])


def test_a_variant_pool_model_that_figure_4_runs_already_is_rejected(ci_config):
    """swelling.variant_pool_models runs beside figure 4's pool models in target variants: not one of them."""
    expected = "swelling.variant_pool_models[0] = 'particles' is one of swelling.pool_models"
    assert expected in bad(ci_config, ["swelling", "variant_pool_models"], ["particles"])


def test_the_old_charge_switch_is_an_unknown_key(ci_config):
    cfg = copy.deepcopy(ci_config)
    cfg["gag"]["fixed_charge_dilution"] = True
    with pytest.raises(config.ConfigError, match=r"unknown key 'gag.fixed_charge_dilution'.*charge_laws"):
        config.validate(cfg, SCHEMA)


@pytest.mark.parametrize(
    "role, value, expected",
    [
        ("fig6", ["low_separation", "pair_2deg"], "delamination.figures.fig6[1] = 'pair_2deg' is not a pool set"),
        ("fig5", "one_pool", "delamination.figures.fig5 = 'one_pool' is not a pool set"),
        ("fig7", "offset", "delamination.figures.fig7 = 'offset' is not a pool set"),
        ("fig7", "single", "delamination.figures.fig7 = 'single' is figure 5's set"),
        ("fig6", [], "delamination.figures.fig6 = [] is invalid"),
    ],
)
def test_a_figure_without_its_pool_set_is_rejected_by_name(ci_config, role, value, expected):
    assert expected in bad(ci_config, ["delamination", "figures", role], value)


def test_a_missing_figure_role_is_rejected_by_name(ci_config):
    assert "missing key 'delamination.figures.fig7'" in bad(ci_config, ["delamination", "figures", "fig7"], KeyError)


def test_pool_sets_with_any_name_are_valid(ci_config):
    """A renamed set (in the set and its role), an extra set no figure shows, and figure 5's set renamed."""
    cfg = copy.deepcopy(ci_config)
    de = cfg["delamination"]
    de["pool_sets"]["pair_2deg"] = de["pool_sets"].pop("low_separation")
    de["pool_sets"]["alone"] = de["pool_sets"].pop("single")
    de["pool_sets"]["extra"] = de["pool_sets"]["high_separation"]
    de["figures"] = dict(fig5="alone", fig6=["pair_2deg", "high_separation"], fig7="radial_offset")
    de["convergence"]["pool_sets"] = ["alone", "pair_2deg"]
    cfg["paper_procedure"]["pool_sets"] = {"alone": [40.0]}
    config.validate(cfg, SCHEMA)


def test_the_procedures_pools_must_be_configured_pools(ci_config):
    message = bad(ci_config, ["paper_procedure", "pool_sets"], {"lonely": [40.0]})
    assert "paper_procedure.pool_sets.lonely is not a set of delamination.pool_sets" in message
    message = bad(ci_config, ["paper_procedure", "cases"], ["I", "V"])
    assert "paper_procedure.cases[1] = 'V' is not a pool of swelling.cases" in message
    message = bad(ci_config, ["paper_procedure", "swelling", "stop_concentration_mEq_l"], 400.0)
    assert "paper_procedure.swelling.stop_concentration_mEq_l = 400 is above the ramp's top" in message


def test_a_resolution_set_that_is_not_a_pool_set_is_rejected_by_name(ci_config):
    message = bad(ci_config, ["delamination", "convergence", "pool_sets"], ["single", "pair_2deg"])
    assert "delamination.convergence.pool_sets[1] = 'pair_2deg' is not a pool set of delamination.pool_sets" in message


def test_figure_5s_set_is_checked_at_the_resolution_studys_spacings(ci_config):
    """The set of the resolution study is figure 5's, whatever its name: its pools must hold particles at every
    delamination.convergence.dx_um."""
    cfg = copy.deepcopy(ci_config)
    de = cfg["delamination"]
    tiny = dict(centre_radius_um=660.0, centre_angle_deg=46.0, radial_extent_um=3.0, angular_extent_deg=0.3)
    de["pool_sets"]["tiny"] = [tiny]  # one particle at dx = 6 um, none at 8 um
    de["convergence"]["dx_um"] = [8.0, 6.0]
    config.validate(cfg, SCHEMA)  # no figure's set: run at bilayer.dx_um = 6 um only, where it holds a particle
    de["figures"]["fig5"] = "tiny"
    with pytest.raises(
        config.ConfigError,
        match=r"delamination.pool_sets.tiny\[0\]: the pool holds no particle of a pool layer at dx = 8 um",
    ):
        config.validate(cfg, SCHEMA)


@pytest.mark.parametrize(
    "path, value, expected",
    [
        (
            ("sensitivity", "inputs", "gag.shear_modulus_kPa", "low"),
            -0.1,
            "sensitivity.inputs.gag.shear_modulus_kPa.low = -0.1 is outside the allowed range of gag.shear_modulus_kPa "
            "(> 0 and <= 1000)",
        ),
        (("sensitivity", "inputs", "bilayer.nope"), dict(low=1, high=2, source="x"), "bilayer.nope is not a number"),
        (("sensitivity", "inputs", "mean.dx_um"), dict(low=1, high=2, source="x"), "an input is a number of one of"),
        (
            ("sensitivity", "inputs", "pool.centre_radius_um"),
            dict(low=650, high=670, source="x"),
            "leaves the pool layers media",
        ),
        (("sensitivity", "inputs", "gag.temperature_K", "high"), 300.0, "low = 306.0 must be below high = 300.0"),
        (("sensitivity", "inputs", "gag.temperature_K", "source"), "", "sensitivity.inputs.gag.temperature_K.source"),
        (("sensitivity", "concentration_mEq_l"), 110.0, "must be a step of the swelling ramp (25, 50, 75, 100, 125"),
        (
            ("sensitivity", "methods", "sobol", "inputs"),
            99,
            "sensitivity.methods.sobol.inputs = 99 exceeds the number of inputs (15)",
        ),
        (("sensitivity", "map", "angular_extents_deg"), [3.0, 89.0], "would reach a symmetry edge"),
    ],
)
def test_a_bad_sensitivity_range_is_rejected_naming_the_input_and_its_allowed_range(full_config, path, value, expected):
    assert expected in bad(full_config, path, value)


@pytest.mark.parametrize(
    "path, value, expected",
    [
        (("sensitivity", "methods", "rank"), {}, "sensitivity.methods = 'rank' is invalid: 'rank' is not one of"),
        (("sensitivity", "methods", "morris"), KeyError, "sensitivity.methods.sobol screens its inputs with morris"),
        (("sensitivity", "methods", "sobol", "seed"), KeyError, "missing key 'sensitivity.methods.sobol.seed'"),
        (("delamination", "damage_law"), "fracture_energy", "damage_law = 'fracture_energy' needs a G_c per run"),
        (("delamination", "damage_law"), "linear", "delamination.damage_law = 'linear' is invalid"),
    ],
)
def test_the_sensitivity_methods_and_the_damage_law_are_checked_by_name_and_by_their_own_settings(
    full_config, path, value, expected
):
    assert expected in bad(full_config, path, value)


def test_the_schemas_enumerations_are_the_registries():
    """A new charge law, onset criterion or candidate rule is an entry of its registry: the schema accepts it with no
    edit."""
    from sphgag.physics.donnan import CHARGE_LAWS
    from sphgag.studies.delamination.settings import CANDIDATE_RULES, CRITERIA
    from sphgag.studies.pool_swelling import POOL_MODELS

    s = config.schema(SCHEMA)
    assert s["properties"]["swelling"]["properties"]["pool_models"]["items"]["enum"] == list(POOL_MODELS)
    assert s["properties"]["delamination"]["properties"]["criteria"]["items"]["enum"] == list(CRITERIA)
    assert s["properties"]["gag"]["properties"]["charge_laws"]["items"]["enum"] == list(CHARGE_LAWS)
    assert s["properties"]["delamination"]["properties"]["candidates"]["enum"] == list(CANDIDATE_RULES)


@pytest.mark.parametrize("value", ["foo", ["contact"], 1, KeyError])
def test_a_bad_candidate_rule_is_rejected_naming_the_key_and_the_rules(ci_config, value):
    """``delamination.candidates`` is one name of :data:`sphgag.studies.delamination.settings.CANDIDATE_RULES`."""
    msg = bad(ci_config, ["delamination", "candidates"], value)
    if value is KeyError:
        assert "missing key 'delamination.candidates'" in msg
    else:
        assert f"delamination.candidates = {value!r} is invalid" in msg and "one of ['contact', 'window']" in msg


@pytest.mark.parametrize("rule", ["contact", "window"])
def test_every_candidate_rule_is_valid(ci_config, rule):
    cfg = copy.deepcopy(ci_config)
    cfg["delamination"]["candidates"] = rule
    config.validate(cfg, SCHEMA)


def test_the_configuration_module_imports_at_its_top_only():
    """sphgag.config imports every section's options at its top: no import inside a function (a deferred import hides
    a dependency and an import cycle)."""
    import ast

    tree = ast.parse((ROOT / "src" / "sphgag" / "config.py").read_text())
    functions = [node for node in ast.walk(tree) if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef)]
    deferred = [
        f"{fn.name}:{node.lineno}"
        for fn in functions
        for node in ast.walk(fn)
        if isinstance(node, ast.Import | ast.ImportFrom)
    ]
    assert not deferred, deferred


def test_a_laws_ramp_top_names_a_charge_law_and_is_that_laws_alone(full_config):
    """delamination.max_concentration_by_law_mEq_l: a key that names no charge law, or a top out of range, is refused
    naming the key; the runs of a law it names ramp to its top, every other law's to max_concentration_mEq_l."""
    from sphgag.studies.delamination.settings import Settings

    msg = bad(full_config, ["delamination", "max_concentration_by_law_mEq_l"], {"neutral": 300.0})
    assert "delamination.max_concentration_by_law_mEq_l.neutral names no charge law (prescribed, conserved)" in msg
    assert "max_concentration_by_law_mEq_l" in bad(
        full_config, ["delamination", "max_concentration_by_law_mEq_l"], {"conserved": -1.0}
    )
    de = dict(full_config["delamination"], max_concentration_by_law_mEq_l={"conserved": 300.0})
    assert Settings.of_law(de, "conserved")["max_concentration_mEq_l"] == 300.0
    assert Settings.of_law(de, "prescribed")["max_concentration_mEq_l"] == de["max_concentration_mEq_l"]
    settings = Settings.from_config(Settings.of_law(de, "conserved"), 40.0, "averaged")
    assert settings.levels[-1] == 300.0 and settings.levels[0] == de["concentration_step_mEq_l"]
