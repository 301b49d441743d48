"""Rule procedure_start: the wall at the procedure's spacing and pressure (equilibrium), saved for its runs."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog, state
from sphgag.studies import convergence

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w, model = sm.params.wall, sm.wildcards.model
run = f"procedure_start_{model}"
with runlog.run(run, sm.log[0]) as log:
    start = convergence.pressurised_wall(**w, active=model == "active", name=run)
    state.save(sm.output.start, start.x, start.load, w, dict(residual=start.convergence.residual))
    log.info("[%s] residual %.2e", run, start.convergence.residual)
    provenance.write_record(sm.output.provenance, rule="procedure_start", params=dict(wall=w),
                            outputs=list(sm.output), summary=dict(residual=start.convergence.residual),
                            started=started)  # fmt: skip
