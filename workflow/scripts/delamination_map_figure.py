"""Rule delamination_map_figure: the delamination map, with the limit concentrations of figure 4's swelling runs."""

import pandas as pd

from sphgag import threads
from sphgag.records import runlog
from sphgag.views import sensitivity, style

sm = snakemake  # noqa: F821
threads.use(sm.threads)
with runlog.run("delamination_map_figure", sm.log[0]):
    table = pd.read_csv(sm.input.map)
    fig = sensitivity.delamination_map(
        table,
        pd.read_csv(sm.input.swelling),
        sm.params.cases,
        sm.params.pressure,
        list(dict.fromkeys(table.charge_law)),
    )
    style.save(fig, [sm.output.pdf, sm.output.png], "Delamination map of figure 5's pool, sphgag")
