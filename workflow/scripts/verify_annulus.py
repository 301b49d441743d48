"""Rule verify_annulus_model: the pressurised annulus below and above its exact limit, at every spacing."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import annulus

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
run = f"verify_annulus_{sm.wildcards.model}"
with runlog.run(run, sm.log[0]) as log:
    p = sm.params
    table = annulus.annulus_study(p.annulus, p.matrix, p.gag, p.numerics, sm.wildcards.model, log=log)
    table.to_csv(sm.output.table, index=False)
    above = table[table.fraction > 1.0]
    provenance.write_record(
        sm.output.provenance,
        rule="verify_annulus",
        params=dict(model=sm.wildcards.model, **dict(p.items())),
        outputs=list(sm.output),
        summary=dict(
            states_above_the_limit=int(above.state.sum()),
            finest_max_volume_error=float(table[table.dx_um == table.dx_um.min()].volume_error.abs().max()),
            max_residual=float(table.residual.max()),
        ),
        started=started,
    )
