"""The grid convergence index (Celik et al. 2008): exact on values with a known order."""

import numpy as np
import pytest

from sphgag.studies import gci


@pytest.mark.parametrize("p", [0.7, 1.0, 1.7, 2.0])
@pytest.mark.parametrize("spacings", [(2.0, 2.83, 4.0), (1.0, 1.3, 2.1), (4.0, 2.0, 3.0)])
def test_a_known_order_and_limit_are_recovered_exactly(p, spacings):
    """phi(h) = phi_0 + C h^p at three spacings, uneven ratios and any order given: the observed order is p and the
    extrapolated value phi_0, to round-off; the GCI is 1.25 times the true relative error of the finest value."""
    phi0, C = 123.7, -4.2
    values = [phi0 + C * h**p for h in spacings]
    e = gci.estimate(spacings, values)
    h1 = min(spacings)
    assert e.h1 == h1 and e.order == pytest.approx(p, rel=1e-9) and not e.oscillatory
    assert e.extrapolated == pytest.approx(phi0, rel=1e-10)
    true = abs((phi0 + C * h1**p) - phi0) / abs(phi0 + C * h1**p)
    assert e.gci_fine == pytest.approx(1.25 * true, rel=1e-8)
    # the spacing the order says reaches a tenth of the GCI: (1/10)^(1/p) of the finest
    assert e.spacing_for(e.gci_fine / 10) == pytest.approx(h1 * 0.1 ** (1 / p), rel=1e-9)


def test_oscillatory_convergence_is_flagged():
    e = gci.estimate([1.0, 1.5, 2.25], [10.0, 10.3, 9.9])
    assert e.oscillatory


def test_equal_fine_values_have_no_error_and_bad_inputs_are_refused():
    assert gci.estimate([1, 2, 4], [5.0, 5.0, 5.0]).gci_fine == 0.0
    assert np.isnan(gci.estimate([1, 2, 4], [5.0, np.nan, 6.0]).order)
    with pytest.raises(ValueError, match="three"):
        gci.estimate([1, 2], [1.0, 2.0])
    with pytest.raises(ValueError, match="differ"):
        gci.estimate([1, 1, 2], [1.0, 2.0, 3.0])


def test_the_delamination_gci_table_has_a_row_per_spacing_and_the_estimate_of_the_three_finest():
    import pandas as pd

    from sphgag.studies.resolution import DELAMINATION_GCI_COLUMNS as GCI_COLUMNS
    from sphgag.studies.resolution import delamination_gci as gci_table

    dx = [4.0, 2.83, 2.0]
    rows = [
        dict(
            charge_law="prescribed",
            criterion="averaged",
            case="single",
            dx_um=h,
            onset_concentration_mEq_l=100 + h,
            runaway_concentration_mEq_l=110 + 2 * h**2,
            merge_concentration_mEq_l=np.nan,
        )
        for h in dx
    ]
    table = gci_table(pd.DataFrame(rows))
    assert list(table.columns) == GCI_COLUMNS
    assert set(table.quantity) == {"onset_concentration_mEq_l", "runaway_concentration_mEq_l"}  # merge: never
    onset = table[table.quantity == "onset_concentration_mEq_l"]
    assert sorted(onset.dx_um) == sorted(dx) and onset.observed_order.iloc[0] == pytest.approx(1.0)
    assert onset.extrapolated.iloc[0] == pytest.approx(100.0)
    runaway = table[table.quantity == "runaway_concentration_mEq_l"]
    assert runaway.observed_order.iloc[0] == pytest.approx(2.0) and runaway.extrapolated.iloc[0] == pytest.approx(110)


def test_values_whose_differences_grow_with_refinement_have_no_order():
    """The onset concentrations 116.7, 108.3 and 95.5 mEq/l at dx = 4, 2.83 and 2 um differ more between the finer
    pair: eq. 3 with absolute values would report a positive order; there is none."""
    e = gci.estimate([4.0, 2.83, 2.0], [116.72, 108.28, 95.47])
    assert e.diverging and np.isnan(e.order) and np.isnan(e.extrapolated) and np.isnan(e.gci_fine)
    assert not gci.estimate([4.0, 2.83, 2.0], [100 + 4.0, 100 + 2.83, 100 + 2.0]).diverging


