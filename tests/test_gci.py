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


# Eca & Hoekstra (2014): the least-squares uncertainty of four or more spacings


@pytest.mark.parametrize("p", [0.7, 1.0, 1.5, 2.0])
@pytest.mark.parametrize("spacings", [(1.0, 1.5, 2.25, 3.375), (0.5, 0.7, 1.0, 1.4, 2.0), (3.0, 1.0, 2.1, 1.3, 4.0)])
def test_least_squares_recovers_a_known_order_and_reduces_to_the_three_grid_gci(p, spacings):
    """phi0 + C h^p with p in the good range: the free-order fit is exact (sigma ~ 0), so the uncertainty is
    1.25 |phi1 - phi0|, which is Celik et al.'s GCI of the three finest spacings, and both extrapolate to phi0."""
    phi0, C = 123.7, -4.2
    values = [phi0 + C * h**p for h in spacings]
    u = gci.least_squares_uncertainty(spacings, values)
    h1 = min(spacings)
    phi1 = phi0 + C * h1**p
    assert u.fit == "power" and u.order == pytest.approx(p, rel=1e-8) and u.observed_order == u.order
    assert u.extrapolated == pytest.approx(phi0, rel=1e-11) and u.std_dev < 1e-9
    assert u.h1 == h1 and u.phi1 == pytest.approx(phi1) and u.safety_factor == 1.25
    assert u.uncertainty_abs == pytest.approx(1.25 * abs(C) * h1**p, rel=1e-8)
    three = sorted(zip(spacings, values))[:3]
    e = gci.estimate([h for h, _ in three], [v for _, v in three])
    assert u.extrapolated == pytest.approx(e.extrapolated, rel=1e-10)
    assert u.uncertainty == pytest.approx(e.gci_fine, rel=1e-7)


def test_least_squares_on_exact_second_order_values_gives_phi0_order_two_and_a_near_zero_uncertainty():
    """phi = 10 + 0.004 h^2 at h = 0.25 ... 2: the order 2 and phi0 are recovered, sigma ~ 0, and U is only the GCI
    part, 1.25 * 0.004 * 0.25^2 = 3.125e-4 (3e-5 of phi1): no fit penalty."""
    spacings = [0.25, 0.5, 1.0, 2.0]
    u = gci.least_squares_uncertainty(spacings, [10 + 0.004 * h**2 for h in spacings])
    assert u.fit == "power" and u.order == pytest.approx(2.0, abs=1e-8)
    assert u.extrapolated == pytest.approx(10.0, abs=1e-11) and u.std_dev < 1e-12
    assert u.uncertainty_abs == pytest.approx(3.125e-4, rel=1e-7) and u.uncertainty < 4e-5


def test_least_squares_on_exact_first_order_values_selects_order_one():
    spacings = [2.0, 0.5, 1.0, 0.7, 1.4]
    u = gci.least_squares_uncertainty(spacings, [2.0 + 0.3 * h for h in spacings])
    assert u.fit == "power" and u.order == pytest.approx(1.0, abs=1e-8) and u.h1 == 0.5
    assert u.extrapolated == pytest.approx(2.0, abs=1e-12) and u.uncertainty_abs == pytest.approx(1.25 * 0.15)


