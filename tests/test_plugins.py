"""Variants of one's own through the pipeline: a damage law, a charge law, a pool model and a sensitivity method, each
written in one file (tests/plugins), named in the configuration's key ``plugins`` and selected by a configuration
value, run the jobs of the CI configuration's DAG that the value selects (in a copy of the session's finished run)
and show up by name in their table. Nothing else reruns: a plug-in file is a code input of the jobs whose scripts
import its kind's module."""

import copy
import re
import shutil

import pandas as pd
import yaml

from sphgag.jobs import kinds, text

from .conftest import snakemake


def plugged(workdir, tmp_path, cfg: dict, plugin: str):
    """A copy of the finished run ``workdir`` and the configuration ``cfg`` with the plug-in file ``plugin``."""
    cfg = copy.deepcopy(cfg)
    cfg["plugins"] = [f"tests/plugins/{plugin}.py"]
    path = tmp_path / "plugged.yaml"
    path.write_text(yaml.safe_dump(cfg, sort_keys=False))
    project = tmp_path / "copy"
    shutil.copytree(workdir, project, symlinks=True)
    return project, path


def runs(project, target: str, config) -> dict:
    """Plan, then run, ``target`` in ``project``: the planned jobs by rule, but the code digests (the run must
    succeed)."""
    plan = snakemake(project, "-n", target, configfile=config)
    assert plan.returncode == 0, (plan.stdout + plan.stderr)[-3000:]
    jobs = {
        m[0]: int(m[1])
        for m in re.findall(r"^(\w+)\s+(\d+)$", plan.stdout, flags=re.M)
        if m[0] not in ("total", "package_digest")
    }
    run = snakemake(project, target, configfile=config)
    assert run.returncode == 0, (run.stdout + run.stderr)[-3000:]
    return jobs


def delamination_summary(cfg: dict, law: str) -> str:
    """The summary table of figure 5's pool set at its first sigma_cr, default criterion, charge law ``law``."""
    de = cfg["delamination"]
    sigma = text(de["critical_stresses_kPa"][0])
    key = kinds.delaminate.key.format(law=law, poolset=de["figures"]["fig5"], sigma=sigma, criterion=de["criteria"][0])
    return f"results/delamination/runs/{key}_summary.csv"


def test_a_damage_law_of_one_file_grows_a_delamination_run(workdir, ci_config, tmp_path):
    cfg = copy.deepcopy(ci_config)
    cfg["delamination"]["damage_law"] = "linear"
    project, config = plugged(workdir, tmp_path, cfg, "damage_law")
    target = delamination_summary(cfg, "prescribed")
    assert runs(project, target, config) == {"delaminate": 1}  # no upstream job: the law is no input of theirs
    summary = pd.read_csv(project / target)
    assert list(summary.damage_law) == ["linear"] and summary.max_residual.iloc[0] < 1e-3
    before = pd.read_csv(workdir / target)
    assert list(before.damage_law) == ["paper"] and summary.onset_concentration_mEq_l.equals(
        before.onset_concentration_mEq_l
    )  # onset is the paper's (sigma_cr); the law acts beyond it


def test_a_charge_law_of_one_file_runs_a_delamination_job(workdir, ci_config, tmp_path):
    cfg = copy.deepcopy(ci_config)
    cfg["gag"]["charge_laws"] = cfg["gag"]["charge_laws"] + ["ideal"]
    tops = cfg["delamination"]["max_concentration_by_law_mEq_l"]
    tops["ideal"] = tops.get("conserved", cfg["delamination"]["max_concentration_mEq_l"])  # the twin's ramp
    project, config = plugged(workdir, tmp_path, cfg, "charge_law")
    target = delamination_summary(cfg, "ideal")
    assert runs(project, target, config) == {"delaminate": 1}
    summary = pd.read_csv(project / target)
    twin = pd.read_csv(workdir / delamination_summary(cfg, "conserved"))  # the law whose rule it follows
    assert list(summary.charge_law) == ["ideal"]
    pd.testing.assert_frame_equal(summary.drop(columns="charge_law"), twin.drop(columns="charge_law"))


def test_a_pool_model_of_one_file_swells_a_pool(workdir, ci_config, tmp_path):
    cfg = copy.deepcopy(ci_config)
    sw = cfg["swelling"]
    sw["variant_pool_models"] = sw["variant_pool_models"] + ["cavity_as_configured"]
    project, config = plugged(workdir, tmp_path, cfg, "pool_model")
    run = dict(law="prescribed", pool="cavity_as_configured", model="passive", case=next(iter(sw["cases"])))
    key = kinds.pool_stresses.key.format(**run, pressure=text(sw["pressures_mmHg"][0]))
    target = f"results/swelling/runs/{key}.csv"
    assert runs(project, target, config) == {"swell": 1, "pool_stresses": 1}
    table = pd.read_csv(project / target)
    assert set(table.pool_model) == {"cavity_as_configured"} and len(table) > 1


def test_a_sensitivity_method_of_one_file_fills_its_index_table(workdir, ci_config, tmp_path):
    cfg = copy.deepcopy(ci_config)
    cfg["sensitivity"]["methods"]["rank_correlation"] = dict(samples=3, seed=7)
    project, config = plugged(workdir, tmp_path, cfg, "sensitivity_method")
    target = "results/sensitivity/rank_correlation/indices.csv"
    laws = len(cfg["gag"]["charge_laws"])
    assert runs(project, target, config) == {
        "sensitivity_design": 1,
        "sensitivity_batch": laws,
        "sensitivity_method": 1,
    }
    indices = pd.read_csv(project / target)
    assert set(indices.method) == {"rank_correlation"} and set(indices["index"]) == {"rho"}
    assert set(indices.input) == set(cfg["sensitivity"]["inputs"]) and indices.charge_law.nunique() == laws
