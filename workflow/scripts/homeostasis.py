"""Rule homeostasis: pre-stretch the bi-layered model at the held in vivo inner radius (figure 2b)."""

import time

import pandas as pd

from sphgag import threads
from sphgag.engine import measure
from sphgag.engine.loading import MMHG_TO_KPA
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, protocols

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
with runlog.run("homeostasis", sm.log[0]) as log:
    cfg = sm.params.slice
    p, numerics, homeo = cfg["bilayer"], cfg["numerics"], cfg["homeostasis"]
    model = artery.bilayer_model(p, numerics, name="homeostasis")
    passive = protocols.homeostasis(model, numerics, homeo)
    state.save(
        sm.output.state,
        passive.state.x,
        passive.state.load,
        cfg,
        info={"carried_pressure_kPa": passive.pressures_kPa["reactions"]},
    )
    # the active tone switched on at the same held radius: what the contracted wall would carry there
    active = protocols.homeostasis(model, numerics, homeo, x0=passive.state.x, start=passive.state.load, activation=1.0)
    rows, profiles, layers = [], [], []
    for label, h in (("passive", passive), ("active", active)):
        tube = artery.bilayer_tube(p, active=label == "active")
        semi = tube.pressure(model.layout.inner_radius) / MMHG_TO_KPA
        row = dict(
            model=label,
            carried_pressure_mmHg=h.pressures_kPa["reactions"] / MMHG_TO_KPA,
            inner_radius_um=measure.surface_radius(model, h.state.x, "inner"),
            outer_radius_um=measure.surface_radius(model, h.state.x, "outer"),
            residual=h.state.convergence.residual,
            inner_stress_pressure_mmHg=h.pressures_kPa["inner_radial_stress"] / MMHG_TO_KPA,
            equilibrium_pressure_mmHg=h.pressures_kPa["hoop_equilibrium"] / MMHG_TO_KPA,
            semi_analytical_pressure_mmHg=semi,
        )
        for _, ls in h.layers.iterrows():
            row[f"{ls.layer}_circ_stress_kPa"] = ls.circ_stress_mean_kPa
            row[f"{ls.layer}_circ_variation"] = ls.circ_variation
        rows.append(row)
        profiles.append(h.profile.assign(model=label))
        layers.append(h.layers.assign(model=label))
        log.info(
            "[homeostasis] %s: carried pressure %.2f mmHg from the reactions, %.2f from global equilibrium, "
            "%.2f from the inner ring's radial stress; semi-analytical %.2f",
            label,
            row["carried_pressure_mmHg"],
            row["equilibrium_pressure_mmHg"],
            row["inner_stress_pressure_mmHg"],
            semi,
        )
        for _, ls in h.layers.iterrows():
            log.info(
                "[homeostasis] %s %s: circumferential stress %.1f kPa, (max - min)/mean over %d rings = %.1f %%",
                label,
                ls.layer,
                ls.circ_stress_mean_kPa,
                ls.rings,
                100 * ls.circ_variation,
            )
    summary = pd.DataFrame(rows)
    summary.to_csv(sm.output.summary, index=False)
    pd.concat(profiles).to_csv(sm.output.profile, index=False)
    pd.concat(layers).to_csv(sm.output.layers, index=False)
    lay = model.layout
    srr, stt, _, J = measure.cauchy_polar(passive.state.evaluation)
    pd.DataFrame(
        dict(
            x_um=lay.X[:, 0],
            y_um=lay.X[:, 1],
            radius_um=lay.radius,
            theta_rad=lay.theta,
            ring=lay.ring,
            layer=[lay.layer_names[k] for k in lay.layer],
            volume_um2=lay.volume,
            radial_stress_kPa=srr,
            circ_stress_kPa=stt,
            jacobian=J,
        )
    ).to_csv(sm.output.particles, index=False)
    provenance.write_record(
        sm.output.provenance,
        rule="homeostasis",
        params=cfg,
        outputs=list(sm.output),
        summary=summary.to_dict(orient="records"),
        started=started,
    )