def test_least_squares_hand_worked_cases():
    """Two sets worked by hand.

    (1) h = 1, 4, 9, 16 and phi = 10 - 0.25 h^1.5 = 9.75, 8, 3.25, -6: the free-order fit is exact with p = 1.5 (in
    0.5 <= p < 2.05) and phi0 = 10, sigma = 0; eps = |9.75 - 10| = 0.25; Delta_phi = (9.75 - (-6)) / 3 = 5.25 >
    sigma, so eq. 20 with Fs = 1.25: U = 1.25 * 0.25 + 0 + 0 = 0.3125, and U / |phi1| = 0.3125 / 9.75 = 0.0320513.

    (2) h = 1, 2, 3, 4 and phi = 10 + 2h - 0.3h^2 = 11.7, 12.8, 13.3, 13.2: the values rise and then fall, which no
    phi0 + alpha h^p with p > 0 follows: its best p lies at the lower end of the search (< 0.5), so the fixed-order
    fits are compared. First order, unweighted: mean h 2.5, mean phi 12.75, S_hh = 5, S_hphi = 1.5 * 1.05 - 0.5 *
    0.05 + 0.5 * 0.55 + 1.5 * 0.45 = 2.5, so phi = 11.5 + 0.5 h with residuals 0.2 - 0.5 = -0.3, 0.3, 0.3, -0.3 and
    sigma = sqrt(0.36 / (4 - 2)) = 0.424; first and second order is exact: phi0 = 10, sigma = 0, the least, so it is
    selected. eps = |11.7 - 10| = 1.7; Delta_phi = (13.3 - 11.7) / 3 = 0.5333 > sigma: eq. 20, but with Fs = 3 (p out
    of range): U = 3 * 1.7 + 0 + 0 = 5.1, and U / |phi1| = 5.1 / 11.7 = 0.435897."""
    u = gci.least_squares_uncertainty([1, 4, 9, 16], [9.75, 8.0, 3.25, -6.0])
    assert u.fit == "power" and u.order == pytest.approx(1.5) and u.extrapolated == pytest.approx(10.0)
    assert u.data_range == pytest.approx(5.25) and u.safety_factor == 1.25
    assert u.uncertainty_abs == pytest.approx(0.3125) and u.uncertainty == pytest.approx(0.0320513, abs=1e-7)

    u = gci.least_squares_uncertainty([1, 2, 3, 4], [11.7, 12.8, 13.3, 13.2])
    assert u.observed_order < 0.5 and u.fit == "first_and_second" and np.isnan(u.order)
    assert u.extrapolated == pytest.approx(10.0) and u.std_dev < 1e-12
    assert u.data_range == pytest.approx(1.6 / 3) and u.safety_factor == 3.0
    assert u.uncertainty_abs == pytest.approx(5.1) and u.uncertainty == pytest.approx(0.435897, abs=1e-6)


def test_least_squares_on_scattered_values_takes_the_cautious_uncertainty():
    """phi = 1.0, 1.3, 0.9, 1.25, 1.0 at h = 1 ... 5 scatter without a trend: every fit's standard deviation exceeds
    the data range Delta_phi = 0.4 / 4 = 0.1, so Fs = 3 and eq. 21, U = 3 sigma / Delta_phi (eps + sigma +
    |phi1 - phi_fit(h1)|). The selected fit's phi0 and sigma are checked against numpy's weighted polyfit."""
    h = np.array([1.0, 2.0, 3.0, 4.0, 5.0])
    phi = np.array([1.0, 1.3, 0.9, 1.25, 1.0])
    u = gci.least_squares_uncertainty(h, phi)
    assert u.observed_order < 0.5 and u.fit in ("first", "second", "first_and_second")
    assert u.data_range == pytest.approx(0.1) and u.std_dev >= u.data_range and u.safety_factor == 3.0
    eps, off = abs(u.phi1 - u.extrapolated), abs(u.phi1 - u.fit_at_h1)
    assert u.uncertainty_abs == pytest.approx(3 * u.std_dev / u.data_range * (eps + u.std_dev + off))
    assert u.uncertainty_abs > 10 * abs(u.phi1 - u.extrapolated)  # the scatter, not the error estimate, dominates
    degree = {"first": 1, "second": 2, "first_and_second": 2}[u.fit]
    x = h if u.fit != "second" else h**2
    w = (1 / h) / np.sum(1 / h) if u.weighted else np.full(h.size, 1 / h.size)
    coefficients = np.polyfit(x, phi, 1 if u.fit == "second" else degree, w=np.sqrt(h.size * w))
    residuals = phi - np.polyval(coefficients, x)
    assert u.extrapolated == pytest.approx(coefficients[-1])
    assert u.std_dev == pytest.approx(np.sqrt(h.size * np.sum(w * residuals**2) / (h.size - degree - 1)))


def test_least_squares_outside_the_order_range_takes_fs_3_and_a_fixed_order_fit():
    """phi = 1 + 0.01 h^4: the free order is 4, above the range, so a fixed-order fit is used and Fs = 3 in eq. 20."""
    h = np.array([1.0, 2.0, 3.0, 4.0])
    u = gci.least_squares_uncertainty(h, 1 + 0.01 * h**4)
    assert u.observed_order == pytest.approx(4.0) and u.fit != "power" and u.safety_factor == 3.0
    assert u.std_dev < u.data_range
    eps, off = abs(u.phi1 - u.extrapolated), abs(u.phi1 - u.fit_at_h1)
    assert u.uncertainty_abs == pytest.approx(3 * eps + u.std_dev + off)


