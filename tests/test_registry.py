"""The variants behind one registry protocol (sphgag.registry): every kind is a registry with one paper's variant, and
a new pool model, damage law and hourglass form, each written in one file (tests/plugins), is accepted by name by the
configuration and the code that runs it, for the test only."""

import copy
import dataclasses
import importlib

import numpy as np
import pytest

from sphgag import config
from sphgag.engine import forces, kernel, measure
from sphgag.engine.loading import Load
from sphgag.engine.model import Model
from sphgag.physics import damage, donnan
from sphgag.registry import Registry, Variant
from sphgag.studies import annulus, inclusion, sensitivity, swollen_pool
from sphgag.studies.delamination.settings import CANDIDATE_RULES, CRITERIA, Settings
from sphgag.studies.pool_swelling import POOL_MODELS

from .conftest import CI_NUMERICS, ROOT, Lattice, isotropic_props

SCHEMA = ROOT / "config" / "schema.yaml"

REGISTRIES = {
    "charge law": donnan.CHARGE_LAWS,
    "damage law": damage.DAMAGE_LAWS,
    "onset criterion": CRITERIA,
    "candidate rule": CANDIDATE_RULES,
    "pool model": POOL_MODELS,
    "hourglass form": forces.HOURGLASS_FORMS,
    "pool model of the annulus": annulus.ANNULUS_POOL_MODELS,
    "stress recovery": measure.RECOVERIES,
    "sensitivity method": sensitivity.SENSITIVITY_METHODS,
}


@dataclasses.dataclass(frozen=True)
class Flavour(Variant):
    name: str
    title: str
    paper: bool = False


def test_a_registry_reads_as_a_mapping_and_names_its_variants_in_errors():
    reg = Registry("flavour", [Flavour("plain", "the paper's", paper=True), Flavour("spiced", "ours")])
    assert tuple(reg) == reg.names == ("plain", "spiced") and "spiced" in reg and reg["spiced"].title == "ours"
    assert reg.paper.name == "plain" and [v.name for v in reg.deviations()] == ["spiced"]
    assert reg.titles == {"plain": "the paper's", "spiced": "ours"}
    with pytest.raises(ValueError, match="unknown flavour 'salted': one of plain, spiced"):
        reg.lookup("salted")
    with pytest.raises(ValueError, match="flavour 'plain' is registered already"):
        reg.register(Flavour("plain", "again"))
    with pytest.raises(ValueError, match="the paper's flavour is 'plain' already"):
        reg.register(Flavour("other", "a second paper's", paper=True))
    with reg.registered(Flavour("sweet", "a plug-in")):
        assert reg.names == ("plain", "spiced", "sweet")
    assert reg.names == ("plain", "spiced")


@pytest.mark.parametrize("kind", REGISTRIES)
def test_every_kind_is_a_registry_with_one_papers_variant_first(kind):
    reg = REGISTRIES[kind]
    assert isinstance(reg, Registry) and reg.kind == kind
    assert sum(bool(v.paper) for v in reg.values()) == 1
    assert all(isinstance(v, Variant) or issubclass(v, Variant) for v in reg.values())
    assert all(v.title for v in reg.values())
    with pytest.raises(ValueError, match=f"unknown {kind} 'bubble': one of {', '.join(reg)}"):
        reg.lookup("bubble")


def test_the_names_the_pipeline_and_the_figures_know_are_unchanged():
    assert tuple(donnan.CHARGE_LAWS) == ("prescribed", "conserved") and donnan.PAPER_LAW == "prescribed"
    assert tuple(damage.DAMAGE_LAWS) == ("paper", "fracture_energy") and damage.DAMAGE_LAWS.paper is damage.DamageLaw
    assert damage.matches_paper("paper") and not damage.matches_paper("0.5") and not damage.matches_paper(None)
    assert tuple(CRITERIA) == ("particle", "averaged") and tuple(CANDIDATE_RULES) == (
        "contact",
        "window",
    )
    assert tuple(POOL_MODELS) == ("particles", "cavity") and tuple(forces.HOURGLASS_FORMS) == ("paper", "energy")
    assert tuple(annulus.ANNULUS_POOL_MODELS) == ("hole", "particles")
    assert tuple(measure.RECOVERIES) == ("paper", "volumetric", "traction")
    assert POOL_MODELS["cavity"].laws == ("prescribed",) and POOL_MODELS["cavity"].hourglass


