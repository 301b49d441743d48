"""The reduced pipeline end to end: snakemake on config/ci.yaml in a temporary directory."""

import copy
import json
import math
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from sphgag.studies import pool_response
from sphgag.studies.claims.evidence import PAPER_POOL
from sphgag.studies.claims.verdicts import COLUMNS as CLAIMS_COLUMNS
from sphgag.studies.delamination.tables import LEVEL_CLASSES
from sphgag.studies.pool_swelling import POOL_MODELS
from sphgag.studies.resolution import BAND_KEYS, DELAMINATION_GCI_COLUMNS, SWELLING_GCI_COLUMNS

from .conftest import ROOT, project_copy, snakemake

pytestmark = pytest.mark.pipeline

CONTRACT = {
    "results/calibration/mean_pressure_diameter.csv": [
        "pressure_mmHg",
        "outer_diameter_um",
        "inner_diameter_um",
        "mean_circ_stress_kPa",
        "mean_circ_stretch",
        "residual",
    ],
    "results/calibration/transmural.csv": [
        "model",
        "pressure_mmHg",
        "radius_um",
        "layer",
        "radial_stress_kPa",
        "circ_stress_kPa",
    ],
    "results/calibration/bilayer_pressure_diameter.csv": [
        "model",
        "pressure_mmHg",
        "outer_diameter_um",
        "inner_diameter_um",
        "residual",
    ],
    "results/homeostasis/summary.csv": [
        "model",
        "carried_pressure_mmHg",
        "inner_radius_um",
        "outer_radius_um",
        "residual",
    ],
    "results/swelling/tip_stress.csv": [
        "charge_law",
        "pool_model",
        "model",
        "case",
        "pressure_mmHg",
        "stage",
        "concentration_mEq_l",
        "swelling_pressure_kPa",
        "tip_radial_stress_kPa",
        "top_circ_stress_kPa",
        "residual",
    ],
    "results/claims.csv": CLAIMS_COLUMNS,
    "results/verification/pressurised_crack.csv": [
        "dx_um",
        "half_length_um",
        "plane_strain_modulus_kPa",
        "fracture_energy_J_m2",
        "critical_pressure_kPa",
        "griffith_kPa",
        "rel_error",
        "pressure_kPa",
        "opening_area_um2",
        "sneddon_um2",
        "dissipated_J_m2",
        "residual",
    ],
    "results/verification/circular_pool.csv": [
        "pool_model",
        "dx_um",
        "target_volume_ratio",
        "path_end",
        "pressure_kPa",
        "volume_ratio",
        "volume_error",
        "lining_error",
        "hoop_error",
        "residual",
    ],
    "results/verification/annulus.csv": [
        "pool_model",
        "outer_ratio",
        "dx_um",
        "fraction",
        "pressure_kPa",
        "limit_pressure_kPa",
        "limit_kind",
        "state",
        "volume_ratio",
        "volume_error",
        "lining_hoop_error",
        "lining_hoop_traction_error",
        "ring_crossing_um",
        "beyond_end",
        "residual",
    ],
    "results/verification/profiles.csv": [
        "wall",
        "lumen_load",
        "recovery",
        "pressure_mmHg",
        "dx_um",
        "material_inner_radial_pct",
        "material_radial_max_pct",
        "material_circ_rms_pct",
        "residual",
    ],
    "results/verification/elliptic_pool.csv": [
        "dx_um",
        "semi_axis_a_um",
        "semi_axis_b_um",
        "pressure_kPa",
        "tip_stress_kPa",
        "reference_kPa",
        "rel_error",
        "traction_jump_kPa",
        "residual",
    ],
    "results/swelling/convergence.csv": [
        "charge_law",
        "pool_model",
        "dx_um",
        "particles",
        "model",
        "case",
        "concentration_mEq_l",
        "tip_radial_stress_kPa",
        "tip_peak_radial_stress_kPa",
        "top_circ_stress_kPa",
        "pool_volume_change",
        "residual",
    ],
    "results/delamination/growth.csv": [
        "charge_law",
        "case",
        "sigma_cr_kPa",
        "criterion",
        "candidates",
        "dx_um",
        "damage_law",
        "fracture_energy_J_m2",
        "step",
        "pseudo_time",
        "concentration_mEq_l",
        "converted_particles",
        "converted_interior",
        "converted_exterior",
        "delaminated_length_um",
        "islands",
        "island_particles",
        "island_distance_um",
        "tip_radial_stress_kPa",
        "residual",
    ],
    "results/delamination/summary.csv": [
        "charge_law",
        "case",
        "sigma_cr_kPa",
        "criterion",
        "candidates",
        "dx_um",
        "damage_law",
        "fracture_energy_J_m2",
        "stop_kind",
        "onset_concentration_mEq_l",
        "runaway_concentration_mEq_l",
        "merge_concentration_mEq_l",
        "limit_concentration_mEq_l",
        "arrested_length_um",
        "final_length_um",
        "passes",
        "islands",
        "island_particles",
        "island_distance_um",
        "growth_rate_um_per_pseudo_time",
        "growth_rate_um_per_mEq_l",
        "merged",
        "merge_step",
        "dissipated_energy_J_m2",
        "max_residual",
    ],
    "results/delamination/convergence.csv": [
        "charge_law",
        "case",
        "sigma_cr_kPa",
        "criterion",
        "dx_um",
        "stop_kind",
        "onset_concentration_mEq_l",
        "runaway_concentration_mEq_l",
        "final_length_um",
        "max_residual",
    ],
    "results/delamination/gci.csv": DELAMINATION_GCI_COLUMNS,
    "results/swelling/gci.csv": SWELLING_GCI_COLUMNS,
    "results/swelling/gci_band.csv": [*BAND_KEYS, "dx_um", "value", "extrapolated", "gci_fine"],
    "results/sensitivity/indices.csv": [
        "method",
        "charge_law",
        "output",
        "input",
        "index",
        "value",
        "conf_low",
        "conf_high",
        "samples_used",
        "samples_missing",
        "samples_failed",
    ],
    "results/sensitivity/samples.csv": ["method", "sample", "charge_law", "status", "error", *pool_response.OUTPUTS],
    "results/sensitivity/delamination_map.csv": [
        "charge_law",
        "angular_extent_deg",
        "sigma_cr_kPa",
        "concentration_mEq_l",
        "state",
        "delaminated_length_um",
    ],
}
FIGURES = [
    f"figures/{name}.{ext}"
    for name in (
        "fig1",
        "fig3a_mean",
        "fig3b",
        "fig3",
        "fig4",
        "verification_pool",
        "verification_annulus",
        "verification_profiles",
        "swelling_convergence",
        "fig5",
        "fig6",
        "fig7",
        "sensitivity",
        "delamination_map",
        "variants_hourglass",
        "variants_pool_models",
        "paper_procedure",
        # figures 4-7 (and figure 4 with every pool model) once per charge law: the CI configuration runs both
        *(f"{stem}_conserved" for stem in ("fig4", "fig5", "fig6", "fig7", "variants_pool_models")),
    )
    for ext in ("pdf", "png")
]

