"""Rule delamination_map_point: figure 5's pool at one angular extent and sigma_cr, grown over the concentration ramp
by eq. (2.28); what it does at each level (sphgag.studies.delamination.tables.level_classes)."""

import time

from sphgag import threads
from sphgag.engine import solver
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, delamination

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
run = f"delamination_map_{w.law}_{w.width}deg_{w.sigma}kPa"
with runlog.run(run, sm.log[0]) as log:
    cfg, de = sm.params.state_slice, sm.params.delamination
    model = artery.bilayer_model(cfg["bilayer"], cfg["numerics"], name=run)
    saved = state.load(sm.input.state, expected_params=cfg)
    settings = delamination.Settings.from_config(de, float(w.sigma), sm.params.criterion)
    result = delamination.grow(
        model,
        solver.State(saved.load, saved.x, None, None),
        [artery.pool_sector(sm.params.pool)],
        settings,
        cfg["numerics"],
        sm.params.gag,
        model.props,
        run=run,
    )
    table = delamination.level_classes(result.growth, result.summary, settings.levels)
    table.insert(0, "charge_law", sm.params.gag["charge_law"])
    table.insert(1, "angular_extent_deg", float(w.width))
    table.insert(2, "sigma_cr_kPa", float(w.sigma))
    s = result.summary
    table = table.assign(
        onset_concentration_mEq_l=s["onset_concentration_mEq_l"],
        stop_level_mEq_l=s["stop_level_mEq_l"],
        stop_kind=s["stop_kind"],
        stop=s["stop"],
        max_residual=s["max_residual"],
    )
    table.to_csv(sm.output.table, index=False)
    log.info(
        "[%s] %s; stopped in level %g mEq/l (%s)",
        run,
        ", ".join(f"{c:g}: {st}" for c, st in zip(table.concentration_mEq_l, table.state)),
        s["stop_level_mEq_l"],
        s["stop"],
    )
    provenance.write_record(
        sm.output.provenance,
        rule="delamination_map_point",
        params=dict(state=cfg, delamination=de, pool=sm.params.pool, gag=sm.params.gag, criterion=sm.params.criterion),
        outputs=list(sm.output),
        summary=dict(max_residual=float(s["max_residual"]), stop=s["stop"]),
        started=started,
    )
