"""Rule swelling_convergence_dx: the figure 4 protocol at one particle spacing (resolution study)."""

import time

import numba

from sphgag import convergence, provenance, runlog

sm = snakemake  # noqa: F821
numba.set_num_threads(sm.threads)
started = time.time()
run = f"swelling_convergence_dx{sm.wildcards.dx}"
with runlog.run(run, sm.log[0]) as log:
    p = sm.params
    table = convergence.study(
        float(sm.wildcards.dx), p.bilayer, p.numerics, p.homeostasis, p.settings, p.gag, p.cases, p.pressure, name=run
    )
    table.to_csv(sm.output.table, index=False)
    for case, g in table.groupby("case", sort=False):
        last = g.iloc[-1]
        log.info(
            "[%s] case %s, %d particles: at %g mEq/l tip %.1f kPa (peak %.1f), top %.1f kPa, pool volume change %+.3f",
            run,
            case,
            int(last.particles),
            last.concentration_mEq_l,
            last.tip_radial_stress_kPa,
            last.tip_peak_radial_stress_kPa,
            last.top_circ_stress_kPa,
            last.pool_volume_change,
        )
    provenance.write_record(
        sm.output.provenance,
        rule="swelling_convergence",
        params=dict(
            dx=sm.wildcards.dx,
            bilayer=p.bilayer,
            numerics=p.numerics,
            homeostasis=p.homeostasis,
            settings=p.settings,
            gag=p.gag,
            cases=p.cases,
            pressure=p.pressure,
        ),
        outputs=list(sm.output),
        summary=dict(max_residual=float(table.residual.max())),
        started=started,
    )
