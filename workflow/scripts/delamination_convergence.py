"""Rule delamination_convergence_dx: figure 5's pool set grown at one particle spacing under one charge law, every
onset criterion."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies.delamination.convergence import convergence_study

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    slices = (p.bilayer, Numerics.of(p.numerics), p.homeostasis, p.delamination, p.gag)
    table = convergence_study(job.w.dedx, *slices, name=job.name)
    table.insert(0, "charge_law", p.gag["charge_law"])
    table.to_csv(job.output.table, index=False)
    for row in table.itertuples():
        job.log.info(
            "[%s] %s onset: at %s mEq/l, delaminated %.1f um, stop: %s",
            *(job.name, row.criterion, row.onset_concentration_mEq_l, row.final_length_um, row.stop),
        )
    params = dict(dx=job.w.dedx, bilayer=p.bilayer, numerics=p.numerics, homeostasis=p.homeostasis)
    params.update(delamination=p.delamination, gag=p.gag)
    job.record(params, dict(max_residual=float(table.max_residual.max())), rule="delamination_convergence")
