"""Rule verify_crack_length: a pressurised crack grown by the fracture-energy damage law, at every spacing."""

from sphgag import jobs
from sphgag.engine.numerics import Numerics
from sphgag.studies import crack, inclusion

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    table = crack.study(job.w.length, p.crack, p.matrix, p.gag, Numerics.of(p.numerics), job.log)
    table.to_csv(job.output.table, index=False)
    errors = ("rel_error", "area_rel_error", "energy_rel_error")
    orders = {k: inclusion.observed_order(table.dx_um, table[k]) for k in errors}
    job.log.info("[%s] observed orders: %s", job.name, ", ".join(f"{k} {v:.2f}" for k, v in orders.items()))
    finest = {f"finest_{k}": float(table[k].iloc[-1]) for k in errors}
    summary = dict(finest, observed_orders=orders, max_residual=float(table.residual.max()))
    job.record(dict(length=job.w.length, **dict(p.items())), summary, rule="verify_crack")
