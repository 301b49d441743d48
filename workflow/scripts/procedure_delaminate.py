"""Rule procedure_delaminate: a pool set grown by the authors' explicit damage stage at one sigma_cr and step factor."""

import time

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery, paper_procedure
from sphgag.studies.delamination.settings import Settings

with jobs.run(snakemake) as job:  # noqa: F821
    p, w, wall, run = job.params, job.w, job.params.wall, job.name
    model = artery.bilayer_model(dict(wall["bilayer"], dx_um=wall["dx"]), Numerics.of(wall["numerics"]), name=run)
    start = state.load(job.input.start[0], wall)
    settings = Settings.from_config(p.delamination, w.sigma, p.criterion)
    sectors = [artery.pool_sector(s) for s in p.pools]
    timing, stage = p.procedure["timing"], p.procedure["damage"]
    t0 = time.perf_counter()
    procedure = (sectors, settings, p.gag, timing, stage, w.factor, run)
    rows, saved = paper_procedure.delaminate(model, start.x, start.load, *procedure)
    seconds, step_time = time.perf_counter() - t0, timing["time_step"]
    state.save_series(job.output.states, [(r.x, r.load, r.info(step_time), None) for r in saved], dict(p))
    rows.assign(pool_set=w.poolset, sigma_cr_kPa=w.sigma, step_factor=w.factor).to_csv(job.output.table, index=False)
    steps = int(rows.step.iloc[-1]) if len(rows) else 0
    summary = dict(steps=steps, seconds=seconds, ms_per_step=1e3 * seconds / max(steps, 1), particles=model.n)
    end = rows.end.iloc[-1] if len(rows) else "no step"
    job.log.info(f"[{run}] {steps} steps in {seconds:.1f} s ({summary['ms_per_step']:.3g} ms per step); end: {end}")
    job.record(dict(p), summary)
