"""Rule procedure_delaminate: a pool set grown by the authors' explicit damage stage at one sigma_cr and step factor."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, delamination, paper_procedure

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
p, w, wall = sm.params, sm.wildcards, sm.params.wall
run = f"procedure_{w.poolset}_{w.sigma}kPa_x{w.factor}"
with runlog.run(run, sm.log[0]) as log:
    model = artery.bilayer_model(dict(wall["bilayer"], dx_um=wall["dx"]), wall["numerics"], name=run)
    start = state.load(sm.input.start[0], expected_params=wall)
    settings = delamination.Settings.from_config(p.delamination, float(w.sigma), p.criterion)
    sectors = [artery.pool_sector(s) for s in p.pools]
    timing, stage = p.procedure["timing"], p.procedure["damage"]
    t0 = time.perf_counter()
    rows, saved = paper_procedure.delaminate(model, start.x, start.load, sectors, settings, p.gag, timing, stage,
                                             int(w.factor), run)  # fmt: skip
    seconds = time.perf_counter() - t0
    step_time = timing["time_step"]
    params = dict(sm.params)
    state.save_series(sm.output.states, [(r.x, r.load, r.info(step_time), None) for r in saved], params)
    rows.assign(pool_set=w.poolset, sigma_cr_kPa=float(w.sigma), step_factor=int(w.factor)).to_csv(
        sm.output.table, index=False
    )
    steps = int(rows.step.iloc[-1]) if len(rows) else 0
    log.info("[%s] %d steps in %.1f s (%.3g ms per step); end: %s", run, steps, seconds,
             1e3 * seconds / max(steps, 1), rows.end.iloc[-1] if len(rows) else "no step")  # fmt: skip
    summary = dict(steps=steps, seconds=seconds, ms_per_step=1e3 * seconds / max(steps, 1), particles=model.n)
    provenance.write_record(sm.output.provenance, rule="procedure_delaminate", params=params,
                            outputs=list(sm.output), summary=summary, started=started)  # fmt: skip
