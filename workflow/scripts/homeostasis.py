"""Rule homeostasis: pre-stretch the bi-layered model at the held in vivo inner radius (figure 2b)."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery, wall
from sphgag.studies.wall_loading import homeostasis

with jobs.run(snakemake) as job:  # noqa: F821
    cfg = job.params.slice
    p, numerics, homeo = cfg["bilayer"], Numerics.of(cfg["numerics"]), cfg["homeostasis"]
    model = artery.bilayer_model(p, numerics, name=job.name)
    path_solver = numerics.solver(model)  # one solver (and factorisation) for both states
    passive = homeostasis(model, numerics, homeo, path_solver=path_solver)
    carried = {"carried_pressure_kPa": passive.pressures_kPa["reactions"]}
    state.save(job.output.state, passive.state.x, passive.state.load, cfg, info=carried)
    # the active tone switched on at the same held radius: what the contracted wall would carry there
    active = homeostasis(
        model, numerics, homeo, x0=passive.state.x, start=passive.state.load, activation=1.0, path_solver=path_solver
    )
    summary, profile, layers = wall.homeostasis_tables(model, p, dict(passive=passive, active=active))
    summary.to_csv(job.output.summary, index=False)
    profile.to_csv(job.output.profile, index=False)
    layers.to_csv(job.output.layers, index=False)
    wall.particle_table(model, passive.state.evaluation).to_csv(job.output.particles, index=False)
    job.record(cfg, summary.to_dict(orient="records"))
