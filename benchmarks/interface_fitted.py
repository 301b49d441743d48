"""The bi-layered wall on interface-fitted particles beside the paper's straddling stencils (docs/physics.md,
"Interface-fitted particles"): the wall of Table 2, passive and active, pressurised by figure 3's path
(:func:`sphgag.studies.wall_profiles.bilayer_states`) at each of ``--pressures``, at each spacing of ``--dx``; every
ring's radial and hoop stress (eq. 2.10 as read) against the exact layered thick wall
(:func:`sphgag.studies.wall_profiles.ring_errors`), the error measures of the verification table
(:func:`sphgag.studies.wall_profiles.summary`), the outer diameter's error, and, on fitted particles, the radial stress
of both sides of the media/adventitia border (:func:`sphgag.engine.measure.interface_stresses`) against the exact one.

    python benchmarks/interface_fitted.py [--dx 3 2.12 1.5] [--pressures 103 145 200]

Prints a table and writes benchmarks/out/interface_fitted.csv.
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

from sphgag import config  # noqa: E402
from sphgag.engine import measure  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.studies import wall_profiles  # noqa: E402
from sphgag.studies.wall_loading import BilayerCalibration  # noqa: E402


def rows(cfg: dict, dx: float, pressures, fitted: bool) -> list[dict]:
    numerics = Numerics.of(cfg["numerics"])
    wall = dict(cfg["bilayer"], dx_um=dx)
    cal = BilayerCalibration.activation(cfg["bilayer_calibration"])
    start = time.perf_counter()
    found = wall_profiles.bilayer_states(
        wall, numerics, cfg["homeostasis"], cal, ["passive", "active"], pressures, fitted=fitted
    )
    seconds = time.perf_counter() - start
    out = []
    for name, model, tube, state in found:
        rings = wall_profiles.ring_errors(model, tube, state, "paper").assign(
            wall=name, pressure_mmHg=state.load.pressure_mmHg, lumen_load="surface", recovery="paper", dx_um=dx
        )
        summary = wall_profiles.summary(rings).iloc[0].to_dict()
        P = state.load.pressure_kPa
        exact = tube.state(P)
        _, OD = measure.diameters(model, state.x)
        row = dict(
            stencils="fitted" if fitted else "straddling",
            particles=model.n,
            seconds_all_states=seconds,
            od_error_pct=100.0 * (OD / (2.0 * exact.r_out) - 1.0),
            **summary,
        )
        sides = measure.interface_stresses(model, state.evaluation)
        border = float(wall["inner_radius_um"] + wall["layers"][0]["thickness_um"])
        exact_border = -P + float(tube._integral(exact.r_in, np.array([border]))[0])
        for _, side in sides.iterrows():
            row[f"border_radial_{side.layer}_pct"] = 100.0 * (side.radial_stress_kPa - exact_border) / P
        out.append(row)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dx", type=float, nargs="+", default=[3.0, 2.12, 1.5])
    parser.add_argument("--pressures", type=float, nargs="+", default=[103.0, 145.0, 200.0])
    args = parser.parse_args()
    cfg = config.load_yaml(ROOT / "config" / "config.yaml")
    table = pd.DataFrame(
        [row for dx in args.dx for fitted in (False, True) for row in rows(cfg, dx, args.pressures, fitted)]
    )
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    table.to_csv(out / "interface_fitted.csv", index=False)
    show = ["stencils", "wall", "pressure_mmHg", "dx_um", "inner_radial_pct", "interior_radial_max_pct"]
    show += ["radial_max_pct", "circ_rms_pct", "od_error_pct"]
    show += [c for c in table.columns if c.startswith("border_radial")]
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(table[show].round(3).to_string(index=False))


if __name__ == "__main__":
    main()
