"""Mesh studies of the finite-element reference of a swelling pool (:mod:`sphgag.studies.fe_swelling`).

The elliptical pool (a/b = 3, b = 15 um, extent = a) up to a pool volume ratio of 10, and figure 4's case I pool in
the all-elastin quarter annulus of the artery's wall (media + adventitia; probes in the media) up to 4.4, each at
three mesh sizes. Matrix: the bilayer's elastin (unweighted), as the pool verification; GAG: the ``gag`` section.
Prints and writes benchmarks/out/fe_<problem>_runs.csv (every state) and fe_<problem>_changes.csv (the finest
mesh's values, their relative change from the second finest and the observed order). About 4 min on one core.

    python benchmarks/fe_reference.py [--sizes 1 0.5 0.25] [--problems ellipse sector]
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
from sphgag.studies import artery, fe_swelling  # noqa: E402

ELLIPSE_PRESSURES = [10, 20, 30, 40, 50, 60, 65, 70, 72, 74]  # kPa; the last: pool volume ratio 10.1
SECTOR_PRESSURES = [10, 20, 30, 40, 42, 44]  # kPa; the last: 4.4


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    parser.add_argument("--sizes", type=float, nargs="+", default=[1.0, 0.5, 0.25], help="h [um], coarse to fine")
    parser.add_argument("--problems", nargs="+", default=["ellipse", "sector"], choices=["ellipse", "sector"])
    args = parser.parse_args()
    threads.use(1)
    cfg = config.load_yaml(args.config)
    bl, gag = cfg["bilayer"], cfg["gag"]
    matrix = dict(shear_modulus_kPa=bl["elastin_shear_modulus_kPa"], lame_lambda_kPa=bl["lame_lambda_kPa"])
    gag = {k: gag[k] for k in ("shear_modulus_kPa", "lame_lambda_kPa", "volumetric")}
    r_in, border, r_out = artery.bilayer_interfaces(bl)
    case = cfg["swelling"]["cases"]["I"]
    pool = tuple(case[k] for k in ("centre_radius_um", "centre_angle_deg", "radial_extent_um", "angular_extent_deg"))
    problems = {
        "ellipse": lambda h: fe_swelling.elliptic_pool(45.0, 15.0, 45.0, matrix, gag, ELLIPSE_PRESSURES, h),
        "sector": lambda h: fe_swelling.sector_pool(
            r_in, r_out, pool, matrix, gag, SECTOR_PRESSURES, h, cfg["swelling"]["probe_length_um"], (r_in, border)
        ),
    }
    out = ROOT / "benchmarks" / "out"
    out.mkdir(parents=True, exist_ok=True)
    pd.set_option("display.width", 200)
    for name in args.problems:

        def timed(h, name=name):
            start = time.perf_counter()
            run = problems[name](h)
            return run.assign(seconds=time.perf_counter() - start)

        runs, changes = fe_swelling.mesh_study(timed, args.sizes)
        runs.to_csv(out / f"fe_{name}_runs.csv", index=False)
        changes.to_csv(out / f"fe_{name}_changes.csv", index=False)
        print(f"{name}:\n{runs.to_string()}\n{changes.to_string()}\n")


if __name__ == "__main__":
    main()
