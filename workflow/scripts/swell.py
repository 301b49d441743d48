"""Rule swell: convert one medial pool to GAG and swell it at fixed lumen pressure (figure 4)."""

import time

import numba

from sphgag import artery, protocols, provenance, runlog, solver, state

sm = snakemake  # noqa: F821
numba.set_num_threads(sm.threads)
started = time.time()
w = sm.wildcards
run = f"swell_{w.model}_{w.case}_{w.pressure}mmHg"
with runlog.run(run, sm.log[0]) as log:
    cfg = sm.params.state_slice
    pool = artery.pool_sector(sm.params.pool)
    model = artery.bilayer_model(cfg["bilayer"], cfg["numerics"], name=run, pool=pool, gag=sm.params.gag)
    saved = state.load(sm.input.state, expected_params=cfg)
    start = solver.State(saved.load, saved.x, None, None)
    table = protocols.swell_pool(model, start, pool, cfg["numerics"], sm.params.settings, sm.params.gag)
    table.insert(0, "model", w.model)
    table.insert(1, "case", w.case)
    table.to_csv(sm.output.table, index=False)
    last = table.iloc[-1]
    first = table[table.stage == "converted"].iloc[0]
    log.info("[%s] %d pool particles; tip radial stress %.1f kPa intact, %.1f converted, %.1f at %g mEq/l; "
             "top hoop stress %.1f -> %.1f -> %.1f kPa", run, int(last.pool_particles), table.tip_radial_stress_kPa.iloc[0],
             first.tip_radial_stress_kPa, last.tip_radial_stress_kPa, last.concentration_mEq_l,
             table.top_circ_stress_kPa.iloc[0], first.top_circ_stress_kPa, last.top_circ_stress_kPa)
    provenance.write_record(sm.output.provenance, rule="swell", params=dict(state=cfg, pool=sm.params.pool,
                            settings=sm.params.settings, gag=sm.params.gag), outputs=list(sm.output),
                            summary=dict(max_residual=float(table.residual.max())), started=started)
