"""Rules paraview_delamination and paraview_swelling: a run's saved states as a ParaView series, one .vtu file per
state and the .pvd collection named after the run (sphgag.views.paraview)."""

from pathlib import Path

from sphgag import jobs
from sphgag.views import paraview

with jobs.run(snakemake) as job:  # noqa: F821
    out = Path(job.output.series)
    frames = paraview.saved_series(job.input.states)
    pvd = paraview.write_series(out / f"{out.name}.pvd", frames)
    job.log.info("[%s] %d states of %s -> %s", job.name, len(frames), job.input.states, pvd)
    job.record(dict(states=job.input.states), dict(states=len(frames)), outputs=[str(pvd)])
