"""The reduced pipeline on a real Slurm cluster, through profiles/slurm.

A one-node cluster is started for the test (as root: munged, slurmctld and slurmd with a
private slurm.conf, MUNGE key and socket in a temporary directory, free ports, no
accounting). A small target of config/ci.yaml (a simulation, a measurement and a figure: SLURM_TARGETS) then runs
through the slurm executor plugin in a copy of the project, and its tables and figure must equal those of the
session's local run of the same config byte for byte.

Skipped without Slurm and MUNGE (``apt-get install slurm-wlm munge``), without root or
without the executor plugin (``pip install -r environment.txt``).
"""

import importlib.util
import os
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd
import pytest
import yaml

from .conftest import ROOT, project_copy

pytestmark = pytest.mark.pipeline

DAEMONS = ("munged", "slurmctld", "slurmd")
CLIENTS = ("sinfo", "sbatch", "squeue", "scancel", "srun")
SUBMITTED = re.compile(r"Job (\d+) has been submitted with SLURM jobid (\d+) \(log: (.+?)\)\.?$", re.M)


def which(name):
    return shutil.which(name) or shutil.which(name, path="/usr/sbin:/usr/bin:/sbin:/bin")


def free_ports(n):
    socks = [socket.socket() for _ in range(n)]
    try:
        for s in socks:
            s.bind(("127.0.0.1", 0))
        return [s.getsockname()[1] for s in socks]
    finally:
        for s in socks:
            s.close()


def profile_partition():
    """The partition profiles/slurm submits to (its default-resources), so the test cluster provides it."""
    profile = yaml.safe_load((ROOT / "profiles" / "slurm" / "config.yaml").read_text())
    resources = profile.get("default-resources") or {}
    if isinstance(resources, list):
        resources = dict(item.split("=", 1) for item in resources)
    return str(resources.get("slurm_partition", "main")).strip("'\"")


def slurm_conf(tmp, sock, host, ports, partition):
    cpus = len(os.sched_getaffinity(0))
    memory_mb = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2**20
    return f"""\
ClusterName=sphgagtest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={ports[0]}
SlurmdPort={ports[1]}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={sock}
StateSaveLocation={tmp}/state
SlurmdSpoolDir={tmp}/spool
SlurmctldPidFile={tmp}/slurmctld.pid
SlurmdPidFile={tmp}/slurmd.pid
SlurmctldLogFile={tmp}/slurmctld.log
SlurmdLogFile={tmp}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
MinJobAge=3600
MailProg=/bin/true
NodeName={host} NodeAddr=127.0.0.1 CPUs={cpus} RealMemory={int(0.9 * memory_mb)} State=UNKNOWN
PartitionName={partition} Nodes={host} Default=YES MaxTime=INFINITE State=UP
"""


def tail(path, n=30):
    try:
        return "\n".join(Path(path).read_text(errors="replace").splitlines()[-n:])
    except OSError:
        return ""


@pytest.fixture(scope="module")
def slurm(tmp_path_factory, request):
    """A running one-node Slurm cluster; yields the environment for its client commands."""
    missing = [name for name in DAEMONS + CLIENTS if which(name) is None]
    if missing:
        pytest.skip(f"Slurm/MUNGE not installed ({', '.join(missing)} missing): apt-get install slurm-wlm munge")
    if os.geteuid() != 0:
        pytest.skip("starting slurmctld, slurmd and munged needs root")
    if importlib.util.find_spec("snakemake_executor_plugin_slurm") is None:
        pytest.skip("snakemake-executor-plugin-slurm not installed: pip install -r environment.txt")

    tmp = tmp_path_factory.mktemp("slurm")
    for d in ("state", "spool"):
        (tmp / d).mkdir()
    host = socket.gethostname().split(".")[0]
    # munged wants every directory above its socket searchable by all (pytest's are 0700)
    sock_dir = Path(tempfile.mkdtemp(prefix="sphgag-munge-"))
    sock_dir.chmod(0o755)
    sock = sock_dir / "munge.socket"
    conf = tmp / "slurm.conf"
    conf.write_text(slurm_conf(tmp, sock, host, free_ports(2), profile_partition()))
    # the job step plugin drops every SLURM_* variable before its srun (a real cluster has /etc/slurm/slurm.conf):
    # an srun first on the jobs' PATH brings SLURM_CONF back
    bin_dir = tmp / "bin"
    bin_dir.mkdir()
    (bin_dir / "srun").write_text(f'#!/bin/sh\nSLURM_CONF="{conf}" exec {which("srun")} "$@"\n')
    (bin_dir / "srun").chmod(0o755)
    env = dict(os.environ, SLURM_CONF=str(conf), PATH=f"{bin_dir}{os.pathsep}{os.environ['PATH']}")
    procs = []

    def stop():
        """Cancel what is left of the test's jobs, then stop the daemons it started, by pid."""
        if any(p.args[0] == which("slurmctld") and p.poll() is None for p in procs):
            jobs = subprocess.run([which("squeue"), "-h", "-o", "%i"], env=env, capture_output=True, text=True)
            ids = jobs.stdout.split()
            if ids:
                subprocess.run([which("scancel"), *ids], env=env, capture_output=True)
                deadline = time.time() + 30
                while time.time() < deadline:
                    active = subprocess.run(
                        [which("squeue"), "-h", "-t", "PD,R,CG", "-o", "%i"], env=env, capture_output=True, text=True
                    ).stdout.split()
                    if not active:
                        break
                    time.sleep(1)
        for p in reversed(procs):
            if p.poll() is None:
                p.terminate()
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
        shutil.rmtree(sock_dir, ignore_errors=True)

    request.addfinalizer(stop)

    def start(name, *args):
        log = open(tmp / f"{name}.out", "w")
        procs.append(
            subprocess.Popen(
                [which(name), *args], env=env, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL
            )
        )
        log.close()

    key = tmp / "munge.key"
    key.write_bytes(os.urandom(1024))
    key.chmod(0o600)
    start(
        "munged",
        "--foreground",
        f"--key-file={key}",
        f"--socket={sock}",
        f"--pid-file={tmp}/munged.pid",
        f"--log-file={tmp}/munged.log",
        f"--seed-file={tmp}/munged.seed",
    )
    wait_for(sock.exists, 20, "munged", tmp / "munged.out", procs)
    start("slurmctld", "-D", "-f", str(conf))
    start("slurmd", "-D", "-f", str(conf))

    def node_idle():
        run = subprocess.run([which("sinfo"), "-h", "-N", "-o", "%T"], env=env, capture_output=True, text=True)
        return run.returncode == 0 and run.stdout.split() == ["idle"]

    wait_for(node_idle, 60, "the node to be idle", tmp / "slurmctld.out", procs)
    yield env


