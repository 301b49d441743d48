"""Rule swelling_convergence_stresses: the pool stresses of the resolution study at one particle spacing, measured on
the states of rule swelling_convergence_dx."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog, state
from sphgag.studies import convergence, protocols

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
run = f"swelling_convergence_stresses_{w.law}_{w.pool}_{w.model}_dx{w.dx}"
with runlog.run(run, sm.log[0]) as log:
    p = sm.params
    simulation = {k: v for k, v in dict(p).items() if k != "probe_length"}
    saved = state.load_series(sm.input.states, dict(dx=w.dx, **simulation))
    states = {case: [protocols.PoolState.from_saved(s) for s in saved if s.info["case"] == case] for case in p.cases}
    dx = float(w.dx)
    table = convergence.measure(dx, p.bilayer, p.numerics, p.gag, p.cases, states, p.probe_length, w.model, name=run)
    table.insert(0, "charge_law", p.gag["charge_law"])
    table.insert(1, "pool_model", table.pop("pool_model"))
    table.to_csv(sm.output.table, index=False)
    for case, g in table.groupby("case", sort=False):
        last = g.iloc[-1]
        log.info(
            "[%s] case %s, %d particles: at %g mEq/l tip %.1f kPa (peak %.1f), top %.1f kPa, pool volume change %+.3f",
            run,
            case,
            int(last.particles),
            last.concentration_mEq_l,
            last.tip_radial_stress_kPa,
            last.tip_peak_radial_stress_kPa,
            last.top_circ_stress_kPa,
            last.pool_volume_change,
        )
    provenance.write_record(
        sm.output.provenance,
        rule="swelling_convergence_stresses",
        params=dict(dx=w.dx, **dict(p)),
        outputs=list(sm.output),
        summary=dict(max_residual=float(table.residual.max())),
        started=started,
    )
