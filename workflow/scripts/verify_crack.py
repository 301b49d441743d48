"""Rule verify_crack_length: a pressurised crack grown by the fracture-energy damage law, at every spacing."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import crack, inclusion

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
run = f"verify_crack_a{sm.wildcards.length}"
with runlog.run(run, sm.log[0]) as log:
    table = crack.study(
        float(sm.wildcards.length), sm.params.crack, sm.params.matrix, sm.params.gag, sm.params.numerics, log
    )
    table.to_csv(sm.output.table, index=False)
    orders = {
        k: inclusion.observed_order(table.dx_um, table[k]) for k in ("rel_error", "area_rel_error", "energy_rel_error")
    }
    log.info("[%s] observed orders: %s", run, ", ".join(f"{k} {v:.2f}" for k, v in orders.items()))
    provenance.write_record(
        sm.output.provenance,
        rule="verify_crack",
        params=dict(length=sm.wildcards.length, **dict(sm.params.items())),
        outputs=list(sm.output),
        summary=dict(
            finest_rel_error=float(table.rel_error.iloc[-1]),
            finest_area_rel_error=float(table.area_rel_error.iloc[-1]),
            finest_energy_rel_error=float(table.energy_rel_error.iloc[-1]),
            observed_orders=orders,
            max_residual=float(table.residual.max()),
        ),
        started=started,
    )
