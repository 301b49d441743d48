"""The swelling claims of figure 4 and section 3 (C6-C12), and their verdicts across figure 4's resolution band
(:func:`across_band`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from .evidence import TARGETS, Claim, Evidence, _group_slack, _monotone_groups, _yes, at_highest, last_converged

# -- swelling (figure 4): C6-C12 ------------------------------------------------------------------------------------


def _ordered(e: Evidence) -> list:
    """The swelling pools, smallest angular extent first."""
    size = {c: e.cases[c]["angular_extent_deg"] for c in e.cases}
    return sorted(size, key=size.get)


def _conversion_change(e: Evidence) -> pd.DataFrame:
    """Per run (model, pressure, case): the tip radial and top hoop stress changes from intact to converted at c = 0."""
    tips = e.tips
    conv0 = tips[(tips.stage == "converted") & (tips.concentration_mEq_l == 0)]
    intact = tips[tips.stage == "intact"]
    key = ["model", "pressure_mmHg", "case"]
    return (
        conv0.set_index(key)[["tip_radial_stress_kPa", "top_circ_stress_kPa"]]
        - intact.set_index(key)[["tip_radial_stress_kPa", "top_circ_stress_kPa"]]
    )


def _highest(e: Evidence) -> tuple[pd.DataFrame, str]:
    """Each run's last converged state and how the claims name it (:func:`last_converged`, :func:`at_highest`)."""
    top = last_converged(e.tips)
    return top, at_highest(top, e.max_concentration)


def c6_conversion_signs(e: Evidence) -> Claim:
    d = _conversion_change(e)
    signs = (d.tip_radial_stress_kPa < 0) & (d.top_circ_stress_kPa > 0)
    return Claim(
        "C6",
        "Converting the pool (no swelling) makes the tip radial stress compressive and raises the top hoop "
        "(tensile) stress",
        "figure 4b,c at c = 0",
        f"tip change {d.tip_radial_stress_kPa.min():.0f} to {d.tip_radial_stress_kPa.max():.0f} kPa, top change "
        f"+{d.top_circ_stress_kPa.min():.0f} to +{d.top_circ_stress_kPa.max():.0f} kPa; signs right in "
        f"{int(signs.sum())}/{len(signs)} runs",
        _yes(signs.all()),
        "tip more compressive and top more tensile than intact in every run",
        margin=float(min((-d.tip_radial_stress_kPa).min(), d.top_circ_stress_kPa.min())),
    )


def c7_conversion_grows_with_size(e: Evidence) -> Claim:
    d = _conversion_change(e)
    ordered = _ordered(e)
    grow, groups = _monotone_groups(
        d.reset_index(),
        ordered,
        lambda g: np.all(np.diff(-g.tip_radial_stress_kPa) >= 0) and np.all(np.diff(g.top_circ_stress_kPa) >= 0),
    )
    return Claim(
        "C7",
        "... in proportion to the pool size (text); the caption says the concentrations tend to decrease as "
        "the pool enlarges",
        "grow with size (text) / decrease with size (caption)",
        f"both changes grow with pool size in {grow}/{groups} model-pressure groups; top change at 103 mmHg "
        "(passive): "
        + ", ".join(
            f"{c} +{d.loc[('passive', 103.0, c), 'top_circ_stress_kPa']:.0f}"
            for c in ordered
            if ("passive", 103.0, c) in d.index
        ),
        _yes(grow == groups) if groups else "n/a",
        "monotone growth in size in every group (the text's reading)",
        margin=_group_slack(
            d.reset_index(),
            ordered,
            lambda g: min(np.diff(-g.tip_radial_stress_kPa).min(), np.diff(g.top_circ_stress_kPa).min()),
        ),
    )


def c8_tensile_tip(e: Evidence) -> Claim:
    top, at = _highest(e)
    tips = e.tips
    high = tips[(tips.stage == "converted") & (tips.concentration_mEq_l > 100 - 1e-9)]
    frac_tensile = (top.tip_radial_stress_kPa > 0).mean()
    frac_50 = (high.tip_radial_stress_kPa > 50).mean()
    return Claim(
        "C8",
        "Swelling turns the tip radial stress from compressive to tensile, typically above ~50 kPa for "
        "concentrations over 100 mEq/l",
        "> ~50 kPa above 100 mEq/l",
        f"{at}: {top.tip_radial_stress_kPa.min():.0f} to {top.tip_radial_stress_kPa.max():.0f} kPa, "
        f"tensile in {100 * frac_tensile:.0f} % of runs; "
        f"> 50 kPa in {100 * frac_50:.0f} % of states above 100 mEq/l",
        _yes(frac_tensile == 1 and frac_50 >= 0.5),
        "tensile in every run at the highest concentration and > 50 kPa in most states above 100 mEq/l",
        margin=float(min(top.tip_radial_stress_kPa.min(), (high.tip_radial_stress_kPa - 50.0).median())),
    )


