"""Rule animation: a delamination run's ParaView series drawn frame by frame as an animated GIF
(sphgag.views.animation)."""

from pathlib import Path

from sphgag import jobs
from sphgag.views import animation, paraview

with jobs.run(snakemake) as job:  # noqa: F821
    series = Path(job.input.series)
    frames = paraview.read_series(series / f"{series.name}.pvd")
    animation.write(job.output[0], frames, f"{job.w.law} charge, {job.w.run}")
    job.log.info("[%s] %d frames -> %s", job.name, len(frames), job.output[0])
