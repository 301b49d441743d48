"""Figure 4's pools at a given volume (sphgag.studies.volume_states): the state at a volume ratio holds it exactly,
is the state concentration control reaches at its concentration, and lies between the path's states around it."""

import numpy as np
import pytest

from sphgag.engine import solver
from sphgag.physics import donnan, materials
from sphgag.studies import artery, volume_states
from sphgag.studies.pool_swelling import swell_pool

from .conftest import CI_NUMERICS


@pytest.fixture(scope="module")
def path(ci_config, ci_wall):
    """The CI pool of case I under the prescribed law, swollen to 100 mEq/l in steps of 25 (concentration control)."""
    gag = materials.law_gag(ci_config["gag"], donnan.PAPER_LAW)
    pool = artery.pool_sector(ci_config["swelling"]["cases"]["I"])
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, pool=pool, gag=gag)
    sw = dict(ci_config["swelling"], max_concentration_mEq_l=100.0, concentration_points=5)
    return model, swell_pool(model, ci_wall, CI_NUMERICS, sw)


def test_a_state_at_a_volume_ratio_holds_it_and_is_the_concentration_paths(ci_config, path):
    model, states = path
    converted = [s for s in states if s.stage == "converted"]
    ratios = [v / v0 for _, v, v0 in (volume_states.volume_of(model, s) for s in converted)]
    middle = 0.5 * (ratios[-2] + ratios[-1])  # between the last two states of the path
    found = volume_states.at_volume_ratios(model, states, [middle, 2.0 * ratios[-1]], CI_NUMERICS)
    assert list(found) == [middle]  # beyond the path's last state: not reached, not extrapolated
    s = found[middle]
    assert s.stage == volume_states.STAGE and s.control == "volume"
    _, v, v0 = volume_states.volume_of(model, s)
    assert v / v0 == pytest.approx(middle, rel=1e-8)
    assert converted[-2].concentration < s.concentration < converted[-1].concentration
    direct = solver.Solver(model, dict(tol=1e-8)).follow_path(converted[-2].x, converted[-2].load, [s.load])[-1]
    assert np.abs(direct.x - s.x).max() < 1e-3 * np.abs(direct.x - converted[-2].x).max()


def test_beyond_a_path_that_lost_equilibrium_the_volume_goes_on_as_the_control(ci_config, path):
    """The same path marked as one that found no equilibrium beyond its last state: a J beyond it is reached from
    there, under volume control, at a concentration above the last one; the next J from the one reached before it."""
    from dataclasses import replace

    model, states = path
    cut = [replace(s, path_end="no equilibrium") for s in states]
    converted = [s for s in cut if s.stage == "converted"]
    last = volume_states.volume_of(model, converted[-1])
    ratio = last[1] / last[2]
    targets = [1.05 * ratio, 1.1 * ratio]
    found = volume_states.at_volume_ratios(model, cut, targets, CI_NUMERICS)
    assert list(found) == targets
    for J, s in found.items():
        _, v, v0 = volume_states.volume_of(model, s)
        assert v / v0 == pytest.approx(J, rel=1e-8) and s.path_end == "no equilibrium"
    assert converted[-1].concentration < found[targets[0]].concentration < found[targets[1]].concentration
