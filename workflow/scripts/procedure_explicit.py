"""Rule procedure_explicit: figure 4's pool by the authors' explicit procedure at one step factor."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, convergence, paper_procedure

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
p, w, wall = sm.params, sm.wildcards, sm.params.wall
run = f"procedure_{w.model}_{w.case}_x{w.factor}"
with runlog.run(run, sm.log[0]) as log:
    entry = p.cases[w.case]
    model = convergence.case_model(wall["dx"], wall["bilayer"], wall["numerics"], p.gag, entry, run)
    start = state.load(sm.input.start, expected_params=wall)
    t0 = time.perf_counter()
    timing = p.procedure["timing"]
    records = paper_procedure.swell(model, start.x, start.load, timing, p.procedure["swelling"], int(w.factor), run)
    seconds = time.perf_counter() - t0
    steps = records[-1].step
    step_time = timing["time_step"]
    params = dict(sm.params)
    state.save_series(sm.output.states, [(r.x, r.load, r.info(step_time), None) for r in records], params)
    table = paper_procedure.table(model, records, artery.pool_sector(entry), p.probe_length, step_time)
    table.assign(model=w.model, case=w.case, step_factor=int(w.factor), particles=model.n).to_csv(
        sm.output.table, index=False
    )
    log.info("[%s] %d particles, %d steps in %.1f s (%.3g ms per step)", run, model.n, steps, seconds,
             1e3 * seconds / steps)  # fmt: skip
    summary = dict(steps=steps, seconds=seconds, ms_per_step=1e3 * seconds / steps, particles=model.n,
                   last_residual=records[-1].residual)  # fmt: skip
    provenance.write_record(sm.output.provenance, rule="procedure_explicit", params=params,
                            outputs=list(sm.output), summary=summary, started=started)  # fmt: skip
