"""What ends the prescribed-law swelling path near the artery's pools, and how it moves with the particle spacing.

Figure 4's protocol for one pool (passive wall, lumen pressure held; conversion, then the fixed-charge
concentration raised in steps under the paper's Donnan law, Pi(c) prescribed, eqs. 2.25-2.27), at several spacings
and for variants of the pool that isolate what the artery's pools add to the smooth circular pool that follows its
exact solution:

* ``--shape``: ``sector`` (the paper's: an annular sector with sharp corners), ``ellipse`` or ``stadium`` (smooth
  outlines of the same radial extent and the same area, centred on the sector);
* ``--gag-hourglass``: the hourglass modulus of the GAG particles (eq. 2.14's E; default the configuration's), e.g.
  0 for no hourglass control inside the pool;
* ``--no-fibres``: the wall without its fibre families (elastin alone);
* ``--pool cavity``: the pool as a pressurised cavity (:mod:`sphgag.engine.pool_cavity`) after its conversion;
* ``--hourglass``: the form of the hourglass control (``numerics.hourglass``: eq. 2.14 as printed or its energy form).

For each spacing: the highest concentration with an equilibrium (steps of ``--step`` mEq/l, each bisected
``--bisections`` times), the pool's volume ratio there, and, at the stall (the last Newton iterate of the step that
finds none), the most negative stiffness eigenvalues with the particles that carry them (participation, and the
share in each class: pool interior, pool boundary, pool corner, lining tissue, other tissue), the hourglass share of
``v.K.v``, and where the largest and smallest J of the pool sit. Writes ``benchmarks/out/pool_failure_<tag>.json``.

    python benchmarks/pool_failure.py --dx 4 3 2.5 2 --shape sector --tag sector
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "benchmarks"))

from loss_of_equilibrium import eigenpairs  # noqa: E402

from sphgag import config, threads  # noqa: E402
from sphgag.engine import geometry, hourglass, measure, pool_cavity, solver  # noqa: E402
from sphgag.engine.model import Model  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.physics import materials  # noqa: E402
from sphgag.studies import artery, protocols  # noqa: E402


@dataclass(frozen=True)
class SmoothPool:
    """A pool with a smooth outline, centred on ``sector``, of its radial extent and its area: an ellipse, or a
    stadium (straight sides along the arc, semicircular ends), in the local frame (arc length at the centre radius,
    radial offset)."""

    sector: geometry.Sector
    shape: str

    @property
    def area(self) -> float:
        (r0, r1), (t0, t1) = self.sector.r_range, self.sector.theta_range
        return 0.5 * (t1 - t0) * (r1 * r1 - r0 * r0)

    def contains(self, radius, theta):
        s = self.sector.centre_radius * (theta - np.deg2rad(self.sector.centre_angle_deg))
        t = radius - self.sector.centre_radius
        b = 0.5 * self.sector.radial_extent
        if self.shape == "ellipse":
            a = self.area / (np.pi * b)
            return (s / a) ** 2 + (t / b) ** 2 <= 1.0
        # stadium: half-length L of the straight part with area 2 L (2 b) + pi b^2
        half = 0.5 * (self.area - np.pi * b * b) / (2.0 * b)
        return (np.maximum(np.abs(s) - half, 0.0) ** 2 + t * t) <= b * b

    def members(self, layout, layer=None):
        mask = self.contains(layout.radius, layout.theta)
        if layer is not None:
            mask &= layout.layer_mask(layer)
        return np.flatnonzero(mask)


def classes(model: Model, members: np.ndarray, sector: geometry.Sector) -> dict:
    """Masks of the particle classes: the pool's interior and boundary particles (a neighbour outside the pool),
    its corners (boundary particles within 1.5 dx of a corner of the sector's outline), the lining tissue (a pool
    neighbour) and the other tissue."""
    n, lay, nb = model.n, model.layout, model.nb
    pool = np.zeros(n, dtype=bool)
    pool[members] = True
    owner = np.repeat(np.arange(n), nb.counts())
    touches_tissue = np.zeros(n, dtype=bool)
    touches_pool = np.zeros(n, dtype=bool)
    np.logical_or.at(touches_tissue, owner, ~pool[nb.nbr])
    np.logical_or.at(touches_pool, owner, pool[nb.nbr])
    boundary = pool & touches_tissue
    (r0, r1), (t0, t1) = sector.r_range, sector.theta_range
    corners = np.array([[r * np.cos(t), r * np.sin(t)] for r in (r0, r1) for t in (t0, t1)])
    near = np.min(np.linalg.norm(lay.X[:, None, :] - corners[None], axis=2), axis=1) <= 1.5 * lay.dx
    return dict(
        interior=pool & ~touches_tissue,
        boundary=boundary & ~near,
        corner=boundary & near,
        lining=~pool & touches_pool,
        tissue=~pool & ~touches_pool,
    )


def modes(model: Model, ev, masks: dict, shifts=(-1000.0, -100.0, -10.0, 0.0), k: int = 2) -> list[dict]:
    """The eigenvalues of K = -d(f_int + f_ext)/dx nearest each of ``shifts`` (the most negative ones, and the
    smallest), each with its participation, its share of |v|^2 per particle class and the hourglass share of
    v.K.v."""
    return [
        dict(
            eigenvalue=float(lam.real),
            participation=float(a.sum() ** 2 / (a * a).sum()),
            share={name: float(a[m].sum() / a.sum()) for name, m in masks.items()},
            hourglass_share=share,
            largest_particle=int(np.argmax(a)),
        )
        for lam, _, a, share in eigenpairs(model, ev, shifts, k, digits=6)
    ]


def extremes(J: np.ndarray, masks: dict) -> dict:
    """The smallest and largest J of each particle class."""
    return {name: [float(J[m].min()), float(J[m].max())] for name, m in masks.items() if m.any()}


def run(cfg, dx, args) -> dict:
    numerics = dict(cfg["numerics"], hourglass=args.hourglass)
    if args.alpha is not None:
        numerics["hourglass_alpha"] = args.alpha
    p = dict(cfg["bilayer"], dx_um=dx)
    if args.no_fibres:
        p["mass_fractions"] = {layer: {"elastin": f["elastin"]} for layer, f in p["mass_fractions"].items()}
    wall = artery.bilayer_model(p, numerics, name=f"wall_dx{dx:g}")
    homeo = protocols.homeostasis(wall, numerics, cfg["homeostasis"])
    start = protocols.pressurise(wall, homeo.state, args.pressure, numerics)
    sector = artery.pool_sector(cfg["swelling"]["cases"][args.case])
    pool = sector if args.shape == "sector" else SmoothPool(sector, args.shape)
    gag = materials.law_gag(cfg["gag"], "prescribed")
    if args.gag_hourglass is not None:
        gag = dict(gag, hourglass_modulus_kPa=args.gag_hourglass)
    model = artery.bilayer_model(p, numerics, name=f"pool_dx{dx:g}", pool=[pool], gag=gag)
    members = model.props.converting
    masks = classes(model, members, sector)
    sw = dict(cfg["swelling"], concentration_points=int(round(150.0 / args.step)) + 1)
    path_solver = Numerics.of(numerics).solver(model).using(max_bisections=args.bisections)
    t0 = time.time()
    base = protocols.swelling_load(start.load, 0.0, 0.0)
    conversion = [protocols.swelling_load(base, f, 0.0) for f in np.linspace(0, 1, sw["conversion_steps"] + 1)[1:]]
    state = path_solver.follow_path(start.x, base, conversion)[-1]
    V = model.layout.volume[members]
    if args.pool == "cavity":
        cav = pool_cavity.Cavity.around(model.layout, members, state.x)
        model = dataclasses.replace(model, cavities=(cav,))
        path_solver = solver.Solver(model, path_solver.options)
    reached, stall, path = 0.0, None, []
    for c in protocols.concentration_steps(sw):
        try:
            state = path_solver.follow_path(state.x, state.load, [protocols.swelling_load(base, 1.0, c)])[-1]
            reached = float(c)
            Jc = measure.cauchy_polar(state.evaluation)[3]
            cavity_ratio = cav.volume_ratio(state.x) if args.pool == "cavity" else None
            ratio = cavity_ratio or float(np.sum(V * Jc[members]) / V.sum())
            path.append([reached, ratio])
        except solver.SimulationError as exc:
            stall = exc
            break
    ev = state.evaluation
    J = measure.cauchy_polar(ev)[3]
    out = dict(
        dx_um=dx,
        particles=model.n,
        pool_particles=int(members.size),
        pool_area_um2=float(V.sum()),
        shape_area_um2=float(pool.area) if args.shape != "sector" else float(SmoothPool(sector, "ellipse").area),
        reached_mEq_l=reached,
        volume_ratio=path[-1][1] if path else float("nan"),
        path=path,
        class_sizes={name: int(m.sum()) for name, m in masks.items()},
        seconds=time.time() - t0,
    )
    out["last_converged"] = dict(J=extremes(J, masks), modes=modes(model, ev, masks))
    last = getattr(stall, "__cause__", None)
    if stall is not None:
        out["stall"] = dict(reason=stall.reason, load=solver.describe(stall.load))
        if last is not None and getattr(last, "evaluation", None) is not None:
            out["stall"]["modes"] = modes(model, last.evaluation, masks)
            out["stall"]["J"] = extremes(measure.cauchy_polar(last.evaluation)[3], masks)
    print(json.dumps(out), flush=True)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--dx", type=float, nargs="+", default=[4.0, 3.0, 2.5, 2.0])
    ap.add_argument("--case", default="I")
    ap.add_argument("--pressure", type=float, default=103.0)
    ap.add_argument("--shape", choices=("sector", "ellipse", "stadium"), default="sector")
    ap.add_argument("--gag-hourglass", type=float, default=None)
    ap.add_argument("--no-fibres", action="store_true")
    ap.add_argument("--hourglass", choices=hourglass.FORMS, default="paper")
    ap.add_argument("--alpha", type=float, default=None, help="alpha of eq. (2.14) (default the configuration's)")
    ap.add_argument("--pool", choices=("particles", "cavity"), default="particles")
    ap.add_argument("--step", type=float, default=12.5)
    ap.add_argument("--bisections", type=int, default=4)
    ap.add_argument("--tag", default="sector")
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    rows = [run(cfg, dx, args) for dx in args.dx]
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    (dest / f"pool_failure_{args.tag}.json").write_text(json.dumps(dict(args=vars(args), runs=rows), indent=1))


if __name__ == "__main__":
    main()
