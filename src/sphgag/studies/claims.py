"""The paper's claims (figures 3-7 and their text), evaluated from the pipeline's tables alone.

Each claim is a function of the tidy CSV tables that returns our number and
whether the claim holds by a criterion written next to it. A claim that does
not hold is reported with our number; nothing here feeds back into a
simulation. A claim whose data the configuration did not produce (e.g. a
reduced sweep) is reported as ``n/a``.

The pool claims (figure 4: C6-C12; delamination: C13-C17) are evaluated once
per charge law (:func:`by_law`; column ``charge_law``), with the same criteria:
``prescribed`` is the paper's model, ``conserved`` our deviation. The
calibration claims (C1-C5) involve no pool (``charge_law`` "-").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd


@dataclass
class Claim:
    claim_id: str
    statement: str
    paper_value: str
    our_value: str
    holds: str  # yes | no | n/a
    criterion: str
    charge_law: str = "-"  # a pool claim's Donnan law (sphgag.physics.materials.CHARGE_LAWS); "-": no pool


def _yes(flag) -> str:
    return "yes" if bool(flag) else "no"


def _hoop_range(profile: pd.DataFrame) -> float:
    s = profile.circ_stress_kPa
    return float((s.max() - s.min()) / s.mean())


def calibration_claims(
    mean: pd.DataFrame,
    bilayer: pd.DataFrame,
    activation: pd.DataFrame,
    homeostasis_layers: pd.DataFrame,
    transmural: pd.DataFrame,
) -> list[Claim]:
    out = []
    m_err = mean.loc[mean.pressure_mmHg >= 10, "od_rel_error"].abs().max()
    b = bilayer[(bilayer.pressure_mmHg >= 60) & (bilayer.pressure_mmHg <= 200)]
    b_err = b.groupby("model").od_rel_error.apply(lambda s: s.abs().max())
    out.append(
        Claim(
            "C1",
            "SPH pressure-outer diameter of the mean and bi-layered models agrees with the analytical solution",
            "'agree well' (figure 3a)",
            f"largest OD error: mean {100 * m_err:.2f} % (10-200 mmHg); bi-layered "
            + ", ".join(f"{k} {100 * v:.2f} %" for k, v in b_err.items())
            + " (60-200 mmHg)",
            _yes(m_err < 0.01 and (b_err < 0.015).all()),
            "mean < 1 %, bi-layered < 1.5 %",
        )
    )

    sph = activation[activation.source == "sph"].iloc[0]
    red = sph.od_reduction
    out.append(
        Claim(
            "C2",
            "Full SMC activation reduces the outer diameter by about 20 % at the homeostatic pressure",
            "about 20 %",
            f"{100 * red:.1f} % at {sph.pressure_mmHg:g} mmHg",
            _yes(0.15 <= red <= 0.25),
            "within 15-25 %",
        )
    )

    passive = homeostasis_layers[homeostasis_layers.model == "passive"]
    worst = passive.circ_variation.max()
    t = transmural[transmural.source == "sph"]
    mean103 = t[(t.model == "mean") & (np.isclose(t.pressure_mmHg, 103.0))]
    mean_var = _hoop_range(mean103) if len(mean103) else np.nan
    out.append(
        Claim(
            "C3",
            "The bi-layered homeostatic state has near-uniform hoop stress within each layer, the mean model "
            "a highly non-uniform one",
            "near uniform per layer (figure 3c) vs highly non-uniform (figure 3b)",
            f"bi-layered (max - min)/mean per layer <= {100 * worst:.1f} %; mean model across the wall at 103 mmHg "
            f"{100 * mean_var:.0f} %",
            _yes(worst < 0.10 and mean_var > 0.5),
            "bi-layered < 10 % in every layer and mean model > 50 %",
        )
    )

    def layer_mean(model, P, layer):
        d = t[(t.model == model) & np.isclose(t.pressure_mmHg, P) & (t.layer == layer)]
        return d.circ_stress_kPa.mean()

    pressures = sorted(set(t[t.model == "passive"].pressure_mmHg))
    if len(pressures) >= 2:
        lo, hi = pressures[0], pressures[-1]
        r_lo = layer_mean("passive", lo, "adventitia") / layer_mean("passive", lo, "media")
        r_hi = layer_mean("passive", hi, "adventitia") / layer_mean("passive", hi, "media")
        out.append(
            Claim(
                "C4",
                "At elevated pressure the adventitia shields the media (passive model)",
                "adventitia carries increasingly more load (figure 3c)",
                f"adventitia/media hoop stress {r_lo:.2f} at {lo:g} mmHg, {r_hi:.2f} at {hi:g} mmHg",
                _yes(r_hi > r_lo),
                "the ratio grows with pressure",
            )
        )
        shares, adv = [], []
        for P in pressures:
            sp = layer_mean("passive", P, "media") / layer_mean("passive", P, "adventitia")
            sa = layer_mean("active", P, "media") / layer_mean("active", P, "adventitia")
            shares.append((P, sp, sa))
            adv.append(layer_mean("active", P, "adventitia") < layer_mean("passive", P, "adventitia"))
        out.append(
            Claim(
                "C5",
                "SMC activation shifts load to the media and lowers the adventitial hoop stress at fixed pressure",
                "media bears more load, adventitial stress reduced (figure 3c)",
                "media/adventitia hoop stress passive -> active: "
                + ", ".join(f"{sp:.2f} -> {sa:.2f} ({P:g} mmHg)" for P, sp, sa in shares),
                _yes(all(sa > sp for _, sp, sa in shares) and all(adv)),
                "ratio larger when active and adventitial hoop stress lower, at every profiled pressure",
            )
        )
    return out


def _monotone_groups(table: pd.DataFrame, ordered: list, holds) -> tuple[int, int]:
    """(groups where ``holds(rows ordered by pool size)``, groups with more than one pool) per model and pressure."""
    hits = groups = 0
    for _, g in table.groupby(["model", "pressure_mmHg"]):
        g = g.set_index("case")
        g = g.loc[[c for c in ordered if c in g.index]]
        if len(g) > 1:
            groups += 1
            hits += bool(holds(g))
    return hits, groups


def last_converged(tips: pd.DataFrame) -> pd.DataFrame:
    """Each swelling run's last converged state (its highest concentration), in the table's order: a run that found
    no equilibrium beyond some concentration ends there, below the requested maximum."""
    conv = tips[tips.stage == "converted"]
    last = conv.groupby(["model", "pressure_mmHg", "case"]).concentration_mEq_l.idxmax()
    return conv[conv.index.isin(last)]


def at_highest(top: pd.DataFrame, max_concentration: float | None) -> str:
    """Where the claims read "the highest concentration": the requested one if every run reached it, else each run's
    last converged state."""
    ends = top.concentration_mEq_l
    if max_concentration is None or np.allclose(ends, max_concentration):
        return f"at {ends.max():g} mEq/l"
    short = int((ends < max_concentration - 1e-9).sum())
    return (
        f"at each run's last converged state ({ends.min():g}-{ends.max():g} mEq/l; {short}/{len(ends)} runs found "
        f"no equilibrium up to {max_concentration:g})"
    )


def swelling_claims(tips: pd.DataFrame, cases: dict, max_concentration: float | None = None) -> list[Claim]:
    """Claims of figure 4 and section 3 from ``tip_stress.csv`` (one charge law); ``cases`` gives each pool's angular
    extent. "The highest concentration" is each run's last converged state (:func:`last_converged`), which is
    ``max_concentration`` unless a run found no equilibrium up to it (then the values say so)."""
    out = []
    size = {c: cases[c]["angular_extent_deg"] for c in cases}
    ordered = sorted(size, key=size.get)
    conv0 = tips[(tips.stage == "converted") & (tips.concentration_mEq_l == 0)]
    intact = tips[tips.stage == "intact"]
    top = last_converged(tips)
    at = at_highest(top, max_concentration)
    key = ["model", "pressure_mmHg", "case"]
    d = (
        conv0.set_index(key)[["tip_radial_stress_kPa", "top_circ_stress_kPa"]]
        - intact.set_index(key)[["tip_radial_stress_kPa", "top_circ_stress_kPa"]]
    )
    signs = (d.tip_radial_stress_kPa < 0) & (d.top_circ_stress_kPa > 0)
    grow, groups = _monotone_groups(
        d.reset_index(),
        ordered,
        lambda g: np.all(np.diff(-g.tip_radial_stress_kPa) >= 0) and np.all(np.diff(g.top_circ_stress_kPa) >= 0),
    )
    out.append(
        Claim(
            "C6",
            "Converting the pool (no swelling) makes the tip radial stress compressive and raises the top hoop "
            "(tensile) stress",
            "figure 4b,c at c = 0",
            f"tip change {d.tip_radial_stress_kPa.min():.0f} to {d.tip_radial_stress_kPa.max():.0f} kPa, top change "
            f"+{d.top_circ_stress_kPa.min():.0f} to +{d.top_circ_stress_kPa.max():.0f} kPa; signs right in "
            f"{int(signs.sum())}/{len(signs)} runs",
            _yes(signs.all()),
            "tip more compressive and top more tensile than intact in every run",
        )
    )
    out.append(
        Claim(
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
        )
    )

    high = tips[(tips.stage == "converted") & (tips.concentration_mEq_l > 100 - 1e-9)]
    frac_tensile = (top.tip_radial_stress_kPa > 0).mean()
    frac_50 = (high.tip_radial_stress_kPa > 50).mean()
    out.append(
        Claim(
            "C8",
            "Swelling turns the tip radial stress from compressive to tensile, typically above ~50 kPa for "
            "concentrations over 100 mEq/l",
            "> ~50 kPa above 100 mEq/l",
            f"{at}: {top.tip_radial_stress_kPa.min():.0f} to {top.tip_radial_stress_kPa.max():.0f} kPa, "
            f"tensile in {100 * frac_tensile:.0f} % of runs; "
            f"> 50 kPa in {100 * frac_50:.0f} % of states above 100 mEq/l",
            _yes(frac_tensile == 1 and frac_50 >= 0.5),
            "tensile in every run at the highest concentration and > 50 kPa in most states above 100 mEq/l",
        )
    )

    mono, groups = _monotone_groups(top, ordered, lambda g: np.all(np.diff(g.tip_radial_stress_kPa) <= 0))
    out.append(
        Claim(
            "C9",
            "Smaller pools give higher tip stress",
            "figure 4, section 3",
            f"tip radial stress {at} decreases with pool size in {mono}/{groups} model-pressure groups",
            _yes(groups > 0 and mono == groups) if groups else "n/a",
            "monotone in every group",
        )
    )

    passive = tips[(tips.model == "passive") & (tips.stage == "converted") & (tips.concentration_mEq_l > 75 - 1e-9)]
    if passive.pressure_mmHg.nunique() > 1:
        by_level = passive.groupby(["case", "concentration_mEq_l"]).tip_radial_stress_kPa
        spread = by_level.agg(np.ptp)[by_level.size() > 1]  # levels that more than one pressure reached
        out.append(
            Claim(
                "C10",
                "In the passive wall the tip stress hardly changes with lumen pressure above 75 mEq/l",
                "does not change appreciably",
                f"largest spread over pressures {spread.max():.1f} kPa (median {spread.median():.1f} kPa)",
                _yes(spread.max() <= 10.0),
                "spread <= 10 kPa at every case and concentration >= 75 mEq/l",
            )
        )
    else:
        out.append(
            Claim(
                "C10",
                "In the passive wall the tip stress hardly changes with lumen pressure above 75 mEq/l",
                "does not change appreciably",
                "needs more than one pressure",
                "n/a",
                "-",
            )
        )

    both = top.pivot_table(index=["case", "pressure_mmHg"], columns="model", values="tip_radial_stress_kPa")
    if {"passive", "active"} <= set(both.columns):
        diff = (both.active - both.passive).rename("active_minus_passive").reset_index()
        top_p = diff.pressure_mmHg.max()
        low = diff[diff.pressure_mmHg < top_p]
        high_p = diff[(diff.pressure_mmHg == top_p) & diff.case.isin(ordered[:2])]
        out.append(
            Claim(
                "C11",
                "Activation lowers the tip stress at 103 and 145 mmHg",
                "lower (section 3)",
                f"active - passive {at}: "
                + ", ".join(
                    f"{r.case} at {r.pressure_mmHg:g} mmHg: {r.active_minus_passive:+.0f}" for r in low.itertuples()
                )
                + " kPa",
                _yes(len(low) and (low.active_minus_passive < 0).all()) if len(low) else "n/a",
                "negative for every case",
            )
        )
        out.append(
            Claim(
                "C12",
                "... but raises it for the two smallest pools at 200 mmHg",
                "higher for cases I-II (section 3)",
                f"active - passive {at}: "
                + ", ".join(
                    f"{r.case} at {r.pressure_mmHg:g} mmHg: {r.active_minus_passive:+.0f}" for r in high_p.itertuples()
                )
                + " kPa",
                _yes((high_p.active_minus_passive > 0).all()) if len(high_p) else "n/a",
                "positive for the two smallest pools",
            )
        )
    return out


def _ruptures(g: pd.DataFrame) -> pd.DataFrame:
    """Rows of one run (ordered) at which the converted count grew."""
    return g[g.converted_particles.diff() > 0]


def _runs(growth: pd.DataFrame, case: str, criterion: str):
    return {
        s: g.sort_values("step")
        for s, g in growth[(growth.case == case) & (growth.criterion == criterion)].groupby("sigma_cr_kPa")
    }


def delamination_claims(growth: pd.DataFrame, summary: pd.DataFrame, criteria: list, figures: dict) -> list[Claim]:
    """Claims of section 3 (figures 5-7) from ``delamination/growth.csv`` and ``summary.csv`` (one charge law).

    ``figures`` gives the pool sets' roles (``delamination.figures``): figure 5's set (C13-C15), figure 6's sets
    (C16) and figure 7's set (C17). ``holds`` is judged on the default onset criterion (``criteria[0]``); the other
    criteria's numbers are reported beside it.
    """
    out = []
    fig5, fig6, fig7 = figures["fig5"], list(figures["fig6"]), figures["fig7"]

    def per_criterion(fn):
        return "; ".join(f"{c}: {fn(c)}" for c in criteria)

    def spontaneous(c):
        found = {}
        for sigma, g in _runs(growth, fig5, c).items():
            r = _ruptures(g)
            levels = r.groupby("concentration_mEq_l").size()
            found[sigma] = (len(r), int(levels.max()) if len(levels) else 0)
        return found

    def spont_text(c):
        return ", ".join(
            f"{s:g} kPa {n} rupture passes (at most {m} at one concentration)" for s, (n, m) in spontaneous(c).items()
        )

    default = spontaneous(criteria[0])
    grew = [v for v in default.values() if v[0] > 0]
    out.append(
        Claim(
            "C13",
            "Propagation is spontaneous: once the tip stress first exceeds sigma_cr, the pool keeps growing at "
            "fixed concentration",
            "section 3, figure 5",
            per_criterion(spont_text),
            _yes(grew and all(m >= 2 for _, m in grew)),
            "in every single-pool run (default criterion) the pool grows, "
            "and ruptures recur at least twice at one concentration",
        )
    )

    def sawtooth(c):
        drops = {}
        for sigma, g in _runs(growth, fig5, c).items():
            tip = g.tip_radial_stress_kPa.to_numpy()
            drops[sigma] = int(np.sum(np.diff(tip) < -0.1 * sigma))
        return drops

    saw = sawtooth(criteria[0])
    out.append(
        Claim(
            "C14",
            "The tip stress rises and drops repeatedly (a sawtooth)",
            "figure 5b",
            per_criterion(lambda c: ", ".join(f"{s:g} kPa {n} drops" for s, n in sawtooth(c).items())),
            _yes(saw and all(n >= 2 for n in saw.values())),
            "at least two drops by > 10 % of sigma_cr in every single-pool run (default criterion)",
        )
    )

    def rates(c):
        s = summary[(summary.case == fig5) & (summary.criterion == c)].set_index("sigma_cr_kPa")
        return s

    def rate_text(c):
        s = rates(c)
        text = ", ".join(
            f"{k:g} kPa {r.growth_rate_um_per_pseudo_time:.3g} um/pass, {r.growth_rate_um_per_mEq_l:.3g} um/(mEq/l)"
            for k, r in s.iterrows()
        )
        if len(s) > 1 and s.index.min() < s.index.max():
            a, b = s.loc[s.index.min()], s.loc[s.index.max()]

            def ratio(x, y):
                return f"{x / y:.3g}" if y > 0 else ("inf" if x > 0 else "-")

            text += (
                f" (ratio {s.index.min():g}/{s.index.max():g} kPa: "
                f"{ratio(a.growth_rate_um_per_pseudo_time, b.growth_rate_um_per_pseudo_time)} per pass, "
                f"{ratio(a.growth_rate_um_per_mEq_l, b.growth_rate_um_per_mEq_l)} per mEq/l)"
            )
        return text

    s = rates(criteria[0])
    lo, hi = (s.index.min(), s.index.max()) if len(s) else (None, None)
    if lo is not None and lo < hi:
        a, b = s.loc[lo], s.loc[hi]
        slows = all(
            x > 0 and (y == 0 or x / y > 2)
            for x, y in (
                (a.growth_rate_um_per_pseudo_time, b.growth_rate_um_per_pseudo_time),
                (a.growth_rate_um_per_mEq_l, b.growth_rate_um_per_mEq_l),
            )
        )
        holds = _yes(slows)
    else:
        holds = "n/a"
    out.append(
        Claim(
            "C15",
            "Raising sigma_cr from 30 to 60 kPa slows propagation more than twofold",
            "section 3, figure 5",
            per_criterion(rate_text),
            holds,
            "rate at the lowest sigma_cr > 2 x the rate at the highest, per pass and per mEq/l (default criterion)",
        )
    )

    def pair_runs(c):
        """``(summary row, growth row at the merge or at the end)`` of every pool-pair run of criterion ``c``."""
        runs = summary[summary.case.isin(fig6) & (summary.criterion == c)]
        for r in runs.itertuples():
            g = growth[(growth.case == r.case) & (growth.criterion == c)].sort_values("step")
            yield r, (g[g.pseudo_time <= r.merge_step].iloc[-1] if r.merged else g.iloc[-1])

    def merge_text(c):
        return ", ".join(
            f"{r.case} {f'merged at pass {r.merge_step:.0f}' if r.merged else 'not merged'}, converted "
            f"interior {at.converted_interior:.0f} / exterior {at.converted_exterior:.0f}"
            for r, at in pair_runs(c)
        )

    pairs = list(pair_runs(criteria[0]))
    ok = any(r.merged and at.converted_exterior > at.converted_interior for r, at in pairs)
    out.append(
        Claim(
            "C16",
            "Two nearby pools grow and merge, and at merging their exterior growth exceeds their interior growth",
            "figure 6",
            per_criterion(merge_text),
            _yes(ok) if len(pairs) else "n/a",
            "a pool pair merges and has more exterior than interior converted particles at the merge (default "
            "criterion)",
        )
    )

    off = summary[(summary.case == fig7)]
    out.append(
        Claim(
            "C17",
            "Radially offset pools link up",
            "figure 7",
            per_criterion(
                lambda c: ", ".join(
                    f"{f'merged at pass {r.merge_step:.0f}' if r.merged else 'not merged'} "
                    f"({r.final_length_um:.1f} um delaminated)"
                    for r in off[off.criterion == c].itertuples()
                )
            ),
            _yes(off[off.criterion == criteria[0]].merged.any()) if len(off) else "n/a",
            "the radially offset pair merges (default criterion)",
        )
    )
    return out


def of_law(table: pd.DataFrame, law: str) -> pd.DataFrame:
    """The rows of one charge law (column ``charge_law``)."""
    return table[table.charge_law == law]


def by_law(laws, evaluate) -> list[Claim]:
    """The claims ``evaluate(law)`` of every charge law in ``laws``, marked with their law: one row per claim and law,
    the laws of a claim next to each other (in the order of ``laws``)."""
    found = [Claim(**dict(c.__dict__, charge_law=law)) for law in laws for c in evaluate(law)]
    order = list(dict.fromkeys(c.claim_id for c in found))
    return sorted(found, key=lambda c: order.index(c.claim_id))  # stable: the laws of a claim keep their order


COLUMNS = ["claim_id", "charge_law", "statement", "paper_value", "our_value", "holds", "criterion"]


def table(claims: list[Claim]) -> pd.DataFrame:
    return pd.DataFrame([c.__dict__ for c in claims], columns=COLUMNS)


def markdown(df: pd.DataFrame) -> str:
    lines = [
        "# The paper's claims against our numbers",
        "",
        "Generated by the `claims` rule from the pipeline's CSV tables. `holds` follows the criterion "
        "in the last column; nothing was tuned to make a claim hold. The pool claims (C6-C17) are evaluated once "
        "per charge law, with the same criteria: `prescribed` (Pi(c), eqs. 2.25-2.27 as printed) is the paper's "
        "model, the one to compare with the paper; `conserved` (Pi at c/J) is our documented deviation.",
        "",
        "| id | charge law | claim | paper | ours | holds | criterion |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in df.itertuples():
        lines.append(
            f"| {r.claim_id} | {r.charge_law} | {r.statement} | {r.paper_value} | {r.our_value} | **{r.holds}** | "
            f"{r.criterion} |"
        )
    return "\n".join(lines) + "\n"
