"""Rule claims: evaluate the paper's claims from the CSV tables and write a table and a Markdown page."""

import pandas as pd

from sphgag import claims, runlog

sm = snakemake  # noqa: F821
with runlog.run("claims", sm.log[0]) as log:
    t = {
        k: pd.read_csv(sm.input[k])
        for k in ("mean", "bilayer", "activation", "layers", "transmural", "tips", "growth", "delamination")
    }
    found = claims.calibration_claims(t["mean"], t["bilayer"], t["activation"], t["layers"], t["transmural"])
    found += claims.swelling_claims(t["tips"], sm.params.cases)
    found += claims.delamination_claims(t["growth"], t["delamination"], sm.params.criteria)
    df = claims.table(found)
    df.to_csv(sm.output.table, index=False)
    with open(sm.output.markdown, "w") as fh:
        fh.write(claims.markdown(df))
    for c in found:
        log.info("[claims] %s holds: %s -- %s (ours: %s)", c.claim_id, c.holds, c.statement, c.our_value)
