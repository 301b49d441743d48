"""The claims table: pool claims once per charge law, runs that end below the requested concentration, pool sets by
their roles (synthetic tables; the pipeline test runs the real ones)."""

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest

from sphgag.studies.claims.calibration import CALIBRATION
from sphgag.studies.claims.delamination import c18_onset_across_inputs
from sphgag.studies.claims.evidence import Claim, Evidence, last_converged, of_law
from sphgag.studies.claims.procedure import procedure_claims
from sphgag.studies.claims.swelling import across_band, c8_tensile_tip, c9_smaller_pools_higher_tip
from sphgag.studies.claims.verdicts import POOL, by_law, delamination_claims, markdown, swelling_claims, variants
from sphgag.studies.claims.verdicts import table as claims_table

CASES = {"I": {"angular_extent_deg": 3.0}, "IV": {"angular_extent_deg": 16.0}}


def tips_table(law: str, last: dict | None = None, levels=(0.0, 50.0, 100.0, 150.0)) -> pd.DataFrame:
    """A tip_stress.csv of one law: every (model, case, pressure) run, an intact row and one converted row per level;
    ``last`` cuts the runs named by (model, case, pressure) at that concentration."""
    rows = []
    for model in ("passive", "active"):
        for case, size in (("I", 1.0), ("IV", 2.0)):
            for pressure in (103.0, 200.0):
                rows.append(
                    dict(model=model, case=case, pressure_mmHg=pressure, stage="intact", concentration_mEq_l=0.0)
                    | dict(tip_radial_stress_kPa=0.0, top_circ_stress_kPa=100.0)
                )
                end = (last or {}).get((model, case, pressure), levels[-1])
                for c in levels:
                    if c > end:
                        break
                    tip = -50.0 * size + c * (1.0 if law == "prescribed" else 0.1) - (pressure - 103.0) / 100.0
                    rows.append(
                        dict(model=model, case=case, pressure_mmHg=pressure, stage="converted", concentration_mEq_l=c)
                        | dict(tip_radial_stress_kPa=tip, top_circ_stress_kPa=200.0 * size + c)
                    )
    return pd.DataFrame(rows).assign(charge_law=law)


def test_every_run_at_the_requested_concentration_reads_as_before():
    found = {c.claim_id: c for c in swelling_claims(tips_table("conserved"), CASES, 150.0)}
    assert found["C8"].our_value.startswith("at 150 mEq/l: ")
    assert "tip radial stress at 150 mEq/l decreases" in found["C9"].our_value


def test_a_run_that_ended_early_is_read_at_its_last_converged_state():
    tips = tips_table("prescribed", last={("passive", "IV", 103.0): 100.0})
    top = last_converged(tips)
    assert len(top) == 8 and sorted(top.concentration_mEq_l.unique()) == [100.0, 150.0]
    found = {c.claim_id: c for c in swelling_claims(tips, CASES, 150.0)}
    assert "at each run's last converged state (100-150 mEq/l; 1/8 runs found no equilibrium up to 150)" in (
        found["C8"].our_value
    )
    # the truncated run's own last state counts: its tip stress at 100 mEq/l, not a missing value
    assert f"{-100.0 + 100.0:.0f} to" in found["C8"].our_value
    assert found["C10"].holds in ("yes", "no") and np.isfinite(float(found["C10"].our_value.split()[4]))


def test_pool_claims_are_one_row_per_claim_law_and_pool_model():
    tips = pd.concat(
        [tips_table("prescribed"), tips_table("conserved"), tips_table("prescribed").assign(pool_model="cavity")],
        ignore_index=True,
    )
    tips["pool_model"] = tips.pool_model.fillna("particles")
    pairs = [("prescribed", "particles"), ("conserved", "particles"), ("prescribed", "cavity")]
    found = by_law(pairs, lambda law, pool: swelling_claims(of_law(tips, law, pool), CASES, 150.0))
    table = claims_table(found)
    assert list(table.columns[:4]) == ["claim_id", "charge_law", "pool_model", "path"]
    assert list(table.claim_id[:6]) == ["C6"] * 3 + ["C7"] * 3
    assert list(zip(table.charge_law[:3], table.pool_model[:3])) == pairs
    c8 = table[(table.claim_id == "C8") & (table.pool_model == "particles")].set_index("charge_law")
    assert c8.loc["prescribed", "our_value"] != c8.loc["conserved", "our_value"]  # each law its own numbers
    assert set(c8.criterion) == {c8.criterion.iloc[0]}  # one criterion for both
    md = markdown(table)
    assert "| C8 | prescribed | particles |" in md and "| C8 | conserved | particles |" in md
    assert "| C8 | prescribed | cavity |" in md


