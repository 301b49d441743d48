"""Rule procedure_explicit: figure 4's pool by the authors' explicit procedure at one step factor."""

import time

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery, convergence, paper_procedure

with jobs.run(snakemake) as job:  # noqa: F821
    p, w, wall, run = job.params, job.w, job.params.wall, job.name
    entry, numerics = p.cases[w.case], Numerics.of(wall["numerics"])
    model = convergence.case_model(wall["dx"], wall["bilayer"], numerics, p.gag, entry, run)
    start = state.load(job.input.start, wall)
    model, base = paper_procedure.controlled(model, start.x, start.load, p.lumen_control, p.hourglass_factor)
    t0 = time.perf_counter()
    timing = p.procedure["timing"]
    records, end = paper_procedure.swell(model, start.x, base, timing, p.procedure["swelling"], w.factor, run)
    seconds, steps, step_time = time.perf_counter() - t0, records[-1].step, timing["time_step"]
    state.save_series(job.output.states, [(r.x, r.load, r.info(step_time), None) for r in records], dict(p))
    table = paper_procedure.table(model, records, artery.pool_sector(entry), p.probe_length, step_time, p.tip_probe)
    table.assign(model=w.model, case=w.case, step_factor=w.factor, particles=model.n, end=end).to_csv(
        job.output.table, index=False
    )
    ms = 1e3 * seconds / steps
    job.log.info(f"[{run}] {end}: {model.n} particles, {steps} steps in {seconds:.1f} s ({ms:.3g} ms per step)")
    summary = dict(steps=steps, seconds=seconds, ms_per_step=ms, particles=model.n, end=end)
    summary.update(last_residual=records[-1].residual)
    job.record(dict(p), summary)
