"""Resolution study of the GAG-pool stresses (figure 4): does the tip stress converge?

Runs, for each particle spacing, the passive homeostatic state, pressurises it to
103 mmHg under pressure control and swells cases I and IV (the smallest and the
largest pool) from 0 to 150 mEq/l, then prints the tip radial and top hoop stress
at conversion (c = 0) and at 150 mEq/l. Writes benchmarks/out/swelling_convergence.csv.

    python benchmarks/swelling_convergence.py [--dx 5 4 3.5 3 2.5] [--cases I IV]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numba
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import artery, config, protocols  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--dx", type=float, nargs="+", default=[5.0, 4.0, 3.5, 3.0, 2.5])
    ap.add_argument("--cases", nargs="+", default=["I", "IV"])
    ap.add_argument("--pressure", type=float, default=103.0)
    args = ap.parse_args()
    numba.set_num_threads(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    numerics, sw, gag = cfg["numerics"], cfg["swelling"], cfg["gag"]
    rows = []
    for dx in args.dx:
        p = dict(cfg["bilayer"], dx_um=dx)
        for case in args.cases:
            t0 = time.time()
            pool = artery.pool_sector(sw["cases"][case])
            model = artery.bilayer_model(p, numerics, name=f"dx{dx:g}_{case}", pool=pool, gag=gag)
            h = protocols.homeostasis(model, numerics, cfg["homeostasis"])
            start = protocols.pressurise(model, h.state, args.pressure, numerics)
            table = protocols.swell_pool(model, start, pool, numerics, sw, gag)
            conv = table[table.stage == "converted"]
            first, last = conv.iloc[0], conv.iloc[-1]
            rows.append(dict(dx_um=dx, particles=model.n, case=case, pool_particles=int(last.pool_particles),
                             tip_intact_kPa=table.tip_radial_stress_kPa.iloc[0],
                             tip_converted_kPa=first.tip_radial_stress_kPa,
                             tip_max_concentration_kPa=last.tip_radial_stress_kPa,
                             top_converted_kPa=first.top_circ_stress_kPa,
                             top_max_concentration_kPa=last.top_circ_stress_kPa,
                             seconds=time.time() - t0))
            print(pd.DataFrame(rows[-1:]).round(2).to_string(index=False, header=len(rows) == 1), flush=True)
    out = pd.DataFrame(rows)
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    out.to_csv(dest / "swelling_convergence.csv", index=False)


if __name__ == "__main__":
    main()
