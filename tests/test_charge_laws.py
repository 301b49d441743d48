"""The charge laws of the GAG pools (eqs. 2.25-2.27) as a registry: a new law is one entry of
:data:`sphgag.physics.donnan.CHARGE_LAWS`, and the configuration, the engine's GAG material and the exact circular pool
follow it."""

import copy

import numpy as np
import pytest

from sphgag import config
from sphgag.engine.history import HistoryMaterial, ParticleHistory
from sphgag.engine.loading import Load
from sphgag.physics import cavity, donnan, materials
from sphgag.views import style

from .conftest import ROOT

SCHEMA = ROOT / "config" / "schema.yaml"
GAG = dict(
    shear_modulus_kPa=0.1,
    lame_lambda_kPa=10.0,
    volumetric="log_squared",
    temperature_K=310.0,
    bath_concentration_mEq_l=300.0,
    hourglass_modulus_kPa=89.71,
)


def test_the_registry_holds_the_paper_law_and_our_deviation():
    assert tuple(donnan.CHARGE_LAWS) == ("prescribed", "conserved")
    assert donnan.PAPER_LAW == "prescribed"
    prescribed, conserved = donnan.CHARGE_LAWS["prescribed"], donnan.CHARGE_LAWS["conserved"]
    assert prescribed.paper and prescribed.holds_pressure()
    assert not conserved.paper and not conserved.holds_pressure()
    # the fixed-charge concentration of eq. (2.26) at the volume ratio J of a particle loaded to c, and its inverse
    assert prescribed.concentration(150.0, 4.0) == 150.0 and conserved.concentration(150.0, 4.0) == 37.5
    assert prescribed.reference_concentration(37.5, 4.0) == 37.5 and conserved.reference_concentration(37.5, 4.0) == 150
    with pytest.raises(ValueError, match="unknown charge law 'literal': one of prescribed, conserved"):
        donnan.charge_law("literal")


@pytest.mark.parametrize("law", donnan.CHARGE_LAWS)
def test_a_laws_pressure_at_a_volume_and_its_inverse_are_eq_2_26(law):
    """The swelling pressure at J of a particle swollen to Pi0 at J = 1 is eq. (2.26) at the law's concentration of
    the charge that has Pi0; the inverse returns Pi0."""
    entry, cb, rt = donnan.CHARGE_LAWS[law], 300.0, donnan.GAS_CONSTANT * 310.0 / 1000.0
    c0 = float(donnan.concentration_for_pressure(91.0, cb, 310.0))
    for J in (0.5, 1.0, 4.0):
        pi = entry.swelling_at(91.0, J, cb, rt)
        assert pi == pytest.approx(float(donnan.swelling_pressure(entry.concentration(c0, J), cb, 310.0)), rel=1e-12)
        assert entry.reference_pressure(pi, J, cb, rt) == pytest.approx(91.0, rel=1e-12)
    assert (entry.swelling_at(91.0, 4.0, cb, rt) == 91.0) == entry.holds_pressure()


@pytest.mark.parametrize("law", donnan.CHARGE_LAWS)
def test_the_figures_name_a_law_from_the_registry(law):
    entry = donnan.CHARGE_LAWS[law]
    assert style.law_title(law) == entry.title and style.law_short(law) == entry.short
    assert style.is_paper_law(law) == entry.paper


def gag_rows(law: str, concentration: float) -> np.ndarray:
    """The property rows of a one-particle pool (seeded, so GAG at the load's concentration) under ``law``."""
    before = ParticleHistory.intact(2).seed([np.array([1])])
    material = HistoryMaterial(lambda load: materials.empty_props(2), before, materials.law_gag(GAG, law))
    return material(Load(1.0, 0.0, material=(("concentration", concentration),)))[1]


def test_the_engine_carries_each_law_in_its_column():
    """``prescribed``: the pressure Pi(c) in the column PI (eqs. 2.25-2.27 as printed); ``conserved``: the fixed charge
    c per reference volume in the column FCD, whose Donnan pressure the kernels take at c/J."""
    pi = donnan.swelling_pressure(120.0, GAG["bath_concentration_mEq_l"], GAG["temperature_K"])
    prescribed, conserved = gag_rows("prescribed", 120.0), gag_rows("conserved", 120.0)
    assert prescribed[materials.PI] == pi and prescribed[materials.FCD] == 0.0
    assert conserved[materials.PI] == 0.0 and conserved[materials.FCD] == 120.0


@pytest.fixture(params=[True, False], ids=["conserving", "prescribing"])
def third_law(request, monkeypatch):
    """A third law, registered in a copy of the registry for this test only."""
    kind = donnan.ConservedCharge if request.param else donnan.PrescribedCharge
    law = kind("ideal", paper=False, title="ideal charge law: a test", short="ideal, test")
    monkeypatch.setattr(donnan, "CHARGE_LAWS", {**donnan.CHARGE_LAWS, law.name: law})
    return law


def test_a_registered_law_is_a_valid_configuration(third_law, ci_config):
    cfg = copy.deepcopy(ci_config)
    cfg["gag"]["charge_laws"] = ["prescribed", "conserved", "ideal"]
    config.validate(cfg, SCHEMA)
    assert config.schema(SCHEMA)["properties"]["gag"]["properties"]["charge_laws"]["items"]["enum"][-1] == "ideal"
    gag = materials.Gag.of(materials.law_gag(cfg["gag"], "ideal"))
    assert gag.charge_law == "ideal" and gag.law is third_law
    cfg["gag"]["charge_laws"] = ["ideal", "literal"]
    with pytest.raises(config.ConfigError, match="gag.charge_laws\\[1\\] = 'literal' is invalid"):
        config.validate(cfg, SCHEMA)


def test_a_registered_law_swells_by_its_rule(third_law):
    """The engine's column, the exact circular pool and the figures' titles of the new law are those of the
    registered law whose fixed charge follows the same rule."""
    twin = "prescribed" if third_law.holds_pressure() else "conserved"
    np.testing.assert_array_equal(gag_rows("ideal", 120.0), gag_rows(twin, 120.0))
    assert third_law.concentration(120.0, 3.0) == donnan.CHARGE_LAWS[twin].concentration(120.0, 3.0)
    m, g, B = cavity.Solid(89.71, 10000.0), cavity.Solid(0.1, 10.0), 4.0
    pool, same = (cavity.circular_pool(1.0, B, m, g, 91.0, law=law) for law in ("ideal", twin))
    assert pool.law == "ideal" and (pool.stretch, pool.swelling_kPa) == (same.stretch, same.swelling_kPa)
    assert (pool.swelling_kPa < 91.0) != third_law.holds_pressure()  # Pi at c0/J, below Pi(c0), where J > 1
    p = cavity.pressure_for_volume_ratio(4.0, 1.0, 20.0, cavity.Solid(1.0, 10.0), cavity.Solid(0.05, 1.0), law="ideal")
    assert p == cavity.pressure_for_volume_ratio(
        4.0, 1.0, 20.0, cavity.Solid(1.0, 10.0), cavity.Solid(0.05, 1.0), law=twin
    )
    assert style.law_title("ideal") == "ideal charge law: a test" and style.law_short("ideal") == "ideal, test"
    assert not style.is_paper_law("ideal")
