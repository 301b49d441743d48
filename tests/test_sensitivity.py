"""The sensitivity study's parts against closed forms: the SALib wrapper (Morris on a linear function, Sobol on a
linear function and on Ishigami), failed samples, the registry of methods and a method of one file
(tests/plugins/sensitivity_method.py), the scenario's inputs, and the delamination map's classes."""

import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from sphgag.studies import pool_response, sensitivity
from sphgag.studies.delamination.tables import level_classes

from .conftest import ROOT
from .plugins import sensitivity_method as plugin

MORRIS, SOBOL = sensitivity.SENSITIVITY_METHODS.values()

LINEAR = np.array([2.0, -3.0, 0.5, 0.0])
PROBLEM = sensitivity.Problem(("a", "b", "c", "d"), (0.0, 1.0, -1.0, 5.0), (1.0, 3.0, 1.0, 6.0))
BOOTSTRAP = dict(resamples=100, confidence=0.95)


def linear(X):
    return X @ LINEAR


def table(rows) -> pd.DataFrame:
    return pd.DataFrame(rows).set_index(["input", "index"]).value


def test_morris_gives_the_elementary_effects_of_a_linear_function_exactly():
    """y = sum a_i x_i: every elementary effect of x_i is a_i (high_i - low_i), so mu* = |a_i| (high_i - low_i),
    mu = a_i (high_i - low_i) and sigma = 0."""
    design = MORRIS.design(PROBLEM, trajectories=6, levels=4, seed=3)
    X = design[list(PROBLEM.names)].to_numpy()
    assert len(design) == 6 * (len(PROBLEM.names) + 1) == MORRIS.size(len(PROBLEM.names), trajectories=6)
    rows = MORRIS.indices(PROBLEM, design, linear(X), np.zeros(len(X), bool), levels=4, **BOOTSTRAP, seed=3)
    v = table(rows)
    span = np.subtract(PROBLEM.high, PROBLEM.low)
    for name, a, s in zip(PROBLEM.names, LINEAR, span):
        assert v[name, "mu_star"] == pytest.approx(abs(a) * s, abs=1e-12)
        assert v[name, "mu"] == pytest.approx(a * s, abs=1e-12)
        assert v[name, "sigma"] == pytest.approx(0.0, abs=1e-9)
    assert all(r["samples_used"] == len(X) and r["samples_missing"] == 0 for r in rows)


def test_sobol_gives_the_variance_shares_of_a_linear_function():
    """Independent uniform inputs: S1_i = ST_i = a_i^2 var_i / sum_j a_j^2 var_j, var_i = (high_i - low_i)^2 / 12."""
    design = SOBOL.design(PROBLEM, inputs=4, base_samples=1024, seed=5)
    X = design[list(PROBLEM.names)].to_numpy()
    v = table(SOBOL.indices(PROBLEM, design, linear(X), np.zeros(len(X), bool), **BOOTSTRAP, seed=5))
    share = LINEAR**2 * np.subtract(PROBLEM.high, PROBLEM.low) ** 2
    share /= share.sum()
    for name, s in zip(PROBLEM.names, share):
        assert v[name, "S1"] == pytest.approx(s, abs=0.02)
        assert v[name, "ST"] == pytest.approx(s, abs=0.02)


def test_sobol_reproduces_the_ishigami_indices_with_intervals_that_hold_them():
    """Ishigami (a = 7, b = 0.1) on [-pi, pi]^3: the closed-form S1 and ST (Ishigami & Homma 1990)."""
    a, b = 7.0, 0.1
    v1 = 0.5 * (1 + b * np.pi**4 / 5) ** 2
    v2 = a**2 / 8
    v13 = b**2 * np.pi**8 * (1 / 18 - 1 / 50)
    total = v1 + v2 + v13
    exact = {"S1": [v1 / total, v2 / total, 0.0], "ST": [(v1 + v13) / total, v2 / total, v13 / total]}
    problem = sensitivity.Problem(("x1", "x2", "x3"), (-np.pi,) * 3, (np.pi,) * 3)
    design = SOBOL.design(problem, inputs=3, base_samples=2048, seed=7)
    X = design[list(problem.names)].to_numpy()
    y = np.sin(X[:, 0]) + a * np.sin(X[:, 1]) ** 2 + b * X[:, 2] ** 4 * np.sin(X[:, 0])
    rows = pd.DataFrame(SOBOL.indices(problem, design, y, np.zeros(len(y), bool), 500, 0.95, 7))
    for r in rows.itertuples():
        target = exact[r.index][problem.names.index(r.input)]
        assert r.value == pytest.approx(target, abs=0.03), (r.input, r.index)
        assert r.conf_low - 0.01 <= target <= r.conf_high + 0.01, (r.input, r.index)


