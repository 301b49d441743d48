"""The damage law of eq. (2.28) (squared form) and the damaged strain energy (1 - D) W (section 2.7)."""

import numpy as np
import pytest

from sphgag.physics import damage
from sphgag.physics import materials as mt

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


# -- the damage law with a fracture energy (crack band) ------------------------------------------------------------
MU = 89.71  # kPa: a neo-Hookean band in uniaxial tension, W_0 = mu/2 (l^2 + 2/l - 3)
GC = 0.5  # J/m^2


def _w(lam):
    return 0.5 * MU * (lam**2 + 2.0 / lam - 3.0)


def _dw(lam):
    return MU * (lam - 1.0 / lam**2)


def _d2w(lam):
    return MU * (1.0 + 2.0 / lam**3)


def test_shape_constant_is_one_minus_the_mean_of_the_shape():
    x = np.linspace(0.0, 1.0, 200001)
    assert damage.SHAPE_K == pytest.approx(1.0 - np.trapezoid(damage.shape(x), x), rel=1e-9)


@pytest.mark.parametrize("dx", [1.0, 3.0])
def test_a_band_dissipates_the_fracture_energy_per_unit_area_at_every_spacing(dx):
    """A band of width h = 2 dx stretched from rest to rupture, damage updated as the delamination protocol does
    (staggered: D from the current state, the energy D releases at fixed deformation): per unit band area it
    dissipates G_c, whatever dx; the paper's law dissipates an energy proportional to h."""
    h = 2.0 * dx
    sigma_cr = 20.0
    results = {}
    for law in (damage.FractureEnergyLaw(sigma_cr, GC), damage.DamageLaw(sigma_cr, 0.05)):
        state = damage.DamageState.intact(1)
        released, lam = 0.0, 1.0
        while not state.ruptured[0]:
            lam += 2e-5
            before = state.D.copy()
            stress = (1.0 - state.D[0]) * _dw(lam)
            state.update(law, np.array([0]), [stress / (1.0 - state.D[0])], [lam], [_w(lam)], h)
            released += float((state.D[0] - before[0]) * _w(lam))
        results[law.name] = released * h / 1e3  # J/m^2
    assert results["fracture_energy"] == pytest.approx(GC, rel=2e-3)
    law = damage.FractureEnergyLaw(sigma_cr, GC)
    assert float(law.dissipated(0.0, 1.0, 3.0, h)) * h / 1e3 == pytest.approx(GC, rel=1e-12)
    paper_per_volume = results["paper"] / h
    assert paper_per_volume == pytest.approx(_paper_band_energy(sigma_cr), rel=2e-3)  # independent of h


def _paper_band_energy(sigma_cr):
    """int W_0 dD of eq. (2.28) for the same band, onset at the stretch where mu (l - 1/l^2) = sigma_cr [kJ/m^3]."""
    from scipy.optimize import brentq

    l0 = brentq(lambda lam: _dw(lam) - sigma_cr, 1.0, 2.0)
    s = np.linspace(0.0, 0.05, 200001)
    D = damage.DamageLaw(sigma_cr, 0.05).damage(s)
    return float(np.sum(np.diff(D) * _w(l0 + s[1:]))) / 1e3


@pytest.mark.parametrize("band_width", [2.0, 6.0])
def test_stress_and_tangent_of_the_fracture_energy_law_against_finite_differences(band_width):
    """Uniaxial band on a monotone path: P = (1 - D(W_0)) W_0', tangent (1 - D) W_0'' - D'(W_0) W_0'^2, through onset
    and up to rupture (D = 1: no stress, no stiffness)."""
    law = damage.FractureEnergyLaw(20.0, GC)
    from scipy.optimize import brentq

    l_on = brentq(lambda lam: _dw(lam) - 20.0, 1.0, 2.0)
    y_on = _w(l_on)
    y_f = float(law.rupture_energy(y_on, band_width))
    l_f = brentq(lambda lam: _w(lam) - y_f, l_on, 50.0)

    def stress(lam):
        D = law.damage_at(lam, l_on, _w(lam), y_on, band_width) if lam >= l_on else 0.0
        return float((1.0 - D) * _dw(lam))

    def tangent(lam):
        if lam < l_on:
            return _d2w(lam)
        D = law.damage_at(lam, l_on, _w(lam), y_on, band_width)
        return float((1.0 - D) * _d2w(lam) - law.damage_rate(_w(lam), y_on, band_width) * _dw(lam) ** 2)

    for lam in np.concatenate([[0.5 * (1 + l_on)], l_on + (l_f - l_on) * np.array([1e-3, 0.1, 0.5, 0.9, 0.999])]):
        eps = 1e-7 * lam
        fd = (stress(lam + eps) - stress(lam - eps)) / (2 * eps)
        assert tangent(lam) == pytest.approx(fd, rel=1e-5, abs=1e-6 * MU)
    assert stress(l_f * 1.001) == 0.0 and tangent(l_f * 1.001) == 0.0
    assert float(law.damage_at(l_f, l_on, y_f, y_on, band_width)) == pytest.approx(1.0)


def test_a_band_too_wide_for_its_fracture_energy_ruptures_at_onset():
    law = damage.FractureEnergyLaw(20.0, 1e-3)  # g = 1 kJ/m^3 over 1 um, below the onset energy
    state = damage.DamageState.intact(1)
    state.update(law, np.array([0]), [25.0], [1.1], [5.0], 1.0)
    assert state.ruptured[0]