def test_least_squares_on_noisy_values_of_a_good_order_adds_the_fit_penalty():
    """phi0 + 0.3 h^1.5 plus small noise: the free-order fit is kept (order near 1.5, Fs = 1.25) and eq. 20 adds sigma
    and the finest value's distance from the fit to 1.25 eps."""
    h = np.array([1.0, 1.3, 1.7, 2.2, 2.9])
    u = gci.least_squares_uncertainty(h, 5 + 0.3 * h**1.5 + np.array([0.002, -0.003, 0.001, 0.002, -0.002]))
    assert u.fit == "power" and u.order == pytest.approx(1.5, abs=0.05) and u.safety_factor == 1.25
    assert 0 < u.std_dev < u.data_range and u.extrapolated == pytest.approx(5.0, abs=0.01)
    eps, off = abs(u.phi1 - u.extrapolated), abs(u.phi1 - u.fit_at_h1)
    assert u.uncertainty_abs == pytest.approx(1.25 * eps + u.std_dev + off) and u.uncertainty_abs > 1.25 * eps
    assert u.uncertainty_abs > abs(u.phi1 - 5.0)  # it covers the true error


def test_least_squares_agrees_with_the_three_grid_gci_on_smooth_mixed_order_values():
    """phi = 5 + 0.4 h + 0.05 h^2 at h = 1.25^k, k = 0..4: no single power fits exactly; the least-squares and the
    three-finest-grid extrapolations agree to a tenth of the uncertainty, and both uncertainties cover the true
    error 0.45 of the finest value."""
    h = 1.25 ** np.arange(5)
    phi = 5 + 0.4 * h + 0.05 * h**2
    u = gci.least_squares_uncertainty(h, phi)
    e = gci.estimate(h[:3], phi[:3])
    assert abs(u.extrapolated - e.extrapolated) < 0.1 * u.uncertainty_abs
    assert u.uncertainty_abs > 0.45 and e.gci_fine * phi[0] > 0.45
    assert u.uncertainty == pytest.approx(e.gci_fine, rel=0.1)


def test_least_squares_refuses_fewer_than_four_spacings_and_bad_inputs():
    with pytest.raises(ValueError, match="four"):
        gci.least_squares_uncertainty([1.0, 2.0, 4.0], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="differ"):
        gci.least_squares_uncertainty([1.0, 2.0, 2.0, 4.0], [1.0, 2.0, 3.0, 4.0])
    with pytest.raises(ValueError, match="as many"):
        gci.least_squares_uncertainty([1.0, 2.0, 3.0, 4.0], [1.0, 2.0, 3.0])
    u = gci.least_squares_uncertainty([1, 2, 3, 4], [5.0, np.nan, 6.0, 7.0])
    assert np.isnan(u.extrapolated) and np.isnan(u.uncertainty)
    u = gci.least_squares_uncertainty([1, 2, 3, 4], [5.0] * 4)  # no error at all
    assert u.fit == "constant" and u.extrapolated == 5.0 and u.uncertainty == 0.0


@pytest.mark.parametrize(
    "spacings, values",
    [
        ((0.5, 0.7, 1.0, 1.4, 2.0), [-3 + 0.7 * h**0.8 for h in (0.5, 0.7, 1.0, 1.4, 2.0)]),
        ((1.0, 4.0, 9.0, 16.0), [9.75, 8.0, 3.25, -6.0]),
        ((1.0, 2.0, 3.0, 4.0), [11.7, 12.8, 13.3, 13.2]),
    ],
)
def test_least_squares_agrees_with_cfdverify_on_exactly_fitted_values(spacings, values):
    """cfdverify's EçaHoekstra2014 (0.0.3), on sets that one of the fits matches exactly. (On scattered values the
    two differ: cfdverify weights the residuals by w_i rather than sqrt(w_i) and so deflates its weighted standard
    deviations, and takes its fit (a) only up to p = 2 and Fs = 1.25 up to p < 2.1.)"""
    pytest.importorskip("cfdverify")
    import warnings

    from cfdverify import discretization

    ours = gci.least_squares_uncertainty(spacings, values)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        theirs = discretization.EçaHoekstra2014(list(spacings), list(values))
    key = theirs.keys[0]
    assert ours.extrapolated == pytest.approx(float(theirs.f_est[key]), rel=1e-7, abs=1e-7)
    assert ours.uncertainty_abs == pytest.approx(float(theirs.u(key, 0)), rel=1e-6)
    model = theirs.model.parameters[key]["model"]
    assert {"power": "model_p", "first_and_second": "model_1and2"}[ours.fit] == model
    if ours.fit == "power":
        assert ours.order == pytest.approx(theirs.model.p_fit, rel=1e-6)
