"""Rule swell: convert one medial pool to GAG and swell it at fixed lumen pressure under one charge law (figure 4);
saves the states."""

import time

from sphgag import threads
from sphgag.engine import solver
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, protocols

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
run = f"swell_{w.law}_{w.pool}_{w.model}_{w.case}_{w.pressure}mmHg"
with runlog.run(run, sm.log[0]) as log:
    cfg = sm.params.state_slice
    pool = artery.pool_sector(sm.params.pool)
    model = artery.bilayer_model(cfg["bilayer"], cfg["numerics"], name=run, pool=pool, gag=sm.params.gag)
    saved = state.load(sm.input.state, expected_params=cfg)
    # every converged state up to the end of the path (each records how the path ended: protocols.PoolState)
    states = protocols.swell_pool(
        model, solver.State(saved.load, saved.x, None, None), cfg["numerics"], sm.params.settings
    )
    end = states[-1].path_end + (f" ({states[-1].end_reason})" if states[-1].end_reason else "")
    params = dict(state=cfg, pool=sm.params.pool, settings=sm.params.settings, gag=sm.params.gag)
    state.save_series(sm.output.states, [(s.x, s.load, s.info(), None) for s in states], params)
    max_residual = max(s.residual for s in states)
    log.info(
        "[%s] %d pool particles; %d converged states up to %g mEq/l (end: %s), largest residual %.2e",
        run,
        model.props.converting.size,
        len(states),
        states[-1].concentration,
        end,
        max_residual,
    )
    provenance.write_record(
        sm.output.provenance,
        rule="swell",
        params=params,
        outputs=list(sm.output),
        summary=dict(max_residual=max_residual, end=end, last_concentration_mEq_l=states[-1].concentration),
        started=started,
    )
