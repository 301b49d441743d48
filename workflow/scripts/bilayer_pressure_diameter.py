"""Rule bilayer_pressure_diameter: passive or active bi-layered model, 0-200 mmHg under pressure control."""

from sphgag import jobs
from sphgag.engine import solver
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery, wall
from sphgag.studies.pressure_diameter import bilayer_pressure_diameter, bilayer_tube

with jobs.run(snakemake) as job:  # noqa: F821
    cfg, label = job.params.slice, job.w.model
    p, numerics, calibration = cfg["bilayer"], Numerics.of(cfg["numerics"]), cfg["bilayer_calibration"]
    model = artery.bilayer_model(p, numerics, name=job.name)
    saved = state.load(job.input.homeostatic, job.params.homeostatic_slice)
    homeostatic = solver.State(saved.load, saved.x, model.evaluate(saved.x, saved.load), None)
    tube = bilayer_tube(p, active=job.params.active)
    res = bilayer_pressure_diameter(
        model, tube, homeostatic, numerics, calibration, active=job.params.active, label=label
    )
    res.states.to_csv(job.output.table, index=False)
    res.analytic.to_csv(job.output.exact, index=False)
    res.transmural.to_csv(job.output.transmural, index=False)
    for P, path in zip(calibration["state_pressures_mmHg"], job.output.states):
        s = res.saved[round(P, 10)]
        state.save(path, s.x, s.load, dict(cfg, model=label), info={"model": label, "pressure_mmHg": P})
    job.record(dict(cfg, model=label), wall.bilayer_summary(model, res, job.name))
