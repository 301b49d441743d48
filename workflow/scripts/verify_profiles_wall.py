"""Rule verify_profiles_wall: one wall section's rings against the exact thick wall at one spacing and lumen load."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import wall_profiles

with jobs.run(snakemake) as job:  # noqa: F821
    p, w = job.params, job.w
    numerics = Numerics.of(dict(p.numerics, lumen_load=w.load))
    wall = dict(p.wall, dx_um=wall_profiles.spacing(p.wall["dx_um"], w.level))
    if w.section == "mean":
        found = wall_profiles.mean_states(wall, numerics, p.calibration, p.pressures)
    else:
        found = wall_profiles.bilayer_states(wall, numerics, p.homeostasis, p.bilayer_calibration, p.walls, p.pressures)
    rings = wall_profiles.wall_rings(found, p.recoveries, lumen_load=w.load, dx_um=wall["dx_um"])
    rings.to_csv(job.output.table, index=False)
    table = wall_profiles.summary(rings)
    wall_profiles.log_summary(table)
    summary = dict(particles=found[0][1].n, max_residual=float(table.residual.max()))
    job.record(dict(dx_um=wall["dx_um"], **dict(p.items())), summary, rule="verify_profiles")