def c9_smaller_pools_higher_tip(e: Evidence) -> Claim:
    top, at = _highest(e)
    mono, groups = _monotone_groups(top, _ordered(e), lambda g: np.all(np.diff(g.tip_radial_stress_kPa) <= 0))
    return Claim(
        "C9",
        "Smaller pools give higher tip stress",
        "figure 4, section 3",
        f"tip radial stress {at} decreases with pool size in {mono}/{groups} model-pressure groups",
        _yes(groups > 0 and mono == groups) if groups else "n/a",
        "monotone in every group",
        margin=_group_slack(top, _ordered(e), lambda g: np.diff(-g.tip_radial_stress_kPa).min()),
    )


def c10_pressure_independent_tip(e: Evidence) -> Claim:
    statement = "In the passive wall the tip stress hardly changes with lumen pressure above 75 mEq/l"
    tips = e.tips
    passive = tips[(tips.model == "passive") & (tips.stage == "converted") & (tips.concentration_mEq_l > 75 - 1e-9)]
    if passive.pressure_mmHg.nunique() <= 1:
        return Claim("C10", statement, "does not change appreciably", "needs more than one pressure", "n/a", "-")
    by_level = passive.groupby(["case", "concentration_mEq_l"]).tip_radial_stress_kPa
    spread = by_level.agg(np.ptp)[by_level.size() > 1]  # levels that more than one pressure reached
    return Claim(
        "C10",
        statement,
        "does not change appreciably",
        f"largest spread over pressures {spread.max():.1f} kPa (median {spread.median():.1f} kPa)",
        _yes(spread.max() <= 10.0),
        "spread <= 10 kPa at every case and concentration >= 75 mEq/l",
        margin=float(10.0 - spread.max()),
    )


HIGH_PRESSURE_MMHG = 200.0  # the paper's high pressure of section 3: C11 reads the pressures below it, C12 this one


def _activation_change(e: Evidence) -> pd.DataFrame | None:
    """Active minus passive tip radial stress of each case and pressure at the highest concentration (None without
    both models)."""
    top, _ = _highest(e)
    both = top.pivot_table(index=["case", "pressure_mmHg"], columns="model", values="tip_radial_stress_kPa")
    if not {"passive", "active"} <= set(both.columns):
        return None
    return (both.active - both.passive).rename("active_minus_passive").reset_index()


def _activation_text(e: Evidence, rows: pd.DataFrame) -> str:
    _, at = _highest(e)
    return (
        f"active - passive {at}: "
        + ", ".join(f"{r.case} at {r.pressure_mmHg:g} mmHg: {r.active_minus_passive:+.0f}" for r in rows.itertuples())
        + " kPa"
    )


def c11_activation_lowers_tip(e: Evidence) -> Claim | None:
    diff = _activation_change(e)
    if diff is None:
        return None
    low = diff[diff.pressure_mmHg < HIGH_PRESSURE_MMHG - 1e-9]
    return Claim(
        "C11",
        "Activation lowers the tip stress at 103 and 145 mmHg",
        "lower (section 3)",
        _activation_text(e, low),
        _yes(len(low) and (low.active_minus_passive < 0).all()) if len(low) else "n/a",
        "negative for every case",
        margin=float((-low.active_minus_passive).min()) if len(low) else np.nan,
    )


def c12_activation_raises_small_tips(e: Evidence) -> Claim | None:
    diff = _activation_change(e)
    if diff is None:
        return None
    high_p = diff[(abs(diff.pressure_mmHg - HIGH_PRESSURE_MMHG) < 1e-9) & diff.case.isin(_ordered(e)[:2])]
    return Claim(
        "C12",
        "... but raises it for the two smallest pools at 200 mmHg",
        "higher for cases I-II (section 3)",
        _activation_text(e, high_p) if len(high_p) else "no run at 200 mmHg",
        _yes((high_p.active_minus_passive > 0).all()) if len(high_p) else "n/a",
        "positive for the two smallest pools",
        margin=float(high_p.active_minus_passive.min()) if len(high_p) else np.nan,
    )


# -- figure 4's claims across the resolution band -------------------------------------------------------------------