def test_a_failed_sample_is_reported_by_its_inputs_and_counted_in_the_indices():
    """A run that fails keeps its row (inputs, status, error); its Morris trajectory leaves that output's indices and
    every index row says so; a bug (any other exception) is not a failed sample."""
    design = MORRIS.design(PROBLEM, trajectories=4, levels=4, seed=1)
    bad = int(design.index[7])

    class Diverged(RuntimeError):
        pass

    def evaluate(inputs):
        x = np.array([inputs[n] for n in PROBLEM.names])
        if np.allclose(x, design.loc[bad, list(PROBLEM.names)].to_numpy(float)):
            raise Diverged("Newton diverged at c = 100 mEq/l")
        return {"y": float(linear(x))}

    out = pool_response.sample_rows(design, PROBLEM.names, evaluate, failure=Diverged, label="test")
    assert len(out) == len(design)
    row = out[out["sample"] == bad].iloc[0]
    assert row.status == "failed" and "Newton diverged at c = 100 mEq/l" in row.error and np.isnan(row.y)
    assert row[list(PROBLEM.names)].to_numpy(float) == pytest.approx(
        design.loc[bad, list(PROBLEM.names)].to_numpy(float)
    )
    failed = (out.status == "failed").to_numpy()
    rows = MORRIS.indices(PROBLEM, design, out.y.to_numpy(), failed, levels=4, **BOOTSTRAP, seed=1)
    k1 = len(PROBLEM.names) + 1
    assert all((r["samples_used"], r["samples_missing"], r["samples_failed"]) == (3 * k1, 1, 1) for r in rows)
    v = table(rows)
    assert v["a", "mu_star"] == pytest.approx(2.0)  # the other trajectories still give the exact effects

    def buggy(inputs):
        raise KeyError("a bug")

    with pytest.raises(KeyError):
        pool_response.sample_rows(design, PROBLEM.names, buggy, failure=Diverged)


def test_sobol_leaves_out_the_base_rows_of_a_missing_sample_and_says_so():
    design = SOBOL.design(PROBLEM, inputs=4, base_samples=64, seed=2)
    y = linear(design[list(PROBLEM.names)].to_numpy())
    y[10] = np.nan  # base row 10 // (k + 2) = 1
    rows = SOBOL.indices(PROBLEM, design, y, np.isnan(y), **BOOTSTRAP, seed=2)
    k2 = len(PROBLEM.names) + 2
    assert all((r["samples_used"], r["samples_missing"], r["samples_failed"]) == (63 * k2, 1, 1) for r in rows)
    assert np.isfinite([r["value"] for r in rows]).all()


def test_the_designs_are_the_same_for_the_same_seed():
    a = MORRIS.design(PROBLEM, 3, 4, seed=11).to_csv()
    assert a == MORRIS.design(PROBLEM, 3, 4, seed=11).to_csv()
    assert a != MORRIS.design(PROBLEM, 3, 4, seed=12).to_csv()
    assert SOBOL.design(PROBLEM, 4, 8, seed=11).to_csv() == SOBOL.design(PROBLEM, 4, 8, 11).to_csv()


def test_the_most_influential_inputs_are_ranked_by_mu_star_relative_to_each_output():
    rows = pd.DataFrame(
        [
            dict(method="morris", charge_law="p", output="o1", input=i, index="mu_star", value=v)
            for i, v in (("a", 100.0), ("b", 50.0), ("c", 1.0), ("d", 0.0))
        ]
        + [
            dict(method="morris", charge_law="p", output="o2", input=i, index="mu_star", value=v)
            for i, v in (("a", 0.0), ("b", 0.0), ("c", 0.9), ("d", 1.0))
        ]
    )
    assert MORRIS.most_influential(rows, 2) == ["a", "d"]  # d leads o2, a leads o1; b is half of o1's top
    assert MORRIS.most_influential(rows, 3) == ["a", "d", "c"]
    # the Sobol design screens with the Morris indices: over the inputs they rank highest, in the problem's order
    assert SOBOL.screening == MORRIS.name and MORRIS.paper and not SOBOL.paper
    design = SOBOL.design(PROBLEM, inputs=2, base_samples=8, seed=1, screening=rows)
    assert list(design.columns) == ["sample", "a", "d"] and len(design) == SOBOL.size(4, inputs=2, base_samples=8)


def test_the_figure_draws_a_panel_per_method_titled_by_the_registry_without_the_engine():
    """views/sensitivity.py reads the methods from the registry's module, which imports no engine (Numba) code; a
    method without a panel of its own has its indices drawn as bars."""
    code = "import sys, sphgag.views.sensitivity as v; print(list(v.PANELS), 'numba' in sys.modules)"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "src"))  # this checkout's package, whatever is installed
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env).stdout
    assert out == "['morris'] False\n"
    assert sensitivity.SENSITIVITY_METHODS.titles == {"morris": "Morris", "sobol": "Sobol"}


# -- a sensitivity method of one file ---------------------------------------------------------------------------------


