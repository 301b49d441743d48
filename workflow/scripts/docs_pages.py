"""Rule docs_pages: the documentation site's results pages from the pipeline's tables (sphgag.views.pages)."""

from pathlib import Path

import pandas as pd

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.views import pages

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("docs_pages", sm.log[0]):
    tables = {k: pd.read_csv(sm.input[k]) for k in ("claims", "tips", "delamination")}
    for name, evidence in sm.params.studies.items():  # a study's table where this run or an earlier one made it
        made = [pd.read_csv(e["path"]) for e in evidence if e["state"] != "not run"]
        tables[name] = pd.concat(made, ignore_index=True) if made and len(made) == len(evidence) else None
    # the checkout's commit: Snakemake reruns every table whose code changed since, so they are this commit's
    header = pages.stamp(provenance.git_commit(), sm.params.configuration)
    pages.write(Path(sm.output.pages[0]).parent, tables, {Path(f).name: f for f in sm.input.figures}, header)
