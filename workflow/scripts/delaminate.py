"""Rules delaminate and delaminate_fracture_energy: seed one pool set in the passive wall, swell it under one charge law
and let damage grow it, by eq. (2.28) as printed (figures 5-7) or by the damage law with a fracture energy G_c
(wildcard ``gc``: J/m^2, or ``paper`` for the energy the paper's law dissipates in the matched run)."""

import time

import numpy as np
import pandas as pd

from sphgag import threads
from sphgag.engine import solver
from sphgag.records import provenance, runlog, state
from sphgag.studies import artery, delamination

sm = snakemake  # noqa: F821
threads.use(sm.threads)
started = time.time()
w = sm.wildcards
gc = getattr(w, "gc", None)
run = f"delaminate_{w.law}_{w.poolset}_{w.sigma}kPa_{w.criterion}" + (f"_Gc{gc}" if gc else "")
with runlog.run(run, sm.log[0]) as log:
    cfg, de = sm.params.state_slice, sm.params.delamination
    model = artery.bilayer_model(cfg["bilayer"], cfg["numerics"], name=run)
    saved = state.load(sm.input.state, expected_params=cfg)
    sectors = [artery.pool_sector(s) for s in sm.params.pools]
    start = solver.State(saved.load, saved.x, None, None)
    fracture_energy, unmatched = None, None
    if gc == "paper":
        fracture_energy = float(pd.read_csv(sm.input.matched).dissipated_energy_J_m2.iloc[0])
        if not fracture_energy > 0.0:  # NaN: the paper's run grew nothing
            fracture_energy = np.nan
            unmatched = f"no G_c to match: the paper's law dissipated no energy in {sm.input.matched} (no growth)"
        else:
            log.info(
                "[%s] G_c = %.4g J/m^2: the energy the paper's law dissipates (%s)",
                run,
                fracture_energy,
                sm.input.matched,
            )
    elif gc is not None:
        fracture_energy = float(gc)
    settings = delamination.Settings.from_config(de, float(w.sigma), w.criterion, fracture_energy)
    if unmatched:
        seeding = delamination.Settings.from_config(de, float(w.sigma), w.criterion)
        result = delamination.seeded_only(
            model, start, sectors, seeding, cfg["numerics"], sm.params.gag, model.props, unmatched, run=run
        )
    else:
        result = delamination.grow(
            model, start, sectors, settings, cfg["numerics"], sm.params.gag, model.props, run=run
        )
    growth, summary = delamination.labelled(result, w.poolset, settings, cfg["bilayer"]["dx_um"])
    if fracture_energy is not None:  # the pool as a pressurised crack in its layer's elastin matrix, E' = 4 phi_e mu_e
        bl = cfg["bilayer"]
        layer = artery.layer_at(bl, sectors[0].centre_radius)
        modulus = 4.0 * bl["mass_fractions"][layer]["elastin"] * bl["elastin_shear_modulus_kPa"]
        closed = delamination.griffith(sectors, fracture_energy, modulus, sm.params.gag, de["max_concentration_mEq_l"])
        summary = summary.assign(plane_strain_modulus_kPa=modulus, **closed)
    growth.insert(0, "charge_law", sm.params.gag["charge_law"])
    summary.insert(0, "charge_law", sm.params.gag["charge_law"])
    growth.to_csv(sm.output.growth, index=False)
    summary.to_csv(sm.output.summary, index=False)
    delamination.save_snapshots(
        sm.output.snapshots, model, result.snapshots, dict(cfg, delamination=de, gag=sm.params.gag)
    )
    s = summary.iloc[0]
    log.info(
        "[%s] stopped (%s) after %d passes: onset at %s mEq/l, delaminated %.1f um (%d islands apart, %s candidates), "
        "merged %s, dissipated %.3g J/m^2, max residual %.2e",
        run,
        s.stop,
        s.passes,
        s.onset_concentration_mEq_l,
        s.final_length_um,
        s.islands,
        s.candidates,
        s.merged,
        s.dissipated_energy_J_m2,
        s.max_residual,
    )
    provenance.write_record(
        sm.output.provenance,
        rule="delaminate",
        params=dict(state=cfg, delamination=de, pools=sm.params.pools, gag=sm.params.gag),
        outputs=list(sm.output),
        summary=dict(max_residual=float(s.max_residual), passes=int(s.passes)),
        started=started,
    )
