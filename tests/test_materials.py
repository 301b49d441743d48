"""Constitutive laws: stress = derivative of the strain energy, tangent = derivative of the stress."""

import numpy as np
import pytest

from sphgag.physics import donnan, volumetric
from sphgag.physics import materials as mt

rng = np.random.default_rng(7)
THETA = 0.6  # reference angle of the test particle (local frame is rotated)


def mean_props():
    fam = [(0, 25.370, 0.036), (90, 16.593, 0.108), (28.783, 0.078, 1.719), (-28.783, 0.078, 1.719)]
    return mt.mean_behaviour(1, 18.53, 1853.0, fam, 18.53)


def mixture_props(active=0.0):
    """A pre-stretched constrained mixture with tension/compression constants (eqs. 2.21-2.24)."""
    p = mt.empty_props(1)
    p[:, mt.MU] = 0.47 * 89.71
    p[:, mt.LAM] = 1000.0
    p[:, mt.GR], p[:, mt.GT], p[:, mt.GZ] = 1.0 / (1.9 * 1.62), 1.9, 1.62
    mt.set_family(p, [0], 0, 0.47, 90.0, 261.4, 0.24, 249.5, 0.15, prestretch=1.2)
    mt.set_family(p, [0], 1, 0.06 * 0.944 / 2, 29.91, 234.9, 4.08, 29.14, 4.08, prestretch=1.25)
    mt.set_family(p, [0], 2, 0.06 * 0.944 / 2, -29.91, 234.9, 4.08, 29.14, 4.08, prestretch=1.25)
    mt.set_family(p, [0], 3, 0.06 * 0.056, 0.0, 234.9, 4.08, 29.14, 4.08, prestretch=1.25)
    p[:, mt.TACT] = active
    return p


def gag_props():
    """GAG: soft neo-Hookean with a Gibbs-Donnan swelling pressure (eq. 2.27; c* = 150 here, any value will do)."""
    p = mt.empty_props(1)
    p[:, mt.MU] = 0.1
    p[:, mt.PI] = float(donnan.swelling_pressure(100.0, 150.0))
    return p


def diluting_gag_props():
    """GAG whose fixed charge is conserved: Donnan pressure at the current concentration c0 / J (eq. 2.26)."""
    p = mt.empty_props(1)
    p[:, mt.MU], p[:, mt.LAM] = 0.1, 10.0
    mt.convert_to_gag(p, [0], 1.0, 0.1, 89.71, kappa=10.0, volumetric="log_squared", fixed_charge=(150.0, 300.0, 310.0))
    return p


def contents_props(form, fraction=1.0):
    """GAG with the contents' volumetric term ``form`` (kappa = 10 kPa, prescribed Pi = 91 kPa), converted from the
    mixture by ``fraction`` (below 1: the homotopy, the tissue's LAM (ln J)^2 and the contents' term both present)."""
    p = mixture_props()
    mt.convert_to_gag(p, [0], fraction, 0.1, 89.71, swelling_pressure=91.0, kappa=10.0, volumetric=form)
    return p


MATERIALS = {"mean": mean_props, "mixture": mixture_props, "gag": gag_props, "diluting_gag": diluting_gag_props}
MATERIALS.update({f"gag_{f}": lambda f=f: contents_props(f) for f in volumetric.VOLUMETRIC_FORMS})
MATERIALS.update({f"converting_{f}": lambda f=f: contents_props(f, 0.6) for f in volumetric.VOLUMETRIC_FORMS})


def energy(F, lz, p):
    c = mt.local_deformation(F[0, 0], F[0, 1], F[1, 0], F[1, 1], np.cos(THETA), np.sin(THETA))[4:]
    return mt.strain_energy(c[0], c[1], c[2], lz, p, 0)


def piola(F, lz, p):
    return np.array(mt.first_piola(F[0, 0], F[0, 1], F[1, 0], F[1, 1], lz, np.cos(THETA), np.sin(THETA), p, 0))


def random_F(spread):
    while True:
        F = np.eye(2) + spread * rng.standard_normal((2, 2))
        if np.linalg.det(F) > 0.5:
            return F


