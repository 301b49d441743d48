"""Rules delaminate and delaminate_fracture_energy: seed one pool set in the passive wall, swell it under one charge law
and let damage grow it, by the configured damage law (delamination.damage_law; eq. 2.28 as printed by default: figures
5-7) or by the damage law with a fracture energy G_c
(wildcard ``gc``: J/m^2, or the energy the paper's law dissipates in the matched run, MATCHED)."""

from sphgag import jobs
from sphgag.engine import solver
from sphgag.engine.numerics import Numerics
from sphgag.records import state
from sphgag.studies import artery
from sphgag.studies.delamination.runs import delaminate, fracture_energy, save_snapshots
from sphgag.studies.delamination.settings import Settings

with jobs.run(snakemake) as job:  # noqa: F821
    p, cfg, w = job.params, job.params.state_slice, job.w
    numerics = Numerics.of(cfg["numerics"])
    model = artery.bilayer_model(cfg["bilayer"], numerics, name=job.name)
    saved = state.load(job.input.state, job.params.state_slice)
    matched = job.input.get("matched") or None
    gc, unmatched = fracture_energy(getattr(w, "gc", None), matched, job.log, job.name)
    settings = Settings.from_config(p.delamination, w.sigma, w.criterion, gc)
    start, sectors = solver.State(saved.load, saved.x, None, None), [artery.pool_sector(s) for s in p.pools]
    growth, summary, result = delaminate(
        model, start, sectors, settings, numerics, cfg["bilayer"], p.gag, w.poolset, unmatched, run=job.name
    )
    growth.to_csv(job.output.growth, index=False)
    summary.to_csv(job.output.summary, index=False)
    params = dict(cfg, delamination=p.delamination, gag=p.gag)
    save_snapshots(job.output.snapshots, model, result.snapshots, params)
    s = summary.iloc[0]
    job.log.info(
        "[%s] stopped (%s) after %d passes: onset at %s mEq/l, delaminated %.1f um (%d islands apart, %s candidates), "
        "merged %s, dissipated %.3g J/m^2, max residual %.2e",
        *(job.name, s.stop, s.passes, s.onset_concentration_mEq_l, s.final_length_um, s.islands, s.candidates),
        *(s.merged, s.dissipated_energy_J_m2, s.max_residual),
    )
    params = dict(state=cfg, delamination=p.delamination, pools=p.pools, gag=p.gag)
    job.record(params, dict(max_residual=float(s.max_residual), passes=int(s.passes)), rule="delaminate")
