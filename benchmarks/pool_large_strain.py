"""The engine's pools at large strain against exact and finite-element solutions of the same problems.

* ``circle``: a circular pool (radius 15 um) in a free elastin annulus to 60 um, swollen by the prescribed Pi that
  gives pool volume ratios of 4, 10 and 25 (:func:`sphgag.physics.cavity.pressure_for_volume_ratio`), at each
  spacing, against the exact radially symmetric solution (:func:`sphgag.studies.swollen_pool.circle_study`);
* ``sector``: figure 4's case I pool in the all-elastin quarter annulus of the artery's wall (media + adventitia,
  free surfaces, probes in the media), Pi = 10, 30, 44 kPa (pool volume ratio up to 4.4), at each spacing
  (:func:`sphgag.studies.swollen_pool.sector_study`), beside the finite-element solution on its finest mesh
  (:func:`sphgag.studies.fe_swelling.sector_pool`, P2/P1, h = 0.25 um at the corners, converged to 0.2 %).

For both pool models (``--pool-models particles cavity``: the paper's GAG particles, or the pool as a pressurised
cavity, :mod:`sphgag.engine.pool_cavity`) and the hourglass form of ``--hourglass``. Matrix: the bilayer's elastin
(unweighted); GAG: the ``gag`` section. Writes ``benchmarks/out/pool_large_strain_<problem>.csv``.

    python benchmarks/pool_large_strain.py --problems circle sector --dx 4 3 2.5 2 --hourglass energy
"""

from __future__ import annotations

import argparse
import logging
import sys
from pathlib import Path

import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config, threads  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.studies import artery, fe_swelling, swollen_pool  # noqa: E402

SECTOR_PRESSURES = [10.0, 30.0, 44.0]  # kPa: the FE sector reaches a pool volume ratio of 4.4 at 44 kPa
FE_SIZE = 0.25  # um at the pool's corners (benchmarks/fe_reference.py: converged to 0.2 % at this size)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--problems", nargs="+", default=["circle", "sector"], choices=["circle", "sector"])
    ap.add_argument("--dx", type=float, nargs="+", default=[4.0, 3.0, 2.5, 2.0])
    ap.add_argument("--pool-models", nargs="+", default=["particles", "cavity"], choices=["particles", "cavity"])
    ap.add_argument("--hourglass", default="energy", choices=["paper", "energy"])
    args = ap.parse_args()
    threads.use(1)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    log = logging.getLogger("pool_large_strain")
    cfg = config.load_yaml(args.config)
    bl = cfg["bilayer"]
    matrix = dict(
        shear_modulus_kPa=bl["elastin_shear_modulus_kPa"],
        lame_lambda_kPa=bl["lame_lambda_kPa"],
        hourglass_modulus_kPa=bl["hourglass_modulus_kPa"],
    )
    numerics = Numerics.of(dict(cfg["numerics"], hourglass=args.hourglass))
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    pd.set_option("display.width", 250)
    for problem in args.problems:
        if problem == "circle":
            vc = dict(radius_um=15.0, outer_radius_um=60.0, dx_um=args.dx, volume_ratios=[4.0, 10.0, 25.0], steps=20)
            table = pd.concat(
                [swollen_pool.circle_study(vc, matrix, cfg["gag"], numerics, m, log=log) for m in args.pool_models]
            )
        else:
            walls = artery.bilayer_interfaces(bl)
            case = cfg["swelling"]["cases"]["I"]
            probe = cfg["swelling"]["probe_length_um"]
            vs = dict(walls_um=walls, pool=case, probe_length_um=probe, pressures_kPa=SECTOR_PRESSURES, steps=11)
            vs["dx_um"] = args.dx
            sph = [swollen_pool.sector_study(vs, matrix, cfg["gag"], numerics, m, log=log) for m in args.pool_models]
            keys = ("centre_radius_um", "centre_angle_deg", "radial_extent_um", "angular_extent_deg")
            pool = tuple(case[k] for k in keys)
            fe = fe_swelling.sector_pool(
                walls[0], walls[2], pool, matrix, cfg["gag"], SECTOR_PRESSURES, FE_SIZE, probe, (walls[0], walls[1])
            )
            fe = fe.rename(columns=dict(top_hoop_stress_kPa="top_circ_stress_kPa")).assign(pool_model="fe", dx_um=0.0)
            table = pd.concat(sph + [fe], ignore_index=True)
        table.to_csv(out / f"pool_large_strain_{problem}.csv", index=False)
        print(table.to_string())


if __name__ == "__main__":
    main()
