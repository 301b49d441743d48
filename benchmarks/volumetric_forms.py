"""The GAG contents' volumetric forms (``gag.volumetric``, :mod:`sphgag.physics.volumetric`) side by side, on the two
measures that choose the default (docs/physics.md, "GAG bulk term (a deviation)"):

* ``annulus``: the pressurised annulus (:mod:`sphgag.studies.annulus`, the paper's pool of GAG particles) at
  ``--fraction`` of the largest pressure the exact solution of each form holds, at every B/A of ``--ratios`` and
  spacing of ``--dx``, swollen from rest with the pool's volume as the control (:func:`sphgag.studies.annulus.
  swell_by_volume`): the volume and hoop errors against the exact solution of the same form
  (:func:`sphgag.studies.swollen_pool.measure_circle`) and the spread of the pool's particle volume ratios
  (largest / smallest ``J_i = det F_i``). Writes ``benchmarks/out/volumetric_annulus.csv``.
* ``conversion``: figure 4's pools (``--cases``) converted at c = 0 in the passive wall at each of ``--pressures``
  (dx = ``bilayer.dx_um``): the wall is pressurised by the path of the pressure-diameter sweep
  (:func:`sphgag.studies.convergence.pressurised_wall`), then the first two stages of
  :func:`sphgag.studies.protocols.swell_pool` (the intact wall, the conversion in ``swelling.conversion_steps``):
  the pool's volume ratio ``sum V_i J_i / sum V_i`` (against the stress-free reference) before and after
  conversion, its particles' smallest and largest J after it, or how far the conversion got where it found no
  equilibrium. Writes ``benchmarks/out/volumetric_conversion.csv``.

    python benchmarks/volumetric_forms.py annulus --forms log_squared convex none --dx 2 1.41 1
    python benchmarks/volumetric_forms.py conversion --forms log_squared convex none --pressures 103 145 200
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
from sphgag.engine import measure, solver  # noqa: E402
from sphgag.engine.history import swelling_load  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.physics import cavity, materials  # noqa: E402
from sphgag.studies import annulus, convergence, swollen_pool  # noqa: E402


def particle_ratios(model, state, members) -> np.ndarray:
    """``J_i = det F_i lz`` of the particles ``members`` at ``state`` (:func:`sphgag.engine.measure.cauchy`)."""
    return measure.cauchy(model.evaluate(state.x, state.load))[1][members]


def annulus_rows(cfg: dict, form: str, ratios, spacings, fraction: float) -> list[dict]:
    """One row per (B/A, dx) of the pool of particles with the contents' form ``form`` at ``fraction`` of the limit."""
    va, bl = cfg["verification"]["annulus"], cfg["bilayer"]
    matrix = dict(
        shear_modulus_kPa=bl["elastin_shear_modulus_kPa"],
        lame_lambda_kPa=bl["lame_lambda_kPa"],
        hourglass_modulus_kPa=bl["hourglass_modulus_kPa"],
    )
    gag = dict(cfg["gag"], volumetric=form)
    numerics = Numerics.of(cfg["numerics"])
    mat = annulus.materials("particles", matrix, gag)
    m_solid, g_solid = swollen_pool.solids(mat)
    A = float(va["radius_um"])
    rows = []
    for ratio in ratios:
        B = float(ratio) * A
        top = annulus.limit(A, B, mat)
        p = fraction * top.pressure_kPa
        exact = cavity.circular_pool(A, B, m_solid, g_solid, p)
        for dx in spacings:
            t0 = time.process_time()
            model = swollen_pool.circle_model(A, B, float(dx), mat, numerics, "particles")
            at, end = annulus.swell_by_volume(numerics.solver(model), [p], float(va["max_volume_ratio"]))
            row = dict(
                form=form,
                outer_ratio=float(ratio),
                dx_um=float(dx),
                particles=model.n,
                limit_kind=top.kind,
                limit_pressure_kPa=top.pressure_kPa,
                limit_volume_ratio=top.volume_ratio,
                fraction=fraction,
                pressure_kPa=p,
                path_end=end,
            )
            if p in at:
                h = numerics.kernel_support_factor * float(dx)
                row.update(swollen_pool.measure_circle(model, at[p], exact, h))
                J = particle_ratios(model, at[p], np.flatnonzero(model.layout.inclusion))
                row.update(pool_J_min=J.min(), pool_J_max=J.max())  # and measure_circle's pool_jacobian_spread
            row["cpu_s"] = time.process_time() - t0
            rows.append(row)
            print(
                f"{form} B/A={ratio:g} dx={dx:g}: Pi {p:.2f} kPa ({top.kind} {top.pressure_kPa:.2f}), "
                f"volume {100 * row.get('volume_error', np.nan):+.2f} %, "
                f"hoop {100 * row.get('lining_hoop_error', np.nan):+.2f} %, "
                f"J {row.get('pool_J_min', np.nan):.3g}-{row.get('pool_J_max', np.nan):.3g} "
                f"(exact {exact.volume_ratio:.3g}), {end}, {row['cpu_s']:.0f} s",
                flush=True,
            )
    return rows


