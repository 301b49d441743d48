"""Rule procedure_equilibrium: figure 4's equilibrium paths at the procedure's spacing and temperature."""

from sphgag import jobs
from sphgag.engine import solver
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import convergence
from sphgag.studies.pool_swelling import swell_pool

with jobs.run(snakemake) as job:  # noqa: F821
    p, wall, run = job.params, job.params.wall, job.name
    numerics = Numerics.of(wall["numerics"])
    saved = state.load(job.input.start, wall)
    start = solver.State(saved.load, saved.x, None, None)
    states = {
        case: swell_pool(
            convergence.case_model(wall["dx"], wall["bilayer"], numerics, p.gag, entry, f"{run}_{case}"),
            start,
            numerics,
            p.settings,
        )
        for case, entry in p.cases.items()
    }
    table = convergence.measure(
        wall["dx"],
        wall["bilayer"],
        numerics,
        p.gag,
        p.cases,
        states,
        p.probe_length,
        job.w.model,
        run,
        tip_probe=p.tip_probe,
    )
    table.to_csv(job.output.table, index=False)
    job.log.info("[%s] %d particles; equilibrium paths of %s", run, int(table.particles.iloc[0]), ", ".join(p.cases))
    job.record(dict(p), dict(max_residual=float(table.residual.max())))
