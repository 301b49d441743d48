"""The pressurised annulus (sphgag.studies.annulus): the engine against the exact solution below the prescribed law's
limit of existence, and no state above it."""

import numpy as np
import pandas as pd
import pytest

from sphgag.studies import annulus, resolution

from .conftest import CI_NUMERICS


@pytest.fixture(scope="module")
def matrix(ci_config):
    b = ci_config["bilayer"]
    return dict(
        shear_modulus_kPa=b["elastin_shear_modulus_kPa"],
        lame_lambda_kPa=b["lame_lambda_kPa"],
        hourglass_modulus_kPa=b["hourglass_modulus_kPa"],
    )


def study(ci_config, matrix, model, dx, fractions, max_volume_ratio=40.0, volumetric=None):
    va = dict(
        radius_um=15.0,
        outer_ratios=[2.0],
        fractions=fractions,
        beyond=1.05,
        dx_um=dx,
        max_volume_ratio=max_volume_ratio,
    )
    gag = dict(ci_config["gag"], volumetric=volumetric or ci_config["gag"]["volumetric"])
    return annulus.annulus_study(va, matrix, gag, CI_NUMERICS, model)


@pytest.fixture(scope="module")
def pool_of_particles(ci_config, matrix):
    """The paper's pool of particles (the configured contents: ``gag.volumetric: convex``) in B/A = 2 at
    dx = 1.41 um: half the limit, 0.9 of it, and 1.05 times it."""
    return study(ci_config, matrix, "particles", [1.41], [0.5, 0.9])


def test_pool_of_particles_at_half_the_limit_is_the_exact_solution(pool_of_particles):
    """B/A = 2, Pi = 0.5 of the pool's limit (the convex contents: a saturation at mu ln 2 + mu_g + kappa =
    72.28 kPa): volume ratio and hoop stress at the hole within 1 % of the exact solution at dx = 1.41 um (measured:
    -0.38 % and -0.21 %; with the log_squared contents -0.21 % and -0.66 %)."""
    half = pool_of_particles[pool_of_particles.fraction == 0.5].iloc[0]
    assert half.limit_kind == "saturation"
    assert half.limit_pressure_kPa == pytest.approx(89.71 * np.log(2.0) + 0.1 + 10.0, rel=1e-5)
    assert abs(half.volume_error) < 0.01
    assert abs(half.lining_hoop_error) < 0.01
    assert half.residual < 1e-4


@pytest.mark.parametrize("volumetric", ["convex", "log_squared"])
def test_pool_of_particles_at_0_9_of_the_limit_by_the_contents_form(ci_config, matrix, volumetric):
    """B/A = 2 at dx = 1 um, 0.9 of each form's limit. The convex contents stay elliptic: the volume within 1.5 % of
    the exact solution (measured -0.97 %, converging at second order: -3.8 / -1.9 / -0.97 % at dx = 2 / 1.41 / 1 um)
    and the particles' J within a factor 3 of each other (measured 2.1 at every spacing). The log_squared contents
    lose ellipticity at J = 2.82 (the exact pool's is 4.57): the particles' J spread 18-fold (measured 1.4 to 24.5)
    and the volume jumps to +3.7 % (-2.0 / -0.6 % at dx = 2 / 1.41 um)."""
    row = study(ci_config, matrix, "particles", [1.0], [0.9], volumetric=volumetric).query("fraction == 0.9").iloc[0]
    assert row.state and row.residual < 1e-4
    if volumetric == "convex":
        assert abs(row.volume_error) < 0.015 and row.pool_jacobian_spread < 3.0
    else:
        assert row.volume_error > 0.02 and row.pool_jacobian_spread > 10.0


def test_no_gag_particle_passes_the_lining_below_the_limit(pool_of_particles):
    """Up to 0.9 of the limit the pool's rings stay inside its lining, as in the exact solution."""
    below = pool_of_particles[pool_of_particles.fraction < 1.0]
    assert below.state.all()
    assert (below.ring_crossing_um < 0.0).all()


