"""Rule delaminate: seed one pool set in the passive wall, swell it under one charge law and let damage grow it
(figures 5-7)."""

import time

import numba

from sphgag import artery, delamination, provenance, runlog, solver, state

sm = snakemake  # noqa: F821
numba.set_num_threads(sm.threads)
started = time.time()
w = sm.wildcards
run = f"delaminate_{w.law}_{w.poolset}_{w.sigma}kPa_{w.criterion}"
with runlog.run(run, sm.log[0]) as log:
    cfg, de = sm.params.state_slice, sm.params.delamination
    model = artery.bilayer_model(cfg["bilayer"], cfg["numerics"], name=run)
    saved = state.load(sm.input.state, expected_params=cfg)
    settings = delamination.Settings.from_config(de, float(w.sigma), w.criterion)
    sectors = [artery.pool_sector(s) for s in sm.params.pools]
    result = delamination.grow(
        model,
        solver.State(saved.load, saved.x, None, None),
        sectors,
        settings,
        cfg["numerics"],
        sm.params.gag,
        model.props,
        run=run,
    )
    growth, summary = delamination.labelled(result, w.poolset, settings, cfg["bilayer"]["dx_um"])
    growth.insert(0, "charge_law", sm.params.gag["charge_law"])
    summary.insert(0, "charge_law", sm.params.gag["charge_law"])
    growth.to_csv(sm.output.growth, index=False)
    summary.to_csv(sm.output.summary, index=False)
    delamination.save_snapshots(
        sm.output.snapshots, model, result.snapshots, dict(cfg, delamination=de, gag=sm.params.gag)
    )
    s = summary.iloc[0]
    log.info(
        "[%s] stopped (%s) after %d passes: onset at %s mEq/l, delaminated %.1f um, merged %s, dissipated "
        "%.3g J/m^2, max residual %.2e",
        run,
        s.stop,
        s.passes,
        s.onset_concentration_mEq_l,
        s.final_length_um,
        s.merged,
        s.dissipated_energy_J_m2,
        s.max_residual,
    )
    provenance.write_record(
        sm.output.provenance,
        rule="delaminate",
        params=dict(state=cfg, delamination=de, pools=sm.params.pools, gag=sm.params.gag),
        outputs=list(sm.output),
        summary=dict(max_residual=float(s.max_residual), passes=int(s.passes)),
        started=started,
    )