def test_claims_evaluate_every_law_with_the_papers_pool_model_and_the_other_pool_models_where_they_ran():
    tips = pd.concat(
        [tips_table("prescribed"), tips_table("conserved"), tips_table("prescribed").assign(pool_model="cavity")],
        ignore_index=True,
    )
    tips["pool_model"] = tips.pool_model.fillna("particles")
    assert variants(tips, ["prescribed", "conserved"]) == [
        ("prescribed", "particles"),
        ("conserved", "particles"),
        ("prescribed", "cavity"),
    ]
    assert variants(None, ["prescribed"]) == [("prescribed", "particles")]


def delamination_tables(names: dict):
    """growth.csv and summary.csv of one law with the pool sets named ``names`` (role -> name)."""
    growth, summary = [], []
    runs = [(names["fig5"], s) for s in (30.0, 60.0)] + [(n, 40.0) for n in names["fig6"]] + [(names["fig7"], 40.0)]
    for case, sigma in runs:
        for step in range(3):
            growth.append(
                dict(case=case, sigma_cr_kPa=sigma, criterion="averaged", step=step, pseudo_time=step)
                | dict(concentration_mEq_l=50.0 * step, converted_particles=step, converted_interior=step)
                | dict(converted_exterior=0, tip_radial_stress_kPa=10.0 * step)
            )
        summary.append(
            dict(case=case, sigma_cr_kPa=sigma, criterion="averaged", merged=case == names["fig7"], merge_step=2.0)
            | dict(final_length_um=2.0, arrested_length_um=0.0, merge_concentration_mEq_l=95.0)
            | dict(stop_kind="merged" if case == names["fig7"] else "unstable")
            | dict(onset_concentration_mEq_l=50.0 + sigma, runaway_concentration_mEq_l=60.0 + sigma)
        )
    return pd.DataFrame(growth), pd.DataFrame(summary)


def test_delamination_claims_follow_the_pool_sets_roles():
    """The same runs under other names give the same claims when the roles name them."""
    default = dict(fig5="single", fig6=["low_separation", "high_separation"], fig7="radial_offset")
    renamed = dict(fig5="alone", fig6=["pair_2deg", "high_separation"], fig7="offset")
    a = delamination_claims(*delamination_tables(default), ["averaged"], default)
    b = delamination_claims(*delamination_tables(renamed), ["averaged"], renamed)
    assert [c.holds for c in a] == [c.holds for c in b]
    assert [c.our_value.replace("pair_2deg", "low_separation") for c in b] == [c.our_value for c in a]
    assert {c.claim_id: c.holds for c in a}["C17"] == "yes"  # figure 7's set, found by its role
    assert "30 kPa unstable (onset 80.0, runaway 90.0 mEq/l" in a[0].our_value  # figure 5's set, by its role
    assert {c.claim_id: c.holds for c in a}["C13"] == "yes" and {c.claim_id: c.holds for c in a}["C15"] == "yes"


def test_each_claim_is_one_function_of_the_list_in_the_tables_order():
    ids = [f.__name__.split("_")[0].upper() for f in CALIBRATION + POOL]
    assert ids == [f"C{k}" for k in range(1, 19)]


def test_a_claim_is_evaluated_alone():
    tips = tips_table("prescribed")
    e = Evidence(tips=tips, cases=CASES, max_concentration=150.0)
    c8 = c8_tensile_tip(e)
    assert c8.claim_id == "C8" and c8.our_value.startswith("at 150 mEq/l: ")
    both = pd.concat([tips, tips_table("conserved")], ignore_index=True)
    assert c8_tensile_tip(Evidence(tips=both, cases=CASES, max_concentration=150.0).of_law("prescribed")) == c8


