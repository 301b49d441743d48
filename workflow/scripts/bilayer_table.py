"""Rule bilayer_table: passive + active pressure-diameter, and the diameter reduction by activation."""

import numpy as np
import pandas as pd

from sphgag import threads
from sphgag.records import runlog

sm = snakemake  # noqa: F821
threads.use(sm.threads)
PAPER_REDUCTION = 0.20  # "approximately 20 %" (paper sections 2.5 and 3)
with runlog.run("bilayer_table", sm.log[0]) as log:
    passive, active = pd.read_csv(sm.input.passive), pd.read_csv(sm.input.active)
    pd.concat([passive, active], ignore_index=True).to_csv(sm.output.table, index=False)
    P = sm.params.pressure
    rows = []
    for col in ("outer_diameter_um", "exact_outer_diameter_um"):
        od_p = float(np.interp(P, passive.pressure_mmHg, passive[col]))
        od_a = float(np.interp(P, active.pressure_mmHg, active[col]))
        rows.append(
            dict(
                source="sph" if col == "outer_diameter_um" else "semi_analytical",
                pressure_mmHg=P,
                passive_outer_diameter_um=od_p,
                active_outer_diameter_um=od_a,
                od_reduction=1.0 - od_a / od_p,
                paper_od_reduction=PAPER_REDUCTION,
            )
        )
    out = pd.DataFrame(rows)
    out.to_csv(sm.output.activation, index=False)
    for r in rows:
        log.info(
            "[bilayer_table] %s: activation at %.0f mmHg reduces the outer diameter from %.1f to %.1f um, "
            "by %.1f %% (paper: about %.0f %%)",
            r["source"],
            P,
            r["passive_outer_diameter_um"],
            r["active_outer_diameter_um"],
            100 * r["od_reduction"],
            100 * PAPER_REDUCTION,
        )
