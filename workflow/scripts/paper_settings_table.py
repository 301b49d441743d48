"""Rule paper_settings_table: the ablation table of the paper_settings study and each setting's step."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import paper_settings

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    table = paper_settings.ablation([pd.read_csv(f) for f in job.input.runs], p.concentrations, p.tolerance)
    table.to_csv(job.output.table, index=False)
    steps = pd.concat([paper_settings.steps(table, c) for c in p.concentrations], ignore_index=True)
    steps.to_csv(job.output.steps, index=False)
    top = max(p.concentrations)
    for r in paper_settings.ranked(table, top).itertuples():
        job.log.info(
            f"[paper_settings] {r.setting}: median share {r.share:.2f} of ours - authors' at {top:g} mEq/l "
            f"(|step| {r.abs_step_kPa:.1f} kPa)"
        )
