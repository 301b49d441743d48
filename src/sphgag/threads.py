"""The threads a computation uses: Numba's parallel kernels and the BLAS/LAPACK pools of NumPy and SciPy (OpenBLAS).

A pipeline job uses the threads its rule declares (``threads:``, Snakemake's ``snakemake.threads``), and nothing
more: with ``--cores 2`` Snakemake runs two one-thread jobs at once, and a job that starts a BLAS pool of its own per
core (OpenBLAS's default) competes with the other job for the same cores, its idle threads spinning while they wait.
Every workflow script therefore calls :func:`use` first, and so does every entry point of the package and of
``benchmarks/`` (one thread unless told otherwise).

:func:`use` limits the libraries already loaded (:mod:`threadpoolctl` for BLAS, ``numba.set_num_threads`` for
Numba) and sets the environment variables that the ones loaded later (and child processes) read when they start.
"""

from __future__ import annotations

import os
import sys

import threadpoolctl

# read by OpenBLAS, MKL, OpenMP runtimes, Accelerate and numexpr when they load (the list Snakemake sets for shell jobs)
ENVIRONMENT = (
    "OMP_NUM_THREADS",
    "OPENBLAS_NUM_THREADS",
    "GOTO_NUM_THREADS",
    "MKL_NUM_THREADS",
    "VECLIB_MAXIMUM_THREADS",
    "NUMEXPR_NUM_THREADS",
)


def use(threads: int) -> int:
    """Let this process compute on ``threads`` threads (at least 1): Numba's parallel kernels and every BLAS pool,
    loaded now or later. Returns the number of threads."""
    n = max(1, int(threads))
    for name in ENVIRONMENT:
        os.environ[name] = str(n)
    if "numba" not in sys.modules:  # the size of its pool, read at import (Numba rereads it: never change it after)
        os.environ["NUMBA_NUM_THREADS"] = str(n)
    else:  # its active threads can still be lowered
        import numba

        numba.set_num_threads(min(n, numba.config.NUMBA_NUM_THREADS))  # starts its threading layer (OpenMP, say)
    threadpoolctl.threadpool_limits(limits=n)  # after Numba's: its OpenMP runtime is one of the pools
    return n


def in_use() -> dict:
    """The threads each loaded library would use now: ``numba`` and one entry per BLAS/OpenMP pool (by its file)."""
    found = {os.path.basename(p["filepath"]): p["num_threads"] for p in threadpoolctl.threadpool_info()}
    if "numba" in sys.modules:
        import numba

        found["numba"] = numba.get_num_threads()
    return found
