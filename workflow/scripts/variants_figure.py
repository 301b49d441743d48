"""Rule variants_figure: the hourglass control's forms side by side (figure 4's first pool, figure 5's pool)."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import style, variants

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("variants_figure", sm.log[0]):
    tables = {
        k: pd.concat([pd.read_csv(p) for p in sm.input[k]], ignore_index=True)
        for k in ("swelling", "growth", "summary")
    }
    fig = variants.hourglass_comparison(
        tables["swelling"], tables["growth"], tables["summary"], sm.params.forms, sm.params.default
    )
    style.save(fig, [sm.output.pdf, sm.output.png], "The hourglass control's forms side by side, sphgag")
