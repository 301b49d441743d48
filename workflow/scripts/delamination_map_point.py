"""Rule delamination_map_point: figure 5's pool at one angular extent and sigma_cr, grown over the concentration ramp
by eq. (2.28); what it does at each level (sphgag.studies.delamination.growth.map_point)."""

from sphgag import jobs
from sphgag.engine import solver
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery
from sphgag.studies.delamination.growth import map_point
from sphgag.studies.delamination.settings import Settings

with jobs.run(snakemake) as job:  # noqa: F821
    p, cfg, w = job.params, job.params.state_slice, job.w
    numerics = Numerics.of(cfg["numerics"])
    model = artery.bilayer_model(cfg["bilayer"], numerics, name=job.name)
    saved = state.load(job.input.state, job.params.state_slice)
    settings = Settings.from_config(p.delamination, w.sigma, p.criterion)
    start, sector = solver.State(saved.load, saved.x, None, None), artery.pool_sector(p.pool)
    table, s = map_point(model, start, sector, settings, numerics, p.gag, w.width, run=job.name)
    table.to_csv(job.output.table, index=False)
    job.log.info(
        "[%s] %s; stopped in level %g mEq/l (%s)",
        job.name,
        ", ".join(f"{c:g}: {st}" for c, st in zip(table.concentration_mEq_l, table.state)),
        s["stop_level_mEq_l"],
        s["stop"],
    )
    params = dict(state=cfg, delamination=p.delamination, pool=p.pool, gag=p.gag, criterion=p.criterion)
    job.record(params, dict(max_residual=float(s["max_residual"]), stop=s["stop"]))