def samples_table(law: str, onsets) -> pd.DataFrame:
    """A sensitivity samples.csv of one law: one row per onset concentration (NaN: no onset, censored)."""
    rows = [
        dict(method="morris", sample=k, charge_law=law, status="ok", onset_concentration_mEq_l=c if c == c else 160.0)
        | dict(onset_censored=c != c, propagated=float(c == c))
        for k, c in enumerate(onsets)
    ]
    return pd.DataFrame(rows)


def test_a_claim_whose_target_has_not_run_is_in_the_table_marked_not_run():
    """C18 rests on the sensitivity study (target sensitivity): without it, each law's row says so and names the
    command; with it, the row holds our number."""
    tips = pd.concat([tips_table("prescribed"), tips_table("conserved")], ignore_index=True)
    laws = ["prescribed", "conserved"]

    def c18(e):
        return by_law([(law, "particles") for law in laws], lambda law, _: [c18_onset_across_inputs(e.of_law(law))])

    without = claims_table(c18(Evidence(tips=tips, cases=CASES)))
    assert list(without.charge_law) == laws and list(without.claim_id) == ["C18", "C18"]
    assert (without.holds == "not run").all() and (without.our_value == "not run: `snakemake sensitivity`").all()
    assert without.statement.iloc[0].startswith("Across the model's input ranges")
    nan = float("nan")
    samples = pd.concat(
        [samples_table("prescribed", [90.0, 100.0, nan]), samples_table("conserved", [nan, nan, 150.0])],
        ignore_index=True,
    )
    e = Evidence(tips=tips, cases=CASES, sensitivity=samples)
    found = {
        c.charge_law: c
        for c in by_law(
            [("prescribed", "particles"), ("conserved", "particles")],
            lambda law, _: [c18_onset_across_inputs(e.of_law(law))],
        )
    }
    assert found["prescribed"].holds == "yes" and found["conserved"].holds == "no"
    assert found["prescribed"].our_value.startswith("onset in 2 of 3 samples (67 %), at 90-100 mEq/l")


def resolution_table(law: str, spacings=(3.0, 2.12, 1.5)) -> pd.DataFrame:
    """A resolution study (convergence.csv) of one law at 103 mmHg: the runs of :func:`tips_table` at every spacing,
    case IV's tip stress at 150 mEq/l 110 - 10 dx kPa (first order, extrapolated 110; case I's is 100)."""
    tips = tips_table(law)
    tips = tips[tips.pressure_mmHg == 103.0].drop(columns="pressure_mmHg")
    rows = []
    for h in spacings:
        t = tips.assign(dx_um=h, pool_model="particles")
        late = (t.case == "IV") & (t.stage == "converted") & (t.concentration_mEq_l == 150.0)
        t.loc[late, "tip_radial_stress_kPa"] = 110.0 - 10.0 * h
        rows.append(t)
    return pd.concat(rows, ignore_index=True)


def test_a_figure_4_claim_holds_only_if_it_holds_at_every_spacing_and_extrapolated():
    """C9 (smaller pools, higher tip stress) holds on figure 4's runs and at each spacing of the study (case IV's
    tip 80, 88.8 and 95 kPa below case I's 100), but not for the extrapolated values (110): it does not hold. C6
    holds everywhere. Without the study, the row says how to run it."""
    from sphgag.studies.resolution import swelling_band

    resolution = resolution_table("prescribed")
    band = swelling_band(resolution, 103.0)
    tips = tips_table("prescribed").assign(pool_model="particles")
    e = Evidence(tips=tips, cases=CASES, max_concentration=150.0, resolution=resolution, band=band)
    e = replace(e, study_pressure=103.0)
    found = {c.claim_id: c for c in across_band(e, swelling_claims(tips, CASES, 150.0))}
    assert c9_smaller_pools_higher_tip(e).holds == "yes"
    c9 = found["C9"]
    assert c9.holds == "no"
    assert c9.across_band.startswith("dx 3: yes (+20), dx 2.12: yes (+11), dx 1.5: yes (+5), extrapolated: no (-10)")
    assert found["C6"].holds == "yes" and found["C6"].across_band.startswith("dx 3: yes (+50), dx 2.12: yes (+50)")
    assert found["C10"].across_band.startswith("n/a")  # one pressure in the study
    alone = across_band(replace(e, resolution=None, band=None), swelling_claims(tips, CASES, 150.0))
    assert all(c.across_band == "not run: `snakemake resolution`" for c in alone)
    assert [c.holds for c in alone] == [c.holds for c in swelling_claims(tips, CASES, 150.0)]
    other = across_band(replace(e, resolution=resolution.iloc[:0]), swelling_claims(tips, CASES, 150.0))
    assert all(c.across_band.startswith("not in the resolution study") for c in other)


