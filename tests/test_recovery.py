"""Stress recovery (engine.measure): homogeneous deformations stay exact, linear fields are averaged exactly, the
surface particles carry their traction, and the equilibrium does not depend on the recovery."""

from dataclasses import replace

import numpy as np
import pytest

from sphgag.engine import measure
from sphgag.engine.loading import MMHG_TO_KPA, Load
from sphgag.physics import materials

from .conftest import CI_NUMERICS


def ghost_free(model) -> np.ndarray:
    """The particles whose stencil has no mirror image."""
    owner = np.repeat(np.arange(model.n), model.nb.counts())
    has_ghost = np.zeros(model.n, bool)
    has_ghost[owner[model.nb.mirror.min(axis=1) < 0]] = True
    return ~has_ghost


def test_the_registry_has_the_papers_reading_first():
    assert measure.RECOVERIES.paper.name == "paper"
    assert set(measure.RECOVERIES) >= {"paper", "volumetric", "traction"}


@pytest.mark.parametrize("name", ["volumetric"])
def test_a_homogeneous_deformation_keeps_its_stress(coarse_mean_model, name):
    """A map that respects both mirror planes is exact at every particle (F, hence J, uniform): the average of J is
    J and the recovered stress is the kernel stress, to round-off."""
    m = coarse_mean_model
    ev = m.evaluate(m.layout.X @ np.diag([1.3, 0.8]).T, Load(1.4, 0.0))
    sig, J = measure.recovered(m, ev, name).cauchy()
    kernel = ev.kernel_cauchy()[0]
    assert np.abs(kernel).max() > 1.0  # stressed
    assert np.abs(sig - kernel).max() <= 1e-10 * np.abs(kernel).max()


def test_linear_fields_are_averaged_exactly_beside_the_surfaces(coarse_mean_model):
    """The corrected weights sum to one and have no first moment: a linear field is its own average at every
    particle whose stencil has no mirror image, the surface particles included."""
    m = coarse_mean_model
    props = m.material(Load())[0]
    v = 3.0 + 0.02 * m.layout.X[:, 0] - 0.05 * m.layout.X[:, 1]
    keep = ghost_free(m)
    assert np.isin(m.layout.inner_surface, np.flatnonzero(keep)).any()
    assert np.abs(measure.averaged(m, props, v) - v)[keep].max() <= 1e-10


def test_the_average_stays_within_a_volumetric_law(ci_config):
    """Across the media/adventitia border (each layer its own lambda) the average is each layer's own: a field
    constant within each layer is kept."""
    from sphgag.studies import artery

    m = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-bilayer")
    props = m.material(Load(1.0, 0.0, material=(("activation", 0.0), ("prestretch", 1.0))))[0]
    v = np.where(m.layout.layer == 0, 1.0, 2.0)
    assert np.abs(measure.averaged(m, props, v) - v).max() <= 1e-12


def test_the_normal_stress_condition_is_solved(coarse_mean_model):
    """For a known state (lr, lt, lz) the radial stress is read from pk2; solving for lr at that stress gives the
    state back, with its hoop stress."""
    props = coarse_mean_model.material(Load())[0]
    lr, lt, lz = 0.62, 1.9, 1.62
    s_rr, s_tt, _ = materials.pk2(lr * lr, lt * lt, 0.0, lz, props, 0)
    J = lr * lt * lz
    rows = np.array([0])
    srr, stt, Js = np.empty(1), np.empty(1), np.empty(1)
    measure.normal_stress_state(props, rows, np.array([lt]), lz, np.array([lr * lr * s_rr / J]), srr, stt, Js)
    assert Js[0] == pytest.approx(J, rel=1e-10)
    assert stt[0] == pytest.approx(lt * lt * s_tt / J, rel=1e-8)


def test_a_surfaces_stretch_is_exact_for_a_uniform_dilation(coarse_mean_model):
    lay = coarse_mean_model.layout
    for ring in (lay.inner_surface, lay.outer_surface):
        assert np.abs(measure.surface_stretch(lay, 1.7 * lay.X, ring) - 1.7).max() <= 1e-12


def test_the_surfaces_carry_their_traction_and_the_equilibrium_is_unchanged(coarse_mean_model, ci_config):
    """On a pressurised mean wall: the traction recovery reads -P at the lumen and 0 outside; the forces, and the
    kernel columns of the profile, are those of the paper's reading."""
    m = coarse_mean_model
    lz = ci_config["mean"]["axial_stretch"]
    P = 120.0 * MMHG_TO_KPA
    loads = [Load(lz, 0.0), Load(lz, P)]
    state = CI_NUMERICS.solver(m).follow_path(m.layout.X, Load(1.0, 0.0), loads, run="t")[-1]
    read = replace(m, stress_recovery="traction").evaluate(state.x, state.load)
    assert np.array_equal(read.f_int, state.evaluation.f_int)
    profile = measure.ring_profile(m, read)
    assert profile.radial_stress_kPa.iloc[0] == pytest.approx(-P, rel=1e-10)
    assert abs(profile.radial_stress_kPa.iloc[-1]) <= 1e-10 * P
    raw = measure.ring_profile(m, state.evaluation)
    assert np.allclose(profile.radial_stress_kernel_kPa, raw.radial_stress_kPa, rtol=0, atol=1e-12 * P)
    assert np.allclose(raw.radial_stress_kernel_kPa, raw.radial_stress_kPa, rtol=0, atol=0)
