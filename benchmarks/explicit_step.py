"""Cost of one step of the authors' explicit procedure (sphgag.engine.dynamics.advance), on one core.

The bi-layered wall at the procedure's spacing (``paper_procedure.dx_um``, the script's resolution) and at the
full configuration's (``bilayer.dx_um``), pressurised to the procedure's pressure (figure 4's case I seeded, at rest):
the median time per leapfrog step without viscosity (the swelling ramp) and with it (the relaxation stages), beside
the authors' script's 2.55 s per step at 1430 particles (55 MPI processes; reference-implementation notes).

    python benchmarks/explicit_step.py [--config config/config.yaml] [--steps 2000]

Writes benchmarks/out/explicit_step.json.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config, threads  # noqa: E402
from sphgag.engine import dynamics  # noqa: E402
from sphgag.engine.history import swelling_load  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.physics.materials import law_gag  # noqa: E402
from sphgag.studies import convergence  # noqa: E402

SCRIPT_SECONDS_PER_STEP = 2.55  # the authors' script at 1430 particles


def per_step(model, x, load, steps, stepping, repeats=5) -> float:
    """Median seconds per step of ``repeats`` blocks of ``steps`` steps from ``x``."""
    dynamics.advance(model, dynamics.Motion.at_rest(x), load, 10, stepping)  # compiled, cached
    samples = []
    for _ in range(repeats):
        motion = dynamics.Motion.at_rest(x)
        t = time.perf_counter()
        dynamics.advance(model, motion, load, steps, stepping)
        samples.append((time.perf_counter() - t) / steps)
    return float(np.median(samples))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--steps", type=int, default=2000)
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    pp, numerics = cfg["paper_procedure"], Numerics.of(cfg["numerics"])
    calibration = {k: cfg["bilayer_calibration"][k] for k in ("activation_pressure_mmHg", "activation_steps")}
    gag = dict(law_gag(cfg["gag"], "prescribed"), temperature_K=pp["temperature_K"])
    case = cfg["swelling"]["cases"][pp["cases"][0]]
    out = []
    for where, dx in (("procedure", pp["dx_um"]), ("full", cfg["bilayer"]["dx_um"])):
        wall = (cfg["bilayer"], numerics, cfg["homeostasis"], calibration)
        start = convergence.pressurised_wall(dx, *wall, False, pp["pressure_mmHg"], "bench")
        model = convergence.case_model(dx, cfg["bilayer"], numerics, gag, case, "bench")
        load = swelling_load(start.load, 0.0, 0.0)  # the cost per step does not depend on the state
        swell, relax = (pp["swelling"][k] for k in ("swell", "relax"))
        row = dict(spacing=where, dx_um=dx, particles=model.n)
        for name, stage in (("no_viscosity", swell), ("viscosity", relax)):
            stepping = dynamics.Stepping(pp["time_step"], stage["density"], stage["viscosity"])
            row[f"ms_per_step_{name}"] = 1e3 * per_step(model, start.x, load, args.steps, stepping)
        row["times_faster_than_script"] = SCRIPT_SECONDS_PER_STEP / (row["ms_per_step_no_viscosity"] / 1e3)
        print(json.dumps(row))
        out.append(row)
    dest = ROOT / "benchmarks" / "out" / "explicit_step.json"
    dest.parent.mkdir(exist_ok=True)
    dest.write_text(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
