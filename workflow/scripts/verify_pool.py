"""Rule verify_pool_ratio: a swelling elliptical inclusion against Inglis and Lame at every resolution."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import inclusion

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    table, profiles = inclusion.study(job.w.ratio, p.pool, p.matrix, p.gag, Numerics.of(p.numerics), log=job.log)
    table.to_csv(job.output.table, index=False)
    profiles.to_csv(job.output.profiles, index=False)
    order = inclusion.observed_order(table.dx_um, table.rel_error)
    job.log.info(
        "[%s] tip error %s; observed order %.2f",
        job.name,
        ", ".join(f"{e:+.2%} (b/dx = {r:g})" for e, r in zip(table.rel_error, table.b_over_dx)),
        order,
    )
    summary = dict(finest_rel_error=float(table.rel_error.iloc[-1]), observed_order=order)
    summary.update(max_residual=float(table.residual.max()))
    job.record(dict(ratio=job.w.ratio, **dict(p.items())), summary, rule="verify_pool")
