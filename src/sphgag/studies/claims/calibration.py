"""The calibration claims of figure 3 (C1-C5): the pressure-diameter curves and the transmural profiles of the
mean and bi-layered walls.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .evidence import Claim, Evidence, _hoop_range, _yes

# -- calibration (figure 3): C1-C5 ----------------------------------------------------------------------------------


def c1_pressure_diameter(e: Evidence) -> Claim:
    m_err = e.mean.loc[e.mean.pressure_mmHg >= 10, "od_rel_error"].abs().max()
    b = e.bilayer[(e.bilayer.pressure_mmHg >= 60) & (e.bilayer.pressure_mmHg <= 200)]
    b_err = b.groupby("model").od_rel_error.apply(lambda s: s.abs().max())
    return Claim(
        "C1",
        "SPH pressure-outer diameter of the mean and bi-layered models agrees with the analytical solution",
        "'agree well' (figure 3a)",
        f"largest OD error: mean {100 * m_err:.2f} % (10-200 mmHg); bi-layered "
        + ", ".join(f"{k} {100 * v:.2f} %" for k, v in b_err.items())
        + " (60-200 mmHg)",
        _yes(m_err < 0.01 and (b_err < 0.015).all()),
        "mean < 1 %, bi-layered < 1.5 %",
    )


def c2_activation_diameter(e: Evidence) -> Claim:
    sph = e.activation[e.activation.source == "sph"].iloc[0]
    red = sph.od_reduction
    return Claim(
        "C2",
        "Full SMC activation reduces the outer diameter by about 20 % at the homeostatic pressure",
        "about 20 %",
        f"{100 * red:.1f} % at {sph.pressure_mmHg:g} mmHg",
        _yes(0.15 <= red <= 0.25),
        "within 15-25 %",
    )


def _sph_profiles(e: Evidence) -> pd.DataFrame:
    return e.transmural[e.transmural.source == "sph"]


def c3_uniform_hoop_stress(e: Evidence) -> Claim:
    passive = e.layers[e.layers.model == "passive"]
    worst = passive.circ_variation.max()
    t = _sph_profiles(e)
    mean103 = t[(t.model == "mean") & (np.isclose(t.pressure_mmHg, 103.0))]
    mean_var = _hoop_range(mean103) if len(mean103) else np.nan
    return Claim(
        "C3",
        "The bi-layered homeostatic state has near-uniform hoop stress within each layer, the mean model "
        "a highly non-uniform one",
        "near uniform per layer (figure 3c) vs highly non-uniform (figure 3b)",
        f"bi-layered (max - min)/mean per layer <= {100 * worst:.1f} %; mean model across the wall at 103 mmHg "
        f"{100 * mean_var:.0f} %",
        _yes(worst < 0.10 and mean_var > 0.5),
        "bi-layered < 10 % in every layer and mean model > 50 %",
    )


# claims C4-C5 are the paper's statements about its two layers: a wall without a layer of either name has no C4-C5
MEDIA, ADVENTITIA = "media", "adventitia"


def _layer_mean(t: pd.DataFrame, model: str, P: float, layer: str) -> float:
    d = t[(t.model == model) & np.isclose(t.pressure_mmHg, P) & (t.layer == layer)]
    return d.circ_stress_kPa.mean()


def _profiled_pressures(t: pd.DataFrame) -> list:
    return sorted(set(t[t.model == "passive"].pressure_mmHg))


def c4_adventitia_shields(e: Evidence) -> Claim | None:
    t = _sph_profiles(e)
    pressures = _profiled_pressures(t)
    if len(pressures) < 2 or not {MEDIA, ADVENTITIA} <= set(t.layer):
        return None
    lo, hi = pressures[0], pressures[-1]
    r_lo = _layer_mean(t, "passive", lo, ADVENTITIA) / _layer_mean(t, "passive", lo, MEDIA)
    r_hi = _layer_mean(t, "passive", hi, ADVENTITIA) / _layer_mean(t, "passive", hi, MEDIA)
    return Claim(
        "C4",
        "At elevated pressure the adventitia shields the media (passive model)",
        "adventitia carries increasingly more load (figure 3c)",
        f"adventitia/media hoop stress {r_lo:.2f} at {lo:g} mmHg, {r_hi:.2f} at {hi:g} mmHg",
        _yes(r_hi > r_lo),
        "the ratio grows with pressure",
    )


def c5_activation_shifts_load(e: Evidence) -> Claim | None:
    t = _sph_profiles(e)
    pressures = _profiled_pressures(t)
    if len(pressures) < 2 or not {MEDIA, ADVENTITIA} <= set(t.layer):
        return None
    shares, adv = [], []
    for P in pressures:
        sp = _layer_mean(t, "passive", P, MEDIA) / _layer_mean(t, "passive", P, ADVENTITIA)
        sa = _layer_mean(t, "active", P, MEDIA) / _layer_mean(t, "active", P, ADVENTITIA)
        shares.append((P, sp, sa))
        adv.append(_layer_mean(t, "active", P, ADVENTITIA) < _layer_mean(t, "passive", P, ADVENTITIA))
    return Claim(
        "C5",
        "SMC activation shifts load to the media and lowers the adventitial hoop stress at fixed pressure",
        "media bears more load, adventitial stress reduced (figure 3c)",
        "media/adventitia hoop stress passive -> active: "
        + ", ".join(f"{sp:.2f} -> {sa:.2f} ({P:g} mmHg)" for P, sp, sa in shares),
        _yes(all(sa > sp for _, sp, sa in shares) and all(adv)),
        "ratio larger when active and adventitial hoop stress lower, at every profiled pressure",
    )


#: the calibration claims (C1-C5): once in the table, with no charge law
CALIBRATION = [
    c1_pressure_diameter,
    c2_activation_diameter,
    c3_uniform_hoop_stress,
    c4_adventitia_shields,
    c5_activation_shifts_load,
]
