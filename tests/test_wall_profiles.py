"""The transmural profile verification (:mod:`sphgag.studies.wall_profiles`): its error measures and orders, its
configuration checks, and a wall whose surfaces the traction reading gets exactly."""

import numpy as np
import pandas as pd
import pytest

from sphgag import config
from sphgag.studies import wall_profiles

from .conftest import CI_NUMERICS, ROOT


def _rings(dx: float, surface: float, interior: float) -> pd.DataFrame:
    """Three rings of one state whose radial errors are ``surface``, ``interior``, ``-surface`` (% of P)."""
    e = np.array([surface, interior, -surface])
    return pd.DataFrame(
        dict(
            wall="mean",
            lumen_load="surface",
            recovery="paper",
            pressure_mmHg=103.0,
            dx_um=dx,
            ring=[0, 1, 2],
            radial_error_pct=e,
            radial_material_error_pct=e,
            circ_error_pct=0.5 * e,
            circ_material_error_pct=0.5 * e,
            residual=1e-6,
        )
    )


def test_the_summary_reads_the_surfaces_and_the_worst_ring_and_the_orders_their_slopes():
    """Surface errors falling as dx^2, the interior one as dx: orders 2 and 1, from the finer pair and from all."""
    rings = pd.concat([_rings(dx, 8.0 * dx**2, 3.0 * dx) for dx in (2.0, 1.0, 0.5)], ignore_index=True)
    table = wall_profiles.summary(rings)
    first = table[table.dx_um == 2.0].iloc[0]
    assert first.material_inner_radial_pct == pytest.approx(32.0)
    assert first.material_outer_radial_pct == pytest.approx(-32.0)
    assert first.material_interior_radial_max_pct == pytest.approx(6.0)
    assert first.material_radial_max_pct == pytest.approx(32.0)
    assert first.residual == pytest.approx(1e-6)
    (o,) = wall_profiles.orders(table).itertuples()
    assert o.dx_um == 0.5
    assert o.material_inner_radial_pct_order == pytest.approx(2.0)
    assert o.material_interior_radial_max_pct_order_all == pytest.approx(1.0)


def test_a_surface_read_from_its_traction_has_no_order():
    rings = pd.concat([_rings(dx, 0.0, dx) for dx in (2.0, 1.0)], ignore_index=True)
    (o,) = wall_profiles.orders(wall_profiles.summary(rings)).itertuples()
    assert np.isnan(o.material_inner_radial_pct_order)
    assert o.material_interior_radial_max_pct_order == pytest.approx(1.0)


def test_the_spacings_halve_every_two_levels():
    assert [wall_profiles.spacing(7.0, k) for k in range(3)] == [7.0, 4.95, 3.5]


@pytest.mark.parametrize(
    "key, value, message",
    [
        ("figure_pressure_mmHg", 150.0, "verification.profiles.figure_pressure_mmHg = 150.0 is not one of"),
        ("pressures_mmHg", [103.0, 240.0], "verification.profiles.pressures_mmHg[1] = 240.0 exceeds"),
        ("lumen_loads", ["surface", "pressure"], "lumen_loads"),
        ("refinements", 1, "refinements"),
    ],
)
def test_a_bad_profile_verification_is_refused_by_key(full_config, key, value, message):
    cfg = {k: v for k, v in full_config.items()}
    cfg["verification"] = dict(cfg["verification"], profiles=dict(cfg["verification"]["profiles"], **{key: value}))
    with pytest.raises(config.ConfigError, match=message.replace("[", r"\[").replace("]", r"\]")):
        config.validate(cfg, ROOT / "config" / "schema.yaml")


def test_the_traction_reading_gets_the_surfaces_and_the_kernel_reading_misses_the_lumen(ci_config):
    """The CI mean wall (dx = 14 um) at 103 mmHg: read from the traction, both surfaces carry the exact radial
    stress; the kernel's own stress at the lumen is far from -P (more than 30 % of P)."""
    (found,) = wall_profiles.mean_states(ci_config["mean"], CI_NUMERICS, ci_config["calibration"], [103.0])
    rings = wall_profiles.wall_rings([found], ["paper", "traction"], lumen_load="surface", dx_um=14.0)
    table = wall_profiles.summary(rings).set_index("recovery")
    assert abs(table.loc["traction", "material_inner_radial_pct"]) < 1e-6
    assert abs(table.loc["traction", "material_outer_radial_pct"]) < 1e-6
    assert abs(table.loc["paper", "material_inner_radial_pct"]) > 30.0
    assert table.loc["paper", "residual"] < ci_config["numerics"]["tolerance"]
