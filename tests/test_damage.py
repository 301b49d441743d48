"""The damage law of eq. (2.28) (squared form) and the damaged strain energy (1 - D) W (section 2.7)."""

import numpy as np
import pytest

from sphgag import damage
from sphgag import materials as mt

from .test_materials import THETA, mixture_props, piola, random_F

LAW = damage.DamageLaw(critical_stress_kPa=40.0, rupture_stretch_increment=0.05)


def test_damage_is_zero_below_the_critical_stress():
    state = damage.DamageState.intact(4)
    grew = state.update(LAW, np.arange(4), radial_stress=[39.9, 10.0, -5.0, 39.99], radial_stretch=[1.3] * 4)
    assert grew.size == 0 and np.all(state.D == 0.0) and np.all(np.isnan(state.onset_stretch))


def test_only_candidates_start_to_damage():
    state = damage.DamageState.intact(3)
    state.update(LAW, np.array([1]), radial_stress=[50.0, 50.0, 50.0], radial_stretch=[1.1, 1.1, 1.1])
    assert np.isnan(state.onset_stretch[[0, 2]]).all() and state.onset_stretch[1] == 1.1


def test_damage_reaches_one_at_the_stated_stretch_increment_and_follows_eq_2_28():
    state = damage.DamageState.intact(1)
    state.update(LAW, np.array([0]), radial_stress=[41.0], radial_stretch=[1.20])
    assert state.D[0] == 0.0 and state.onset_stretch[0] == 1.20
    for dl in (0.01, 0.03, 0.049):
        state.update(LAW, np.array([0]), radial_stress=[0.0], radial_stretch=[1.20 + dl])  # stress no longer matters
        assert state.D[0] == pytest.approx(np.exp((dl * np.sqrt(np.log(2.0)) / 0.05) ** 2) - 1.0, rel=1e-12)
    state.update(LAW, np.array([0]), radial_stress=[0.0], radial_stretch=[1.25])
    assert state.D[0] == pytest.approx(1.0, abs=1e-12) and state.ruptured[0]
    assert LAW.damage(1.0) == 1.0  # capped


def test_damage_never_decreases():
    state = damage.DamageState.intact(1)
    state.update(LAW, np.array([0]), radial_stress=[45.0], radial_stretch=[1.0])
    history = []
    for lr in (1.02, 1.04, 1.01, 0.98, 1.03, 1.045):
        state.update(LAW, np.array([0]), radial_stress=[45.0], radial_stretch=[lr])
        history.append(state.D[0])
    assert np.all(np.diff(history) >= 0.0)
    assert history[2] == history[1]  # unloading keeps the damage


def test_radial_stretch_is_that_of_the_reference_radial_direction():
    theta = np.array([0.0, 0.5 * np.pi, 0.3])
    F = np.repeat(np.diag([1.2, 0.9])[None], 3, axis=0)
    lam = damage.radial_stretch(F, theta)
    assert lam[0] == pytest.approx(1.2) and lam[1] == pytest.approx(0.9)
    assert lam[2] == pytest.approx(np.hypot(1.2 * np.cos(0.3), 0.9 * np.sin(0.3)))


@pytest.mark.parametrize("D", [0.0, 0.3, 0.95, 1.0])
def test_damaged_stress_and_tangent_are_one_minus_d_times_the_intact_ones(D):
    """Every constituent (pre-stretched elastin, SMC and collagen in tension and compression, active tone)."""
    intact = mixture_props(active=258.0)
    weak = damage.weaken(intact, np.array([D]))
    C, A, Cw, Aw = np.empty((3, 3)), np.empty((4, 4)), np.empty((3, 3)), np.empty((4, 4))
    c, s = np.cos(THETA), np.sin(THETA)
    for spread in (0.05, 0.25):
        F = random_F(spread)
        assert np.allclose(piola(F, 1.1, weak), (1.0 - D) * piola(F, 1.1, intact), rtol=1e-12, atol=1e-12)
        mt.tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], 1.1, c, s, intact, 0, C, A)
        mt.tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], 1.1, c, s, weak, 0, Cw, Aw)
        assert np.allclose(Aw, (1.0 - D) * A, rtol=1e-12, atol=1e-12)
        cl = mt.local_deformation(F[0, 0], F[0, 1], F[1, 0], F[1, 1], c, s)[4:]
        assert mt.strain_energy(*cl, 1.1, weak, 0) == pytest.approx(
            (1.0 - D) * mt.strain_energy(*cl, 1.1, intact, 0), rel=1e-12, abs=1e-12
        )
    assert weak[0, mt.HG_E] == intact[0, mt.HG_E]
