"""Shared fixtures: small layouts and models that compile and solve in seconds."""

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import pytest

from sphgag import config, threads
from sphgag.engine import geometry, kernel
from sphgag.engine.model import Model
from sphgag.engine.numerics import Numerics
from sphgag.physics import materials
from sphgag.studies import artery
from sphgag.studies.wall_loading import pressurised_wall
from sphgag.views import overlap

ROOT = Path(__file__).resolve().parents[1]
#: the CI configuration's numerics as the package takes them (the fixture ``ci_config`` holds the section's mapping)
CI_NUMERICS = Numerics.of(config.load_yaml(ROOT / "config" / "ci.yaml")["numerics"])


def project_copy(dest):
    """The project's files (git-tracked, and new files git does not ignore) in ``dest``, without results."""
    files = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    if files.returncode == 0:
        for name in filter(None, files.stdout.split("\0")):
            src = ROOT / name
            if src.is_file():
                (dest / name).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(src, dest / name)
    else:  # not a git checkout
        shutil.copytree(
            ROOT,
            dest,
            dirs_exist_ok=True,
            ignore=shutil.ignore_patterns(
                ".git", ".snakemake", "results", "logs", "figures", "__pycache__", "*.egg-info", ".pytest_cache"
            ),
        )
    return dest


def law_gag(cfg: dict, law: str = "conserved") -> dict:
    """The ``gag`` parameters of one run of ``cfg`` under one charge law (what the pipeline passes a run)."""
    return materials.law_gag(cfg["gag"], law)


def snakemake(project, *args, configfile="config/ci.yaml", env=None):
    """``snakemake *args --configfile X --cores 2`` run in ``project`` (a copy of the project root), as a user
    does; ``configfile=None`` gives no ``--configfile``."""
    cmd = [sys.executable, "-m", "snakemake", *args, "--cores", "2"]
    cmd += ["--configfile", str(configfile)] if configfile is not None else []
    return subprocess.run(cmd, cwd=project, capture_output=True, text=True, env=dict(os.environ, **(env or {})))


