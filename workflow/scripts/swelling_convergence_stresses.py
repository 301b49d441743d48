"""Rule swelling_convergence_stresses: the pool stresses of the resolution study at one particle spacing, measured on
the states of rule swelling_convergence_dx."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import convergence

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    saved = state.load_series(job.input.states, {k: v for k, v in dict(p).items() if k != "probe_length"})
    numerics = Numerics.of(p.numerics)
    table = convergence.measure_saved(
        saved, job.w.dx, p.bilayer, numerics, p.gag, p.cases, p.probe_length, job.w.model, job.name, p.grading
    )
    table.to_csv(job.output.table, index=False)
    job.record(dict(p), dict(max_residual=float(table.residual.max())))
