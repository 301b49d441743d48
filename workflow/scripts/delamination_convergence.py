"""Rule delamination_convergence_dx: figure 5's pool set grown at one particle spacing under one charge law, every
onset criterion."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import delamination

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
run = f"delamination_convergence_{sm.wildcards.law}_dx{sm.wildcards.dedx}_{sm.wildcards.criterion}"
with runlog.run(run, sm.log[0]) as log:
    p = sm.params
    table = delamination.convergence_study(
        float(sm.wildcards.dedx), p.bilayer, p.numerics, p.homeostasis, p.delamination, p.gag, name=run
    )
    table.insert(0, "charge_law", p.gag["charge_law"])
    table.to_csv(sm.output.table, index=False)
    for row in table.itertuples():
        log.info(
            "[%s] %s onset: at %s mEq/l, delaminated %.1f um, stop: %s",
            run,
            row.criterion,
            row.onset_concentration_mEq_l,
            row.final_length_um,
            row.stop,
        )
    provenance.write_record(
        sm.output.provenance,
        rule="delamination_convergence",
        params=dict(
            dx=sm.wildcards.dedx,
            bilayer=p.bilayer,
            numerics=p.numerics,
            homeostasis=p.homeostasis,
            delamination=p.delamination,
            gag=p.gag,
        ),
        outputs=list(sm.output),
        summary=dict(max_residual=float(table.max_residual.max())),
        started=started,
    )
