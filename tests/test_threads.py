"""A job uses the threads its rule declares: Numba's and every BLAS pool's (sphgag.threads)."""

import ast
import json
import os
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

from sphgag import jobs

from .conftest import ROOT

# the BLAS pools of NumPy and SciPy, Numba's parallel kernels (forces._stresses is parallel) and what threads.in_use
# reports, in a fresh interpreter without the environment variables Snakemake sets for its jobs
PROBE = """
import json, sys
import numpy as np
{before}
import numba, scipy.linalg, scipy.sparse.linalg
from sphgag import threads
from sphgag.engine import forces
{after}
numba.njit(lambda a: a + 1)(1)  # a compilation after the limit: Numba rereads its configuration
found = threads.in_use()
print(json.dumps(found))
"""


def probe(before: str = "", after: str = "") -> dict:
    env = {k: v for k, v in os.environ.items() if not k.endswith("_NUM_THREADS") and k != "VECLIB_MAXIMUM_THREADS"}
    env["PYTHONPATH"] = str(ROOT / "src")
    out = subprocess.run(
        [sys.executable, "-c", PROBE.format(before=before, after=after)],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


@pytest.mark.skipif(len(os.sched_getaffinity(0)) < 2, reason="needs two cores to see a default of more than one thread")
def test_without_a_limit_the_libraries_take_every_core():
    found = probe()
    assert found["numba"] > 1 and max(v for k, v in found.items() if k != "numba") > 1, found


@pytest.mark.parametrize("where", ["after the libraries loaded", "before they loaded"])
def test_use_limits_numba_and_every_blas_pool(where):
    call = "from sphgag import threads as t; t.use(1)"
    found = probe(**({"after": call} if where.startswith("after") else {"before": call}))
    assert found.pop("numba") == 1
    assert found and set(found.values()) == {1}, found  # NumPy's and SciPy's OpenBLAS


def test_every_workflow_script_enters_its_job_before_any_work():
    """Each script's first statement after its docstring and imports is ``with jobs.run(snakemake...)``, which sets the
    rule's threads (:func:`sphgag.jobs.run`: :func:`sphgag.threads.use`) before the work of the job."""
    missing = []
    for path in sorted((ROOT / "workflow" / "scripts").glob("*.py")):
        body = [n for n in ast.parse(path.read_text()).body if not isinstance(n, ast.Import | ast.ImportFrom)]
        body = body[1:] if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) else body
        first = body[0] if body else None
        enters = isinstance(first, ast.With) and ast.unparse(first.items[0].context_expr).startswith(
            "jobs.run(snakemake"
        )
        if not enters:
            missing.append(Path(path).name)
    assert not missing, missing


def test_a_job_uses_the_threads_its_rule_declares(tmp_path, monkeypatch):
    """:func:`sphgag.jobs.run` limits the job to its rule's threads before it yields (whatever the environment said)."""
    monkeypatch.setenv("OMP_NUM_THREADS", "7")
    sm = SimpleNamespace(threads=1, rule="fig1", wildcards={}, log=[str(tmp_path / "fig1.log")])
    with jobs.run(sm, name="fig1"):
        assert os.environ["OMP_NUM_THREADS"] == "1"