# the tables of snakemake --report besides the figures' PNGs (report() in workflow/rules/*.smk)
REPORT_TABLES = [
    "results/claims.csv",
    "results/calibration/mean_pressure_diameter.csv",
    "results/homeostasis/summary.csv",
    "results/swelling/tip_stress.csv",
    "results/swelling/convergence.csv",
    "results/swelling/gci.csv",
    "results/verification/elliptic_pool.csv",
    "results/verification/annulus.csv",
    "results/verification/profiles.csv",
    "results/delamination/summary.csv",
    "results/delamination/convergence.csv",
    "results/delamination/gci.csv",
    "results/sensitivity/indices.csv",
    "results/sensitivity/delamination_map.csv",
    "results/variants/tip_stress.csv",
    "results/variants/claims.csv",
    "results/paper_procedure/summary.csv",
]


def edited_config(tmp_path, ci_config, section, key, value):
    """A copy of the CI config with one key replaced."""
    cfg = copy.deepcopy(ci_config)
    cfg[section][key] = value
    path = tmp_path / "edited.yaml"
    path.write_text(yaml.safe_dump(cfg, sort_keys=False))
    return path


def test_fracture_energy_runs_are_rows_of_their_tables_beside_their_closed_form(workdir, ci_config):
    """Figure 5's pool under every charge law, at every configured G_c and at the one the paper's law dissipates,
    each with Griffith's closed form for the same pool (target fracture_energy)."""
    de = ci_config["delamination"]
    fe = pd.read_csv(workdir / "results/delamination/fracture_energy/summary.csv")
    growth = pd.read_csv(workdir / "results/delamination/fracture_energy/growth.csv")
    assert set(fe.damage_law) == set(growth.damage_law) == {"fracture_energy"}
    # the paper law's prescribed run of the same pool (it runs for this match alone where figure 5's sigmas lack it)
    paper = f"{de['figures']['fig5']}_{de['critical_stress_kPa']:g}kPa_{de['criteria'][0]}_summary.csv"
    matched = float(pd.read_csv(workdir / "results/delamination/runs/prescribed" / paper).dissipated_energy_J_m2[0])
    configured = de["fracture_energy"]["fracture_energies_J_m2"]
    for law in ci_config["gag"]["charge_laws"]:
        rows = fe[fe.charge_law == law]
        assert (rows.case == de["figures"]["fig5"]).all() and (rows.criterion == de["criteria"][0]).all()
        unmatched = rows[rows.stop.str.startswith("no G_c to match")]
        if matched > 0:
            assert np.allclose(sorted(rows.fracture_energy_J_m2), sorted(configured + [matched])), law
            assert unmatched.empty
        else:  # the paper's run grew nothing: its match is a row that says so, seeded and not grown
            assert np.allclose(sorted(rows.fracture_energy_J_m2.dropna()), sorted(configured)), law
            assert len(unmatched) == 1 and unmatched.fracture_energy_J_m2.isna().all()
            assert (unmatched.outcome == "no growth").all() and (unmatched.passes == 0).all()
    grown = fe[fe.fracture_energy_J_m2.notna()]
    assert (grown.griffith_concentration_mEq_l > 0).all() and (grown.griffith_half_length_um > 0).all()
    # the tougher the media, the higher the concentration Griffith needs
    prescribed = grown[grown.charge_law == "prescribed"].sort_values("fracture_energy_J_m2")
    assert np.all(np.diff(prescribed.griffith_concentration_mEq_l) > 0)


def test_outputs_follow_the_data_contracts(workdir, ci_config):
    for path, columns in CONTRACT.items():
        table = pd.read_csv(workdir / path)
        assert set(columns) <= set(table.columns), path
        assert len(table) > 0
    for table in (
        "calibration/mean_pressure_diameter.csv",
        "calibration/bilayer_pressure_diameter.csv",
        "homeostasis/summary.csv",
        "swelling/tip_stress.csv",
        "swelling/convergence.csv",
        "verification/elliptic_pool.csv",
        "verification/profiles.csv",
    ):
        states = pd.read_csv(workdir / "results" / table)
        assert (states.residual < ci_config["numerics"]["tolerance"]).all(), table
    annulus = pd.read_csv(workdir / "results/verification/annulus.csv")
    assert not annulus[annulus.fraction > 1.0].state.any()  # no state above the exact limit of existence
    for table in ("delamination/summary.csv", "delamination/convergence.csv"):
        assert (pd.read_csv(workdir / "results" / table).max_residual < ci_config["numerics"]["tolerance"]).all()
    assert (
        pd.read_csv(workdir / "results/delamination/growth.csv").residual < ci_config["numerics"]["tolerance"]
    ).all()
    de, laws = ci_config["delamination"], ci_config["gag"]["charge_laws"]
    summary = pd.read_csv(workdir / "results/delamination/summary.csv")
    for law in laws:  # every pool set runs under every law, whatever its name and role
        runs = summary[summary.charge_law == law]
        assert set(runs.case) == set(de["pool_sets"]) and set(runs.criterion) == set(de["criteria"]), law
    for table in (
        "swelling/tip_stress.csv",
        "swelling/convergence.csv",
        "delamination/growth.csv",
        "delamination/summary.csv",
        "delamination/convergence.csv",
    ):  # every pool table holds both laws, by name
        assert sorted(pd.read_csv(workdir / "results" / table).charge_law.unique()) == sorted(laws), table
    transmural = pd.read_csv(workdir / "results/calibration/transmural.csv")
    assert set(transmural.model) == {"mean", "passive", "active"}
    assert set(pd.read_csv(workdir / "results/calibration/bilayer_pressure_diameter.csv").model) == {
        "passive",
        "active",
    }
    tips = pd.read_csv(workdir / "results/swelling/tip_stress.csv")
    sw = ci_config["swelling"]
    runs = tips.groupby(["charge_law", "pool_model", "model", "case", "pressure_mmHg"])
    assert runs.ngroups == pool_variants(ci_config) * len(sw["models"]) * len(sw["cases"]) * len(sw["pressures_mmHg"])
    assert (runs.stage.apply(lambda s: (s == "intact").sum()) == 1).all()
    # a run ends at its last converged state (the prescribed law may find no equilibrium up to the maximum)
    assert (runs.size() <= 1 + sw["concentration_points"]).all()
    assert (
        tips[tips.charge_law == "conserved"].groupby(["model", "case", "pressure_mmHg"]).size()
        == 1 + sw["concentration_points"]
    ).all()
    claims = pd.read_csv(workdir / "results/claims.csv", keep_default_na=False)
    assert set(claims.holds) <= {"yes", "no", "n/a"} and len(claims) >= 10  # every target ran: nothing "not run"
    assert sorted(claims[claims.claim_id == "C18"].charge_law) == sorted(ci_config["gag"]["charge_laws"])
    calibration = claims.claim_id.isin([f"C{k}" for k in range(1, 6)])
    assert set(claims[calibration].charge_law) == {"-"}
    equilibrium = claims.path == "equilibrium"
    pool = claims[~calibration & (claims.pool_model == PAPER_POOL) & claims.claim_id.str.startswith("C")]
    assert all(sorted(rows.charge_law) == sorted(laws) for _, rows in pool.groupby("claim_id"))  # C6-C18: per law
    assert (pool.path == "equilibrium").all()
    # target paper_procedure: P1-P4 by every explicit path (the paper's law), beside the equilibrium's verdict
    procedure = claims[claims.claim_id.str.startswith("P")]
    factors = ci_config["paper_procedure"]["step_factors"]
    assert set(procedure.claim_id) == {"P1", "P2", "P3", "P4", "P5"} and set(procedure.charge_law) == {"prescribed"}
    assert set(procedure[procedure.claim_id == "P1"].path) == {"equilibrium", *(f"explicit x{f}" for f in factors)}
    assert set(procedure[~equilibrium].holds) <= {"yes", "no", "n/a"}
    # target variants: the claims of figure 4 under every other pool model, under each law it carries
    variant_claims = pd.read_csv(workdir / "results/variants/claims.csv", keep_default_na=False)
    paper = variant_claims[variant_claims.pool_model == PAPER_POOL].reset_index(drop=True)
    assert paper.equals(claims[claims.pool_model == PAPER_POOL].reset_index(drop=True))
    for model in ci_config["swelling"]["variant_pool_models"]:
        other = variant_claims[variant_claims.pool_model == model]
        carried = sorted(set(laws) & set(POOL_MODELS[model].laws))
        assert set(other.claim_id) == {f"C{k}" for k in range(6, 13)}
        assert all(sorted(rows.charge_law) == carried for _, rows in other.groupby("claim_id"))
    markdown = (workdir / "figures/claims.md").read_text()
    assert all(f"| C7 | {law} |" in markdown and f"| C13 | {law} |" in markdown for law in laws)
    # figure 4's claims judged on its resolution study too (two CI spacings: no extrapolation)
    figure4 = claims[claims.claim_id.isin([f"C{k}" for k in range(6, 13)]) & (claims.pool_model == PAPER_POOL)]
    assert figure4.across_band.str.match(r"^(dx \d|n/a)").all(), figure4.across_band.tolist()
    for fig in FIGURES:
        assert (workdir / fig).stat().st_size > 5000