@pytest.mark.parametrize("name", MATERIALS)
@pytest.mark.parametrize("spread", [0.05, 0.25])
def test_stress_is_the_derivative_of_the_strain_energy(name, spread):
    """P = dW/dF (eq. 2.10) by central differences, for random F (fibres in tension and compression)."""
    p = MATERIALS[name]()
    for _ in range(5):
        F = random_F(spread)
        lz = 1.0 + 0.3 * rng.random()
        P = piola(F, lz, p).reshape(2, 2)
        fd = np.zeros((2, 2))
        h = 1e-6
        for a in range(2):
            for b in range(2):
                Fp, Fm = F.copy(), F.copy()
                Fp[a, b] += h
                Fm[a, b] -= h
                fd[a, b] = (energy(Fp, lz, p) - energy(Fm, lz, p)) / (2 * h)
        assert np.allclose(P, fd, rtol=1e-6, atol=1e-6 * np.abs(P).max())


@pytest.mark.parametrize("name", list(MATERIALS) + ["active"])
def test_tangent_is_the_derivative_of_the_stress(name):
    """A = dP/dF by central differences, including the active tone (which has no energy)."""
    p = mixture_props(active=258.0) if name == "active" else MATERIALS[name]()
    C, A = np.empty((3, 3)), np.empty((4, 4))
    for _ in range(5):
        F = random_F(0.15)
        lz = 1.0 + 0.3 * rng.random()
        mt.tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], lz, np.cos(THETA), np.sin(THETA), p, 0, C, A)
        fd = np.zeros((4, 4))
        h = 1e-6
        for k in range(4):
            Fp, Fm = F.copy().ravel(), F.copy().ravel()
            Fp[k] += h
            Fm[k] -= h
            fd[:, k] = (piola(Fp.reshape(2, 2), lz, p) - piola(Fm.reshape(2, 2), lz, p)) / (2 * h)
        assert np.allclose(A, fd, rtol=1e-5, atol=1e-6 * np.abs(A).max())


def test_both_sides_of_the_tension_compression_switch_are_exercised():
    I4_circ = []
    for _ in range(50):
        F = random_F(0.25)
        c_tt = mt.local_deformation(F[0, 0], F[0, 1], F[1, 0], F[1, 1], np.cos(THETA), np.sin(THETA))[5]
        I4_circ.append(1.2**2 * c_tt)
    assert min(I4_circ) < 1.0 < max(I4_circ)


def test_mean_model_is_stress_free_in_its_reference():
    p = mean_props()
    assert np.abs(piola(np.eye(2), 1.0, p)).max() < 1e-12


def test_prestretch_gives_the_homeostatic_stress_at_F_equal_I():
    """With F = I the mixture carries its deposition stresses: MU (G^2 - I) + fibre terms."""
    p = mixture_props()
    S = np.array(mt.pk2(1.0, 1.0, 0.0, 1.0, p, 0))
    mu = p[0, mt.MU]
    assert S[0] == pytest.approx(mu * (p[0, mt.GR] ** 2 - 1.0))
    assert S[1] > mu * (1.9**2 - 1.0)  # plus the circumferential SMC/collagen
    assert S[2] == 0.0


def test_active_tone_adds_the_circumferential_cauchy_stress_of_eq_2_24():
    lam = 1.05
    F_ref = np.array([[np.cos(THETA), -np.sin(THETA)], [np.sin(THETA), np.cos(THETA)]])
    # F stretches the local e_theta by lam (F = Q diag(1, lam) Q^T), J = lam
    F = F_ref @ np.diag([1.0, lam]) @ F_ref.T
    passive, active = mixture_props(), mixture_props(active=258.0)
    dP = (piola(F, 1.0, active) - piola(F, 1.0, passive)).reshape(2, 2)
    sigma = dP @ F.T / np.linalg.det(F)
    e_t = F_ref[:, 1]
    T = 258.0 * lam * (1 - ((1.1 - lam) / (1.1 - 0.6)) ** 2)
    assert e_t @ sigma @ e_t == pytest.approx(T, rel=1e-12)
    assert np.abs(sigma - T * np.outer(e_t, e_t)).max() < 1e-9


def test_gag_cauchy_stress_is_eq_2_27():
    p = gag_props()
    F = random_F(0.2)
    sigma = piola(F, 1.0, p).reshape(2, 2) @ F.T / np.linalg.det(F)
    J = np.linalg.det(F)
    expected = 0.1 * (F @ F.T - np.eye(2)) / J - p[0, mt.PI] * np.eye(2)
    assert np.allclose(sigma, expected, atol=1e-12)


