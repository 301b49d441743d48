"""Transmural radial and hoop stress against the exact thick wall, raw and recovered.

The mean wall (figure 2a's protocol, :func:`sphgag.studies.protocols.mean_pressure_diameter` with a coarser sweep)
and the bi-layered wall, passive and active (:func:`sphgag.studies.protocols.activated`, then the pressures), at 103,
145 and 200 mmHg, each at the configuration's spacing and two finer ones (ratio sqrt 2). Every ring's radial and hoop
Cauchy stress, read by each stress recovery (:mod:`sphgag.engine.recovery`), is compared with the exact tube
(:mod:`sphgag.physics.analytic`) at the ring's current radius and at its material point, in the ring's layer: the
radial stress in % of the lumen pressure P, the hoop stress in % of the exact one. The converged states are kept in
``benchmarks/out/radial_stress/``, so a new recovery is measured without solving again.

Writes ``benchmarks/out/radial_stress_rings.csv`` (every ring), ``benchmarks/out/radial_stress.csv`` (per model,
pressure, spacing and recovery: the inner- and outer-surface radial error, the largest interior radial error, the
hoop rms error) and ``benchmarks/out/radial_stress_orders.csv`` (the observed order of each, from the two finest
spacings).

    PYTHONPATH=src python benchmarks/radial_stress.py [--refinements 3] [--models mean passive active]
"""

from __future__ import annotations

import argparse
import pickle
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config, threads  # noqa: E402
from sphgag.engine import measure, recovery  # noqa: E402
from sphgag.engine.loading import MMHG_TO_KPA, Load  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.studies import artery, protocols  # noqa: E402

OUT = ROOT / "benchmarks" / "out"
PRESSURES = (103.0, 145.0, 200.0)


def mean_states(cfg, dx: float) -> dict:
    """``{("mean", P): (x, load)}``: the mean wall at ``dx`` (figure 2a's path, pressures every 50 mmHg and
    ``PRESSURES``)."""
    p = dict(cfg["mean"], dx_um=dx)
    model = artery.mean_model(p, cfg["numerics"])
    lz = p["axial_stretch"]
    steps = cfg["calibration"]["axial_stretch_steps"]
    loads = [Load(s, 0.0) for s in np.linspace(1.0, lz, steps + 1)[1:]]
    loads += [Load(lz, P * MMHG_TO_KPA) for P in sorted({50.0, 100.0, 150.0, *PRESSURES})]
    states = Numerics.of(cfg["numerics"]).solver(model).follow_path(model.layout.X, Load(1.0, 0.0), loads, run="mean")
    return {("mean", P): (s.x, s.load) for s in states for P in PRESSURES if _at(s.load, P)}


def bilayer_states(cfg, dx: float) -> dict:
    """``{(model, P): (x, load)}``: the passive and active bi-layered wall at ``dx`` (homeostasis, pressure control,
    the active tone at the activation pressure, then the pressures: the path of
    :func:`sphgag.studies.protocols.bilayer_pressure_diameter`)."""
    p = dict(cfg["bilayer"], dx_um=dx)
    model = artery.bilayer_model(p, cfg["numerics"])
    path_solver = Numerics.of(cfg["numerics"]).solver(model)
    h = protocols.homeostasis(model, cfg["numerics"], cfg["homeostasis"], path_solver=path_solver)
    cal = cfg["bilayer_calibration"]
    out = {}
    for name in ("passive", "active"):
        start = protocols.activated(model, h.state, cfg["numerics"], cal, name == "active", path_solver=path_solver)
        loads = [Load(1.0, P * MMHG_TO_KPA, material=start.load.material) for P in PRESSURES if P > 103.0]
        states = [start] + path_solver.follow_path(start.x, start.load, loads, run=model.name)
        out.update({(name, P): (s.x, s.load) for s in states for P in PRESSURES if _at(s.load, P)})
    return out


def _at(load: Load, P: float) -> bool:
    return load.pressure_kPa is not None and abs(load.pressure_mmHg - P) < 1e-9


def states(cfg, name: str, dx: float) -> tuple:
    """``(model, tube, {P: (x, load)})`` of the wall ``name`` (mean, passive, active) at ``dx``: the states are
    solved once (the passive and active walls together) and kept in ``OUT / radial_stress``."""
    wall = "mean" if name == "mean" else "bilayer"
    p = dict(cfg[wall], dx_um=dx)
    path = OUT / "radial_stress" / f"{wall}_{dx:.3f}.pkl"
    if not path.exists():
        t0 = time.time()
        found = mean_states(cfg, dx) if wall == "mean" else bilayer_states(cfg, dx)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(pickle.dumps(found))
        print(f"# solved the {wall} wall at dx = {dx:.3f} um in {time.time() - t0:.0f} s", flush=True)
    found = pickle.loads(path.read_bytes())
    if wall == "mean":
        model, tube = artery.mean_model(p, cfg["numerics"]), artery.mean_thick_wall(p)
    else:
        model, tube = artery.bilayer_model(p, cfg["numerics"]), artery.bilayer_tube(p, active=name == "active")
    return model, tube, {P: v for (m, P), v in found.items() if m == name}