def test_figures_4_to_7_fit_a_screen_and_their_snapshots_show_the_pools(workdir):
    """Figures 4-7, one per charge law, are at most 2000 px a side at the default dpi; the pools cover at least a
    tenth of every snapshot panel figures 5-7 can draw (each framed on its pools, sphgag.views.snapshots)."""
    from PIL import Image

    from sphgag.views import snapshots

    for stem in ("fig4", "fig5", "fig6", "fig7"):
        for name in (f"{stem}.png", f"{stem}_conserved.png"):
            assert max(Image.open(workdir / "figures" / name).size) <= 2000, name
    runs = sorted((workdir / "results/delamination/runs").glob("*/*_snapshots.npz"))
    assert runs
    for path in runs:
        snap = snapshots.read_snapshots(path)
        for k in range(len(snap["steps"])):
            assert snapshots.pool_fraction(snap, k) >= 0.1, (path.name, k)


def test_every_run_has_its_paraview_series_and_every_delamination_run_its_animation(workdir):
    """The series read back as the saved states (positions, history) and the animation has a frame per state."""
    from PIL import Image

    from sphgag.records import state
    from sphgag.views import paraview

    runs = sorted((workdir / "results/delamination/runs").glob("*/*_snapshots.npz"))
    runs += sorted((workdir / "results/swelling/states").glob("*/*/*.npz"))
    assert len(runs) > 10
    for path in runs:
        kind = "delamination" if path.name.endswith("_snapshots.npz") else "swelling"
        run = path.name.removesuffix("_snapshots.npz").removesuffix(".npz")
        folder = path.parent.relative_to(workdir / f"results/{kind}/{'runs' if kind == 'delamination' else 'states'}")
        series = paraview.read_series(workdir / f"results/paraview/{kind}/{folder.as_posix()}/{run}/{run}.pvd")
        saved = state.load_series(path)
        assert len(series) == len(saved), path
        for frame, s in zip(series, saved):
            np.testing.assert_array_equal(frame.x, s.x)
            if s.history is not None:
                np.testing.assert_array_equal(frame.data["damage"], s.history.D)
        if kind == "delamination":
            with Image.open(workdir / f"figures/animations/{folder.as_posix()}/{run}.gif") as gif:
                assert gif.n_frames == len(series), run


def test_logs_show_progress_and_the_verification_numbers(workdir):
    log = (workdir / "logs/calibrate_mean.log").read_text()
    assert log.count("converged at") >= 5
    assert "max |OD error| over 10-200 mmHg" in log
    assert "carried pressure" in (workdir / "logs/homeostasis.log").read_text()
    assert "over 60-200 mmHg" in (workdir / "logs/bilayer_pressure_diameter_active.log").read_text()
    assert "(paper: about 20 %)" in (workdir / "logs/bilayer_table.log").read_text()


def test_provenance_records_code_and_parameters(workdir, ci_config):
    record = json.loads((workdir / "results/provenance/calibrate_mean.json").read_text())
    assert record["params"]["mean"] == ci_config["mean"]
    assert len(record["code"]["source_sha256"]) == 64


def report_variable(html: str, name: str):
    """The JSON value of ``<script id="{name}"> var ... = {...}; </script>`` in Snakemake's report page."""
    found = re.search(rf'<script id="{name}">\s*var \w+ = (.*?);\s*</script>', html, re.S)
    assert found, name
    return json.loads(found.group(1))


def test_the_report_holds_every_figure_and_the_claims_table_first(workdir):
    report = workdir / "report.zip"
    run = snakemake(workdir, "everything", "--report", str(report))
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    with zipfile.ZipFile(report) as z:
        html = z.read("report/report.html").decode()
        results, categories = report_variable(html, "results"), report_variable(html, "categories")
        pngs = [f for f in FIGURES if f.endswith(".png")]
        assert set(pngs + REPORT_TABLES) <= set(results), sorted(set(pngs + REPORT_TABLES) - set(results))
        for path, entry in results.items():
            # the file itself, byte for byte, and a caption that docutils rendered without complaint
            assert z.read(f"report/{entry['data_uri']}") == (workdir / path).read_bytes(), path
            assert len(entry["caption"]) > 300 and "system-message" not in entry["caption"], path
        assert all(results[path]["mime_type"] == "image/png" for path in pngs)  # shown inline
        animations = [str(p.relative_to(workdir)) for p in sorted((workdir / "figures/animations").glob("*/*.gif"))]
        assert animations and set(animations) <= set(results), sorted(set(animations) - set(results))
        # the menu sorts the categories by name (localeCompare; the same order as Python's for these names)
        first = sorted(categories)[0]
        assert [p for paths in categories[first].values() for p in paths] == ["results/claims.csv"], categories
        claims = pd.read_csv(workdir / "results/claims.csv")
        caption = results["results/claims.csv"]["caption"]
        assert all(f"<td>{claim}</td>" in caption for claim in claims.claim_id)  # the table, rendered
        description = report_variable(html, "workflow-desc")
        assert "Ahmadzadeh" in description and "system-message" not in description


