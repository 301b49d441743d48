"""Rule variants_figure: the hourglass control's forms side by side (figure 4's first pool, figure 5's pool)."""

import pandas as pd

from sphgag import jobs
from sphgag.views import style, variants

with jobs.run(snakemake) as job:  # noqa: F821
    tables = {
        k: pd.concat([pd.read_csv(p) for p in job.input[k]], ignore_index=True)
        for k in ("swelling", "growth", "summary")
    }
    fig = variants.hourglass_comparison(
        tables["swelling"], tables["growth"], tables["summary"], job.params.forms, job.params.default
    )
    style.save(fig, [job.output.pdf, job.output.png], "The hourglass control's forms side by side, sphgag")