def test_the_swelling_gci_table_reads_each_quantity_at_its_volume_ratio_and_concentration():
    """Synthetic rows of the resolution study at three spacings: the concentration that holds J = 5 converges at
    second order, the tip stress at 100 mEq/l at fourth (outside 0.5-3: Roache's cautious GCI, flagged)."""
    import pandas as pd

    from sphgag.studies import resolution, volume_states

    rows = []
    for h in (1.5, 2.12, 3.0):
        common = dict(
            charge_law="prescribed",
            pool_model="particles",
            model="passive",
            case="I",
            dx_um=h,
            top_circ_stress_kPa=400.0,
        )
        rows.append(
            dict(
                common,
                stage=volume_states.STAGE,
                concentration_mEq_l=120 + h**2,
                pool_volume_change=4.0,
                tip_radial_stress_kPa=50.0,
            )
        )
        rows.append(
            dict(
                common,
                stage="converted",
                concentration_mEq_l=100.0,
                pool_volume_change=2.0 + 0.1 * h,
                tip_radial_stress_kPa=80 + h**4,
            )
        )
    table = resolution.swelling_gci(pd.DataFrame(rows), [100.0], 103.0)
    assert list(table.columns) == resolution.SWELLING_GCI_COLUMNS
    c = table[(table.quantity == "concentration_at_volume_mEq_l") & (table["at"] == 5.0)]
    assert (
        len(c) == 3 and c.observed_order.iloc[0] == pytest.approx(2.0) and c.extrapolated.iloc[0] == pytest.approx(120)
    )
    assert c.order_in_range.all()
    j = table[(table.quantity == "volume_ratio") & (table["at"] == 100.0)]
    assert j.value.min() == pytest.approx(3.15) and j.observed_order.iloc[0] == pytest.approx(1.0)
    tip = table[(table.quantity == "tip_radial_stress_kPa") & (table["at"] == 100.0)].iloc[0]
    assert tip.observed_order == pytest.approx(4.0) and not tip.order_in_range
    e21 = abs(((80 + 2.12**4) - (80 + 1.5**4)) / (80 + 1.5**4))
    assert tip.gci_fine == pytest.approx(3.0 * e21 / ((2.12 / 1.5) ** 3.0 - 1.0))


def test_figure_4s_band_gives_every_step_of_the_ramp_and_the_intact_wall_its_estimate():
    """Synthetic rows at three spacings: the tip stress at each converted level converges at first order to 10 c
    kPa, the intact wall's is exact (no error: GCI 0); one row per spacing, quantity and state."""
    import pandas as pd

    from sphgag.studies import resolution

    rows = []
    for h in (1.5, 2.12, 3.0):
        common = dict(charge_law="prescribed", pool_model="particles", model="active", case="I", dx_um=h)
        rows.append(
            dict(common, stage="intact", concentration_mEq_l=0.0, tip_radial_stress_kPa=-5.0, top_circ_stress_kPa=100.0)
        )
        for c in (50.0, 100.0):
            rows.append(
                dict(
                    common,
                    stage="converted",
                    concentration_mEq_l=c,
                    tip_radial_stress_kPa=10 * c + 4 * h,
                    top_circ_stress_kPa=300.0 + h**2,
                )
            )
    band = resolution.swelling_band(pd.DataFrame(rows), 103.0)
    assert len(band) == 3 * 2 * 3 and (band.pressure_mmHg == 103.0).all()
    tip = band[(band.quantity == "tip_radial_stress_kPa") & (band.stage == "converted")]
    assert tip.observed_order.to_numpy() == pytest.approx(1.0)
    assert sorted(set(tip.extrapolated.round(9))) == [500.0, 1000.0]
    intact = band[(band.stage == "intact")]
    assert (intact.gci_fine == 0.0).all() and (intact.extrapolated == intact.value).all()
    top = band[(band.quantity == "top_circ_stress_kPa") & (band.stage == "converted")]
    assert top.observed_order.to_numpy() == pytest.approx(2.0) and top.extrapolated.to_numpy() == pytest.approx(300.0)
