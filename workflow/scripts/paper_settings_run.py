"""Rule paper_settings_run: figure 4's protocol under one configuration of the paper_settings study, measured."""

from sphgag import jobs
from sphgag.studies import paper_settings

with jobs.run(snakemake) as job:  # noqa: F821
    table = paper_settings.run(job.params.run, job.w.model == "active", job.name)
    table = table.assign(base=job.w.base, setting=job.w.setting)
    table.to_csv(job.output.table, index=False)
    for case, g in table.groupby("case", sort=False):
        last = g.iloc[-1]
        job.log.info(
            "[%(run)s] case %(case)s, %(particles)d particles: at %(concentration_mEq_l)g mEq/l tip "
            "%(tip_radial_stress_kPa).1f kPa, top %(top_circ_stress_kPa).1f kPa, J %(J).3g (end: %(path_end)s)",
            dict(last, run=job.name, case=case, J=last.pool_volume_change + 1.0),
        )
    job.record(dict(job.params), dict(max_residual=float(table.residual.max())))
