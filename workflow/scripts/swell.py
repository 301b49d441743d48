"""Rule swell: convert one medial pool to GAG and swell it at fixed lumen pressure under one charge law (figure 4);
saves the states."""

from sphgag import jobs
from sphgag.engine import solver
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery
from sphgag.studies.pool_swelling import swell_pool

with jobs.run(snakemake) as job:  # noqa: F821
    p, cfg = job.params, job.params.state_slice
    pool = artery.pool_sector(p.pool)
    numerics = Numerics.of(cfg["numerics"])
    model = artery.bilayer_model(cfg["bilayer"], numerics, job.name, pool, p.gag, p.grading)
    saved = state.load(job.input.state, job.params.state_slice)
    start = solver.State(saved.load, artery.carried(cfg["bilayer"], saved.x, model.layout), None, None)
    # every converged state up to the end of the path (each records how the path ended: PoolState)
    states = swell_pool(model, start, numerics, p.settings)
    end = states[-1].path_end + (f" ({states[-1].end_reason})" if states[-1].end_reason else "")
    params = dict(state=cfg, pool=p.pool, settings=p.settings, gag=p.gag, grading=p.grading)
    state.save_series(job.output.states, [(s.x, s.load, s.info(), None) for s in states], params)
    max_residual = max(s.residual for s in states)
    job.log.info(
        "[%s] %d pool particles; %d converged states up to %g mEq/l (end: %s), largest residual %.2e",
        *(job.name, model.props.converting.size, len(states), states[-1].concentration, end, max_residual),
    )
    summary = dict(max_residual=max_residual, end=end, last_concentration_mEq_l=states[-1].concentration)
    job.record(params, summary)
