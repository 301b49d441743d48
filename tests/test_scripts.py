"""The workflow's scripts are only what their jobs compute (a lint of workflow/scripts), and the job layer they enter
(:mod:`sphgag.jobs`): a kind's paths, run names and typed wildcards, and a job run on a fake Snakemake object."""

import ast
import json
import re
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from sphgag import jobs
from sphgag.jobs import kinds
from sphgag.studies import crack
from sphgag.studies.delamination.runs import fracture_energy
from sphgag.studies.delamination.settings import MATCHED, Settings
from sphgag.studies.inclusion import Materials
from sphgag.studies.paper_procedure import Timing

from .conftest import ROOT

SCRIPTS = sorted((ROOT / "workflow" / "scripts").glob("*.py"))
MAX_LINES = 40
# the names a script would hold its own run key in
KEY_NAMES = {"run", "name", "key", "run_name", "label"}
WILDCARDS = {"w", "wildcards"}


def _parts(node) -> list[str]:
    """The names of an attribute chain (``job.w.sigma``: job, w, sigma)."""
    names = []
    while isinstance(node, ast.Attribute):
        names.append(node.attr)
        node = node.value
    if isinstance(node, ast.Name):
        names.append(node.id)
    return names[::-1]


def _has_fstring(node) -> bool:
    return any(isinstance(n, ast.JoinedStr) for n in ast.walk(node))


def faults(source: str) -> list[str]:
    """What a script does that its job layer does for it (empty for a good script): more than :data:`MAX_LINES`
    lines, a run key of its own (an f-string assigned to a key's name, or a ``.format(`` of one), a wildcard
    parsed by ``float(``/``int(`` (typed wildcards instead), no ``jobs.run``."""
    found = []
    lines = source.count("\n") + (not source.endswith("\n"))
    if lines > MAX_LINES:
        found.append(f"{lines} lines (at most {MAX_LINES})")
    tree = ast.parse(source)
    enters = False
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign | ast.AnnAssign | ast.AugAssign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names = {t.id for t in targets if isinstance(t, ast.Name)}
            if names & KEY_NAMES and node.value is not None and _has_fstring(node.value):
                found.append(f"line {node.lineno}: builds its own run key ({', '.join(sorted(names))})")
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        if isinstance(func, ast.Attribute) and func.attr == "format":  # a key's pattern filled in
            found.append(f"line {node.lineno}: formats a key (.format)")
        if isinstance(func, ast.Name) and func.id in ("float", "int"):
            if any(WILDCARDS & set(_parts(arg)[:-1]) for arg in node.args):
                found.append(f"line {node.lineno}: {func.id}() of a wildcard (the job's wildcards are typed)")
        if _parts(func) == ["jobs", "run"]:
            enters = True
    if not enters:
        found.append("does not enter its job (jobs.run)")
    return found


@pytest.mark.parametrize("script", SCRIPTS, ids=[p.name for p in SCRIPTS])
def test_a_script_is_only_what_its_job_computes(script):
    assert faults(script.read_text()) == []


OLD_DELAMINATE = '''"""A script as the rules' scripts were before the job layer."""

import time

from sphgag import threads
from sphgag.records import runlog

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
gc = getattr(w, "gc", None)
run = f"delaminate_{w.law}_{w.poolset}_{w.sigma}kPa_{w.criterion}" + (f"_Gc{gc}" if gc else "")
with runlog.run(run, sm.log[0]) as log:
    sigma, dx = float(w.sigma), float(sm.wildcards.dedx)
    path = "{law}/{run}".format(law=w.law, run=run)
'''


def test_the_lint_names_what_a_script_of_the_old_kind_does():
    found = faults(OLD_DELAMINATE)
    assert any("builds its own run key (run)" in f for f in found)
    assert any("float() of a wildcard" in f for f in found)
    assert any("formats a key" in f for f in found)
    assert any("does not enter its job" in f for f in found)
    assert faults(OLD_DELAMINATE + "\n" * 30)[0] == f"{OLD_DELAMINATE.count(chr(10)) + 30} lines (at most 40)"
    good = "from sphgag import jobs\n\nwith jobs.run(snakemake) as job:  # noqa: F821\n    job.log.info(job.w.sigma)\n"
    assert faults(good) == []


