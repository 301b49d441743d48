"""Rule variant: figure 4's first pool and figure 5's pool at one form of the hourglass control, from a wall of their
own (sphgag.studies.variants)."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import variants

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    numerics = Numerics.of(p.numerics)
    v = variants.run_variant(p.bilayer, numerics, p.homeostasis, p.swelling, p.delamination, p.gag, name=job.name)
    for what in ("swelling", "growth", "summary"):  # each table first by its form and charge law
        table = getattr(v, what)
        table.insert(0, "hourglass", job.w.form)
        table.insert(1, "charge_law", p.gag["charge_law"])
        table.to_csv(job.output[what], index=False)
    s, last = v.summary.iloc[0], v.swelling.iloc[-1]
    job.log.info(
        "[%s] figure 4's pool: %g mEq/l reached, volume change %.3g; figure 5's pool: %s (%s), onset %.2f mEq/l, "
        "runaway %.2f mEq/l, %.1f um",
        *(job.name, last.concentration_mEq_l, last.pool_volume_change, s.stop_kind, s.stop),
        *(s.onset_concentration_mEq_l, s.runaway_concentration_mEq_l, s.final_length_um),
    )
    job.record(dict(p), dict(max_residual=float(max(v.swelling.residual.max(), s.max_residual)), stop_kind=s.stop_kind))
