"""Scaling of the quasi-static solver with the number of particles (bi-layered passive wall).

For each particle spacing (default 5, 3, 2 and 1.5 um: about 1.9k, 4.9k, 11k and 19k
particles) a fresh process builds the homeostatic state, pressurises it to 103 mmHg
under pressure control and measures, on one core:

* one force evaluation (forces and stresses with the lumen pressure), median;
* one Jacobian assembly, one sparse LU factorisation and one LU solve;
* the converged state after a small load step (+1 mmHg, median of three successive
  steps) and after converting one medial particle to GAG (conversion 0 -> 1 at
  c = 0, one increment, median of three), each starting as a run would, with the
  factorisation of the previous state, and solved as configured
  (``numerics.reuse_factorisation``) and with fresh Newton steps only; and after a
  particle whose damage has reached D = 1 ((1 - D) W = 0, section 2.7) becomes GAG,
  the conversion of delamination;
* the process's peak memory.

Prints a table and writes benchmarks/out/solver.json (a list of rows).

    python benchmarks/bench_solver.py [--dx 5 3 2 1.5]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from sphgag import threads
from sphgag.engine.numerics import Numerics

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))


def median_time(fn, repeats):
    fn()
    samples = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        samples.append(time.perf_counter() - t)
    return float(np.median(samples))


def measure(dx: float, config_path: str) -> dict:
    import scipy.sparse.linalg as spla

    from sphgag import config
    from sphgag.engine import geometry, solver
    from sphgag.engine.history import HistoryMaterial, swelling_load
    from sphgag.engine.loading import MMHG_TO_KPA, Load
    from sphgag.engine.model import Model
    from sphgag.physics import materials
    from sphgag.studies import artery
    from sphgag.studies.wall_loading import homeostasis, pressurise

    threads.use(1)
    cfg = config.validate(config.load_yaml(config_path), ROOT / "config" / "schema.yaml")
    cfg["gag"] = materials.law_gag(cfg["gag"], "conserved")  # the charge law of the measured states
    p, numerics = dict(cfg["bilayer"], dx_um=dx), Numerics.of(cfg["numerics"])
    wall = artery.bilayer_model(p, numerics, name=f"bench_dx{dx:g}")
    # a pool of one medial particle: the particle nearest (663 um, 51.5 deg)
    lay = wall.layout
    k = int(np.argmin(np.hypot(lay.radius - 663.0, np.deg2rad(51.5) - lay.theta)))
    one = geometry.Sector(lay.radius[k], np.rad2deg(lay.theta[k]), 0.1 * dx, 0.1 * np.rad2deg(dx / lay.radius[k]))
    model = artery.bilayer_model(p, numerics, name=f"bench_dx{dx:g}", pool=one, gag=cfg["gag"])
    assert model.props.converting.size == 1
    h = homeostasis(model, numerics, cfg["homeostasis"])
    start = pressurise(model, h.state, 103.0, numerics)
    load, x = start.load, start.x
    ev = model.evaluate(x, load)
    row = dict(particles=model.n, dx_um=dx, dof=2 * model.n)
    row["force_evaluation_ms"] = 1e3 * median_time(lambda: model.evaluate(x, load), 50)
    row["jacobian_ms"] = 1e3 * median_time(lambda: model.jacobian(ev), 5)
    data = model.jacobian(ev)
    A = model.block_matrix(data).tocsc()
    row["nonzeros"] = int(A.nnz)
    row["bandwidth"] = model.band[0]
    row["factorisation_ms"] = 1e3 * median_time(lambda: solver.lu_solver(model, data), 3)
    solve = solver.lu_solver(model, data)
    rhs = np.ones(A.shape[0])
    row["solve_ms"] = 1e3 * median_time(lambda: solve(rhs), 10)
    row["superlu_factorisation_ms"] = 1e3 * median_time(lambda: spla.splu(A, permc_spec="NATURAL"), 3)

    def factorised_at_start(path_solver):
        """The solver as a run leaves it at the start state: with the LU of the Jacobian there."""
        path_solver.cache.keep(solver.factorise(model, ev, model.jacobian(ev), 0.0, model.name))

    for label, reuse in (("", numerics.reuse_factorisation), ("_fresh_newton", False)):
        path_solver = numerics.solver(model).using(reuse=reuse)
        factorised_at_start(path_solver)
        times, xs, current = [], x, load
        for _ in range(3):
            target = Load(1.0, current.pressure_kPa + MMHG_TO_KPA, material=current.material)
            t = time.perf_counter()
            xs, _, conv = path_solver.newton(xs, target)
            times.append(time.perf_counter() - t)
            current = target
        row[f"state_after_load_step_ms{label}"] = 1e3 * float(np.median(times))
        converted = swelling_load(load, 1.0, 0.0)
        times = []
        for _ in range(3):
            factorised_at_start(path_solver)
            t = time.perf_counter()
            path_solver.newton(x, converted)
            times.append(time.perf_counter() - t)
        row[f"state_after_conversion_ms{label}"] = 1e3 * float(np.median(times))
        # the conversion of delamination: a particle whose damage has reached D = 1 ((1 - D) W = 0) becomes GAG
        one, intact = model.props.converting, model.props.before
        damaged = intact.with_damage(np.isin(np.arange(model.n), one).astype(float), intact.onset_stretch)
        ruptured = HistoryMaterial(model.props.base, damaged, cfg["gag"])
        gag = HistoryMaterial(model.props.base, damaged.rupture(one, np.zeros(one.size, dtype=int), 1), cfg["gag"])
        fixed = Model(model.name, model.layout, model.nb, ruptured, model.hourglass_alpha)
        fixed_solver = solver.Solver(fixed, path_solver.options)
        xd, evd, _ = fixed_solver.newton(x, load)
        times = []
        for _ in range(3):
            fixed.set_props(ruptured)
            fixed_solver.cache.keep(solver.factorise(fixed, evd, fixed.jacobian(evd), 0.0, model.name))
            fixed.set_props(gag)
            t = time.perf_counter()
            fixed_solver.newton(xd, load)
            times.append(time.perf_counter() - t)
        row[f"state_after_ruptured_conversion_ms{label}"] = 1e3 * float(np.median(times))
    row["peak_memory_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--dx", type=float, nargs="+", default=[5.0, 3.0, 2.0, 1.5])
    ap.add_argument("--one", type=float, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.one is not None:
        print(json.dumps(measure(args.one, args.config)))
        return
    rows = []
    for dx in args.dx:  # one process per size: its peak memory is its own
        out = subprocess.run(
            [sys.executable, __file__, "--config", args.config, "--one", str(dx)],
            capture_output=True,
            text=True,
            check=True,
        )
        rows.append(json.loads(out.stdout.strip().splitlines()[-1]))
        r = rows[-1]
        print(
            f"{r['particles']:>6} particles: force {r['force_evaluation_ms']:.2f} ms, Jacobian "
            f"{r['jacobian_ms']:.1f} ms, LU {r['factorisation_ms']:.0f} ms, solve {r['solve_ms']:.1f} ms, "
            f"state after +1 mmHg {r['state_after_load_step_ms']:.0f} ms "
            f"(fresh Newton {r['state_after_load_step_ms_fresh_newton']:.0f}), after one conversion "
            f"{r['state_after_conversion_ms']:.0f} ms (fresh {r['state_after_conversion_ms_fresh_newton']:.0f}), "
            f"after a ruptured particle becomes GAG {r['state_after_ruptured_conversion_ms']:.0f} ms "
            f"(fresh {r['state_after_ruptured_conversion_ms_fresh_newton']:.0f}), "
            f"peak {r['peak_memory_mb']:.0f} MB",
            flush=True,
        )
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    (dest / "solver.json").write_text(json.dumps(rows, indent=1) + "\n")


if __name__ == "__main__":
    main()
