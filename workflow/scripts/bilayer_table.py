"""Rule bilayer_table: passive + active pressure-diameter, and the diameter reduction by activation."""

import pandas as pd

from sphgag import jobs
from sphgag.studies import wall

with jobs.run(snakemake) as job:  # noqa: F821
    passive, active = pd.read_csv(job.input.passive), pd.read_csv(job.input.active)
    pd.concat([passive, active], ignore_index=True).to_csv(job.output.table, index=False)
    wall.activation_table(passive, active, job.params.pressure).to_csv(job.output.activation, index=False)