def test_a_plugin_method_is_accepted_by_name_draws_its_design_and_fills_the_index_table():
    """tests/plugins/sensitivity_method.py, registered for the test only: looked up by name, its design draws its
    samples inside the ranges, and :func:`sensitivity.indices_table` gives its rows with the table's columns."""
    reg, method = plugin.REGISTRY, plugin.VARIANT
    with pytest.raises(ValueError, match="unknown sensitivity method 'rank_correlation': one of morris, sobol"):
        sensitivity.indices_table(method.name, None, None, {}, [], {})
    with reg.registered(method):
        assert reg.lookup(method.name) is method and reg.names == ("morris", "sobol", method.name)
        design = method.design(PROBLEM, samples=64, seed=4)
        X = design[list(PROBLEM.names)].to_numpy()
        assert len(design) == method.size(4, samples=64) and ((X >= PROBLEM.low) & (X <= PROBLEM.high)).all()
        y = linear(X)
        y[5] = np.nan
        samples = design.assign(charge_law="prescribed", status=["failed" if k == 5 else "ok" for k in range(64)], y=y)
        ranges = {n: dict(low=lo, high=hi) for n, lo, hi in zip(PROBLEM.names, PROBLEM.low, PROBLEM.high)}
        out = sensitivity.indices_table(method.name, design, samples, ranges, ["y"], {})
    assert method.name not in reg
    assert list(out.columns) == ["method", "charge_law", "output", "input"] + sensitivity.INDEX_COLUMNS
    assert len(out) == 4 and (out.method == method.name).all() and (out.samples_failed == 1).all()
    rho = out.set_index("input").value
    assert rho.abs().idxmax() == "b" and rho["b"] < -0.8 and rho["a"] > 0.0  # y = 2a - 3b + c/2 over their ranges


# -- the scenario of a sample -----------------------------------------------------------------------------------------

SCENARIO = dict(
    bilayer=dict(aligned_radii_um=[655.5, 670.5], prestretch=dict(smc=1.2), dx_um=3.0),
    gag=dict(shear_modulus_kPa=0.1),
    pool=dict(centre_radius_um=663.0, angular_extent_deg=3.0),
    swelling=dict(max_concentration_mEq_l=150.0, concentration_points=7),
    concentration_mEq_l=100.0,
)


def test_an_input_sets_its_dotted_path_and_the_grid_moves_with_the_pool():
    out = pool_response.perturbed(
        SCENARIO, {"bilayer.prestretch.smc": 1.25, "pool.centre_radius_um": 660.0, "gag.shear_modulus_kPa": 0.3}
    )
    assert out["bilayer"]["prestretch"]["smc"] == 1.25 and out["gag"]["shear_modulus_kPa"] == 0.3
    assert out["bilayer"]["aligned_radii_um"] == [652.5, 667.5]  # the pool's edges stay cell boundaries
    assert SCENARIO["bilayer"]["prestretch"]["smc"] == 1.2  # the nominal scenario is untouched
    assert pool_response.perturbed(SCENARIO, {})["bilayer"]["aligned_radii_um"] == [655.5, 670.5]
    assert pool_response.nominal(SCENARIO, "pool.angular_extent_deg") == 3.0


def test_an_unknown_input_is_named():
    with pytest.raises(KeyError, match="bilayer.nope"):
        pool_response.check_inputs(SCENARIO, ["gag.shear_modulus_kPa", "bilayer.nope"])
    with pytest.raises(KeyError, match="bilayer.prestretch"):
        pool_response.check_inputs(SCENARIO, ["bilayer.prestretch"])  # a section, not a number


def test_the_swelling_ramp_is_cut_at_the_stated_concentration_on_the_pipelines_steps():
    assert pool_response.swelling_settings(SCENARIO) == dict(max_concentration_mEq_l=100.0, concentration_points=5)
    with pytest.raises(ValueError, match="not a step"):
        pool_response.swelling_settings(dict(SCENARIO, concentration_mEq_l=110.0))


# -- the delamination map's classes -----------------------------------------------------------------------------------


def run(rows, stop_kind, stop_level, onset):
    growth = pd.DataFrame(rows, columns=["concentration_mEq_l", "delaminated_length_um"])
    summary = dict(stop_kind=stop_kind, stop_level_mEq_l=stop_level, onset_concentration_mEq_l=onset)
    return level_classes(growth, summary, [10.0, 20.0, 30.0, 40.0]).state.tolist()


def test_map_classes_of_a_run_that_arrests_at_the_top_of_the_ramp():
    rows = [(10, 0), (20, 0), (30, 0), (30, 3), (40, 3)]
    assert run(rows, "arrested", 40.0, 30.0) == ["no onset", "no onset", "onset, arrested", "onset, arrested"]
    assert run(rows[:3] + [(40, 0)], "arrested", 40.0, np.nan) == ["no onset"] * 4


def test_map_classes_of_a_run_that_ends_growing_in_a_level():
    rows = [(10, 0), (20, 0), (30, 0), (30, 5), (30, 12)]
    classes = run(rows, "numerical", 30.0, 20.0)
    assert classes == ["no onset", "onset, arrested", "propagation", "propagation"]
    assert run(rows, "unstable", 30.0, 20.0)[2:] == ["propagation", "propagation"]


def test_map_classes_of_a_ramp_that_cannot_reach_a_level():
    rows = [(10, 0), (20, 0), (30, 0)]  # raising 30 -> 40 finds no stable state, before any new damage
    classes = run(rows, "limit point", 40.0, 30.0)
    assert classes == ["no onset", "no onset", "onset, arrested", "no equilibrium"]
