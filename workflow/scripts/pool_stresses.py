"""Rule pool_stresses: the stresses around one swollen pool (figure 4), measured on the states of rule swell."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery
from sphgag.studies.pool_swelling import run_table

with jobs.run(snakemake) as job:  # noqa: F821
    p, cfg = job.params, job.params.state_slice
    pool = artery.pool_sector(p.pool)
    model = artery.bilayer_model(cfg["bilayer"], Numerics.of(cfg["numerics"]), job.name, pool, p.gag, p.grading)
    run = dict(state=cfg, pool=p.pool, settings=p.settings, gag=p.gag, grading=p.grading)
    saved = state.load_series(job.input.states, run)
    table = run_table(model, saved, pool, p.probe_length, p.gag, job.w.model, job.w.case, job.name, p.tip_probe)
    table.to_csv(job.output.table, index=False)
    job.record(dict(p), dict(max_residual=float(table.residual.max())))
