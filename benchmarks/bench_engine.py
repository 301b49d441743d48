"""Speed of the sphgag engine at the full configuration's resolution.

Prints: time per force evaluation (median of many, one core), time per Jacobian
assembly and sparse LU factorisation, force evaluations and Newton iterations
per converged state of the calibration protocol, and the wall time of the
``calibrate_mean`` rule run by Snakemake in a scratch directory.

    python benchmarks/bench_engine.py [--config config/config.yaml] [--no-rule]

Results are also written to benchmarks/out/engine.json. Timings depend on the
machine: compare runs on the same one.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd
import scipy.sparse.linalg as spla

from sphgag import threads
from sphgag.engine.numerics import Numerics

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config  # noqa: E402
from sphgag.engine import forces  # noqa: E402
from sphgag.engine.loading import MMHG_TO_KPA, Load  # noqa: E402
from sphgag.studies import artery  # noqa: E402
from sphgag.studies.pressure_diameter import mean_pressure_diameter, mean_thick_wall  # noqa: E402


def median_time(fn, repeats, inner):
    fn()
    samples = []
    for _ in range(repeats):
        t = time.perf_counter()
        for _ in range(inner):
            fn()
        samples.append((time.perf_counter() - t) / inner)
    return float(np.median(samples))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--no-rule", action="store_true", help="skip timing the Snakemake rule")
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    p, numerics = cfg["mean"], Numerics.of(cfg["numerics"])
    model = artery.mean_model(p, numerics, name="bench")
    out = {
        "particles": model.n,
        "neighbour_entries": model.nb.n_entries,
        "kernel_support_factor": numerics.kernel_support_factor,
    }

    # a representative pressurised state: 103 mmHg
    lz = p["axial_stretch"]
    load = Load(lz, 103 * MMHG_TO_KPA)
    states = numerics.solver(model).follow_path(model.layout.X, Load(1.0, 0.0), [Load(lz, 0.0), load])
    x = states[-1].x
    props, _, pairs = model.material(load)
    n = model.n
    FP, f = np.empty((n, 12)), np.empty((n, 2))

    def kernel_call():
        forces.evaluate_forces(x, pairs, lz, model.cth, model.sth, props, model._xe, model._fe, FP, f)

    out["force_evaluation_ms"] = 1e3 * median_time(kernel_call, 15, 200)
    out["force_evaluation_ms_per_1400_particles"] = out["force_evaluation_ms"] * 1400 / n
    out["evaluate_with_pressure_ms"] = 1e3 * median_time(lambda: model.evaluate(x, load), 15, 100)
    ev = model.evaluate(x, load)
    out["jacobian_assembly_ms"] = 1e3 * median_time(lambda: model.jacobian(ev), 5, 5)
    A = model.block_matrix(model.jacobian(ev)).tocsc()
    out["sparse_lu_ms"] = 1e3 * median_time(lambda: spla.splu(A, permc_spec="NATURAL"), 5, 2)
    out["jacobian_nonzeros"] = int(A.nnz)

    t = time.perf_counter()
    res = mean_pressure_diameter(model, mean_thick_wall(p), p, numerics, cfg["calibration"])
    out["calibration_protocol_s"] = time.perf_counter() - t
    s = res.states
    out["converged_states"] = int(len(s))
    out["force_evaluations_per_state"] = float(s.force_evaluations.mean())
    out["newton_iterations_per_state"] = float(s.newton_iterations.mean())
    out["max_od_rel_error_10_200_mmHg"] = res.max_od_error(10.0)

    if not args.no_rule:
        with tempfile.TemporaryDirectory() as wd:
            t = time.perf_counter()
            run = subprocess.run(
                [
                    sys.executable,
                    "-m",
                    "snakemake",
                    "-s",
                    str(ROOT / "Snakefile"),
                    "--directory",
                    wd,
                    "--configfile",
                    args.config,
                    "--cores",
                    "1",
                    "calibrate_mean",
                ],
                capture_output=True,
                text=True,
            )
            out["calibration_rule_wall_s"] = time.perf_counter() - t
            if run.returncode:
                print(run.stderr[-2000:], file=sys.stderr)
                raise SystemExit("calibrate_mean failed")
            bench = pd.read_csv(Path(wd) / "results/benchmarks/calibrate_mean.tsv", sep="\t")
            out["calibration_rule_job_s"] = float(bench["s"].iloc[0])

    width = max(map(len, out))
    for k, v in out.items():
        print(f"{k:<{width}}  {v:.4g}" if isinstance(v, float) else f"{k:<{width}}  {v}")
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    (dest / "engine.json").write_text(json.dumps(out, indent=2) + "\n")


if __name__ == "__main__":
    main()