def test_nothing_to_do_after_a_complete_run(workdir):
    run = snakemake(workdir, "-n", "everything")
    assert run.returncode == 0
    assert "Nothing to be done" in run.stdout + run.stderr
    # `all` after `everything`: the claims and figure 4 read the sensitivity and resolution studies as they stand
    # instead of waiting for them (a parameter where it was an input), so their jobs rerun, to the same bytes;
    # nothing else does
    run = snakemake(workdir, "-n", "all")
    assert planned_jobs(run.stdout + run.stderr) == {"claims": 1, "fig4": 1, "all": 1}


def test_changing_a_parameter_reruns_only_what_it_affects(workdir, ci_config, tmp_path):
    edited = edited_config(tmp_path, ci_config, "calibration", "pressure_points", 6)
    run = snakemake(workdir, "-n", "everything", configfile=edited)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out
    assert "rule calibrate_mean:" in out and "rule fig3a_mean:" in out
    assert "rule homeostasis:" not in out and "rule bilayer_pressure_diameter:" not in out


def planned_jobs(out: str) -> dict:
    """``{rule: count}`` of the last "Job stats" table a snakemake run printed."""
    table = out.rsplit("Job stats:", 1)[1].splitlines()
    jobs = {}
    for line in table[3:]:
        parts = line.split()
        if len(parts) != 2 or parts[0] == "total":
            break
        jobs[parts[0]] = int(parts[1])
    return jobs


def test_a_reference_value_reruns_only_the_table_and_figures_that_show_it(workdir, ci_config, tmp_path):
    """homeostasis.target_pressure_mmHg: the table that compares the carried pressure with it, and the figures that
    mark it (figure 3a of the mean model, figure 3)."""
    edited = edited_config(tmp_path, ci_config, "homeostasis", "target_pressure_mmHg", 110.0)
    run = snakemake(workdir, "-n", "everything", configfile=edited)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out
    # and the site's results pages, which show figure 3
    expected = {"homeostasis_target": 1, "fig3a_mean": 1, "fig3": 1, "docs_pages": 1, "site": 1, "everything": 1}
    assert planned_jobs(out) == expected, out[-3000:]


def test_a_measurement_setting_reruns_the_measurement_not_the_simulations(workdir, ci_config, tmp_path):
    """``swelling.probe_length_um`` only sets where the pool stresses are measured: the saved swelling states stay."""
    edited = edited_config(tmp_path, ci_config, "swelling", "probe_length_um", 12.0)
    run = snakemake(workdir, "-n", "everything", configfile=edited)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out
    jobs = planned_jobs(out)
    print("\nprobe_length_um edit reruns:", jobs)
    sw, variants = ci_config["swelling"], pool_variants(ci_config, every_pool_model(ci_config))
    assert jobs.pop("pool_stresses") == variants * len(sw["models"]) * len(sw["cases"]) * len(sw["pressures_mmHg"])
    sc = ci_config["swelling_convergence"]
    assert jobs.pop("swelling_convergence_stresses") == study_variants(ci_config) * len(sc["dx_um"]) * len(sc["models"])
    simulations = {"swell", "swelling_convergence_dx", "homeostasis", "bilayer_pressure_diameter", "delaminate"}
    assert not simulations & set(jobs), jobs


def edited_copy(workdir, tmp_path, module: str) -> Path:
    """A copy of the finished run with a comment appended to ``src/sphgag/<module>``."""
    dest = tmp_path / "copy"
    shutil.copytree(workdir, dest, symlinks=True)
    with open(dest / "src" / "sphgag" / module, "a") as fh:
        fh.write("# a comment\n")
    return dest


def test_a_comment_in_a_module_that_computes_no_number_reruns_nothing_but_the_site(workdir, tmp_path):
    """No simulation, table or figure: only the site, whose API page documents the module."""
    run = snakemake(edited_copy(workdir, tmp_path, "records/provenance.py"), "-n", "everything")
    assert run.returncode == 0, run.stdout[-3000:]
    assert planned_jobs(run.stdout + run.stderr) == {"site": 1, "everything": 1}


def test_an_edit_of_a_figure_family_redraws_its_figures_only(workdir, tmp_path):
    """views/delamination.py draws figures 5-7 (their code input: the modules their script imports)."""
    run = snakemake(edited_copy(workdir, tmp_path, "views/delamination.py"), "-n", "everything")
    jobs = planned_jobs(run.stdout + run.stderr)
    print("\nviews/delamination.py edit reruns:", jobs)
    # and the site's results pages, which show them
    expected = {"package_digest": 1, "fig5": 1, "fig6": 1, "fig7": 1, "docs_pages": 1, "site": 1, "everything": 1}
    assert jobs == expected, jobs


def test_an_edit_of_the_paraview_module_rewrites_the_series_and_animations_only(workdir, tmp_path):
    run = snakemake(edited_copy(workdir, tmp_path, "views/paraview.py"), "-n", "everything")
    jobs = planned_jobs(run.stdout + run.stderr)
    # and the site, whose API pages it documents
    expected = {"package_digest", "paraview_swelling", "paraview_delamination", "animation", "site", "everything"}
    assert set(jobs) == expected, jobs


def test_an_edit_of_a_module_in_a_subpackage_reruns_the_simulations_that_import_it(workdir, tmp_path):
    """engine/forces.py is imported by every model: its edit reruns every simulation (and what reads them), and
    the Numba cache is keyed anew (sphgag._source_hash covers the subpackages)."""
    run = snakemake(edited_copy(workdir, tmp_path, "engine/forces.py"), "-n", "everything")
    jobs = planned_jobs(run.stdout + run.stderr)
    print("\nengine/forces.py edit reruns:", jobs)
    simulations = {"calibrate_mean", "homeostasis", "bilayer_pressure_diameter", "swell", "delaminate"}
    assert simulations <= set(jobs), jobs
    assert {"paraview_delamination", "animation", "fig5", "claims"} <= set(jobs), jobs


