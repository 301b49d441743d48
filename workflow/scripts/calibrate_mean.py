"""Rule calibrate_mean: the figure 2a protocol on the mean-behaviour model."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import artery, wall
from sphgag.studies.pressure_diameter import mean_pressure_diameter, mean_thick_wall

with jobs.run(snakemake) as job:  # noqa: F821
    p, numerics, calibration = dict(job.params.mean), Numerics.of(job.params.numerics), dict(job.params.calibration)
    model = artery.mean_model(p, numerics, name=job.name)
    result = mean_pressure_diameter(model, mean_thick_wall(p), p, numerics, calibration)
    result.states.to_csv(job.output.states, index=False)
    result.analytic.to_csv(job.output.exact, index=False)
    result.transmural.to_csv(job.output.transmural, index=False)
    job.record(dict(job.params), wall.mean_summary(model, result, numerics.tolerance))
