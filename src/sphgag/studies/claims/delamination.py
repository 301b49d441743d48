"""The delamination claims of figures 5-7 and section 3 (C13-C17), and the abstract's sensitivity claim (C18)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from .evidence import Claim, Evidence, _runs, _yes

# -- delamination (figures 5-7): C13-C17 ----------------------------------------------------------------------------
# ``holds`` is judged on the default onset criterion (``criteria[0]``); the other criteria's numbers are reported
# beside it.


def _per_criterion(e: Evidence, fn) -> str:
    return "; ".join(f"{c}: {fn(c)}" for c in e.criteria)


def _single_runs(e: Evidence, criterion: str) -> pd.DataFrame:
    """The summary rows of figure 5's set under one criterion, by sigma_cr."""
    s = e.delamination
    return s[(s.case == e.figures["fig5"]) & (s.criterion == criterion)].sort_values("sigma_cr_kPa")


def _concentration(c: float) -> str:
    return f"{c:.1f}" if np.isfinite(c) else "-"


def _events_text(runs: pd.DataFrame) -> str:
    """Per sigma_cr: how the run ended and the concentrations of its onset and runaway."""
    return ", ".join(
        f"{r.sigma_cr_kPa:g} kPa {r.stop_kind} (onset {_concentration(r.onset_concentration_mEq_l)}, runaway "
        f"{_concentration(r.runaway_concentration_mEq_l)} mEq/l, arrested {r.arrested_length_um:.3g} um, "
        f"final {r.final_length_um:.3g} um)"
        for r in runs.itertuples()
    )


def c13_spontaneous_propagation(e: Evidence) -> Claim:
    runs = _single_runs(e, e.criteria[0])
    unstable = len(runs) and all(
        r.stop_kind in ("unstable", "edge", "layer") and np.isfinite(r.runaway_concentration_mEq_l)
        for r in runs.itertuples()
    )
    return Claim(
        "C13",
        "Propagation is spontaneous: once the tip stress first exceeds sigma_cr, the pool grows catastrophically",
        '"the propagation of a single GAG pool is spontaneous; once the radial stress exceeds the critical value, the '
        'GAG pool grows catastrophically within the otherwise homogeneous media" (section 3, figure 5)',
        _per_criterion(e, lambda c: _events_text(_single_runs(e, c))),
        _yes(unstable),
        "our reading: every single-pool run (default criterion) ends with growth at a fixed concentration that does "
        "not arrest (stop unstable, edge or layer), at a runaway concentration found by bisection",
    )


def _sawtooth(e: Evidence, criterion: str) -> dict:
    """Per sigma_cr of figure 5's set: the drops of the tip stress by more than 10 % of sigma_cr."""
    drops = {}
    for sigma, g in _runs(e.growth, e.figures["fig5"], criterion).items():
        tip = g.tip_radial_stress_kPa.to_numpy()
        drops[sigma] = int(np.sum(np.diff(tip) < -0.1 * sigma))
    return drops


def c14_sawtooth(e: Evidence) -> Claim:
    saw = _sawtooth(e, e.criteria[0])
    return Claim(
        "C14",
        "The tip stress rises and drops repeatedly (a sawtooth)",
        '"delamination can progress within a medial layer as stresses build up and then drop as the pool expands, '
        'only to potentially build up again and repeat (figure 5)" (section 4, figure 5b)',
        _per_criterion(e, lambda c: ", ".join(f"{s:g} kPa {n} drops" for s, n in _sawtooth(e, c).items())),
        _yes(saw and all(n >= 2 for n in saw.values())),
        "at least two drops by > 10 % of sigma_cr in every single-pool run (default criterion)",
    )


def c15_sigma_cr_slows_growth(e: Evidence) -> Claim:
    runs = _single_runs(e, e.criteria[0])
    holds = "n/a"
    if len(runs) > 1 and runs.sigma_cr_kPa.min() < runs.sigma_cr_kPa.max():
        lo, hi = runs.iloc[0], runs.iloc[-1]
        later = [
            hi[k] > lo[k] or (np.isnan(hi[k]) and np.isfinite(lo[k]))
            for k in ("onset_concentration_mEq_l", "runaway_concentration_mEq_l")
        ]
        holds = _yes(all(later))
    return Claim(
        "C15",
        "Raising sigma_cr from 30 to 60 kPa slows propagation more than twofold",
        '"increases from sigma_cr = 30 kPa to 60 kPa reduce the rate of GAG propagation by more than two-fold" '
        "(section 3, figure 5b)",
        _per_criterion(e, lambda c: _events_text(_single_runs(e, c))),
        holds,
        "our reading: at equilibrium growth either arrests or runs away at a fixed concentration, so a rate per pass "
        "is set by the pass, not the physics; a higher sigma_cr slows propagation if it raises both the onset and the "
        "runaway concentration (lowest against highest sigma_cr, default criterion; none at the highest counts as "
        "raised). The twofold factor has no converged counterpart",
    )