def test_a_warm_numba_cache_gives_the_bytes_of_a_cold_one(workdir, numba_cache, tmp_path, ci_config):
    """Same config, same bytes, whatever the state of the Numba cache: the CI run compiled every kernel itself
    (cold cache); these jobs, rerun in a copy of it, load them all from that cache (warm)."""
    warm = tmp_path / "warm"
    shutil.copytree(workdir, warm, symlinks=True)
    targets = [
        "results/calibration/mean_pressure_diameter.csv",
        "results/homeostasis/summary.csv",
        "results/swelling/runs/conserved/particles/passive_I_103mmHg.csv",
        f"results/delamination/runs/conserved/{ci_config['delamination']['figures']['fig5']}_30kPa_particle_growth.csv",
    ]
    run = snakemake(
        warm,
        *targets,
        "--forcerun",
        "calibrate_mean",
        "homeostasis",
        "swell",
        "pool_stresses",
        "delaminate",
        env=dict(NUMBA_CACHE_DIR=str(numba_cache)),
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    assert "calibrate_mean" in planned_jobs(run.stdout + run.stderr)
    for target in targets:
        assert (warm / target).stat().st_mtime > (workdir / target).stat().st_mtime, target  # really rerun
        assert (warm / target).read_bytes() == (workdir / target).read_bytes(), target


def test_a_bad_config_stops_the_workflow_with_a_named_key(fresh_copy, tmp_path, ci_config):
    edited = edited_config(tmp_path, ci_config, "numerics", "kernel_support_factor", 9.0)
    run = snakemake(fresh_copy, "-n", "all", configfile=edited)
    assert run.returncode != 0
    assert "numerics.kernel_support_factor = 9.0" in run.stdout + run.stderr


def test_a_later_rule_refuses_a_state_from_another_configuration(workdir, ci_config, tmp_path):
    """Rerun only the pressure-diameter rule with a different bilayer resolution (homeostasis not rerun,
    as if its outputs had been copied from elsewhere): it must refuse the old state."""
    edited = edited_config(tmp_path, ci_config, "bilayer", "dx_um", 7.0)
    copy_dir = tmp_path / "copy"
    shutil.copytree(workdir, copy_dir)
    run = snakemake(
        copy_dir,
        "results/calibration/bilayer_passive.csv",
        "--forcerun",
        "bilayer_pressure_diameter",
        "--rerun-triggers",
        "mtime",
        configfile=edited,
    )
    assert run.returncode != 0
    log = (copy_dir / "logs/bilayer_pressure_diameter_passive.log").read_text()
    assert "StateMismatch" in log and "bilayer.dx_um: expected 7.0, file has 6.0" in log


def test_lint_is_clean():
    run = subprocess.run(
        [sys.executable, "-m", "snakemake", "--snakefile", str(ROOT / "Snakefile"), "--lint"],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert "Congratulations" in run.stdout + run.stderr, run.stdout[-2000:]


@pytest.fixture(scope="module")
def fresh_copy(tmp_path_factory):
    """A copy of the project root before any run."""
    return project_copy(tmp_path_factory.mktemp("project"))


def plan(project, *args, target="everything"):
    run = snakemake(project, "-n", target, *args, configfile=None)
    return run, run.stdout + run.stderr


def test_a_configfile_stands_alone(fresh_copy, ci_config):
    """--configfile X means X: nothing of config/config.yaml (pools II, III, pressure 145) leaks in."""
    run, out = plan(fresh_copy, "--configfile", "config/ci.yaml")
    assert run.returncode == 0, out
    sw = ci_config["swelling"]
    expected = pool_variants(ci_config, every_pool_model(ci_config)) * len(sw["models"]) * len(sw["cases"])
    expected *= len(sw["pressures_mmHg"])
    swell = [line for line in out.splitlines() if line.startswith("swell ")]
    assert swell and int(swell[0].split()[-1]) == expected, swell
    run, out = plan(fresh_copy)  # no --configfile: the full study
    full = yaml.safe_load((ROOT / "config/config.yaml").read_text())
    runs = (
        pool_variants(full, every_pool_model(full)) * len(full["swelling"]["models"]) * len(full["swelling"]["cases"])
    )
    assert f"swell {runs * len(full['swelling']['pressures_mmHg'])}".split() in [
        line.split() for line in out.splitlines()
    ]


def test_a_config_missing_a_section_is_rejected_naming_it(fresh_copy, ci_config, tmp_path):
    cfg = copy.deepcopy(ci_config)
    del cfg["delamination"]
    path = tmp_path / "partial.yaml"
    path.write_text(yaml.safe_dump(cfg, sort_keys=False))
    run, out = plan(fresh_copy, "--configfile", str(path))
    assert run.returncode != 0
    assert "missing key 'delamination'" in out, out[-2000:]


def test_a_nested_config_override_is_read_as_yaml(fresh_copy):
    """``--config numerics='{tolerance: 0.001}'`` (Snakemake passes nested values as text) is a valid override."""
    run, out = plan(fresh_copy, "--configfile", "config/ci.yaml", "--config", "numerics={tolerance: 0.001}")
    assert run.returncode == 0, out[-2000:]
    run, out = plan(fresh_copy, "--configfile", "config/ci.yaml", "--config", "numerics={tolerance: 1e-4}")
    assert run.returncode != 0 and "write 1.0e-4" in out


# -- charge laws and pool sets by name ----------------------------------------------------------------

SIMULATIONS = {
    "swell",
    "pool_stresses",
    "swelling_convergence_dx",
    "swelling_convergence_stresses",
    "delaminate",
    "delaminate_fracture_energy",
    "sensitivity_batch",
    "delamination_map_point",
    "delamination_convergence_dx",
    "verify_crack_length",
}


def written_config(tmp_path, cfg, name="edited.yaml"):
    path = tmp_path / name
    path.write_text(yaml.safe_dump(cfg, sort_keys=False))
    return path


def pool_variants(cfg, pools=None) -> int:
    """The (charge law, pool model) pairs the swelling runs of ``cfg`` run (each pool model under its laws), of the
    pool models ``pools`` if given."""
    laws = set(cfg["gag"]["charge_laws"])
    pools = cfg["swelling"]["pool_models"] if pools is None else pools
    return sum(len(laws & set(POOL_MODELS[pool].laws)) for pool in pools)


def every_pool_model(cfg) -> list[str]:
    """Figure 4's pool models and the variants' (target `variants`): every pool model that `everything` runs."""
    return cfg["swelling"]["pool_models"] + cfg["swelling"]["variant_pool_models"]


def study_variants(cfg) -> int:
    """The (charge law, pool model) pairs of figure 4's resolution study."""
    return pool_variants(cfg, cfg["swelling_convergence"]["pool_models"])


SWELLING_RULES = ("swell", "pool_stresses")
STUDY_RULES = ("swelling_convergence_dx", "swelling_convergence_stresses")


def law_jobs(cfg) -> dict:
    """The simulation jobs of one charge law of ``cfg``, per rule."""
    sw, de, sc = cfg["swelling"], cfg["delamination"], cfg["swelling_convergence"]
    runs = sum(len(de["critical_stresses_kPa"]) if name == de["figures"]["fig5"] else 1 for name in de["pool_sets"])
    return {
        "swell": len(sw["models"]) * len(sw["cases"]) * len(sw["pressures_mmHg"]),
        "pool_stresses": len(sw["models"]) * len(sw["cases"]) * len(sw["pressures_mmHg"]),
        "swelling_convergence_dx": len(sc["dx_um"]) * len(sc["models"]),
        "swelling_convergence_stresses": len(sc["dx_um"]) * len(sc["models"]),
        "delaminate": runs * len(de["criteria"]),
        "delamination_convergence_dx": len(de["convergence"]["dx_um"]) * len(de["criteria"]),
    }


def test_removing_a_charge_law_reruns_no_simulation(workdir, ci_config, tmp_path):
    """Each run's params hold its own law only: without ``prescribed`` the ``conserved`` runs stay, and only the tables,
    figures and claims that showed both laws are redone."""
    cfg = copy.deepcopy(ci_config)
    cfg["gag"]["charge_laws"] = ["conserved"]
    cfg["swelling"]["pool_models"] = ["particles"]  # the cavity carries the prescribed law only
    cfg["swelling"]["variant_pool_models"] = []
    run = snakemake(workdir, "-n", "everything", configfile=written_config(tmp_path, cfg))
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    jobs = planned_jobs(out)
    print("\nremoving a charge law reruns:", jobs)
    # the Sobol inputs are those Morris ranks highest over every law: they may change, and their samples with them
    se = ci_config["sensitivity"]
    sobol_batches = math.ceil(
        se["methods"]["sobol"]["base_samples"] * (se["methods"]["sobol"]["inputs"] + 2) / se["batch_size"]
    )
    assert jobs.pop("sensitivity_batch", 0) in (0, sobol_batches), jobs
    assert jobs and not SIMULATIONS & set(jobs), jobs


def test_adding_a_charge_law_adds_its_own_jobs(fresh_copy, ci_config, tmp_path):
    """From nothing, the two laws plan each law's simulation jobs once: a law adds its jobs and no others (the
    swelling runs once per pool model that carries the law: the cavity carries the prescribed law only)."""
    one = copy.deepcopy(ci_config)
    one["gag"]["charge_laws"] = ["conserved"]
    one["swelling"]["pool_models"] = ["particles"]
    one["swelling"]["variant_pool_models"] = []
    alone = planned_jobs(plan(fresh_copy, "--configfile", str(written_config(tmp_path, one)))[1])
    both = planned_jobs(plan(fresh_copy, "--configfile", "config/ci.yaml")[1])
    assert ci_config["gag"]["charge_laws"] == ["prescribed", "conserved"]
    de = ci_config["delamination"]
    # the G_c the paper's law dissipates comes from its prescribed-law run of figure 5's pool at critical_stress_kPa,
    # which runs for that alone where figure 5's sigmas do not include it
    matched = de["fracture_energy"]["match_paper"] and de["critical_stress_kPa"] not in de["critical_stresses_kPa"]
    variants = pool_variants(ci_config, every_pool_model(ci_config))
    for rule, n in law_jobs(ci_config).items():
        per_law = variants if rule in SWELLING_RULES else study_variants(ci_config) if rule in STUDY_RULES else 2
        assert (alone[rule], both[rule]) == (n, per_law * n + (matched if rule == "delaminate" else 0)), rule
    n = len(de["fracture_energy"]["fracture_energies_J_m2"])
    assert (alone["delaminate_fracture_energy"], both["delaminate_fracture_energy"]) == (n, 2 * (n + 1))


def renamed(ci_config, old="low_separation", new="pair_2deg"):
    """The CI config with one pool set renamed, in the set and in its figure's role."""
    cfg = copy.deepcopy(ci_config)
    de = cfg["delamination"]
    de["pool_sets"] = {new if k == old else k: v for k, v in de["pool_sets"].items()}
    de["figures"] = {
        k: [new if n == old else n for n in v] if isinstance(v, list) else v for k, v in de["figures"].items()
    }
    de["convergence"]["pool_sets"] = [new if n == old else n for n in de["convergence"]["pool_sets"]]
    return cfg


def test_a_renamed_pool_set_builds_its_dag_and_runs(workdir, ci_config, tmp_path):
    """Renaming figure 6's low-separation set (set, role and resolution study) runs that set under its new name, and
    nothing else."""
    cfg = renamed(ci_config)
    config = written_config(tmp_path, cfg)
    copy_dir = tmp_path / "copy"
    shutil.copytree(workdir, copy_dir, symlinks=True)
    run = snakemake(copy_dir, "-n", "everything", configfile=config)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    jobs = planned_jobs(out)
    laws, criteria = len(cfg["gag"]["charge_laws"]), len(cfg["delamination"]["criteria"])
    assert jobs.get("delaminate") == laws * criteria and "fig6" in jobs, jobs
    assert set(re.findall(r"poolset=(\w+)", out)) == {"pair_2deg"}
    # the resolution study grows that set too (delamination.convergence.pool_sets): its runs carry the new name
    assert not (SIMULATIONS - {"delaminate", "delamination_convergence_dx"}) & set(jobs), jobs
    run = snakemake(copy_dir, "all", configfile=config)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    summary = pd.read_csv(copy_dir / "results/delamination/summary.csv")
    assert "pair_2deg" in set(summary.case) and "low_separation" not in set(summary.case)
    assert (copy_dir / "figures/fig6.png").stat().st_mtime > (workdir / "figures/fig6.png").stat().st_mtime
    assert "pair_2deg" in pd.read_csv(copy_dir / "results/claims.csv").query("claim_id == 'C16'").our_value.iloc[0]


def test_an_extra_pool_set_runs_and_joins_the_tables(workdir, ci_config, tmp_path):
    """A set that no figure shows runs under every law and criterion, and its rows join the delamination tables (the
    figures of the delamination runs, which read those tables, are redrawn)."""
    cfg = copy.deepcopy(ci_config)
    de = cfg["delamination"]
    de["pool_sets"]["extra"] = copy.deepcopy(de["pool_sets"][de["figures"]["fig7"]])
    run = snakemake(workdir, "-n", "everything", configfile=written_config(tmp_path, cfg))
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    jobs = planned_jobs(out)
    assert jobs.get("delaminate") == len(cfg["gag"]["charge_laws"]) * len(de["criteria"]), jobs
    assert set(re.findall(r"poolset=(\w+)", out)) == {"extra"}
    assert {"delamination_growth", "delamination_summary", "claims"} <= set(jobs)
    assert not (SIMULATIONS - {"delaminate"}) & set(jobs), jobs


def test_a_figure_without_its_pool_set_is_rejected_by_name_before_any_job(fresh_copy, ci_config, tmp_path):
    cfg = copy.deepcopy(ci_config)
    cfg["delamination"]["figures"]["fig6"] = ["pair_2deg", "high_separation"]  # no such set
    run = snakemake(fresh_copy, "all", configfile=written_config(tmp_path, cfg))
    out = run.stdout + run.stderr
    assert run.returncode != 0
    assert "delamination.figures.fig6[0] = 'pair_2deg' is not a pool set of delamination.pool_sets" in out, out[-2000:]
    assert "Job stats" not in out and not (fresh_copy / "results").exists()


def test_the_nominal_sample_reruns_the_pipelines_runs_of_figure_5s_pool_to_the_bit(workdir, ci_config):
    """The sensitivity study's nominal sample (its own homeostasis, pressurisation, swelling and growth) gives the
    numbers of the main pipeline's runs of the same pool, as printed: figure 4's quantities at the stated concentration
    and, where the pipeline runs the pool at critical_stress_kPa (among figure 5's sigmas, or for the fracture-energy
    match under the prescribed law), the delamination summary."""
    se, de, sw = ci_config["sensitivity"], ci_config["delamination"], ci_config["swelling"]
    pool = de["pool_sets"][de["figures"]["fig5"]][0]
    [case] = [name for name, c in sw["cases"].items() if c == pool]
    assert de["pressure_mmHg"] in sw["pressures_mmHg"]
    run = f"{de['figures']['fig5']}_{de['critical_stress_kPa']:g}kPa_{de['criteria'][0]}"
    runs = {
        law: workdir / f"results/delamination/runs/{law}/{run}_summary.csv" for law in ci_config["gag"]["charge_laws"]
    }
    assert any(path.exists() for path in runs.values())
    for law, path in runs.items():
        nominal = pd.read_csv(workdir / f"results/sensitivity/nominal/{law}/batch0.csv", dtype=str).iloc[0]
        assert nominal.status == "ok", nominal.error
        swelling = workdir / f"results/swelling/runs/{law}/particles/passive_{case}_{de['pressure_mmHg']:g}mmHg.csv"
        table = pd.read_csv(swelling)
        at = np.flatnonzero((table.stage == "converted") & (table.concentration_mEq_l == se["concentration_mEq_l"]))
        printed = pd.read_csv(swelling, dtype=str).iloc[at[0]]
        for column in pool_response.SWELLING_OUTPUTS:
            assert nominal[column] == printed[column], (law, column)
        if not path.exists():
            continue
        summary = pd.read_csv(path, dtype=str).iloc[0]
        assert nominal.final_length_um == summary.final_length_um, law
        assert (nominal.outcome, nominal.delamination_stop) == (summary.outcome, summary.stop), law
        assert nominal.delamination_stop_kind == summary.stop_kind, law
        if pd.isna(summary.onset_concentration_mEq_l):  # censored one step above the ramp
            assert nominal.onset_censored == "True"
            censored = de["max_concentration_mEq_l"] + de["concentration_step_mEq_l"]
            assert float(nominal.onset_concentration_mEq_l) == censored
        else:
            assert nominal.onset_concentration_mEq_l == summary.onset_concentration_mEq_l, law


def test_the_sensitivity_study_accounts_for_every_sample_and_maps_every_level(workdir, ci_config):
    se, laws = ci_config["sensitivity"], ci_config["gag"]["charge_laws"]
    inputs, k = list(se["inputs"]), len(se["inputs"])
    indices = pd.read_csv(workdir / "results/sensitivity/indices.csv")
    samples = pd.read_csv(workdir / "results/sensitivity/samples.csv")
    failures = pd.read_csv(workdir / "results/sensitivity/failures.csv")
    sizes = dict(
        nominal=1,
        morris=se["methods"]["morris"]["trajectories"] * (k + 1),
        sobol=se["methods"]["sobol"]["base_samples"] * (se["methods"]["sobol"]["inputs"] + 2),
    )
    for method, n in sizes.items():
        for law in laws:
            rows = samples[(samples.method == method) & (samples.charge_law == law)]
            assert sorted(rows["sample"]) == list(range(n)), (method, law)
    morris = indices[indices.method == "morris"]
    sobol = indices[indices.method == "sobol"]
    for law in laws:
        for output in pool_response.OUTPUTS:
            m = morris[(morris.charge_law == law) & (morris.output == output)]
            assert sorted(m.input.unique()) == sorted(inputs) and set(m["index"]) == {"mu_star", "mu", "sigma"}
            s = sobol[(sobol.charge_law == law) & (sobol.output == output)]
            assert s.input.nunique() == se["methods"]["sobol"]["inputs"] and set(s.input) <= set(inputs)
            assert set(s["index"]) == {"S1", "ST"}
            # a sample without the output is counted; the used ones are whole trajectories or base rows
            runs = samples[(samples.charge_law == law)]
            for method, rows, block in (("morris", m, k + 1), ("sobol", s, se["methods"]["sobol"]["inputs"] + 2)):
                y = runs[runs.method == method][output]
                assert (rows.samples_missing == y.isna().sum()).all(), (law, output, method)
                assert (rows.samples_used % block == 0).all() and (rows.samples_used <= len(y)).all()
    lacking = samples[(samples.status != "ok") | samples[list(pool_response.OUTPUTS)].isna().any(axis=1)]
    assert len(failures) == len(lacking) and set(inputs) <= set(failures.columns)
    assert (failures.status != "ok").sum() == (samples.status != "ok").sum()
    table = pd.read_csv(workdir / "results/sensitivity/delamination_map.csv")
    levels = (
        ci_config["delamination"]["max_concentration_mEq_l"] / ci_config["delamination"]["concentration_step_mEq_l"]
    )
    assert (
        len(table)
        == len(laws) * len(se["map"]["angular_extents_deg"]) * len(se["map"]["critical_stresses_kPa"]) * levels
    )
    assert set(table.state) <= set(LEVEL_CLASSES)
    assert set(table.charge_law) == set(laws)


def test_the_source_of_a_range_is_documentation_and_reruns_nothing_but_the_site_stamp(workdir, ci_config, tmp_path):
    """No simulation, table or figure: only the site's results pages, stamped with the configuration's digest."""
    cfg = copy.deepcopy(ci_config)
    first = next(iter(cfg["sensitivity"]["inputs"]))
    cfg["sensitivity"]["inputs"][first]["source"] = "a better reference"
    run = snakemake(workdir, "-n", "everything", configfile=written_config(tmp_path, cfg))
    assert run.returncode == 0, run.stdout[-3000:]
    assert planned_jobs(run.stdout + run.stderr) == {"docs_pages": 1, "site": 1, "everything": 1}


# -- targets by purpose, params that hold what a job reads, claims of targets not run, resources --------

HEAVY = {
    "swelling_convergence_dx",
    "delamination_convergence_dx",
    "verify_crack_length",
    "delaminate_fracture_energy",
    "sensitivity_batch",
    "delamination_map_point",
    "paraview_swelling",
    "paraview_delamination",
    "animation",
}
PAPER = {"fig1", "fig3a_mean", "fig3b", "fig3", "fig4", "fig5", "fig6", "fig7", "verification_pool_figure", "claims"}
TARGET_RULES = (
    "all",
    "resolution",
    "verification",
    "fracture_energy",
    "sensitivity",
    "variants",
    "paper_procedure",
    "paper_settings",
    "views",
    "docs",
    "everything",
)


def planned(out: str) -> set:
    """``{(rule, wildcards)}`` of every job a dry run printed."""
    jobs, rule = set(), None
    for line in out.splitlines():
        if line.startswith(("rule ", "localrule ")) and line.endswith(":"):
            rule = line.split()[1].rstrip(":")
            jobs.add((rule, ""))
        elif rule and line.startswith("    wildcards: "):
            jobs.discard((rule, ""))
            jobs.add((rule, line.split(": ", 1)[1]))
        elif not line.startswith("    "):
            rule = None
    return jobs


def test_all_makes_the_papers_figures_and_claims_and_no_heavy_study(fresh_copy):
    """The full configuration's default target: every figure of the paper, the claims and the pool verification;
    no sensitivity, resolution, crack-verification, fracture-energy or view job."""
    run, out = plan(fresh_copy, "--forceall", target="all")
    assert run.returncode == 0, out[-2000:]
    jobs = planned_jobs(out)
    assert PAPER <= set(jobs) and not HEAVY & set(jobs), jobs


def test_everything_plans_every_job_the_configuration_defines(fresh_copy):
    """``everything`` is the union of the targets, and every rule of the workflow has a job in it."""
    found = {}
    for target in TARGET_RULES:
        run, out = plan(fresh_copy, "--forceall", target=target)
        assert run.returncode == 0, (target, out[-2000:])
        found[target] = {job for job in planned(out) if job[0] not in TARGET_RULES}
    union = set().union(*(found[t] for t in TARGET_RULES[:-1]))
    assert found["everything"] == union
    listed = subprocess.run(
        [sys.executable, "-m", "snakemake", "--list-rules"], cwd=fresh_copy, capture_output=True, text=True
    ).stdout
    rules = [line.split()[0] for line in listed.splitlines() if line and not line[0].isspace()]
    assert set(rules) - set(TARGET_RULES) == {rule for rule, _ in found["everything"]}


@pytest.mark.parametrize(
    "edit, rerun",
    [
        (  # a delamination key: which onset measures run; the other measure's runs and every study that reads only
            # the default measure stay
            lambda cfg: cfg["delamination"].update(criteria=["averaged"]),
            {"delamination_growth", "delamination_summary", "delamination_convergence", "delamination_gci"}
            | {"fig5", "fig6", "fig7"},
        ),
        (  # a swelling key: the steps of the pools' conversion; read by the swelling runs (figure 4, the resolution
            # study, the sensitivity samples) and the measurements that check their states, not by the delamination
            lambda cfg: cfg["swelling"].update(conversion_steps=3),
            {"swell", "pool_stresses", "tip_stress", "fig4", "paraview_swelling", "swelling_convergence_dx"}
            | {"swelling_convergence_stresses", "swelling_convergence", "swelling_convergence_figure", "swelling_gci"}
            | {"sensitivity_batch", "sensitivity_method", "screened_design", "sensitivity_tables", "sensitivity_figure"}
            | {"delamination_map_figure", "variant", "variants_figure", "variants_tip_stress", "variants_fig4"}
            | {"procedure_equilibrium", "procedure_summary", "procedure_figure"}  # not the explicit runs
            | {"paper_settings_run", "paper_settings_table", "paper_settings_figure"},
        ),
        (  # a sensitivity key: the bootstrap of the Sobol intervals; read by the Sobol indices alone
            lambda cfg: cfg["sensitivity"]["methods"]["sobol"].update(resamples=50),
            {"sensitivity_method", "sensitivity_tables", "sensitivity_figure"},
        ),
        (  # a figure-only key: which pool sets figure 6 shows
            lambda cfg: cfg["delamination"]["figures"].update(fig6=[cfg["delamination"]["figures"]["fig6"][0]]),
            {"fig6"},
        ),
    ],
    ids=["delamination.criteria", "swelling.conversion_steps", "sensitivity.methods.sobol.resamples", "figures.fig6"],
)
def test_an_edit_plans_only_the_jobs_that_read_the_key_and_what_follows(workdir, ci_config, tmp_path, edit, rerun):
    cfg = copy.deepcopy(ci_config)
    edit(cfg)
    run = snakemake(workdir, "-n", "everything", configfile=written_config(tmp_path, cfg))
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    # the claims read nearly every table (the variants' claims too), and the site's results pages show them
    jobs = set(planned_jobs(out)) - {"everything", "claims", "variants_claims", "docs_pages", "site"}
    assert jobs == rerun, (sorted(jobs - rerun), sorted(rerun - jobs))


def test_a_claim_whose_target_has_not_run_says_so(workdir, ci_config, tmp_path):
    """Without the sensitivity study, `snakemake all` redraws the claims table (and figure 4, which reads the
    resolution study as it stands), and C18 is in it, once per law, naming the command that makes its evidence."""
    copy_dir = tmp_path / "copy"
    shutil.copytree(workdir, copy_dir, symlinks=True)
    shutil.rmtree(copy_dir / "results/sensitivity")
    run = snakemake(copy_dir, "all")
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    assert planned_jobs(out) == {"claims": 1, "fig4": 1, "all": 1}
    claims = pd.read_csv(copy_dir / "results/claims.csv", keep_default_na=False)
    c18 = claims[claims.claim_id == "C18"]
    assert sorted(c18.charge_law) == sorted(ci_config["gag"]["charge_laws"])
    assert (c18.holds == "not run").all() and (c18.our_value == "not run: `snakemake sensitivity`").all()
    assert (claims[claims.claim_id != "C18"].holds != "not run").all()
    assert "not run: `snakemake sensitivity`" in (copy_dir / "figures/claims.md").read_text()


def rule_resources(*args) -> subprocess.CompletedProcess:
    """``python benchmarks/rule_resources.py *args`` (the resource check), planning in ``ROOT``."""
    cmd = [sys.executable, str(ROOT / "benchmarks" / "rule_resources.py"), "--configfile", "config/ci.yaml", *args]
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)


def test_every_job_of_the_ci_run_stays_within_its_declared_resources(workdir):
    """The resource check on the CI run: every job has a benchmark, and none exceeds its rule's runtime or mem_mb."""
    run = rule_resources("--project", str(workdir), "--benchmarks", str(workdir / "results/benchmarks"), "--check")
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    jobs, measured = re.search(r"(\d+) jobs of everything; (\d+) measured", run.stdout).groups()
    assert jobs == measured, run.stdout[:3000]


def test_the_resource_check_names_a_rule_that_exceeds_its_declaration(workdir, tmp_path):
    benchmarks = tmp_path / "benchmarks"
    shutil.copytree(workdir / "results/benchmarks", benchmarks)
    slow = benchmarks / "fig4.tsv"
    rows = slow.read_text().splitlines()
    header, values = rows[0].split("\t"), rows[1].split("\t")
    values[header.index("s")] = "99999.0"
    values[header.index("max_rss")] = "123456.0"
    slow.write_text("\t".join(header) + "\n" + "\t".join(values) + "\n")
    run = rule_resources("--project", str(workdir), "--benchmarks", str(benchmarks), "--check")
    assert run.returncode == 1, run.stdout[-3000:] + run.stderr[-3000:]
    assert "EXCEEDS: fig4: measured 99999 s > declared runtime 5 min" in run.stdout
    assert "EXCEEDS: fig4: measured 123456 MB > declared mem_mb 1000" in run.stdout
    assert run.stdout.count("EXCEEDS:") == 2
