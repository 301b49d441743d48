"""Rule swelling_convergence_dx: the figure 4 protocol at one particle spacing (resolution study); saves the states."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import convergence

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    # each case's converged states up to the end of its path (each records how the path ended)
    numerics = Numerics.of(p.numerics)
    wall = (p.bilayer, numerics, p.homeostasis, p.settings, p.gag, p.cases, p.pressure, p.calibration, p.active)
    states = convergence.swell_cases(job.w.dx, *wall, job.name, p.volume_ratios, p.grading)
    state.save_series(job.output.states, convergence.series(states, job.name), dict(p))
    max_residual = max(s.residual for ss in states.values() for s in ss)
    job.record(dict(p), dict(max_residual=max_residual, ends={case: ss[-1].path_end for case, ss in states.items()}))
