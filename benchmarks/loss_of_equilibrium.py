"""Why growth under the prescribed Donnan law loses equilibrium: a residual floor, a kink, or the discretisation?

The single pool (case I) under the paper's law (Pi(c) prescribed,
eqs. 2.25-2.27), averaged onset, sigma_cr = 40 kPa, passive wall at 103 mmHg:

1. grow it with a snapshot at every pass until the first damage pass whose transition
   has no equilibrium on its path (the run then follows a snap, sphgag.engine.snap);
2. from the converged state before that pass, walk the transition t = 0 -> 1 with
   halved increments (down to 1/1024) to the furthest t reached quasi-statically, and
   keep the last Newton iterate at the first t it cannot reach (the stall);
3. at the stall: check the exact Jacobian against central differences of the residual
   along the Newton direction (a kink or a residual floor shows as an error that does
   not fall with the step), count the fibre families whose I4 crosses 1 (the switch of
   eq. 2.22's constants) along the step, and the residual's round-off;
4. at the last converged state and at the stall: the stiffness eigenvalues nearest
   -3000, -300 and 0 (shift-invert), each with the number of particles it involves
   (participation) and the share the hourglass penalty of eq. (2.14) contributes to
   ``v.K.v``.

Writes benchmarks/out/loss_of_equilibrium.json and prints a summary.

    python benchmarks/loss_of_equilibrium.py [--dx 4]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np
import scipy.sparse.linalg as spla

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from sphgag import config, threads  # noqa: E402
from sphgag.engine import measure, solver  # noqa: E402
from sphgag.engine.history import HistoryMaterial  # noqa: E402
from sphgag.engine.model import Model  # noqa: E402
from sphgag.engine.numerics import Numerics  # noqa: E402
from sphgag.physics import materials  # noqa: E402
from sphgag.studies import artery, delamination, protocols  # noqa: E402


def eigenpairs(model, ev, shifts, k, hourglass=True, digits=4):
    """Eigenpairs of K = -d(f_int + f_ext)/dx nearest each shift, each once (eigenvalues equal to ``digits``
    decimals are one), by eigenvalue: ``(eigenvalue, real eigenvector, |v|^2 per particle, hourglass share of
    v.K.v)``. With ``hourglass=False`` the stiffness without the hourglass term (alpha = 0) is the K."""
    no_hg = Model(model.name + "_no_hg", model.layout, model.nb, model.props, 0.0)
    K0 = -no_hg.block_matrix(no_hg.jacobian(no_hg.evaluate(ev.x, ev.load))).tocsc()
    K = -model.block_matrix(model.jacobian(ev)).tocsc() if hourglass else K0
    found = {}
    for shift in shifts:
        vals, vecs = spla.eigs(K, k=k, sigma=shift - 1e-3, which="LM")
        for lam, v in zip(vals, vecs.T):
            found[round(float(lam.real), digits)] = (lam, v)
    out = []
    for lam, v in sorted(found.values(), key=lambda p: p[0].real):
        v = np.real(v)
        out.append((lam, v, (v.reshape(-1, 2) ** 2).sum(axis=1), float(v @ (K - K0) @ v / (v @ K @ v))))
    return out


def stiffness_modes(model, ev, shifts=(-3000.0, -300.0, 0.0), k=3, hourglass=True):
    """Eigenvalues of K = -d(f_int + f_ext)/dx nearest each shift: value, participation, hourglass share (with
    ``hourglass=False``: of the stiffness without the hourglass term, alpha = 0)."""
    return [
        dict(
            eigenvalue=float(lam.real),
            imag=float(lam.imag),
            participation=float(a.sum() ** 2 / (a * a).sum()),
            hourglass_share=share,
        )
        for lam, _, a, share in eigenpairs(model, ev, shifts, k, hourglass)
    ]


def fibre_I4(model, ev):
    props = model.material(ev.load)[0]
    out = np.full((model.n, materials.MAX_FAMILIES), np.nan)
    for i in range(model.n):
        F = ev.F[i]
        ctt = materials.local_deformation(F[0, 0], F[0, 1], F[1, 0], F[1, 1], model.cth[i], model.sth[i])[5]
        for k in range(int(props[i, materials.NFAM])):
            base = materials.FAM0 + k * materials.FAM_STRIDE
            if props[i, base + materials.SIN2]:
                out[i, k] = materials._fibre_I4(props, i, base, ctt, ev.load.axial_stretch)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--config", default=str(ROOT / "config" / "config.yaml"))
    ap.add_argument("--dx", type=float, default=4.0)
    args = ap.parse_args()
    threads.use(1)
    cfg = config.validate(config.load_yaml(args.config), ROOT / "config" / "schema.yaml")
    numerics, de = cfg["numerics"], cfg["delamination"]
    gag = materials.law_gag(cfg["gag"], "prescribed")
    p = dict(cfg["bilayer"], dx_um=args.dx)
    wall = artery.bilayer_model(p, numerics, name="wall")
    start = protocols.pressurise(
        wall, protocols.homeostasis(wall, numerics, cfg["homeostasis"]).state, de["pressure_mmHg"], numerics
    )
    sectors = [artery.pool_sector(s) for s in de["pool_sets"]["single"]]
    settings = delamination.Settings.from_config(de, 40.0, "averaged")
    model = artery.bilayer_model(p, numerics, name="loss_of_equilibrium")
    base = model.props
    result = delamination.grow(
        model,
        solver.State(start.load, start.x, None, None),
        sectors,
        settings,
        numerics,
        gag,
        base,
        snapshot_steps=range(settings.max_passes + 1),
    )
    g = result.growth
    if not g.snap.any():
        print(f"no snap at dx = {args.dx:g} um: {result.summary['stop']}")
        return
    first = int(g[g.snap].pseudo_time.iloc[0])
    step, state, hist = [s for s in result.snapshots if s[0] == first - 1][-1]
    out = dict(
        dx_um=args.dx,
        particles=model.n,
        snap_pass=first,
        concentration_mEq_l=state.load.material_value("concentration"),
    )
    # the pass before the snap, rebuilt from its snapshot
    run = delamination.GrowthRun.resume(
        model, (solver.State(state.load, state.x, None, None), hist, step), sectors, settings, numerics, gag, base
    )
    out["last_converged"] = dict(
        residual=run.state.convergence.residual, modes=stiffness_modes(model, run.state.evaluation)
    )
    new = run.next_history().history
    model.set_props(HistoryMaterial(base, hist, gag, new))
    load = state.load
    x, t, dt, stall = state.x, 0.0, 0.25, None
    handoffs = solver.Solver(model, Numerics.of(numerics).solver_options().newton_budget())
    while t < 1.0 and dt >= 1.0 / 1024:
        target = min(t + dt, 1.0)
        try:
            x = handoffs.newton(x, load.with_material(transition=target), run="loss_of_equilibrium")[0]
            t = target
        except solver.NotConverged as exc:
            stall = exc
            dt /= 2
    out["transition_reached"] = t
    ev = stall.evaluation
    r = ev.residual_vector
    fac = solver.factorise(model, ev, model.jacobian(ev), 0.0, "diagnosis")
    d = fac.step(ev)
    checks = []
    for eps in (1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6):
        rr = model.evaluate(ev.x + eps * d, ev.load).residual_vector
        checks.append(
            dict(
                step=eps,
                residual_ratio=float(np.linalg.norm(rr) / np.linalg.norm(r)),
                jacobian_error=float(np.linalg.norm((rr - r) / eps + r) / np.linalg.norm(r)),
            )
        )
    again = model.evaluate(ev.x.copy(), ev.load).residual_vector
    I4_a, I4_b = fibre_I4(model, ev), fibre_I4(model, model.evaluate(ev.x + d, ev.load))
    srr, _, _, J = measure.cauchy_polar(ev)
    out["stall"] = dict(
        transition=float(ev.load.material_value("transition")),
        residual=solver.relative_residual(model, ev),
        reason=stall.reason,
        newton_step_um=float(np.abs(d).max()),
        directional_checks=checks,
        fibre_switches_along_step=int(np.nansum((I4_a - 1) * (I4_b - 1) < 0)),
        roundoff=float(np.linalg.norm(again - r) / np.linalg.norm(r)),
        pool_J_min=float(J[new.gag].min()),
        pool_J_max=float(J[new.gag].max()),
        modes=stiffness_modes(model, ev),
        elastic_modes=stiffness_modes(model, ev, shifts=(-30.0, 0.0), hourglass=False),
    )
    dest = ROOT / "benchmarks" / "out"
    dest.mkdir(exist_ok=True)
    (dest / "loss_of_equilibrium.json").write_text(json.dumps(out, indent=1))
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
