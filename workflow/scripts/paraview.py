"""Rules paraview_delamination and paraview_swelling: a run's saved states as a ParaView series, one .vtu file per
state and the .pvd collection named after the run (sphgag.views.paraview)."""

import time
from pathlib import Path

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.views import paraview

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
out = Path(sm.output.series)
run = "_".join(
    [sm.rule, sm.wildcards.law] + ([sm.wildcards.pool] if "pool" in sm.wildcards.keys() else []) + [out.name]
)
with runlog.run(run, sm.log[0]) as log:
    frames = paraview.saved_series(sm.input.states)
    pvd = paraview.write_series(out / f"{out.name}.pvd", frames)
    log.info("[%s] %d states of %s -> %s", run, len(frames), sm.input.states, pvd)
    provenance.write_record(
        sm.output.provenance,
        rule=sm.rule,
        params=dict(states=sm.input.states),
        outputs=[str(pvd)],
        summary=dict(states=len(frames)),
        started=started,
    )
