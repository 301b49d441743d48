"""Rule docs_pages: the documentation site's results pages from the pipeline's tables (sphgag.views.pages)."""

from pathlib import Path

import pandas as pd

from sphgag import jobs
from sphgag.records import provenance
from sphgag.views import pages

with jobs.run(snakemake) as job:  # noqa: F821
    tables = {k: pd.read_csv(job.input[k]) for k in ("claims", "tips", "delamination")}
    for name, evidence in job.params.studies.items():  # a study's table where this run or an earlier one made it
        made = [pd.read_csv(e["path"]) for e in evidence if e["state"] != "not run"]
        tables[name] = pd.concat(made, ignore_index=True) if made and len(made) == len(evidence) else None
    # the checkout's commit: Snakemake reruns every table whose code changed since, so they are this commit's
    header = pages.stamp(provenance.git_commit(), job.params.configuration)
    figures = {Path(f).name: f for f in job.input.figures}
    pages.write(Path(job.output.pages[0]).parent, tables, figures, header, job.params.laws)
