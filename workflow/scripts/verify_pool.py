"""Rule verify_pool_ratio: a swelling elliptical inclusion against Inglis and Lame at every resolution."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import inclusion

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
run = f"verify_pool_ab{sm.wildcards.ratio}"
with runlog.run(run, sm.log[0]) as log:
    table, profiles = inclusion.study(
        float(sm.wildcards.ratio), sm.params.pool, sm.params.matrix, sm.params.gag, sm.params.numerics, log=log
    )
    table.to_csv(sm.output.table, index=False)
    profiles.to_csv(sm.output.profiles, index=False)
    order = inclusion.observed_order(table.dx_um, table.rel_error)
    log.info(
        "[%s] tip error %s; observed order %.2f",
        run,
        ", ".join(f"{e:+.2%} (b/dx = {r:g})" for e, r in zip(table.rel_error, table.b_over_dx)),
        order,
    )
    provenance.write_record(
        sm.output.provenance,
        rule="verify_pool",
        params=dict(
            ratio=sm.wildcards.ratio,
            pool=sm.params.pool,
            matrix=sm.params.matrix,
            gag=sm.params.gag,
            numerics=sm.params.numerics,
        ),
        outputs=list(sm.output),
        summary=dict(
            finest_rel_error=float(table.rel_error.iloc[-1]),
            observed_order=order,
            max_residual=float(table.residual.max()),
        ),
        started=started,
    )