def _pair_runs(e: Evidence, criterion: str):
    """``(summary row, growth row at the merge or at the end)`` of every pool-pair run (figure 6's sets)."""
    summary, growth = e.delamination, e.growth
    runs = summary[summary.case.isin(list(e.figures["fig6"])) & (summary.criterion == criterion)]
    for r in runs.itertuples():
        g = growth[(growth.case == r.case) & (growth.criterion == criterion)].sort_values("step")
        yield r, (g[g.pseudo_time <= r.merge_step].iloc[-1] if r.merged else g.iloc[-1])


def c16_pairs_merge(e: Evidence) -> Claim:
    def text(c):
        return ", ".join(
            f"{r.case} {f'merged at {r.merge_concentration_mEq_l:.1f} mEq/l' if r.merged else r.stop_kind}, converted "
            f"interior {at.converted_interior:.0f} / exterior {at.converted_exterior:.0f}"
            for r, at in _pair_runs(e, c)
        )

    pairs = list(_pair_runs(e, e.criteria[0]))
    ok = any(r.merged and at.converted_exterior > at.converted_interior for r, at in pairs)
    return Claim(
        "C16",
        "Two nearby pools grow and merge, and at merging their exterior growth exceeds their interior growth",
        '"The model predicts that the pools grow in both interior and exterior regions, though the rate of the '
        'exterior growth is faster" (figure 6)',
        _per_criterion(e, text),
        _yes(ok) if len(pairs) else "n/a",
        "a pool pair merges and has more exterior than interior converted particles at the merge (default criterion)",
    )


def c17_offset_pools_link(e: Evidence) -> Claim:
    off = e.delamination[(e.delamination.case == e.figures["fig7"])]
    return Claim(
        "C17",
        "Radially offset pools link up",
        '"the same mechanism underlies the extension and coalescence of two pools of GAGs with or without radial '
        'offset" (section 3, figure 7)',
        _per_criterion(
            e,
            lambda c: ", ".join(
                f"{f'merged at {r.merge_concentration_mEq_l:.1f} mEq/l' if r.merged else r.stop_kind} "
                f"({r.final_length_um:.1f} um delaminated)"
                for r in off[off.criterion == c].itertuples()
            ),
        ),
        _yes(off[off.criterion == e.criteria[0]].merged.any()) if len(off) else "n/a",
        "the radially offset pair merges (default criterion)",
    )


def c18_onset_across_inputs(e: Evidence) -> Claim:
    """The abstract: the findings, "combined with a sensitivity study on the input parameters of the model", suggest
    that localised swelling can cause damage. Our reading: delamination starts (eq. 2.28 reaches sigma_cr) in most
    samples of the sensitivity study, whose inputs span the ranges of its configuration (README)."""
    claim = Claim(
        "C18",
        "Across the model's input ranges (the sensitivity study), swelling pools start delamination",
        "abstract: a sensitivity study on the input parameters supports the findings",
        "",
        "",
        "damage starts (onset below the end of the ramp) in more than half of the samples that ran",
    )
    if e.sensitivity is None:
        return e.not_run(claim, "sensitivity")
    ran = e.sensitivity[e.sensitivity.status == "ok"]
    if not len(ran):
        return replace(claim, our_value="no sample ran", holds="n/a")
    onset = ran[~ran.onset_censored.astype(bool)]
    share = len(onset) / len(ran)
    where = (
        f", at {onset.onset_concentration_mEq_l.min():g}-{onset.onset_concentration_mEq_l.max():g} mEq/l"
        if len(onset)
        else ""
    )
    value = (
        f"onset in {len(onset)} of {len(ran)} samples ({100 * share:.0f} %){where}; "
        f"{int(ran.propagated.sum())} propagate; {len(e.sensitivity) - len(ran)} failed"
    )
    return replace(claim, our_value=value, holds=_yes(share > 0.5))


#: the delamination claims (C13-C17) and the sensitivity claim (C18): once per charge law, the paper's pool model
DELAMINATION = [
    c13_spontaneous_propagation,
    c14_sawtooth,
    c15_sigma_cr_slows_growth,
    c16_pairs_merge,
    c17_offset_pools_link,
]
SENSITIVITY = [c18_onset_across_inputs]