def test_a_kind_names_its_paths_and_runs_by_its_key():
    k = kinds.delaminate
    assert k.output("delamination/runs", "_growth.csv") == (
        "results/delamination/runs/{law}/{poolset}_{sigma}kPa_{criterion}_growth.csv"
    )
    assert k.log == "logs/delaminate/{law}/{poolset}_{sigma}kPa_{criterion}.log"
    assert k.benchmark == "results/benchmarks/delaminate_{law}_{poolset}_{sigma}kPa_{criterion}.tsv"
    assert k.provenance == "results/provenance/delaminate_{law}_{poolset}_{sigma}kPa_{criterion}.json"
    w = dict(law="conserved", poolset="single", sigma="40", criterion="particle")
    assert k.name(w) == "delaminate_conserved_single_40kPa_particle"
    # two rules of one computation share its names; a rule named after its study
    fe = kinds.delaminate_fracture_energy
    assert fe.name(dict(w, gc="paper")) == "delaminate_conserved_single_40kPa_particle_Gcpaper"
    assert fe.provenance == "results/provenance/delaminate_{law}_{poolset}_{sigma}kPa_{criterion}_Gc{gc}.json"
    assert kinds.verify_pool_ratio.flat_output("verification/runs", "elliptic_pool", ".csv") == (
        "results/verification/runs/elliptic_pool_ab{ratio}.csv"
    )
    assert kinds.verify_pool_ratio.log == "logs/verify_pool/ab{ratio}.log"
    assert kinds.delamination_map_point.log == "logs/sensitivity/map/{law}/{width}deg_{sigma}kPa.log"
    assert kinds.screened_design.name(dict(method="sobol")) == "sensitivity_sobol_design"
    assert jobs.kind("sensitivity_batch") is kinds.sensitivity_batch
    with pytest.raises(KeyError, match="no kind of job"):
        jobs.kind("no_such_rule")
    with pytest.raises(ValueError, match="already has a kind"):
        jobs.register(jobs.Kind("delaminate", "{law}"))


def test_the_wildcards_of_a_job_are_typed():
    w = jobs.typed(dict(law="prescribed", sigma="40", dedx="0.5", batch="3", ratio="2", model="hole"))
    assert (w.law, w.sigma, w.dedx, w.batch, w.ratio, w.model) == ("prescribed", 40.0, 0.5, 3, 2.0, "hole")
    assert isinstance(w.sigma, float) and isinstance(w.batch, int)
    # the text in a file name is the number's :g form: one quantity
    assert all(f"{v:g}" == t for v, t in ((w.sigma, "40"), (w.dedx, "0.5"), (w.ratio, "2")))


class _Files(list):
    """A Snakemake input or output list: its files, by position and by name."""

    def __init__(self, **named):
        super().__init__(named.values())
        self.__dict__.update(named)


def test_a_job_on_a_fake_snakemake_object_logs_and_records_its_provenance(tmp_path):
    cfg = dict(bilayer=dict(dx_um=10.0), numerics=dict(tol=1e-9))
    wildcards = dict(law="conserved", poolset="single", sigma="40", criterion="particle")
    sm = SimpleNamespace(
        rule="delaminate",
        wildcards=wildcards,
        threads=1,
        log=[str(tmp_path / "job.log")],
        params=SimpleNamespace(state_slice=cfg),
        output=_Files(table=str(tmp_path / "t.csv"), provenance=str(tmp_path / "p.json")),
    )
    with jobs.run(sm) as job:
        assert job.name == "delaminate_conserved_single_40kPa_particle"
        assert job.w.sigma == 40.0 and job.w.criterion == "particle"
        job.log.info("[%s] computed", job.name)
        job.record(dict(state=cfg), dict(passes=3))
    record = json.loads(Path(sm.output.provenance).read_text())
    assert record["rule"] == "delaminate" and record["params"] == dict(state=cfg)
    assert record["outputs"] == list(sm.output) and record["summary"] == dict(passes=3)
    log = Path(sm.log[0]).read_text()
    assert "[delaminate_conserved_single_40kPa_particle] computed" in log
    # a rule without a kind names its run
    sm.rule = "sensitivity_figure"
    with jobs.run(sm, name="sensitivity_figure") as job:
        assert job.name == "sensitivity_figure"


