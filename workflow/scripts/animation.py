"""Rule animation: a delamination run's ParaView series drawn frame by frame as an animated GIF
(sphgag.views.animation)."""

from pathlib import Path

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import animation, paraview

sm = snakemake  # noqa: F821
threads.use(sm.threads)
series = Path(sm.input.series)
run = f"animation_{sm.wildcards.law}_{series.name}"
with runlog.run(run, sm.log[0]) as log:
    frames = paraview.read_series(series / f"{series.name}.pvd")
    animation.write(sm.output[0], frames, f"{sm.wildcards.law} charge, {series.name}")
    log.info("[%s] %d frames -> %s", run, len(frames), sm.output[0])
