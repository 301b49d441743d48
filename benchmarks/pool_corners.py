"""Where figure 4's first-order error comes from: the sector pool against its finite-element reference, by layout.

Figure 4's case I pool in the all-elastin quarter annulus of the wall (the problem of
:func:`sphgag.studies.swollen_pool.sector_study`; media + adventitia, free surfaces, elastin matrix mu = 89.71,
lambda = 10 000 kPa, GAG mu = 0.1 kPa with the configured contents), swollen by Pi = 10, 30, 44 kPa, against the P2/P1
finite elements of :func:`sphgag.studies.fe_swelling.sector_pool` graded into the corners (h = 0.25 um there,
converged to 0.2 %). Per layout (``--layouts``: ``dx:pool:corners`` with ``pool`` and ``corners`` the spacings of
:class:`sphgag.engine.grading.Grading` as fractions of dx, ``1:1`` uniform) the error of the pool's volume change
``J - 1``, measured as ``sum V J`` and as the area the lining encloses. ``--walls`` moves the free surfaces (a thick
wall: no thin ligaments). Writes benchmarks/out/pool_corners.csv.

    python benchmarks/pool_corners.py --layouts 3:1:1 2.12:1:1 1.5:1:1 3:0.5:0.5 3:1:0.333 3:0.5:0.1667
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
from sphgag.studies import artery, fe_swelling, swollen_pool  # noqa: E402

PRESSURES = [10.0, 30.0, 44.0]  # kPa: the FE pool holds J = 1.36, 2.42, 4.43 in the artery's wall
FE_SIZE = 0.25  # um at the pool's corners


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--layouts", nargs="+", default=["3:1:1", "2.12:1:1", "1.5:1:1", "3:0.5:0.1667"])
    ap.add_argument("--walls", type=float, nargs=3, default=None, help="inner radius, media border, outer radius")
    args = ap.parse_args()
    threads.use(1)
    logging.basicConfig(level=logging.WARNING)
    cfg = config.load_yaml(args.config)
    bl, gag = cfg["bilayer"], {k: v for k, v in cfg["gag"].items() if k != "charge_laws"}
    matrix = dict(
        shear_modulus_kPa=bl["elastin_shear_modulus_kPa"],
        lame_lambda_kPa=bl["lame_lambda_kPa"],
        hourglass_modulus_kPa=bl["hourglass_modulus_kPa"],
    )
    walls = args.walls or artery.bilayer_interfaces(bl)  # inner radius, media/adventitia border, outer radius
    case = cfg["swelling"]["cases"]["I"]
    keys = ("centre_radius_um", "centre_angle_deg", "radial_extent_um", "angular_extent_deg")
    fe = fe_swelling.sector_pool(
        walls[0], walls[2], tuple(case[k] for k in keys), matrix, gag, PRESSURES, FE_SIZE, media=(walls[0], walls[1])
    ).set_index("pressure_kPa")
    rows = []
    for spec in args.layouts:
        dx, pool, corners = (float(v) for v in spec.split(":"))
        graded = dict(pool=pool, corners=corners, reach_um=cfg["grading"]["reach_um"])
        vs = dict(walls_um=walls, pool=case, probe_length_um=10.0, pressures_kPa=PRESSURES, steps=11, dx_um=[dx])
        table = swollen_pool.sector_study(vs, matrix, gag, cfg["numerics"], "particles", graded=graded)
        for _, r in table.iterrows():
            ref = fe.loc[r.pressure_kPa, "pool_volume_ratio"]
            rows.append(
                dict(
                    layout=spec,
                    particles=int(r.particles),
                    pressure_kPa=r.pressure_kPa,
                    fe_volume_ratio=ref,
                    volume_ratio=r.pool_volume_ratio,
                    lining_volume_ratio=r.lining_volume_ratio,
                    change_error=(r.pool_volume_ratio - 1) / (ref - 1) - 1,
                    lining_change_error=(r.lining_volume_ratio - 1) / (ref - 1) - 1,
                    residual=r.residual,
                )
            )
            print(pd.DataFrame(rows[-1:]).to_string(header=len(rows) == 1, index=False), flush=True)
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    pd.DataFrame(rows).to_csv(out / "pool_corners.csv", index=False)


if __name__ == "__main__":
    main()
