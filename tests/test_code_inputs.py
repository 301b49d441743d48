"""A rule's code input is the set of package modules its job imports (workflow/code_inputs.py, common.smk: CODE):
the import graph of the workflow scripts, and what an edit of a module reruns (Snakemake dry runs)."""

import contextlib
import importlib.util
import os
import re
import time

import pytest

from .conftest import ROOT, project_copy, snakemake
from .test_pipeline import planned, planned_jobs

_spec = importlib.util.spec_from_file_location("code_inputs", ROOT / "workflow" / "code_inputs.py")
code_inputs = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(code_inputs)

SCRIPTS, PACKAGE = ROOT / "workflow" / "scripts", ROOT / "src" / "sphgag"
# the simulations that start from the wall or a pool (not the explicit procedure's): none reruns for a module that
# only verification, figures or the explicit procedure import
SIMULATIONS = {
    "calibrate_mean",
    "homeostasis",
    "bilayer_pressure_diameter",
    "swell",
    "pool_stresses",
    "swelling_convergence_dx",
    "delaminate",
    "delaminate_fracture_energy",
    "delamination_convergence_dx",
    "delamination_map_point",
    "sensitivity_batch",
    "variant",
}


@pytest.fixture(scope="module")
def code():
    """{script: the modules its job imports} of every workflow script."""
    return code_inputs.code_inputs(SCRIPTS, PACKAGE)


def importers(code, module):
    """The scripts whose jobs import ``module``."""
    return {script for script, modules in code.items() if module in modules}