def _procedure_summary():
    """A summary of target paper_procedure (sphgag.studies.paper_procedure.summary): figure 4's tip stress by the
    equilibrium and two explicit paths, figure 5's runs at two sigma_cr and a pool pair's."""
    rows = []
    for path, factor, tips in (
        ("equilibrium", np.nan, (120.0, 300.0)),
        ("explicit", 1, (60.0, 90.0)),
        ("explicit", 4, (40.0, 80.0)),
    ):
        for case, tip in zip(("I", "IV"), tips):
            rows.append(
                dict(
                    figure="4",
                    model="passive",
                    pool=case,
                    sigma_cr_kPa=np.nan,
                    path=path,
                    step_factor=factor,
                    quantity="tip_radial_stress_kPa",
                    value=tip,
                    residual=0.5,
                )
            )
    for factor, (fast, slow) in ((1, (3.0, 1.0)), (4, (2.0, 1.5))):
        for sigma, rate, teeth in ((30.0, fast, 3), (60.0, slow, 1)):
            for quantity, value in (("growth_rate_um_per_time", rate), ("teeth", teeth)):
                rows.append(
                    dict(
                        figure="5",
                        model="passive",
                        pool="single",
                        sigma_cr_kPa=sigma,
                        path="explicit",
                        step_factor=factor,
                        quantity=quantity,
                        value=value,
                        residual=2.0,
                    )
                )
    return pd.DataFrame(rows)


def _procedure_damage():
    """Rows of a pool pair's damage runs (sphgag.studies.paper_procedure.delaminate): at x1 the exterior side leads
    where the interior side stops growing (the merge), at x4 it trails there and overtakes only after."""
    rows = []
    for factor, exterior in ((1, (2, 6, 9, 12)), (4, (1, 2, 3, 12))):
        for t, (interior, ext) in enumerate(zip((1, 3, 5, 5), exterior)):
            rows.append(
                dict(
                    pool_set="pair",
                    sigma_cr_kPa=40.0,
                    step_factor=factor,
                    pseudo_time=100.0 * t,
                    interior_particles=interior,
                    exterior_particles=ext,
                    residual=3.0,
                )
            )
    return pd.DataFrame(rows)


def test_the_procedure_claims_judge_every_path_with_its_residual():
    evidence = Evidence(procedure=_procedure_summary(), procedure_damage=_procedure_damage())
    found = {(c.claim_id, c.path): c for c in procedure_claims(evidence, [])}
    assert found["P1", "equilibrium"].holds == "no" and found["P1", "explicit x1"].holds == "yes"
    assert found["P1", "explicit x4"].holds == "no" and found["P1", "explicit x4"].margin == pytest.approx(-10.0)
    assert "residual 0.5" in found["P1", "explicit x1"].our_value
    assert found["P2", "explicit x1"].holds == "no"  # 1 tooth at 60 kPa
    assert found["P3", "explicit x1"].holds == "yes" and found["P3", "explicit x4"].holds == "no"  # ratios 3, 1.33
    assert found["P4", "explicit x1"].holds == "yes" and found["P4", "explicit x4"].holds == "no"  # 9 > 5, 3 < 5
    assert "interior 5 / exterior 3 at pseudo-time 200" in found["P4", "explicit x4"].our_value


def test_the_procedure_claims_stand_beside_the_equilibriums_and_say_when_not_run():
    c14 = Claim("C14", "sawtooth", "", "30 kPa 4 drops", "yes", "two drops", charge_law="prescribed")
    rows = procedure_claims(Evidence(procedure=_procedure_summary()), [c14])
    p2 = [c for c in rows if c.claim_id == "P2"]
    assert p2[0].path == "equilibrium" and p2[0].holds == "yes" and p2[0].our_value.startswith("C14: ")
    missing = procedure_claims(Evidence(), [])
    assert [c.holds for c in missing] == ["not run"] * 4
    assert all("snakemake paper_procedure" in c.our_value for c in missing)
