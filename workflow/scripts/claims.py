"""Rule claims: evaluate the paper's claims from the CSV tables and write a table and a Markdown page.

The pool claims (figure 4, delamination) are evaluated once per charge law (``params.laws``), the delamination
claims on the pool sets of their figures (``params.figures``, i.e. ``delamination.figures``)."""

import pandas as pd

from sphgag import jobs
from sphgag.studies.claims.evidence import TARGETS, Evidence
from sphgag.studies.claims.verdicts import evaluate, markdown, table

with jobs.run(snakemake) as job:  # noqa: F821
    p = job.params
    t = {
        k: pd.read_csv(job.input[k])
        for k in ("mean", "bilayer", "activation", "layers", "transmural", "tips", "growth", "delamination")
    }
    # the evidence of other targets: read where this run or an earlier one made it, else the claim says "not run"
    studies = {name: pd.read_csv(p[name]["path"]) if p[name]["state"] != "not run" else None for name in TARGETS}
    evidence = Evidence(
        **t,
        **studies,
        cases=p.cases,
        max_concentration=p.max_concentration,
        criteria=tuple(p.criteria),
        figures=p.figures,
        study_pressure=p.study_pressure,
    )
    found = evaluate(evidence, p.laws)
    df = table(found)
    df.to_csv(job.output.table, index=False)
    with open(job.output.markdown, "w") as fh:
        fh.write(markdown(df))
    for c in found:
        job.log.info(
            "[claims] %s (%s) holds: %s -- %s (ours: %s)", c.claim_id, c.charge_law, c.holds, c.statement, c.our_value
        )
