"""Typed options: the configuration's sections as frozen dataclasses, built from the plain dicts the pipeline keeps."""

import dataclasses

import pytest

from sphgag import config
from sphgag.engine import solver
from sphgag.engine.numerics import Numerics
from sphgag.engine.solver import PathOptions
from sphgag.physics.materials import Gag, law_gag
from sphgag.studies.artery import Bilayer, FibreConstants


def test_numerics_from_the_configuration(ci_config):
    n = Numerics.of(ci_config["numerics"])
    assert n.tolerance == ci_config["numerics"]["tolerance"] and Numerics.of(n) is n
    assert n.solver_options().tol == n.tolerance
    with pytest.raises(dataclasses.FrozenInstanceError):
        n.tolerance = 1.0


def test_a_misspelt_or_missing_key_raises_naming_it(ci_config):
    bad = dict(ci_config["numerics"], tolerence=1e-4)
    del bad["tolerance"]
    with pytest.raises(ValueError, match=r"unknown key numerics\.tolerence; missing key numerics\.tolerance"):
        Numerics.of(bad)
    bilayer = dict(ci_config["bilayer"], collagen=dict(ci_config["bilayer"]["collagen"], c1_kpa=1.0))
    with pytest.raises(ValueError, match=r"unknown key bilayer\.collagen\.c1_kpa"):
        Bilayer.of(bilayer)


def test_the_solver_options_of_a_path_are_typed(ci_config):
    """A run's numerics give the :class:`PathOptions` of its paths (the solver's defaults for the rest); options built
    from a mapping take the same keys, and a key they do not know raises naming it."""
    n = Numerics.of(ci_config["numerics"])
    opts = n.solver_options()
    assert PathOptions.of(opts) is opts and PathOptions.of(dataclasses.asdict(opts)) == opts
    assert (opts.tol, opts.max_iter, opts.reuse, opts.stall) == (
        n.tolerance,
        n.max_newton_iterations,
        n.reuse_factorisation,
        None,
    )
    assert PathOptions.of({}) == PathOptions()
    with pytest.raises(ValueError, match=r"unknown key solver\.tolerance"):
        PathOptions.of(dict(dataclasses.asdict(opts), tolerance=1e-4))
    with pytest.raises(dataclasses.FrozenInstanceError):
        opts.tol = 1.0


def test_the_options_of_every_kind_of_path_derive_from_the_runs(ci_config):
    """A transition (whose fallback is a snap) bisects at most FALLBACK_BISECTIONS times and stops where Newton
    stagnates; volume control's load steps and a snap's handoffs keep Newton's budget alone; the options of a solver
    are checked when it is made."""
    opts = Numerics.of(ci_config["numerics"]).solver_options()
    transition = opts.for_transition()
    assert transition.max_bisections == min(opts.max_bisections, solver.FALLBACK_BISECTIONS)
    assert transition.stall == solver.STALL_ITERATIONS and transition.reuse == opts.reuse
    assert opts.newton_budget() == PathOptions(tol=opts.tol, max_iter=opts.max_iter)
    with pytest.raises(ValueError, match=r"unknown key solver\.tolerance"):
        solver.Solver(None, dict(tolerance=1e-4))


def test_the_bilayer_is_typed_all_the_way_down(ci_config):
    b = Bilayer.of(ci_config["bilayer"])
    assert isinstance(b.collagen, FibreConstants) and b.smc.angle_deg == 0.0
    assert b.prestretch.collagen == ci_config["bilayer"]["prestretch"]["collagen"]
    assert b.aligned_radii_um == tuple(ci_config["bilayer"]["aligned_radii_um"])
    assert b.mass_fractions["media"]["elastin"] == ci_config["bilayer"]["mass_fractions"]["media"]["elastin"]
    with pytest.raises(TypeError):
        b.mass_fractions["media"]["elastin"] = 0.0  # read-only


def test_the_gag_of_one_run_has_one_charge_law(ci_config):
    g = Gag.of(law_gag(ci_config["gag"], "conserved"))
    assert g.charge_law == "conserved" and g.temperature_K == ci_config["gag"]["temperature_K"]
    with pytest.raises(ValueError, match="gag charge_law: unknown charge law 'literal': one of prescribed, conserved"):
        Gag.of(dict(law_gag(ci_config["gag"], "conserved"), charge_law="literal"))
    with pytest.raises(ValueError, match=r"unknown key gag\.charge_laws"):
        Gag.of(ci_config["gag"])  # the configuration's section lists the laws: a run has one


@pytest.mark.parametrize("name", ["full_config", "ci_config"])
def test_every_section_of_the_configuration_has_options_that_build_from_it(name, request):
    """Each top-level section of config/config.yaml (and config/ci.yaml) has its options class, named by its
    ``SECTION``, and they build from the section (every key known, none missing); the one top-level list, ``plugins``,
    is the files :mod:`sphgag.plugins` loads."""
    cfg = request.getfixturevalue(name)
    by_section = {options.SECTION: options for options in config.SECTIONS}
    assert len(by_section) == len(config.SECTIONS) and sorted(by_section) == sorted(set(cfg) - {"plugins"})
    assert cfg["plugins"] == []
    for section, options in by_section.items():
        built = options.of(cfg[section])
        assert isinstance(built, options) and options.of(built) is built
    with pytest.raises(ValueError, match=r"unknown key swelling\.colour"):
        by_section["swelling"].of(dict(cfg["swelling"], colour=1.0))
