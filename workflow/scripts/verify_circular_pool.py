"""Rule verify_circular_pool_model: a circular pool at large strain against its exact solution at every spacing."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import inclusion, swollen_pool

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
run = f"verify_circular_pool_{sm.wildcards.model}"
with runlog.run(run, sm.log[0]) as log:
    table = swollen_pool.circle_study(
        sm.params.pool, sm.params.matrix, sm.params.gag, sm.params.numerics, sm.wildcards.model, log=log
    )
    table.to_csv(sm.output.table, index=False)
    orders = {j: inclusion.observed_order(g.dx_um, g.volume_error) for j, g in table.groupby("target_volume_ratio")}
    shown = ", ".join(f"{o:.2f} (J = {j:g})" for j, o in orders.items())
    log.info("[%s] observed order of the volume error: %s", run, shown)
    finest = table[table.dx_um == table.dx_um.min()]
    provenance.write_record(
        sm.output.provenance,
        rule="verify_circular_pool",
        params=dict(model=sm.wildcards.model, **dict(sm.params.items())),
        outputs=list(sm.output),
        summary=dict(
            finest_max_volume_error=float(finest.volume_error.abs().max()),
            observed_orders={f"{j:g}": o for j, o in orders.items()},
            max_residual=float(table.residual.max()),
        ),
        started=started,
    )
