"""The lumen load through the force operator's boundary term (``numerics.lumen_load: operator``,
:data:`sphgag.engine.loading.LUMEN_LOADS`): a uniform pressure is an exact discrete equilibrium, the tangent is exact,
and the ring beside the lumen reads the exact wall's radial stress where the surface load leaves it 25 % of P off."""

from dataclasses import replace

import numpy as np
import pytest

from sphgag.engine import loading
from sphgag.engine.loading import MMHG_TO_KPA, Load
from sphgag.engine.numerics import Numerics
from sphgag.studies import wall_profiles

from .test_forces import assert_jacobian_matches_fd, rng


def _uniform_pressure_residual(model, p: float) -> np.ndarray:
    """The net force on every particle at x = X (lambda_z = 1) under the stress -p I and the lumen pressure p."""
    X = model.layout.X
    ev = model.evaluate(X, Load(1.0, 0.0))  # the mean wall is stress free at X: its internal forces vanish
    assert np.abs(ev.f_int).max() < 1e-9
    cof = np.zeros((model.n, 4))
    cof[:, 0] = cof[:, 3] = -p  # P = -p J F^-T at F = I
    loaded = model.evaluate(X, Load(1.0, p), extra_stress=cof)
    return loaded.f_int + loaded.f_ext


def test_a_uniform_pressure_is_in_equilibrium_through_the_operator_and_not_on_the_surface(coarse_mean_model):
    """The operator's load balances -p I to round-off on the inner half of the wall; the surface load leaves the
    boundary residual of nodal integration on the rings within the kernel's reach (0.2-0.4 of the traction)."""
    p = 10.0
    operator = replace(coarse_mean_model, lumen_load="operator")
    scale = p * np.linalg.norm(loading.pressure_forces(operator.layout.X, operator.layout.inner_surface, 1.0, 1.0))
    inner = loading.inner_layer(operator.layout.X, operator.layout.inner_surface, operator.layout.outer_surface)
    assert np.abs(_uniform_pressure_residual(operator, p)[inner]).max() < 1e-9 * scale
    assert np.abs(_uniform_pressure_residual(coarse_mean_model, p)[inner]).max() > 1e-2 * scale


def test_the_operators_lumen_load_has_the_surface_loads_total_and_an_exact_tangent(coarse_mean_model):
    m = replace(coarse_mean_model, lumen_load="operator")
    load = Load(1.5, 60 * MMHG_TO_KPA)
    x = m.layout.X * 1.3 + 0.4 * rng.standard_normal(m.layout.X.shape)
    total = m.evaluate(x, load).f_ext.sum(axis=0)
    surface = loading.pressure_forces(x, m.layout.inner_surface, load.pressure_kPa, load.axial_stretch).sum(axis=0)
    assert total == pytest.approx(surface, rel=2e-2)
    cols = np.concatenate([rng.choice(2 * m.n, 10, replace=False), 2 * m.layout.inner_surface[:2]])
    assert_jacobian_matches_fd(m, load, x, cols)


@pytest.mark.parametrize("lumen_load, bound", [("surface", None), ("operator", 6.0)])
def test_the_ring_beside_the_lumen_reads_the_exact_wall(full_config, lumen_load, bound):
    """The mean wall at dx = 7 um, 103 mmHg: the radial stress of the ring one spacing inside the lumen against the
    exact thick wall at its material point (% of P). Measured: surface +25.6, operator -3.1 (docs/physics.md)."""
    p = dict(full_config["mean"], dx_um=7.0)
    numerics = Numerics.of(dict(full_config["numerics"], lumen_load=lumen_load))
    (found,) = wall_profiles.mean_states(p, numerics, full_config["calibration"], [103.0])
    error = wall_profiles.ring_errors(*found[1:], "paper").radial_material_error_pct.iloc[1]
    if bound is None:
        assert error > 15.0
    else:
        assert abs(error) < bound
