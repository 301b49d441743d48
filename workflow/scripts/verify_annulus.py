"""Rule verify_annulus_model: the pressurised annulus below and above its exact limit, at every spacing."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import annulus

with jobs.run(snakemake) as job:  # noqa: F821
    p, model = job.params, job.w.model
    table = annulus.annulus_study(p.annulus, p.matrix, p.gag, Numerics.of(p.numerics), model, log=job.log)
    table.to_csv(job.output.table, index=False)
    above, finest = table[table.fraction > 1.0], table[table.dx_um == table.dx_um.min()]
    summary = dict(
        states_above_the_limit=int(above.state.sum()),
        finest_max_volume_error=float(finest.volume_error.abs().max()),
        max_residual=float(table.residual.max()),
    )
    job.record(dict(model=model, **dict(p.items())), summary, rule="verify_annulus")
