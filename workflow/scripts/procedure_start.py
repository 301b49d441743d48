"""Rule procedure_start: the wall at the procedure's spacing and pressure (equilibrium), saved for its runs."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import convergence

with jobs.run(snakemake) as job:  # noqa: F821
    wall = job.params.wall
    typed = dict(wall, numerics=Numerics.of(wall["numerics"]))
    start = convergence.pressurised_wall(**typed, active=job.w.model == "active", name=job.name)
    state.save(job.output.start, start.x, start.load, wall, dict(residual=start.convergence.residual))
    job.log.info("[%s] residual %.2e", job.name, start.convergence.residual)
    job.record(dict(wall=wall), dict(residual=start.convergence.residual))
