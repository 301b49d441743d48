"""Rule pool_stresses: the stresses around one swollen pool (figure 4), measured on the states of rule swell."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, protocols

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
run = f"pool_stresses_{w.law}_{w.pool}_{w.model}_{w.case}_{w.pressure}mmHg"
with runlog.run(run, sm.log[0]) as log:
    cfg, p = sm.params.state_slice, sm.params
    pool = artery.pool_sector(p.pool)
    model = artery.bilayer_model(cfg["bilayer"], cfg["numerics"], name=run, pool=pool, gag=p.gag)
    saved = state.load_series(sm.input.states, dict(state=cfg, pool=p.pool, settings=p.settings, gag=p.gag))
    table = protocols.pool_table(model, [protocols.PoolState.from_saved(s) for s in saved], pool, p.probe_length, p.gag)
    table.insert(0, "charge_law", p.gag["charge_law"])
    table.insert(1, "pool_model", table.pop("pool_model"))
    table.insert(2, "model", w.model)
    table.insert(3, "case", w.case)
    table.to_csv(sm.output.table, index=False)
    last = table.iloc[-1]
    first = table[table.stage == "converted"].iloc[0]
    log.info(
        "[%s] %d pool particles; tip radial stress %.1f kPa intact, %.1f converted, %.1f at %g mEq/l; "
        "top hoop stress %.1f -> %.1f -> %.1f kPa",
        run,
        int(last.pool_particles),
        table.tip_radial_stress_kPa.iloc[0],
        first.tip_radial_stress_kPa,
        last.tip_radial_stress_kPa,
        last.concentration_mEq_l,
        table.top_circ_stress_kPa.iloc[0],
        first.top_circ_stress_kPa,
        last.top_circ_stress_kPa,
    )
    provenance.write_record(
        sm.output.provenance,
        rule="pool_stresses",
        params=dict(p),
        outputs=list(sm.output),
        summary=dict(max_residual=float(table.residual.max())),
        started=started,
    )
