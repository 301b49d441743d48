"""Rule swelling_convergence_dx: the figure 4 protocol at one particle spacing (resolution study); saves the states."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog, state
from sphgag.studies import convergence

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
run = f"swelling_convergence_{w.law}_{w.pool}_{w.model}_dx{w.dx}"
with runlog.run(run, sm.log[0]) as log:
    p = sm.params
    # each case's converged states up to the end of its path (each records how the path ended)
    states = convergence.swell_cases(
        float(w.dx),
        p.bilayer,
        p.numerics,
        p.homeostasis,
        p.settings,
        p.gag,
        p.cases,
        p.pressure,
        p.calibration,
        p.active,
        name=run,
        volume_ratios=p.volume_ratios,
    )
    ends = {case: ss[-1].path_end for case, ss in states.items()}
    params = dict(dx=w.dx, **dict(p))
    series = [(s.x, s.load, dict(s.info(), case=case), None) for case, ss in states.items() for s in ss]
    state.save_series(sm.output.states, series, params)
    max_residual = max(s.residual for ss in states.values() for s in ss)
    log.info("[%s] %d converged states of %d pools, largest residual %.2e", run, len(series), len(states), max_residual)
    for case, end in ends.items():
        path = [s for s in states[case] if s.stage == "converted"]
        held = ", ".join(f"{s.concentration:.4g}" for s in states[case] if s.stage == "at volume") or "none"
        log.info(
            "[%s] case %s: path up to %g mEq/l (end: %s); concentrations at the volume ratios: %s",
            run, case, path[-1].concentration, end, held,
        )  # fmt: skip
    provenance.write_record(
        sm.output.provenance,
        rule="swelling_convergence",
        params=params,
        outputs=list(sm.output),
        summary=dict(max_residual=max_residual, ends=ends),
        started=started,
    )