def test_diluting_gag_pressure_is_eq_2_26_at_the_current_concentration():
    """sigma = -PI(c0 / J) I (+ the small neo-Hookean and bulk terms, removed here):
    J = 1 gives PI(c0), J = 2 PI(c0/2)."""
    p = diluting_gag_props()
    p[:, mt.MU] = p[:, mt.LAM] = p[:, mt.KAPPA] = 0.0
    for J, c in ((1.0, 150.0), (2.0, 75.0), (0.8, 187.5)):
        F = np.sqrt(J) * np.eye(2)
        P = piola(F, 1.0, p).reshape(2, 2)
        sigma = P @ F.T / J
        assert np.allclose(sigma, -float(donnan.swelling_pressure(c, 300.0, 310.0)) * np.eye(2), rtol=1e-12, atol=1e-12)


def test_swelling_pressure_hand_values():
    """Pi = R T (sqrt(c^2 + c*^2) - c*) (eqs. 2.25-2.26): hand-computed values."""
    RT = 8.314462618 * 310.0  # J/mol
    assert donnan.swelling_pressure(0.0, 150.0) == 0.0
    assert donnan.swelling_pressure(150.0, 150.0) == pytest.approx(RT * 150.0 * (np.sqrt(2) - 1) / 1000, rel=1e-12)
    # 100 mEq/l against a 150 mM bath: 2577.48 J/mol * 30.2776 mol/m^3 = 78.04 kPa
    assert donnan.swelling_pressure(100.0, 150.0) == pytest.approx(78.04, abs=0.01)


def test_identical_fibre_families_are_merged_exactly():
    p4 = mixture_props()
    merged = mt.merge_identical_families(p4)
    assert merged[0, mt.NFAM] == 3
    F = random_F(0.2)
    assert np.allclose(piola(F, 1.2, merged), piola(F, 1.2, p4), rtol=1e-13)


def test_a_converted_particle_stretched_many_fold_has_a_finite_tangent():
    """A ruptured particle (fibre fractions set to 0) inside a swollen pool reaches J of 30-60: its
    fibre laws overflow there (exp of a huge I4), and 0 x inf made its tangent NaN, which LU turned
    into an exactly zero pivot. A family a particle has lost contributes nothing, exactly."""
    p = mixture_props()
    mt.convert_to_gag(p, [0], 1.0, 0.1, 89.71, swelling_pressure=91.0)
    C, A = np.empty((3, 3)), np.empty((4, 4))
    F = 7.0 * np.eye(2)
    mt.tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], 1.0, np.cos(THETA), np.sin(THETA), p, 0, C, A)
    assert np.isfinite(A).all() and np.isfinite(piola(F, 1.0, p)).all() and np.isfinite(energy(F, 1.0, p))
    g = gag_props()
    g[0, mt.PI] = 91.0
    assert np.allclose(piola(F, 1.0, p), piola(F, 1.0, g), rtol=1e-12)


@pytest.mark.parametrize("form", volumetric.VOLUMETRIC_FORMS)
def test_swollen_contents_stress_and_tangent_are_the_derivatives(form):
    """The GAG contents of each volumetric form at swollen states (J of 4 to 50, where log_squared is no longer
    elliptic): P = dW/dF and A = dP/dF by central differences."""
    p = contents_props(form)
    C, A = np.empty((3, 3)), np.empty((4, 4))
    for scale in (2.0, 4.0, 7.0):
        F = scale * (np.eye(2) + 0.1 * rng.standard_normal((2, 2)))
        h = 1e-6 * scale
        P = piola(F, 1.0, p)
        mt.tangent_modulus(F[0, 0], F[0, 1], F[1, 0], F[1, 1], 1.0, np.cos(THETA), np.sin(THETA), p, 0, C, A)
        dW, dP = np.zeros(4), np.zeros((4, 4))
        for k in range(4):
            Fp, Fm = F.copy().ravel(), F.copy().ravel()
            Fp[k] += h
            Fm[k] -= h
            dW[k] = (energy(Fp.reshape(2, 2), 1.0, p) - energy(Fm.reshape(2, 2), 1.0, p)) / (2 * h)
            dP[:, k] = (piola(Fp.reshape(2, 2), 1.0, p) - piola(Fm.reshape(2, 2), 1.0, p)) / (2 * h)
        assert np.allclose(P, dW, rtol=1e-6, atol=1e-6 * np.abs(P).max())
        assert np.allclose(A, dP, rtol=1e-5, atol=1e-6 * np.abs(A).max())
