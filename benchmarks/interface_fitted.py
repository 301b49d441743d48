"""The bi-layered wall on interface-fitted particles beside the paper's straddling stencils (docs/physics.md,
"Interface-fitted particles").

``wall`` (the default): the wall of Table 2, passive and active, pressurised by figure 3's path
(:func:`sphgag.studies.wall_profiles.bilayer_states`) at each of ``--pressures``, at each spacing of ``--dx``; every
ring's radial and hoop stress (eq. 2.10 as read) against the exact layered thick wall
(:func:`sphgag.studies.wall_profiles.ring_errors`), the error measures of the verification table
(:func:`sphgag.studies.wall_profiles.summary`), the outer diameter's error, and, on fitted particles, the radial stress
of both sides of the media/adventitia border (:func:`sphgag.engine.measure.interface_stresses`) against the exact one.

``tube``: a plain two-layer tube, neo-Hookean media and adventitia (their elastin shear moduli, 42.2 and 3.6 kPa), no
fibres or pre-stretch, lambda/mu of ``--bulk``, at lz = 1 under the lumen pressure that gives the exact incompressible
tube a hoop stretch of 1.2 at the lumen; every ring's radial error [% of P], and the outer radius's.

    python benchmarks/interface_fitted.py [wall|tube] [--dx 3 2.12 1.5] [--pressures 103 145 200] [--bulk 1000 100]

Prints a table and writes benchmarks/out/interface_fitted.csv (wall) or interface_fitted_tube.csv (tube).
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
from sphgag.engine import geometry, kernel, measure, quadrature  # noqa: E402
from sphgag.engine.loading import Load  # noqa: E402
from sphgag.engine.model import Model  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.engine.solver import PathOptions, Solver  # noqa: E402
from sphgag.physics import analytic, materials  # noqa: E402
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


TUBE = (646.8, 675.2, 687.0)  # the media and the adventitia of Table 2 [um]
TUBE_MODULI = {"media": 0.47 * 89.71, "adventitia": 0.04 * 89.71}  # their elastin shear moduli [kPa]


def tube_rows(dx: float, bulk: float, fitted: bool) -> dict:
    """The plain two-layer tube (module docstring) at spacing ``dx``: every ring's radial error against the exact
    incompressible tube [% of P], and the outer radius's relative error."""
    names = tuple(TUBE_MODULI)
    layout = geometry.quarter_annulus(TUBE, dx, layer_names=names, fitted=fitted)
    nb = kernel.for_layout(layout, 2.5)
    points = quadrature.build(layout, nb) if fitted else None
    rows_of = layout if points is None else points.layout
    props = materials.empty_props(rows_of.n)
    for name, mu in TUBE_MODULI.items():
        props[rows_of.layer_mask(name), materials.MU] = mu
        props[rows_of.layer_mask(name), materials.LAM] = bulk * mu
    props[:, materials.HG_E] = TUBE_MODULI["media"]
    model = Model("tube", layout, nb, props, hourglass_alpha=5.0, hourglass="energy", points=points)
    laws = [(a, b, analytic.Mixture(TUBE_MODULI[n]), n) for n, a, b in zip(names, TUBE, TUBE[1:])]
    tube = analytic.ThickWallTube(laws, lz=1.0)
    P = tube.pressure(1.2 * TUBE[0])
    loads = [Load(1.0, f * P) for f in (0.25, 0.5, 0.75, 1.0)]
    state = Solver(model, PathOptions(tol=1e-8, max_iter=40)).follow_path(layout.X, Load(1.0, 0.0), loads)[-1]
    profile = measure.ring_profile(model, state.evaluation)
    r_in = tube.inner_radius(P)
    exact = -P + tube._integral(r_in, profile.reference_radius_um.to_numpy())
    error = 100.0 * (profile.radial_stress_kPa.to_numpy() - exact) / P
    r_out = float(np.linalg.norm(state.x[layout.outer_surface], axis=1).mean())
    return dict(
        stencils="fitted" if fitted else "straddling",
        lambda_over_mu=bulk,
        dx_um=dx,
        particles=model.n,
        outer_radius_error=r_out / float(tube.radius(TUBE[-1], r_in)) - 1.0,
        lumen_radial_pct=error[0],
        radial_max_pct=float(np.abs(error).max()),
        rings_pct=" ".join(f"{e:+.1f}" for e in error),
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("problem", nargs="?", choices=["wall", "tube"], default="wall")
    parser.add_argument("--dx", type=float, nargs="+", default=[3.0, 2.12, 1.5])
    parser.add_argument("--pressures", type=float, nargs="+", default=[103.0, 145.0, 200.0])
    parser.add_argument("--bulk", type=float, nargs="+", default=[1000.0, 100.0])
    args = parser.parse_args()
    out = ROOT / "benchmarks" / "out"
    out.mkdir(exist_ok=True)
    if args.problem == "tube":
        table = pd.DataFrame(
            [tube_rows(dx, bulk, fitted) for bulk in args.bulk for dx in args.dx for fitted in (False, True)]
        )
        table.to_csv(out / "interface_fitted_tube.csv", index=False)
        with pd.option_context("display.width", 250, "display.max_colwidth", 200):
            print(table.round(5).to_string(index=False))
        return
    cfg = config.load_yaml(ROOT / "config" / "config.yaml")
    table = pd.DataFrame(
        [row for dx in args.dx for fitted in (False, True) for row in rows(cfg, dx, args.pressures, fitted)]
    )
    table.to_csv(out / "interface_fitted.csv", index=False)
    show = ["stencils", "wall", "pressure_mmHg", "dx_um", "inner_radial_pct", "interior_radial_max_pct"]
    show += ["radial_max_pct", "circ_rms_pct", "od_error_pct"]
    show += [c for c in table.columns if c.startswith("border_radial")]
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(table[show].round(3).to_string(index=False))


if __name__ == "__main__":
    main()
