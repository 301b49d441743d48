"""Rule calibrate_mean: the figure 2a protocol on the mean-behaviour model."""

import time

from sphgag import threads
from sphgag.records import provenance, runlog
from sphgag.studies import artery, protocols

sm = snakemake  # noqa: F821 (injected by Snakemake)
threads.use(sm.threads)
started = time.time()
with runlog.run("calibrate_mean", sm.log[0]) as log:
    p, numerics, calibration = dict(sm.params.mean), dict(sm.params.numerics), dict(sm.params.calibration)
    model = artery.mean_model(p, numerics, name="calibrate_mean")
    result = protocols.mean_pressure_diameter(model, artery.mean_thick_wall(p), p, numerics, calibration)
    result.states.to_csv(sm.output.states, index=False)
    result.analytic.to_csv(sm.output.exact, index=False)
    result.transmural.to_csv(sm.output.transmural, index=False)
    s = result.states
    summary = dict(
        particles=model.n,
        max_od_rel_error_10_200_mmHg=result.max_od_error(10.0),
        max_residual=float(s.residual.max()),
        max_equilibrium_error=float(s.equilibrium_error.abs().max()),
        mean_force_evaluations_per_state=float(s.force_evaluations.mean()),
        mean_newton_iterations_per_state=float(s.newton_iterations.mean()),
    )
    log.info(
        "[calibrate_mean] SPH vs exact thick wall: max |OD error| over 10-200 mmHg = %.4f %% (%d particles)",
        100 * summary["max_od_rel_error_10_200_mmHg"],
        model.n,
    )
    log.info(
        "[calibrate_mean] largest residual %.2e (tolerance %.0e); global equilibrium "
        "|int sigma_tt dr / (P r_in) - 1| <= %.2e",
        summary["max_residual"],
        numerics["tolerance"],
        summary["max_equilibrium_error"],
    )
    log.info(
        "[calibrate_mean] %.1f force evaluations and %.1f Newton iterations per converged state",
        summary["mean_force_evaluations_per_state"],
        summary["mean_newton_iterations_per_state"],
    )
    provenance.write_record(
        sm.output.provenance,
        rule="calibrate_mean",
        params=dict(sm.params),
        outputs=list(sm.output),
        summary=summary,
        started=started,
    )
