"""The pressure-volume path of an artery's pool modelled as a cavity, traced with its volume as the control, at
several spacings: does the concentration that holds a given pool volume converge, and is there a limit point?

Figure 4's protocol for one pool (passive wall at 103 mmHg, the paper's Donnan law Pi(c), eqs. 2.25-2.27): the pool
is converted, becomes a cavity (``swelling.pool_models: cavity``, :mod:`sphgag.engine.pool_cavity`) and is swollen to
``--start`` mEq/l under concentration control; from there its volume is the control
(:func:`sphgag.engine.pool_volume.continue_path`, 5 % per step) up to ``--max-ratio`` times its reference volume or a
limit point. Each converged state gives the concentration, the pool's volume ratio and the stresses of figure 4
(:func:`sphgag.studies.protocols.pool_measurements`). Writes ``benchmarks/out/cavity_path_<case>.csv``.

    python benchmarks/cavity_path.py --dx 4 3 2.5 2 --case I
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config, threads  # noqa: E402
from sphgag.engine import pool_volume, solver  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.physics import materials  # noqa: E402
from sphgag.studies import artery, convergence, protocols  # noqa: E402


def trace(cfg: dict, dx: float, case: str, start: float, max_ratio: float) -> pd.DataFrame:
    numerics, sw = cfg["numerics"], dict(cfg["swelling"], pool_model="cavity")
    alpha = numerics["hourglass_alpha"]
    gag = materials.law_gag(cfg["gag"], "prescribed")
    entry = sw["cases"][case]
    steps = protocols.concentration_steps(dict(sw))
    ramp = dict(sw, max_concentration_mEq_l=start, concentration_points=int(np.sum(steps <= start + 1e-9)) + 1)
    t0 = time.time()
    states = convergence.swell_cases(
        dx, cfg["bilayer"], numerics, cfg["homeostasis"], ramp, gag, {case: entry}, 103.0, cfg["bilayer_calibration"]
    )
    last = states[case][-1]
    if last.path_end != "complete":
        print(f"dx = {dx:g} um: the swelling path ends at c = {last.concentration:g} mEq/l ({last.end_reason})")
        return pd.DataFrame()
    model = convergence.case_model(dx, cfg["bilayer"], numerics, gag, entry, f"cavity_path_dx{dx:g}")
    hollow = protocols.state_model(model, True, last.x)
    path_solver = solver.Solver(hollow, Numerics.of(numerics).solver_options().newton_budget())
    path, _ = pool_volume.continue_path(
        path_solver, solver.State(last.load, last.x, None, None), hollow.props.converting, [1e9], max_ratio=max_ratio
    )
    pool = artery.pool_sector(entry)
    rows = []
    for s in path.states:
        ev = hollow.evaluate(s.x, s.load)
        row = dict(
            dx_um=dx, particles=model.n, case=case, concentration_mEq_l=s.concentration, residual=s.convergence.residual
        )
        row.update(protocols.pool_measurements(hollow, ev, pool, hollow.props.converting, sw["probe_length_um"]))
        rows.append(row)
    table = pd.DataFrame(rows).assign(
        alpha=alpha, path_end=path.end, limit_mEq_l=path.limit_concentration, seconds=time.time() - t0
    )
    print(
        f"dx = {dx:g} um: {len(rows)} states, J up to {table.pool_volume_change.max() + 1:.3g}, end {path.end} "
        f"({path.reason}), {time.time() - t0:.0f} s",
        flush=True,
    )
    return table


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--dx", type=float, nargs="+", default=[4.0, 3.0, 2.5, 2.0])
    ap.add_argument("--case", default="I")
    ap.add_argument("--start", type=float, default=75.0, help="concentration [mEq/l] where volume control starts")
    ap.add_argument("--max-ratio", type=float, default=150.0, help="largest pool volume ratio traced")
    ap.add_argument("--alpha", type=float, default=None, help="alpha of eq. (2.14) (default the configuration's)")
    ap.add_argument("--tag", default="", help="suffix of the output file")
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    if args.alpha is not None:
        cfg["numerics"]["hourglass_alpha"] = args.alpha
    out = ROOT / "benchmarks" / "out" / f"cavity_path_{args.case}{args.tag}.csv"
    out.parent.mkdir(parents=True, exist_ok=True)
    tables = []
    for dx in args.dx:
        tables.append(trace(cfg, dx, args.case, args.start, args.max_ratio))
        pd.concat(tables, ignore_index=True).to_csv(out, index=False)


if __name__ == "__main__":
    main()