def exact_at(tube, P_kPa: float, radius: np.ndarray, layer: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The exact radial and hoop stress at current radii ``radius`` inside each ring's layer ``layer``."""
    ex = tube.state(P_kPa, n_per_layer=401)
    srr, stt = np.empty_like(radius), np.empty_like(radius)
    for name in np.unique(layer):
        m, e = layer == name, ex.layer == name
        srr[m] = np.interp(radius[m], ex.radius[e], ex.radial_stress[e])
        stt[m] = np.interp(radius[m], ex.radius[e], ex.circ_stress[e])
    return srr, stt


def ring_errors(model, tube, x, load, treatment: str) -> pd.DataFrame:
    """Every ring's radial error [% of P] and hoop error [% of the exact] under ``treatment`` (a stress recovery's
    name), against the exact tube at the ring's current radius and (``*_material_*``) at its material point: the
    exact tube's radius of the ring's reference radius (the SPH wall's diameter is off by 0.1 %, which at the stiff
    end of the pressure-diameter curve moves the hoop stress at a given radius by several %)."""
    ev = model.evaluate(x, load)
    profile = measure.ring_profile(model, recovery.recovered(model, ev, treatment))
    P = load.pressure_kPa
    layer = profile.layer.to_numpy()
    srr, stt = exact_at(tube, P, profile.radius_um.to_numpy(), layer)
    r_material = tube.radius(profile.reference_radius_um.to_numpy(), tube.inner_radius(P))
    srr_m, stt_m = exact_at(tube, P, r_material, layer)
    return profile.assign(
        radial_error_pct=100.0 * (profile.radial_stress_kPa - srr) / P,
        circ_error_pct=100.0 * (profile.circ_stress_kPa / stt - 1.0),
        radial_material_error_pct=100.0 * (profile.radial_stress_kPa - srr_m) / P,
        circ_material_error_pct=100.0 * (profile.circ_stress_kPa / stt_m - 1.0),
        exact_radial_kPa=srr,
        exact_circ_kPa=stt,
    )


MATERIAL = ("radial_material_error_pct", "circ_material_error_pct")


def summary(rings: pd.DataFrame) -> pd.DataFrame:
    """Per model, pressure, spacing and treatment: the inner- and outer-surface radial error and the largest interior
    one [% of P], the hoop rms error [%], at the rings' current radii and (``material_*``) at their material points."""
    keys = ["model", "pressure_mmHg", "dx_um", "treatment"]

    def one(g):
        out = {}
        for tag, radial, circ in (("", "radial_error_pct", "circ_error_pct"), ("material_", *MATERIAL)):
            e = g[radial].to_numpy()
            out[f"{tag}inner_radial_pct"] = e[0]
            out[f"{tag}outer_radial_pct"] = e[-1]
            out[f"{tag}interior_radial_max_pct"] = np.abs(e[1:-1]).max()
            out[f"{tag}circ_rms_pct"] = float(np.sqrt(np.mean(g[circ] ** 2)))
        return pd.Series(out)

    return rings.groupby(keys, sort=False).apply(one, include_groups=False).reset_index()


def orders(table: pd.DataFrame) -> pd.DataFrame:
    """Observed order of each error measure (an error against the exact value) from the two finest spacings:
    ``ln(|e_2| / |e_3|) / ln(dx_2 / dx_3)``; none where the error is round-off (a surface read from its traction)."""
    rows = []
    measures = [c for c in table.columns if c.endswith("_pct")]
    for key, g in table.groupby(["model", "pressure_mmHg", "treatment"], sort=False):
        g = g.sort_values("dx_um", ascending=False)
        if len(g) < 2:
            continue
        dx = g.dx_um.to_numpy()
        row = dict(zip(["model", "pressure_mmHg", "treatment"], key))
        for m in measures:
            e = np.abs(g[m].to_numpy())
            exact = e[-2:].min() < 1e-6  # a recovered surface: exact to round-off, no order
            row[f"{m}_order"] = np.nan if exact else float(np.log(e[-2] / e[-1]) / np.log(dx[-2] / dx[-1]))
        rows.append(row)
    return pd.DataFrame(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--refinements", type=int, default=3, help="spacings: dx, dx/sqrt2, dx/2 (the first n)")
    ap.add_argument("--models", nargs="+", default=["mean", "passive", "active"])
    ap.add_argument("--treatments", nargs="+", default=list(recovery.RECOVERIES))
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    rings = []
    for name in args.models:
        base = cfg["mean" if name == "mean" else "bilayer"]["dx_um"]
        for k in range(args.refinements):
            dx = round(base / np.sqrt(2.0) ** k, 3)
            model, tube, found = states(cfg, name, dx)
            for P, (x, load) in sorted(found.items()):
                for t in args.treatments:
                    rings.append(
                        ring_errors(model, tube, x, load, t).assign(model=name, pressure_mmHg=P, dx_um=dx, treatment=t)
                    )
    rings = pd.concat(rings, ignore_index=True)
    table = summary(rings)
    OUT.mkdir(exist_ok=True)
    rings.to_csv(OUT / "radial_stress_rings.csv", index=False)
    table.to_csv(OUT / "radial_stress.csv", index=False)
    order = orders(table)
    order.to_csv(OUT / "radial_stress_orders.csv", index=False)
    with pd.option_context("display.width", 200, "display.max_rows", 500):
        print(table.round(2).to_string(index=False))
        print(order.round(2).to_string(index=False))


if __name__ == "__main__":
    main()