class _Pipeline:
    """The CI configuration's run of target ``everything`` in a copy of the project, from a cold Numba cache: started
    in the background as soon as the tests are collected (when a test needs it), so that it computes on the cores the
    unit tests leave idle; the tests that read it run last (:func:`pytest_collection_modifyitems`)."""

    def __init__(self):
        self.root = Path(tempfile.mkdtemp(prefix="sphgag-pipeline-"))
        self.cache = self.root / "numba_cache"
        self.project = project_copy(self.root / "project")
        self.log = (self.root / "snakemake.log").open("w")
        cmd = [sys.executable, "-m", "snakemake", "everything", "--cores", "2", "--configfile", "config/ci.yaml"]
        # every figure the run saves records its text overlaps here (sphgag.views.overlap.record)
        self.text_checks = self.root / "text_checks"
        env = dict(os.environ, NUMBA_CACHE_DIR=str(self.cache), **{overlap.CHECK_DIR: str(self.text_checks)})
        self.process = subprocess.Popen(cmd, cwd=self.project, stdout=self.log, stderr=subprocess.STDOUT, env=env)

    def wait(self) -> Path:
        code = self.process.wait()
        self.log.close()
        assert code == 0, (self.root / "snakemake.log").read_text()[-6000:]
        return self.project

    def remove(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        shutil.rmtree(self.root, ignore_errors=True)


_PIPELINE: list[_Pipeline] = []


def pytest_collection_modifyitems(session, config, items):
    """Start the pipeline run if a collected test reads it, and run those tests last (in their collected order)."""
    if config.option.collectonly:
        return
    reads = [item for item in items if "workdir" in getattr(item, "fixturenames", ())]
    if reads:
        _PIPELINE.append(_Pipeline())
        items[:] = [item for item in items if item not in reads] + reads
        # the run takes both cores: the tests compute on one thread meanwhile, so that no BLAS or Numba pool of this
        # process spins on a core the run holds (oversubscribed, the LU-heavy tests ran ten times slower)
        threads.use(1)


def pytest_sessionfinish(session, exitstatus):
    for run in _PIPELINE:
        run.remove()


@pytest.fixture(scope="session")
def numba_cache():
    """The Numba cache the pipeline run compiled into (empty when it started: as on a fresh machine)."""
    return _PIPELINE[0].cache


@pytest.fixture(scope="session")
def text_checks(workdir):
    """The folder in which every figure of the pipeline run recorded its text overlaps (one JSON file a figure)."""
    return _PIPELINE[0].text_checks


@pytest.fixture(scope="session")
def workdir():
    """A copy of the project root in which the CI configuration ran to the end (target ``everything``: every job it
    defines), from a cold Numba cache (one run for the session, started at collection: tests/test_pipeline.py reads
    and reruns it, tests/test_slurm.py compares the Slurm run with it)."""
    return _PIPELINE[0].wait()


@pytest.fixture(scope="session")
def full_config():
    return config.load_yaml(ROOT / "config" / "config.yaml")


@pytest.fixture(scope="session")
def ci_config():
    return config.load_yaml(ROOT / "config" / "ci.yaml")


@pytest.fixture(scope="session")
def ci_wall(ci_config):
    """The passive CI wall pressurised to the delamination pressure (a state to seed pools in)."""
    return pressurised_wall(
        ci_config["bilayer"],
        CI_NUMERICS,
        ci_config["homeostasis"],
        ci_config["delamination"]["pressure_mmHg"],
        "test-wall",
    )[1]


@pytest.fixture(scope="session")
def mean_params(ci_config):
    return ci_config["mean"]


@pytest.fixture(scope="session")
def coarse_mean_model(ci_config):
    """Mean-behaviour model at the CI resolution (dx = 14 um)."""
    return artery.mean_model(ci_config["mean"], CI_NUMERICS, name="test-mean")


@pytest.fixture(scope="session")
def printed_mean_model(ci_config):
    """The same model with eq. (2.14) as printed (``numerics.hourglass: paper``): the tests of the directed pair
    formula compare the kernel with it entry by entry."""
    numerics = Numerics.of(dict(ci_config["numerics"], hourglass="paper"))
    return artery.mean_model(ci_config["mean"], numerics, name="test-mean-printed")


def lattice(n=14, spacing=1.0):
    """A free square patch of particles on a uniform lattice (for patch tests)."""
    g = np.arange(n) * spacing
    X, Y = np.meshgrid(g, g, indexing="ij")
    return np.column_stack([X.ravel(), Y.ravel()]), np.full(n * n, spacing * spacing)


class Lattice:
    """Minimal layout-like object for a free lattice patch."""

    def __init__(self, n=14, spacing=1.0):
        self.X, self.volume = lattice(n, spacing)
        self.theta = np.zeros(len(self.volume))
        self.dx = spacing
        self.n = len(self.volume)
        self.inner_surface = np.empty(0, dtype=np.int64)
        self.outer_radius = float(np.abs(self.X).max())


def isotropic_props(n, mu=10.0, lam=100.0, hourglass_modulus=10.0):
    p = materials.empty_props(n)
    p[:, materials.MU] = mu
    p[:, materials.LAM] = lam
    p[:, materials.HG_E] = hourglass_modulus
    return p


@pytest.fixture
def free_lattice_model():
    """Isotropic neo-Hookean lattice patch without symmetry planes (free body)."""
    lay = Lattice()
    nb = kernel.build_neighbours(lay.X, lay.volume, 2.5 * lay.dx, mirrors=())
    return Model("lattice", lay, nb, isotropic_props(lay.n), hourglass_alpha=50.0)


@pytest.fixture(scope="session")
def annulus_layout():
    return geometry.quarter_annulus([332.0, 444.0], 14.0)


def assert_jacobian_matches_fd(model, load, x, cols, eps=1e-6, rel=1e-6):
    """The exact Jacobian ``d(f_int + f_ext)/dx`` equals central differences in the columns ``cols``."""
    J = model.block_matrix(model.jacobian(model.evaluate(x, load))).toarray()
    for k in cols:
        xp, xm = x.copy().ravel(), x.copy().ravel()
        xp[k] += eps
        xm[k] -= eps
        ep, em = model.evaluate(xp.reshape(-1, 2), load), model.evaluate(xm.reshape(-1, 2), load)
        fd = ((ep.f_int + ep.f_ext) - (em.f_int + em.f_ext)).ravel() / (2 * eps)
        assert np.abs(fd - J[:, k]).max() <= rel * np.abs(fd).max()


def direct_pair_sum(model, x, load):
    """Eqs. (2.11) and (2.14) summed entry by entry (directed, with mirror images): the reference for the fused
    half-list kernel. The hourglass term uses F~ (the hourglass stencil's F, equal to F without an interface)."""
    nb = model.nb
    ev = model.evaluate(x, load)
    _, hgc, _ = model.material(load)
    V = model.layout.volume
    f = np.zeros_like(x)
    owner = np.repeat(np.arange(model.n), nb.counts())
    for e in range(nb.n_entries):
        i, j, M = owner[e], nb.nbr[e], nb.mirror[e]
        r = M * x[j] - x[i]
        n = r / np.linalg.norm(r)
        delta = (ev.F_hourglass[i] @ nb.R[e] - r) @ n
        t = V[i] * ev.P[i] @ nb.a[e] - hgc[e] * delta * n
        f[i] += t
        f[j] -= M * t
    return f, ev.f_int