def study_sets(e: Evidence) -> dict[str, Evidence]:
    """The evidence of figure 4's resolution study (``e`` of one charge law and pool model) as the claims read it:
    its intact and converted states at every spacing (``dx 3``, ...), and the Richardson-extrapolated values of its
    band (``extrapolated``; the finest value where the three spacings give no order), each as a tip_stress.csv at
    the study's pressure, with the study's pools. Empty without the study."""
    if e.resolution is None or not len(e.resolution):
        return {}
    rows = e.resolution[e.resolution.stage.isin(["intact", "converted"])].assign(pressure_mmHg=e.study_pressure)
    pools = {c: e.cases[c] for c in dict.fromkeys(rows.case) if c in e.cases}
    sets = {f"dx {dx:g}": rows[rows.dx_um == dx] for dx in sorted(rows.dx_um.unique(), reverse=True)}
    if e.band is not None and e.band.dx_um.nunique() >= 3:  # an extrapolation needs three spacings
        fine = e.band[e.band.dx_um == e.band.dx_um.min()]
        fine = fine.assign(value=fine.extrapolated.where(fine.extrapolated.notna(), fine.value))
        key = ["model", "case", "stage", "concentration_mEq_l", "pressure_mmHg"]
        sets["extrapolated"] = fine.pivot_table(index=key, columns="quantity", values="value").reset_index()
    return {name: replace(e, tips=tips, cases=pools) for name, tips in sets.items()}


def _highest_level(c: pd.Series) -> pd.Series:
    return c >= c.max() - 1e-9


#: the band rows each figure 4 claim reads: its stresses (gci_band.csv quantities) and concentrations (of the ramp)
BAND_READS = {
    "C6": (("tip_radial_stress_kPa", "top_circ_stress_kPa"), lambda c: c == 0.0),
    "C7": (("tip_radial_stress_kPa", "top_circ_stress_kPa"), lambda c: c == 0.0),
    "C8": (("tip_radial_stress_kPa",), lambda c: c >= 100.0 - 1e-9),
    "C9": (("tip_radial_stress_kPa",), _highest_level),
    "C10": (("tip_radial_stress_kPa",), lambda c: c >= 75.0 - 1e-9),
    "C11": (("tip_radial_stress_kPa",), _highest_level),
    "C12": (("tip_radial_stress_kPa",), _highest_level),
}


def band_width(band: pd.DataFrame | None, claim_id: str) -> str:
    """The widest GCI band (kPa: GCI times the finest value's magnitude) among the rows claim ``claim_id`` reads, as
    the claims table says it (empty without them)."""
    if band is None or claim_id not in BAND_READS or not len(band):
        return ""
    quantities, levels = BAND_READS[claim_id]
    fine = band[(band.dx_um == band.dx_um.min()) & band.quantity.isin(quantities)]
    fine = fine[levels(fine.concentration_mEq_l)]
    if not len(fine):
        return ""
    half = fine.gci_fine * fine.value.abs()
    missing = int(half.isna().sum())
    parts = [f"widest band it reads +-{half.max():.0f} kPa"] if missing < len(half) else []
    parts += [f"no order (no band) at {missing} of the {len(half)} values it reads"] if missing else []
    return "; " + ", ".join(parts) if parts else ""


def _margin(m: float) -> str:
    return f"{m:+.0f}" if np.isfinite(m) else "-"


def across_band(e: Evidence, found: list[Claim]) -> list[Claim]:
    """The figure 4 claims of ``found`` (one charge law and pool model) judged again on the resolution study
    (:func:`study_sets`): each gets ``across_band``, its verdict and margin at every spacing and extrapolated, with
    the widest GCI band it reads (:func:`band_width`); a claim holds only if it also holds on every one of them
    that has its data (n/a: the study lacks it, e.g. a second pressure). Without the study, ``not run``; for a
    charge law or pool model the study does not run, ``not in the resolution study``."""
    sets = study_sets(e)
    fns = {fn.__name__.split("_")[0].upper(): fn for fn in SWELLING}
    out = []
    for claim in found:
        if claim.claim_id not in fns:
            out.append(claim)
            continue
        if e.resolution is None:
            out.append(replace(claim, across_band=f"not run: `snakemake {TARGETS['resolution']}`"))
            continue
        if not sets:
            out.append(replace(claim, across_band="not in the resolution study (swelling_convergence.pool_models)"))
            continue
        verdicts = {name: fns[claim.claim_id](study) for name, study in sets.items()}
        verdicts = {name: v for name, v in verdicts.items() if v is not None and v.holds != "n/a"}
        if not verdicts:
            out.append(replace(claim, across_band="n/a (the resolution study lacks its data)"))
            continue
        text = ", ".join(f"{name}: {v.holds} ({_margin(v.margin)})" for name, v in verdicts.items())
        text += " kPa" + band_width(e.band, claim.claim_id)
        holds = claim.holds if all(v.holds == "yes" for v in verdicts.values()) else "no"
        out.append(replace(claim, holds=holds, across_band=text))
    return out


#: the figure 4 claims (C6-C12): once per charge law and pool model
SWELLING = [
    c6_conversion_signs,
    c7_conversion_grows_with_size,
    c8_tensile_tip,
    c9_smaller_pools_higher_tip,
    c10_pressure_independent_tip,
    c11_activation_lowers_tip,
    c12_activation_raises_small_tips,
]
