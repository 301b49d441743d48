"""Cost of the stress treatments of the damage criterion's input (docs/physics.md, "Stress recovery"): the lumen
loads (``numerics.lumen_load``) per force evaluation and per Jacobian assembly, and the stress readings
(``numerics.stress_recovery``) per evaluation read, on the bi-layered passive wall at 103 mmHg (pressure control),
one core, median of repeated calls. The factorisation is the same for every treatment: the operator load's tangent
adds entries to existing blocks of the Jacobian (no new pattern).

    python benchmarks/bench_stress_treatments.py [--dx 3 1.5]

Prints a table and writes benchmarks/out/stress_treatments.csv.
"""

from __future__ import annotations

import argparse
import sys
from functools import partial
from pathlib import Path

import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from bench_solver import median_time  # noqa: E402

from sphgag import config, threads  # noqa: E402
from sphgag.engine import loading, measure  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.studies import artery  # noqa: E402
from sphgag.studies.wall_loading import homeostasis, pressurise  # noqa: E402


def median_ms(fn, repeats: int) -> float:
    """``fn``'s median wall time over ``repeats`` calls after one warm-up [ms]."""
    return 1e3 * median_time(fn, repeats)


def load_row(cfg: dict, dx: float, load_name: str):
    """The lumen load ``load_name``'s row at spacing ``dx``, and the model and evaluation it was measured on."""
    numerics = Numerics.of(dict(cfg["numerics"], lumen_load=load_name))
    model = artery.bilayer_model(dict(cfg["bilayer"], dx_um=dx), numerics, name=f"bench_{load_name}")
    h = homeostasis(model, numerics, cfg["homeostasis"])
    state = pressurise(model, h.state, 103.0, numerics)
    ev = model.evaluate(state.x, state.load)
    row = dict(
        dx_um=dx,
        particles=model.n,
        treatment=f"lumen load {load_name}",
        force_evaluation_ms=median_ms(partial(model.evaluate, state.x, state.load), 30),
        jacobian_ms=median_ms(partial(model.jacobian, ev), 5),
    )
    return row, model, ev


def read_row(model, ev, name: str) -> dict:
    """The stress reading ``name``'s row: one read of every particle's stress from the evaluation ``ev``."""
    ms = median_ms(lambda: measure.recovered(model, ev, name).cauchy(), 10)
    return dict(dx_um=model.layout.dx, particles=model.n, treatment=f"reading {name}", read_ms=ms)


def rows_at(cfg: dict, dx: float) -> list[dict]:
    """One row per lumen load and per stress reading at spacing ``dx``."""
    rows = []
    for load_name in loading.LUMEN_LOADS:
        row, model, ev = load_row(cfg, dx, load_name)
        rows.append(row)
    return rows + [read_row(model, ev, name) for name in measure.RECOVERIES]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--dx", type=float, nargs="+", default=[3.0, 1.5])
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(ROOT / "config" / "config.yaml"), ROOT / "config" / "schema.yaml")
    table = pd.DataFrame([r for dx in args.dx for r in rows_at(cfg, dx)])
    (ROOT / "benchmarks" / "out").mkdir(exist_ok=True)
    table.to_csv(ROOT / "benchmarks" / "out" / "stress_treatments.csv", index=False)
    print(table.round(3).to_string(index=False))


if __name__ == "__main__":
    main()
