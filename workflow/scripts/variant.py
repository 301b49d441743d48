"""Rule variant: figure 4's first pool and figure 5's pool at one form of the hourglass control, from a wall of their
own (sphgag.studies.variants)."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import variants

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
run = f"variant_hourglass_{sm.wildcards.form}"
with runlog.run(run, sm.log[0]) as log:
    p = sm.params
    v = variants.run_variant(p.bilayer, p.numerics, p.homeostasis, p.swelling, p.delamination, p.gag, name=run)
    for table, path in ((v.swelling, sm.output.swelling), (v.growth, sm.output.growth), (v.summary, sm.output.summary)):
        table.insert(0, "hourglass", sm.wildcards.form)
        table.insert(1, "charge_law", p.gag["charge_law"])
        table.to_csv(path, index=False)
    s, last = v.summary.iloc[0], v.swelling.iloc[-1]
    log.info(
        "[%s] figure 4's pool: %g mEq/l reached, volume change %.3g; figure 5's pool: %s (%s), onset %.2f mEq/l, "
        "runaway %.2f mEq/l, %.1f um",
        run,
        last.concentration_mEq_l,
        last.pool_volume_change,
        s.stop_kind,
        s.stop,
        s.onset_concentration_mEq_l,
        s.runaway_concentration_mEq_l,
        s.final_length_um,
    )
    provenance.write_record(
        sm.output.provenance,
        rule="variant",
        params=dict(p),
        outputs=list(sm.output),
        summary=dict(max_residual=float(max(v.swelling.residual.max(), s.max_residual)), stop_kind=s.stop_kind),
        started=started,
    )
