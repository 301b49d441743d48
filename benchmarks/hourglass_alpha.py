"""How the hourglass parameter alpha (eq. 2.14) shapes the stress field around a swelling inclusion.

The pool verification problem (sphgag.studies.inclusion: elliptical GAG inclusion in the
elastin matrix, exact far field, Pi = 0.5 kPa) at one aspect ratio and two
resolutions, for several alpha, with the hourglass penalty measured within each
material (the package's scheme) and, for comparison, across the interface (the
scheme without the interface treatment). Prints and writes benchmarks/out/hourglass_alpha.csv.

    python benchmarks/hourglass_alpha.py [--ratio 2] [--resolutions 8 16] [--alpha 1 2 5 10 20 50]
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
from sphgag.physics import materials  # noqa: E402
from sphgag.studies import inclusion  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--ratio", type=float, default=2.0)
    ap.add_argument("--resolutions", type=float, nargs="+", default=[8.0, 16.0])
    ap.add_argument("--alpha", type=float, nargs="+", default=[1.0, 2.0, 5.0, 10.0, 20.0, 50.0])
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    vp, bil = cfg["verification"]["pool"], cfg["bilayer"]
    mat = inclusion.Materials(
        bil["elastin_shear_modulus_kPa"],
        bil["lame_lambda_kPa"],
        cfg["gag"]["shear_modulus_kPa"],
        0.0,
        bil["hourglass_modulus_kPa"],
        cfg["gag"]["hourglass_modulus_kPa"],
        "none",  # eq. 2.27 as printed: no volumetric term
    )
    b, Pi = vp["semi_axis_b_um"], vp["swelling_pressure_kPa"]
    a = args.ratio * b
    rows = []
    for scheme in ("per material", "across the interface"):
        for alpha in args.alpha:
            for res in args.resolutions:
                t0 = time.time()
                numerics = dict(cfg["numerics"], hourglass_alpha=alpha)
                model = inclusion.inclusion_model(a, b, b / res, max(vp["extent_factor"] * a, 3 * b), mat, numerics)
                if scheme != "per material":
                    model.props.table[:, materials.TISSUE] = 1.0
                try:
                    state = inclusion.swell(model, Pi, numerics)
                except Exception as exc:  # noqa: BLE001 - a failed solve is a result here
                    rows.append(dict(scheme=scheme, alpha=alpha, b_over_dx=res, failed=str(exc)))
                    continue
                r = inclusion.measure_state(model, state, Pi, mat)
                rows.append(
                    dict(
                        scheme=scheme,
                        alpha=alpha,
                        b_over_dx=res,
                        tip_rel_error=r["rel_error"],
                        first_particle_rel_error=r["first_particle_rel_error"],
                        field_rms_error_per_Pi=r["field_rms_error_kPa"] / Pi,
                        traction_jump_per_Pi=r["traction_jump_kPa"] / Pi,
                        residual=r["residual"],
                        seconds=time.time() - t0,
                    )
                )
                print(pd.DataFrame(rows[-1:]).round(4).to_string(index=False, header=len(rows) == 1), flush=True)
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    pd.DataFrame(rows).to_csv(dest / "hourglass_alpha.csv", index=False)


if __name__ == "__main__":
    main()