def write(path, text):
    """``text`` in the file ``path``, its directories made."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def test_the_import_graph_follows_relative_absolute_and_function_level_imports(tmp_path):
    """Through the package, transitively, with the __init__.py of every package on the way; a module that runs no
    code (a docstring alone) and the bookkeeping modules are followed but are inputs of nothing."""
    pkg = tmp_path / "sphgag"
    write(pkg / "__init__.py", "CODE_HASH = 'x'\n")  # bookkeeping, as the package's root
    write(pkg / "threads.py", "from .engine import numbers\n")  # bookkeeping, followed
    write(pkg / "engine" / "__init__.py", '"""A docstring alone."""\n')
    write(pkg / "engine" / "numbers.py", "ONE = 1\n")
    write(pkg / "studies" / "__init__.py", "from .. import threads\nDEFAULT = 2\n")
    write(pkg / "studies" / "run.py", "def run():\n    from ..physics import law\n    from . import helper\n")
    write(pkg / "studies" / "helper.py", "import sphgag.physics.deep.kernel as k\n")
    write(pkg / "physics" / "__init__.py", "")
    write(pkg / "physics" / "law.py", "from .deep.kernel import *\n")
    write(pkg / "physics" / "deep" / "__init__.py", "X = 3\n")
    write(pkg / "physics" / "deep" / "kernel.py", "import numpy\n")
    write(pkg / "unused.py", "Y = 4\n")
    write(tmp_path / "script.py", "import numpy\nfrom sphgag.studies import run\n")
    write(tmp_path / "bookkeeping.py", "from sphgag import threads\n")
    modules = code_inputs.Package(pkg).modules
    assert modules(tmp_path / "script.py") == [
        "engine/numbers.py",  # through threads.py, which studies/__init__.py imports
        "physics/deep/__init__.py",
        "physics/deep/kernel.py",
        "physics/law.py",  # imported inside a function
        "studies/__init__.py",
        "studies/helper.py",  # `from . import helper`: a module, not a name
        "studies/run.py",
    ]
    assert modules(tmp_path / "bookkeeping.py") == ["engine/numbers.py"]


def test_a_figure_counts_the_studies_code_it_prints(code):
    """The verification figure prints the observed order of studies/inclusion.py (observed_order)."""
    assert {"studies/inclusion.py", "views/verification.py", "views/style.py"} <= set(code["verification_pool_figure"])


def test_a_delamination_run_reads_its_simulation_and_no_reference(code):
    """``delaminate`` depends on at most 26 modules: the engine (with its integration points, engine/quadrature.py),
    the constitutive laws and the delamination protocol.
    The closed forms of the exact tubes (physics/analytic.py) are code inputs of the walls' calibration, homeostasis
    and profile verification alone (and of the site's pages), so editing them reruns no pool, swelling, delamination,
    procedure or sensitivity job."""
    assert len(code["delaminate"]) <= 26, code["delaminate"]
    walls = {"calibrate_mean", "homeostasis", "bilayer_pressure_diameter", "bilayer_table", "verify_profiles"}
    assert importers(code, "physics/analytic.py") <= walls | {"verify_profiles_wall", "docs_pages"}
    for script in ("swell", "pool_stresses", "delaminate", "delamination_map_point", "delamination_convergence"):
        assert "physics/analytic.py" not in code[script], script
    for script in ("procedure_explicit", "sensitivity_batch", "variant", "swelling_convergence", "paper_settings_run"):
        assert "physics/analytic.py" not in code[script], script


def test_the_explicit_procedure_is_an_input_of_the_procedures_jobs_only(code):
    """engine/dynamics.py (leapfrog pseudo-dynamics) runs in the explicit procedure's jobs, no other simulation's."""
    runs = importers(code, "engine/dynamics.py")
    assert "procedure_explicit" in runs and all(script.startswith("procedure_") for script in runs), runs
    assert "engine/solver.py" in code["swell"] and "engine/dynamics.py" not in code["swell"]


def test_a_module_no_script_imports_and_the_bookkeeping_are_inputs_of_nothing(code):
    counted = set().union(*code.values())
    assert "studies/fe_swelling.py" not in counted
    assert not counted & code_inputs.BOOKKEEPING
    assert code["concat_tables"] == []  # it imports the bookkeeping alone: no code input but its script


# a rule, a rule of a loop (`for ...:` then `    rule:`) or a rule derived from another (`use rule A as B with:`)
RULE = re.compile(r"^(?:use rule (\w+) as (\w+) with:|rule (\w+):|    rule:)", re.M)


def test_every_rule_that_runs_a_script_takes_the_digest_of_its_scripts_modules(code):
    """``code=code_of("<script>")`` in every rule whose script imports a module computing a number (a derived rule
    that redefines its inputs included), and no code input in the others."""
    scripts, wrong = {}, []
    for smk in sorted((ROOT / "workflow" / "rules").glob("*.smk")):
        text = smk.read_text()
        starts = [m.start() for m in RULE.finditer(text)] + [len(text)]
        for start, end in zip(starts, starts[1:]):
            block, head = text[start:end], RULE.match(text, start)
            name = head.group(2) or head.group(3) or f"{smk.name}:{start}"
            own = re.search(r"scripts/(\w+)\.py", block)
            scripts[name] = script = own.group(1) if own else scripts.get(head.group(1))
            if script is None or (head.group(1) and "input:" not in block):
                continue  # no script (the site's MkDocs), or inputs inherited with the rule
            found = re.findall(r"^\s+code=(.*),$", block, re.M)
            if found != ([f'code_of("{script}")'] if code[script] else []):
                wrong.append((name, script, found))
    assert not wrong, wrong


def dry_run_jobs(out: str) -> list[tuple[str, dict]]:
    """``(rule, {field: value})`` of every job a dry run printed (its input, output, wildcards ...)."""
    jobs = []
    for line in out.splitlines():
        if line.startswith(("rule ", "localrule ")) and line.endswith(":"):
            jobs.append((line.split()[1].rstrip(":"), {}))
        elif jobs and line.startswith("    ") and ": " in line:
            field, value = line.strip().split(": ", 1)
            jobs[-1][1][field] = value
    return jobs


# What an edit of a module reruns. A project in which every output of target `everything` exists and is up to date,
# without a job run: the outputs are made empty, all with one modification time later than every source's (Snakemake
# compares times; with no metadata, nothing else triggers a rerun). A dry run after an edit then plans the digests of
# the scripts that import the module, and what reads them.
@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    """The project and the jobs of its DAG (``dry_run_jobs``)."""
    project = project_copy(tmp_path_factory.mktemp("finished"))
    run = snakemake(project, "-n", "--forceall", "everything")
    assert run.returncode == 0, run.stderr[-3000:]
    jobs, stamp = dry_run_jobs(run.stdout), time.time()
    for rule, job in jobs:
        for name in filter(None, job.get("output", "").split(", ")):
            path = project / name
            path.parent.mkdir(parents=True, exist_ok=True)
            directory = rule == "site" or (rule.startswith("paraview_") and path.suffix != ".json")
            path.mkdir(exist_ok=True) if directory else path.touch()
            os.utime(path, (stamp, stamp))
    assert "Nothing to be done" in snakemake(project, "-n", "everything").stdout
    return project, jobs


@contextlib.contextmanager
def edited(project, module, old, new):
    """``src/sphgag/<module>`` with ``old`` replaced by ``new``, then restored with its modification time."""
    path = project / "src" / "sphgag" / module
    text, stat = path.read_text(), path.stat()
    assert old in text
    path.write_text(text.replace(old, new, 1))
    try:
        yield
    finally:
        path.write_text(text)
        os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns))


def replan(project, module, old, new):
    """``({rule: jobs}, {scripts whose digest is planned})`` of a dry run of `everything` after the edit."""
    with edited(project, module, old, new):
        run = snakemake(project, "-n", "everything")
    out = run.stdout + run.stderr
    assert run.returncode == 0, out[-3000:]
    digests = {wildcards.split("=", 1)[1] for rule, wildcards in planned(out) if rule == "package_digest"}
    return planned_jobs(out), digests


def test_every_module_is_an_input_of_the_digests_of_the_scripts_that_import_it(finished, code):
    """Each script's digest reads the modules its job imports (CODE); no other job reads a module, but the site's
    (its API pages document every module)."""
    jobs = finished[1]
    digests = {job["wildcards"].split("=", 1)[1]: job["input"] for rule, job in jobs if rule == "package_digest"}
    assert digests == {script: ", ".join(f"src/sphgag/{m}" for m in ms) for script, ms in code.items() if ms}
    readers = {rule for rule, job in jobs if rule != "package_digest" and "src/sphgag/" in job.get("input", "")}
    assert readers == {"site"}


def test_editing_a_function_a_figure_prints_redraws_it_and_reruns_no_simulation(finished, code):
    jobs, digests = replan(finished[0], "studies/inclusion.py", "def observed_order(", "# an edit\ndef observed_order(")
    assert digests == importers(code, "studies/inclusion.py")
    assert "verification_pool_figure" in jobs, jobs
    assert not SIMULATIONS & set(jobs), jobs


def test_editing_the_explicit_dynamics_reruns_only_the_rules_whose_jobs_import_it(finished, code):
    """The explicit procedure's runs and what reads them (its summary, figure, the claims and the pages); not its
    start or its equilibria, which do not import it, nor any other simulation."""
    jobs, digests = replan(finished[0], "engine/dynamics.py", '"""', '"""An edit. ')
    assert digests == importers(code, "engine/dynamics.py")
    assert {"procedure_explicit", "procedure_delaminate", "procedure_summary"} <= set(jobs), jobs
    assert not {"procedure_start", "procedure_equilibrium"} & set(jobs), jobs
    assert not SIMULATIONS & set(jobs), jobs


# every rule whose job computes an equilibrium or a pseudo-dynamic path (a simulation), the verification's and the
# explicit procedure's included
EVERY_SIMULATION = SIMULATIONS | {
    "procedure_start",
    "procedure_equilibrium",
    "procedure_explicit",
    "procedure_delaminate",
    "paper_settings_run",
    "verify_pool_ratio",
    "verify_crack_length",
    "verify_circular_pool_model",
    "verify_annulus_model",
    "verify_profiles_wall",
}


def test_editing_the_gci_reruns_no_simulation_and_editing_the_damage_law_reruns_the_delamination(finished, code):
    """studies/gci.py (the grid convergence index) is read by the resolution tables only (studies/resolution.py): its
    edit re-tabulates, and no simulation's digest changes. physics/damage.py (eq. 2.28) is a code input of every
    delamination run."""
    jobs, digests = replan(finished[0], "studies/gci.py", '"""', '"""An edit. ')
    assert digests == importers(code, "studies/gci.py")
    assert {"swelling_gci", "delamination_gci"} <= set(jobs), jobs
    assert not EVERY_SIMULATION & set(jobs), jobs
    assert {"delaminate", "delamination_convergence", "delamination_map_point"} <= importers(code, "physics/damage.py")
