"""Rule bilayer_pressure_diameter: passive or active bi-layered model, 0-200 mmHg under pressure control."""

import time

from sphgag import threads
from sphgag.engine import solver
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, protocols

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
label = sm.wildcards.model
run = f"bilayer_{label}"
with runlog.run(run, sm.log[0]) as log:
    cfg = sm.params.slice
    p, numerics = cfg["bilayer"], cfg["numerics"]
    model = artery.bilayer_model(p, numerics, name=run)
    saved = state.load(sm.input.homeostatic, expected_params=sm.params.homeostatic_slice)
    homeostatic = solver.State(saved.load, saved.x, model.evaluate(saved.x, saved.load), None)
    tube = artery.bilayer_tube(p, active=sm.params.active)
    res = protocols.bilayer_pressure_diameter(
        model, tube, homeostatic, numerics, cfg["bilayer_calibration"], active=sm.params.active, label=label
    )
    res.states.to_csv(sm.output.table, index=False)
    res.analytic.to_csv(sm.output.exact, index=False)
    res.transmural.to_csv(sm.output.transmural, index=False)
    pressures = cfg["bilayer_calibration"]["state_pressures_mmHg"]
    for P, path in zip(pressures, sm.output.states):
        s = res.saved[round(P, 10)]
        state.save(path, s.x, s.load, dict(cfg, model=label), info={"model": label, "pressure_mmHg": P})
    s = res.states
    summary = dict(
        particles=model.n,
        max_od_rel_error_60_200_mmHg=res.max_od_error(60.0),
        max_od_rel_error_0_200_mmHg=res.max_od_error(0.0),
        max_residual=float(s.residual.max()),
        mean_force_evaluations_per_state=float(s.force_evaluations.mean()),
    )
    log.info(
        "[%s] SPH vs semi-analytical bi-layered tube: max |OD error| %.3f %% over 60-200 mmHg, %.3f %% over "
        "0-200 mmHg (%d particles); largest residual %.2e",
        run,
        100 * summary["max_od_rel_error_60_200_mmHg"],
        100 * summary["max_od_rel_error_0_200_mmHg"],
        model.n,
        summary["max_residual"],
    )
    provenance.write_record(
        sm.output.provenance,
        rule="bilayer_pressure_diameter",
        params=dict(cfg, model=label),
        outputs=list(sm.output),
        summary=summary,
        started=started,
    )
