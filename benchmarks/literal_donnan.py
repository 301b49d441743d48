"""The pools under the Donnan law as eq. (2.27) is printed: a swelling pressure Pi(c) that does not fall as the
pool swells (``gag.charge_laws: [prescribed]``, the law ``prescribed`` of :data:`sphgag.physics.donnan.LAWS`).

For each particle spacing: passive homeostatic state at 103 mmHg, then the figure 4
protocol for cases I and IV. Prints, per run, the pool's volume ratio and the tip
stress at the last converged concentration, and the concentration at which no
equilibrium was found (if any). Writes benchmarks/out/literal_donnan.csv.

    python benchmarks/literal_donnan.py [--dx 5 4 3] [--cases I IV]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config, threads  # noqa: E402
from sphgag.engine import solver  # noqa: E402
from sphgag.physics import materials  # noqa: E402
from sphgag.studies import artery, protocols  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--dx", type=float, nargs="+", default=[5.0, 4.0, 3.0])
    ap.add_argument("--cases", nargs="+", default=["I", "IV"])
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    numerics, sw = cfg["numerics"], cfg["swelling"]
    gag = materials.law_gag(cfg["gag"], "prescribed")
    rows = []
    for dx in args.dx:
        p = dict(cfg["bilayer"], dx_um=dx)
        wall = artery.bilayer_model(p, numerics, name=f"literal_dx{dx:g}")
        start = protocols.pressurise(
            wall, protocols.homeostasis(wall, numerics, cfg["homeostasis"]).state, 103.0, numerics
        )
        for case in args.cases:
            t0 = time.time()
            pool = artery.pool_sector(sw["cases"][case])
            model = artery.bilayer_model(p, numerics, name=f"literal_dx{dx:g}_{case}", pool=pool, gag=gag)
            row = dict(dx_um=dx, case=case, particles=model.n)
            try:
                states = protocols.swell_pool(model, solver.State(start.load, start.x, None, None), numerics, sw)
                table = protocols.pool_table(model, states, pool, sw["probe_length_um"], gag)
                failed_at = None
            except solver.SimulationError as exc:
                table, failed_at = None, dict(exc.load.material).get("concentration")
            if table is not None:
                last = table.iloc[-1]
                row.update(
                    last_concentration_mEq_l=last.concentration_mEq_l,
                    pool_volume_change=last.pool_volume_change,
                    tip_radial_stress_kPa=last.tip_radial_stress_kPa,
                )
            row.update(no_equilibrium_at_mEq_l=failed_at, seconds=time.time() - t0)
            rows.append(row)
            print(pd.DataFrame(rows[-1:]).round(3).to_string(index=False, header=len(rows) == 1), flush=True)
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    pd.DataFrame(rows).to_csv(dest / "literal_donnan.csv", index=False)


if __name__ == "__main__":
    main()
