"""Rule verify_profiles: every wall's rings in one table, each state's errors and their observed orders."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import wall_profiles

with jobs.run(snakemake) as job:  # noqa: F821
    rings = pd.concat([pd.read_csv(path) for path in job.input.tables], ignore_index=True)
    rings.to_csv(job.output.rings, index=False)
    table = wall_profiles.summary(rings)
    table.to_csv(job.output.table, index=False)
    wall_profiles.orders(table).to_csv(job.output.orders, index=False)
    wall_profiles.log_summary(table)