def test_the_schema_enumerates_and_titles_every_registry(ci_config):
    s = config.schema(SCHEMA)["properties"]
    hg = s["numerics"]["properties"]["hourglass"]
    assert hg["enum"] == ["paper", "energy"] and forces.HOURGLASS_FORMS["energy"].title in hg["description"]
    reading = s["numerics"]["properties"]["stress_recovery"]
    assert reading["enum"] == list(measure.RECOVERIES)
    assert measure.RECOVERIES["traction"].title in reading["description"]
    annulus_pools = s["verification"]["properties"]["annulus"]["properties"]["pool_models"]
    assert annulus_pools["items"]["enum"] == ["hole", "particles"]
    circle = s["verification"]["properties"]["circular_pool"]["properties"]["pool_models"]
    assert circle["items"]["enum"] == list(POOL_MODELS)


def test_a_variants_own_check_names_the_key_and_its_range(ci_config):
    cfg = copy.deepcopy(ci_config)
    cfg["delamination"]["averaging_length_um"] = 0.01
    problems = CRITERIA.problems(cfg, "delamination.criteria", ["particle", "averaged"])
    assert len(problems) == 1 and problems[0].startswith("delamination.averaging_length_um = 0.01 is below")
    cfg["gag"]["charge_laws"] = ["conserved"]
    problems = POOL_MODELS.problems(cfg, "swelling.pool_models", ["particles", "cavity"])
    assert problems == [
        "swelling.pool_models[1] = 'cavity' carries the charge laws prescribed, none of gag.charge_laws = ['conserved']"
    ]


# -- the plug-ins: one file each -------------------------------------------------------------------------------------

PLUGINS = ("pool_model", "damage_law", "hourglass_form", "charge_law")


def plugged(name: str):
    """The plug-in ``name`` of tests/plugins, registered for the test only: the registry is as shipped before and
    after."""
    module = importlib.import_module(f"tests.plugins.{name}")
    before = module.REGISTRY.names
    with module.REGISTRY.registered(module.VARIANT):
        yield module
    assert module.REGISTRY.names == before and module.VARIANT.name not in module.REGISTRY


@pytest.fixture(params=PLUGINS)
def plugin(request):
    yield from plugged(request.param)


@pytest.fixture
def pool_plugin():
    yield from plugged("pool_model")


@pytest.fixture
def damage_plugin():
    yield from plugged("damage_law")


@pytest.fixture
def hourglass_plugin():
    yield from plugged("hourglass_form")


def configured(ci_config, module, name):
    """``ci_config`` naming the plug-in ``name`` of ``module`` where the configuration names its kind."""
    cfg = copy.deepcopy(ci_config)
    if module.REGISTRY is POOL_MODELS:
        cfg["swelling"]["variant_pool_models"] = ["cavity", name]
        cfg["verification"]["circular_pool"]["pool_models"] = ["particles", name]
    elif module.REGISTRY is forces.HOURGLASS_FORMS:
        cfg["numerics"]["hourglass"] = name
    elif module.REGISTRY is donnan.CHARGE_LAWS:
        cfg["gag"]["charge_laws"] = [*cfg["gag"]["charge_laws"], name]
    return cfg


def test_the_configuration_accepts_a_plugin_by_name_and_refuses_an_unknown_one(plugin, ci_config):
    name = plugin.VARIANT.name
    assert name in plugin.REGISTRY and plugin.REGISTRY.lookup(name) is plugin.VARIANT
    if plugin.REGISTRY is damage.DAMAGE_LAWS:  # also a run's setting (Settings.damage_law), refused by name there
        base = Settings.from_config(ci_config["delamination"], 40.0, "particle")
        settings = dataclasses.replace(base, damage_law=name)
        assert isinstance(settings.law, plugin.VARIANT)
        with pytest.raises(ValueError, match="damage_law must be one of paper, fracture_energy, linear, got 'bubble'"):
            dataclasses.replace(base, damage_law="bubble")
        return
    config.validate(configured(ci_config, plugin, name), SCHEMA)
    with pytest.raises(config.ConfigError, match=f"'bubble' is not one of .*'{name}'"):
        config.validate(configured(ci_config, plugin, "bubble"), SCHEMA)


