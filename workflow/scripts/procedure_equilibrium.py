"""Rule procedure_equilibrium: figure 4's equilibrium paths at the procedure's spacing and temperature."""

import time

from sphgag import threads
from sphgag.engine import solver
from sphgag.records import provenance, runlog, state
from sphgag.studies import convergence, protocols

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
p, w, model = sm.params, sm.params.wall, sm.wildcards.model
run = f"procedure_equilibrium_{model}"
with runlog.run(run, sm.log[0]) as log:
    saved = state.load(sm.input.start, expected_params=w)
    start = solver.State(saved.load, saved.x, None, None)
    states = {
        case: protocols.swell_pool(convergence.case_model(w["dx"], w["bilayer"], w["numerics"], p.gag, entry,
                                                          f"{run}_{case}"), start, w["numerics"], p.settings)
        for case, entry in p.cases.items()
    }  # fmt: skip
    params = dict(sm.params)
    table = convergence.measure(w["dx"], w["bilayer"], w["numerics"], p.gag, p.cases, states, p.probe_length, model,
                                run)  # fmt: skip
    table.to_csv(sm.output.table, index=False)
    log.info("[%s] %d particles; equilibrium paths of %s", run, int(table.particles.iloc[0]), ", ".join(p.cases))
    provenance.write_record(sm.output.provenance, rule="procedure_equilibrium", params=params,
                            outputs=list(sm.output), summary=dict(max_residual=float(table.residual.max())),
                            started=started)  # fmt: skip