def test_a_delamination_job_has_one_shape_of_settings(ci_config, tmp_path):
    """Its params hold what every run reads; sigma_cr and the criterion are its typed wildcards, or the section's own
    float for a study at the configured sigma_cr; either way one Settings."""
    de = ci_config["delamination"]
    params = Settings.params(de)
    assert list(params) == list(Settings.config_keys())
    assert not {"critical_stress_kPa", "criterion", "fracture_energy_J_m2"} & set(params)
    assert params["damage_law"] == de["damage_law"] == "paper"  # the section's damage law, by name
    study = Settings.params(de, "critical_stress_kPa", "pressure_mmHg", criteria=["particle"])
    assert list(study)[-3:] == ["criteria", "critical_stress_kPa", "pressure_mmHg"]
    sigma = f"{de['critical_stress_kPa']:g}"  # the text of the run's file names
    w = jobs.typed(dict(sigma=sigma, criterion="particle"))
    assert Settings.from_config(params, w.sigma, w.criterion) == Settings.from_config(
        study, study["critical_stress_kPa"], "particle"
    )
    # G_c: none, a number, or the energy the paper's law dissipated in the matched run
    assert fracture_energy(None) == (None, "")
    assert fracture_energy("51") == (51.0, "")
    summary = tmp_path / "matched.csv"
    summary.write_text("dissipated_energy_J_m2\n12.5\n")
    assert fracture_energy(MATCHED, str(summary)) == (12.5, "")
    summary.write_text("dissipated_energy_J_m2\nnan\n")
    gc, unmatched = fracture_energy(MATCHED, str(summary))
    assert np.isnan(gc) and "no G_c to match" in unmatched


def test_the_rules_hold_no_key_filter_of_their_own():
    """A rule passes a section's keys by a declaration of the package (the options' roles, ``Options.keys_in``, a
    reader's ``gag_settings``), never by key names written in the rule: no mapping built from a literal list of keys,
    or filtered by one."""
    by_names = re.compile(r"""\{\s*(\w+)\s*:[^{}]*?\[\1\]\s*for \1 in [(\[]\s*["']""")
    filtered = re.compile(r"""\.items\(\)\s*if \w+ (?:not )?in [(\[]\s*["']""")
    found = [
        f"{path.name}: {m.group(0)!r}"
        for path in sorted((ROOT / "workflow" / "rules").glob("*.smk"))
        for pattern in (by_names, filtered)
        for m in pattern.finditer(path.read_text())
    ]
    assert found == []
    assert by_names.search('{\n    k: config["gag"][k]\n    for k in ("shear_modulus_kPa", "temperature_K")\n}')
    assert filtered.search('{k: v for k, v in sw.items() if k not in ("cases", "pressures_mmHg")}')


@pytest.mark.parametrize("bulk", [False, True])
def test_a_verification_reads_exactly_the_gag_keys_it_declares(ci_config, bulk):
    """The GAG of the pool verifications (:meth:`Materials.gag_settings`) is what :meth:`Materials.of` reads: enough
    to build the materials, and each key needed."""
    matrix = dict(shear_modulus_kPa=89.71, lame_lambda_kPa=1.0e4, hourglass_modulus_kPa=89.71)
    declared = Materials.gag_settings(ci_config["gag"], bulk=bulk)
    assert Materials.of(matrix, declared, bulk=bulk) == Materials.of(matrix, ci_config["gag"], bulk=bulk)
    for key in declared:
        with pytest.raises(KeyError):
            Materials.of(matrix, {k: v for k, v in declared.items() if k != key}, bulk=bulk)
    assert list(crack.gag_settings(ci_config["gag"]))[2:] == ["bath_concentration_mEq_l", "temperature_K"]
    assert Timing.keys_in(ci_config["paper_procedure"]) == {
        k: ci_config["paper_procedure"][k] for k in ("time_step", "load_update_steps")
    }