def test_a_plugin_pool_model_holds_the_pool_as_its_class_says(pool_plugin, ci_config):
    plugin = pool_plugin
    plugin.VARIANT.check(ci_config, "swelling.variant_pool_models[1]")  # it carries the configured prescribed law
    assert plugin.VARIANT.rebuilds and plugin.VARIANT.hourglass is None  # keeps numerics.hourglass once converted
    b = ci_config["bilayer"]
    matrix = dict(
        shear_modulus_kPa=b["elastin_shear_modulus_kPa"],
        lame_lambda_kPa=b["lame_lambda_kPa"],
        hourglass_modulus_kPa=b["hourglass_modulus_kPa"],
    )
    mat = inclusion.Materials.of(matrix, ci_config["gag"], bulk=True)
    model = swollen_pool.circle_model(10.0, 20.0, 2.5, mat, CI_NUMERICS, plugin.VARIANT.name)
    assert model.name == "circular_cavity_as_configured_dx2.5" and len(model.cavities) == 1


def test_a_plugin_damage_law_damages_by_its_own_rule(damage_plugin):
    law = damage_plugin.VARIANT(30.0, 0.1)
    state = damage.DamageState.intact(3)
    state.update(law, np.arange(3), np.array([10.0, 31.0, 40.0]), np.ones(3))
    state.update(law, np.arange(3), np.zeros(3), np.array([1.05, 1.05, 1.2]))
    np.testing.assert_allclose(state.D, [0.0, 0.5, 1.0])


def test_a_plugin_hourglass_form_is_what_the_model_computes_with(hourglass_plugin):
    plugin = hourglass_plugin
    lay = Lattice(n=6)
    nb = kernel.build_neighbours(lay.X, lay.volume, 2.5, mirrors=())
    model = Model("patch", lay, nb, isotropic_props(lay.n), 1.0, hourglass=plugin.VARIANT.name)
    _, hgc, _ = model.material(Load(1.0, 0.0))
    assert hgc.max() == 0.0 and model.hourglass_forces(lay.X * 1.1, Load(1.0, 0.0)) is None
    paper = dataclasses.replace(model, hourglass="paper")
    assert paper.material(Load(1.0, 0.0))[1].max() > 0.0


def test_the_figures_name_the_pool_models_as_the_registry_titles_them():
    """The views name the pool models without importing the engine (views/style.py): the same names and titles."""
    from sphgag.studies.claims.evidence import PAPER_POOL
    from sphgag.views import style

    assert style.PAPER_POOL == PAPER_POOL == POOL_MODELS.paper.name


def test_a_plugin_file_registers_its_variant_once_and_a_bad_one_is_named(tmp_path):
    """sphgag.plugins loads a file of the configuration's key ``plugins``: its VARIANT joins its REGISTRY (once, however
    often the file is loaded); a missing file, or one without REGISTRY and VARIANT, is refused naming the key."""
    from sphgag import plugins

    path = ROOT / "tests" / "plugins" / "damage_law.py"
    try:
        (first,), (again,) = plugins.load([path]), plugins.load([path])
        assert damage.DAMAGE_LAWS["linear"] is first.VARIANT and again.VARIANT is not first.VARIANT
        assert plugins.variant_of(path) == (damage.DAMAGE_LAWS, "linear")
    finally:
        damage.DAMAGE_LAWS.unregister("linear")
    with pytest.raises(ValueError, match="plugins: .*nowhere.py is no Python file"):
        plugins.load([tmp_path / "nowhere.py"])
    (tmp_path / "empty.py").write_text("x = 1\n")
    with pytest.raises(ValueError, match="plugins: .*empty.py defines no REGISTRY and VARIANT"):
        plugins.load([tmp_path / "empty.py"])
