"""Rule verify_circular_pool_model: a circular pool at large strain against its exact solution at every spacing."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import inclusion, swollen_pool

with jobs.run(snakemake) as job:  # noqa: F821
    p, model = job.params, job.w.model
    table = swollen_pool.circle_study(p.pool, p.matrix, p.gag, Numerics.of(p.numerics), model, log=job.log)
    table.to_csv(job.output.table, index=False)
    orders = {j: inclusion.observed_order(g.dx_um, g.volume_error) for j, g in table.groupby("target_volume_ratio")}
    shown = ", ".join(f"{o:.2f} (J = {j:g})" for j, o in orders.items())
    job.log.info("[%s] observed order of the volume error: %s", job.name, shown)
    finest = table[table.dx_um == table.dx_um.min()]
    summary = dict(
        finest_max_volume_error=float(finest.volume_error.abs().max()),
        observed_orders={f"{j:g}": o for j, o in orders.items()},
        max_residual=float(table.residual.max()),
    )
    job.record(dict(model=model, **dict(p.items())), summary, rule="verify_circular_pool")