def conversion_rows(cfg: dict, forms, pressures, cases) -> list[dict]:
    """One row per (pressure, case, form): the pool's volume ratio right after conversion at c = 0 (passive wall)."""
    bl, numerics, sw = cfg["bilayer"], Numerics.of(cfg["numerics"]), cfg["swelling"]
    dx = float(bl["dx_um"])
    rows = []
    for pressure in pressures:
        t0 = time.process_time()
        start = convergence.pressurised_wall(
            dx, bl, numerics, cfg["homeostasis"], cfg["bilayer_calibration"], False, float(pressure), "volumetric"
        )
        print(f"wall at {pressure:g} mmHg: {time.process_time() - t0:.0f} s", flush=True)
        for case in cases:
            for form in forms:
                t0 = time.process_time()
                gag = dict(materials.law_gag(cfg["gag"], "prescribed"), volumetric=form)
                model = convergence.case_model(dx, bl, numerics, gag, sw["cases"][case], f"volumetric_{case}_{form}")
                members = model.props.converting
                path_solver = numerics.solver(model)
                base = swelling_load(start.load, 0.0, 0.0)
                intact = path_solver.follow_path(start.x, base, [base], run=model.name)[-1]
                steps = np.linspace(0.0, 1.0, int(sw["conversion_steps"]) + 1)[1:]
                reached = [intact]
                row = dict(
                    pressure_mmHg=float(pressure),
                    case=case,
                    form=form,
                    particles=model.n,
                    pool=members.size,
                    intact_volume_ratio=swollen_pool.volume_ratio_of(model, intact.evaluation, members),
                )
                try:
                    path_solver.follow_path(
                        intact.x,
                        base,
                        [swelling_load(base, f, 0.0) for f in steps],
                        run=model.name,
                        on_state=reached.append,
                    )
                    row["end"] = "converted"
                except solver.SimulationError as exc:
                    row["end"] = f"no equilibrium: {exc}"
                last = reached[-1]
                J = particle_ratios(model, last, members)
                row.update(
                    fraction=float(last.load.material_value("transition", 0.0)),
                    pool_volume_ratio=swollen_pool.volume_ratio_of(model, model.evaluate(last.x, last.load), members),
                    pool_J_min=J.min(),
                    pool_J_max=J.max(),
                    cpu_s=time.process_time() - t0,
                )
                rows.append(row)
                print(
                    f"{pressure:g} mmHg case {case} {form}: conversion {row['fraction']:.3g}, pool J "
                    f"{row['pool_volume_ratio']:.3f} (particles {J.min():.3f}-{J.max():.3f}), {row['end'][:80]}, "
                    f"{row['cpu_s']:.0f} s",
                    flush=True,
                )
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("study", choices=["annulus", "conversion"])
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--forms", nargs="+", default=["log_squared", "convex", "none"])
    ap.add_argument("--ratios", type=float, nargs="+", default=[2.0, 4.0])
    ap.add_argument("--dx", type=float, nargs="+", default=[2.0, 1.41, 1.0])
    ap.add_argument("--fraction", type=float, default=0.9)
    ap.add_argument("--pressures", type=float, nargs="+", default=[103.0, 145.0, 200.0])
    ap.add_argument("--cases", nargs="+", default=["I", "II", "III", "IV"])
    ap.add_argument("--out", default=None, help="output CSV (default benchmarks/out/volumetric_<study>.csv)")
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    if args.study == "annulus":
        rows = [r for f in args.forms for r in annulus_rows(cfg, f, args.ratios, args.dx, args.fraction)]
    else:
        rows = conversion_rows(cfg, args.forms, args.pressures, args.cases)
    out = Path(args.out) if args.out else ROOT / "benchmarks" / "out" / f"volumetric_{args.study}.csv"
    out.parent.mkdir(exist_ok=True)
    pd.DataFrame(rows).to_csv(out, index=False)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