def wait_for(condition, seconds, what, log, procs):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if condition():
            return
        if any(p.poll() is not None for p in procs):
            break
        time.sleep(0.5)
    pytest.fail(f"waiting for {what} failed:\n{tail(log)}")


# five jobs: the homeostatic wall and its pressurised state (simulations), one pool swollen (a simulation) and
# measured (a measurement), and figure 1 (a figure)
SLURM_TARGETS = ["results/swelling/runs/conserved/particles/passive_I_103mmHg.csv", "figures/fig1.png"]


def snakemake_cmd(*args):
    return [sys.executable, "-m", "snakemake", *SLURM_TARGETS, "--configfile", "config/ci.yaml", *args]


def differences(a, b):
    """The columns in which two CSV tables differ (for the failure message of a byte comparison)."""
    ta, tb = pd.read_csv(a), pd.read_csv(b)
    if list(ta.columns) != list(tb.columns) or ta.shape != tb.shape:
        return f"columns or shape differ: {list(ta.columns)} {ta.shape} vs {list(tb.columns)} {tb.shape}"
    return f"columns differ: {[c for c in ta.columns if not ta[c].astype(str).equals(tb[c].astype(str))]}"


@pytest.fixture(scope="module")
def runs(slurm, workdir, tmp_path_factory):
    """A small target of the CI configuration run through Slurm in its own copy of the project, beside the session's
    local run of it (``workdir``, tests/conftest.py)."""
    cluster = project_copy(tmp_path_factory.mktemp("cluster"))
    t0 = time.time()
    # first status check 2 s after a submission and then every 2 s (the defaults, 40 s and 10 s, suit a busy cluster,
    # not a test whose jobs take seconds)
    run_cluster = subprocess.run(
        snakemake_cmd(
            "--profile",
            "profiles/slurm",
            "--slurm-keep-successful-logs",
            "--slurm-init-seconds-before-status-checks",
            "2",
            "--seconds-between-status-checks",
            "2",
        ),
        cwd=cluster,
        env=slurm,
        capture_output=True,
        text=True,
        timeout=900,  # five jobs of seconds each, and Slurm's round trip of a few seconds per job
    )
    print(f"\nSlurm run {time.time() - t0:.0f} s")
    assert run_cluster.returncode == 0, run_cluster.stdout[-3000:] + run_cluster.stderr[-5000:]
    return workdir, cluster, run_cluster


def test_the_jobs_ran_as_slurm_jobs(runs, slurm):
    _, cluster, run = runs
    out = run.stdout + run.stderr
    submitted = SUBMITTED.findall(out)
    steps = re.findall(r"(\d+) of (\d+) steps \(100%\) done", out)
    assert steps, out[-2000:]
    # every job went to Slurm but the code digests (rule package_digest, one per script: a local rule); the targets
    # are files, so no target rule runs in Snakemake itself
    digests = len(re.findall(r"^(?:local)?rule package_digest:", out, re.M))
    assert digests == 5, out[-3000:]
    assert len({slurm_id for _, slurm_id, _ in submitted}) == int(steps[-1][1]) - digests == 5
    states = subprocess.run(
        ["squeue", "-h", "--states=all", "-o", "%i|%T"], env=slurm, capture_output=True, text=True
    ).stdout
    state = dict(line.split("|") for line in states.split())
    for _, slurm_id, log in submitted:
        assert state.get(slurm_id) == "COMPLETED", (slurm_id, states)
        # the job's own log (kept by --slurm-keep-successful-logs): Snakemake ran the rule inside the allocation
        assert re.search(r"Finished jobid: \d+ \(Rule: \w+\)", (cluster / log).read_text()), log


def test_slurm_and_local_runs_give_the_same_tables(runs):
    """Same config, same bytes: every result table and the figure of the Slurm run equal the local run's byte for
    byte."""
    local, cluster, _ = runs
    names = sorted(p.relative_to(cluster).as_posix() for p in (cluster / "results").rglob("*.csv"))
    assert len(names) >= 5 and set(SLURM_TARGETS) <= set(names) | {"figures/fig1.png"}
    assert (cluster / "figures/fig1.png").read_bytes() == (local / "figures/fig1.png").read_bytes()
    failures = [
        f"{name}: {differences(local / name, cluster / name)}"
        for name in names
        if (local / name).read_bytes() != (cluster / name).read_bytes()
    ]
    print(f"\n{len(names) - len(failures)} of {len(names)} result tables byte-identical")
    assert not failures, failures