@pytest.mark.parametrize("model", ["particles", "hole", "log_squared particles"])
def test_above_the_limit_no_run_reports_a_state(ci_config, matrix, pool_of_particles, model):
    """At 1.05 times the largest pressure the exact solution holds: load control finds no state, and volume control
    finds the discrete limit point (the pool of log_squared particles, within 1 % of the exact one at dx = 1.41 um)
    or the pressure still rising towards the saturation (the hole at dx = 2 um: 62.6 kPa held at J = 40, 0.7 % above
    the exact saturation pressure, which the discretisation's error allows; the pool of convex particles at
    dx = 1.41 um: 72.04 kPa held at J = 40, 0.3 % below the exact saturation), and says so."""
    if model == "particles":
        table = pool_of_particles
    elif model == "hole":
        table = study(ci_config, matrix, "hole", [2.0], [0.5])
    else:
        table = study(ci_config, matrix, "particles", [1.41], [0.9], volumetric="log_squared")
    above = table[table.fraction > 1.0].iloc[0]
    assert not above.state
    assert "load control" in above.beyond_reason
    top = above.limit_pressure_kPa
    if above.limit_kind == "limit point":
        assert above.beyond_end == "limit point"
        assert above.discrete_limit_kPa == pytest.approx(top, rel=0.01)
    else:
        assert above.limit_kind == "saturation"
        assert above.beyond_end == "no equilibrium" and "still rising" in above.beyond_reason
        assert above.largest_held_kPa == pytest.approx(top, rel=0.02) and above.largest_held_kPa < above.pressure_kPa
    assert (above.limit_kind == "limit point") == (model == "log_squared particles")


@pytest.mark.xfail(strict=True, reason="measured: the hole's hoop stress is 6-13 % off at half its limit, growing")
def test_hole_hoop_stress_at_half_the_limit(ci_config, matrix):
    """The empty hole at half its saturation pressure: the hoop stress at the hole within 1 % at dx = 1.41 um. It is
    not (+6.2, +9.8, +13.4 % at dx = 2, 1.41, 1 um): the particles next to a free surface carry a stress error that
    refinement does not remove (docs/physics.md, "The pressurised annulus")."""
    half = study(ci_config, matrix, "hole", [1.41], [0.5], max_volume_ratio=2.0).query("fraction == 0.5").iloc[0]
    assert abs(half.lining_hoop_error) < 0.01


def test_hole_hoop_stress_recovered_from_the_traction_converges_to_the_exact_one(ci_config, matrix):
    """The empty hole at 0.5 and 0.75 of its limit, dx = 2 and 1.41 um: the hoop stress at the hole recovered from its
    traction (swollen_pool.traction_hoop) is within 2 % of the exact one, and closer at the finer spacing, by at least
    the first order (measured, B/A = 2: +1.12/+0.60/+0.28 % at 0.5 and +1.01/+0.64/+0.32 % at 0.75, dx = 2/1.41/1;
    the kernel stress, fitted to the hole, +6.2/+9.8/+13.4 % and +1.6/+4.3/+7.0 %)."""
    table = study(ci_config, matrix, "hole", [2.0, 1.41], [0.5, 0.75], max_volume_ratio=5.0)
    for f in (0.5, 0.75):
        coarse, fine = (table.query(f"fraction == {f} and dx_um == {dx}").iloc[0] for dx in (2.0, 1.41))
        assert abs(fine.lining_hoop_traction_error) < 0.02 and abs(coarse.lining_hoop_traction_error) < 0.02
        assert abs(fine.lining_hoop_traction_error) < abs(coarse.lining_hoop_traction_error) * (1.41 / 2.0)


def test_orders_of_three_spacings_with_known_errors():
    """The observed order from errors e = C h^p at three spacings is p, and the GCI's extrapolated value is exact."""
    h = np.array([1.0, 1.5, 2.25])
    rows = [
        dict(
            pool_model="hole",
            outer_ratio=2.0,
            fraction=0.5,
            state=True,
            dx_um=d,
            volume_ratio=3.0 * (1 + 0.02 * d**2),
            volume_ratio_exact=3.0,
            lining_hoop_kPa=50.0 * (1 - 0.03 * d),
            lining_hoop_exact_kPa=50.0,
            lining_hoop_traction_kPa=50.0 * (1 + 0.01 * d**2),
        )
        for d in h
    ]
    o = resolution.annulus_orders(pd.DataFrame(rows)).set_index("quantity")
    assert o.loc["volume_ratio", "order_fine"] == pytest.approx(2.0)
    assert o.loc["volume_ratio", "order_coarse"] == pytest.approx(2.0)
    assert o.loc["lining_hoop_kPa", "order_fine"] == pytest.approx(1.0)
    assert o.loc["volume_ratio", "extrapolated"] == pytest.approx(3.0)
    assert o.loc["lining_hoop_kPa", "extrapolated"] == pytest.approx(50.0)
    assert o.loc["lining_hoop_traction_kPa", "order_fine"] == pytest.approx(2.0)


def test_contents_that_hold_any_pressure_have_no_limit_to_verify(ci_config, matrix):
    """The hartmann_neff contents' stress grows without bound: the exact pool has no largest pressure, and the
    verification says so rather than loading the annulus to a fraction of an infinite pressure."""
    mat = annulus.materials("particles", matrix, dict(ci_config["gag"], volumetric="hartmann_neff"))
    with pytest.raises(ValueError, match="holds any pressure"):
        annulus.limit(15.0, 30.0, mat)
