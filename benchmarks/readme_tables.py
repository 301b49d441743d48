"""The README's result tables, generated from a finished run's tables (nothing typed by hand).

Reads, where they exist (:data:`SOURCES`: README marker -> the table it is made from):

* ``results/delamination/summary.csv`` (figures 5-7, every charge law and onset measure): ``delamination-runs``;
* ``results/delamination/gci.csv`` (the resolution study's event concentrations with their uncertainty):
  ``delamination-gci``;
* ``results/variants/hourglass_*_summary.csv`` (target ``variants``): ``hourglass-variants``;
* ``results/sensitivity/morris/indices.csv`` (Morris screening): ``morris-ranking``, the inputs ranked by mu* per
  output and charge law, with the numerics' share of the top input's mu*;
* ``results/verification/annulus.csv`` (the pressurised annulus): ``annulus-verification``;
* ``results/swelling/tip_stress.csv`` (figure 4's runs): ``figure4-runs``;
* ``results/swelling/gci.csv`` (figure 4's resolution study with its uncertainty): ``swelling-gci``;
* ``results/swelling/gci_band.csv`` (figure 4's bands): ``figure4-bands``, where each band first exceeds 10 %;
* ``results/claims.csv``: ``figure4-claims``, claims C6-C12 on figure 4's runs and across the resolution band;

and writes each as a Markdown table between the README's markers ``<!-- name -->`` and ``<!-- /name -->``.

    python benchmarks/readme_tables.py                    # print the tables
    python benchmarks/readme_tables.py --readme README.md # rewrite them in the README
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from rule_resources import replace_block

from sphgag.studies import annulus, gci

ROOT = Path(__file__).resolve().parents[1]


def _c(value: float) -> str:
    return f"{value:.1f}" if np.isfinite(value) else "-"


def _um(value: float) -> str:
    return f"{value:.2g} um" if np.isfinite(value) else "-"


def runs_table(summary: pd.DataFrame) -> str:
    """One row per run of figures 5-7: how it ended and the concentrations of its events [mEq/l]."""
    head = (
        "| law | onset measure | pool set | sigma_cr (kPa) | stop | onset | runaway | merge | limit | "
        "arrested length (um) | final length (um) | passes | largest residual |"
    )
    rows = [head, "|" + " --- |" * 13]
    order = summary.sort_values(["charge_law", "criterion", "case", "sigma_cr_kPa"], kind="stable")
    for r in order.itertuples():
        rows.append(
            f"| {r.charge_law} | {r.criterion} | {r.case} | {r.sigma_cr_kPa:g} | {r.stop_kind} | "
            f"{_c(r.onset_concentration_mEq_l)} | {_c(r.runaway_concentration_mEq_l)} | "
            f"{_c(r.merge_concentration_mEq_l)} | {_c(r.limit_concentration_mEq_l)} | {r.arrested_length_um:.1f} | "
            f"{r.final_length_um:.1f} | {r.passes:.0f} | {r.max_residual:.1e} |"
        )
    return "\n".join(rows)


def gci_table(table: pd.DataFrame) -> str:
    """Per event concentration: its value at every spacing, the observed order, the extrapolated value and the GCI."""
    spacings = sorted(table.dx_um.unique(), reverse=True)
    head = (
        "| law | onset measure | pool set | quantity | "
        + " | ".join(f"dx = {dx:g} um" for dx in spacings)
        + " | observed order | extrapolated | GCI (finest) | spacing for a GCI of 10 % |"
    )
    rows = [head, "|" + " --- |" * (8 + len(spacings))]
    groups = table.groupby(["charge_law", "criterion", "case", "quantity"], sort=False)
    for (law, criterion, case, quantity), g in groups:
        values = g.set_index("dx_um").value
        first = g.iloc[0]
        cells = " | ".join(_c(values.get(dx, np.nan)) for dx in spacings)
        finest = values.sort_index().iloc[:3]
        e = gci.estimate(finest.index, finest.to_numpy()) if len(finest) == 3 else None
        order = f"{first.observed_order:.2f}" if np.isfinite(first.observed_order) else "-"
        if e is not None and e.diverging:
            order = "none: the differences grow"
        elif e is not None and e.oscillatory and np.isfinite(first.observed_order):
            order += " (oscillating)"
        gci_fine = f"{100 * first.gci_fine:.1f} %" if np.isfinite(first.gci_fine) else "-"
        name = quantity.removesuffix("_concentration_mEq_l")
        target = e.spacing_for(0.1) if e is not None and not e.diverging else np.nan
        target = "reached" if np.isfinite(first.gci_fine) and first.gci_fine <= 0.1 else _um(target)
        rows.append(
            f"| {law} | {criterion} | {case} | {name} | {cells} | {order} | {_c(first.extrapolated)} | {gci_fine} | "
            f"{target} |"
        )
    return "\n".join(rows)


def variants_table(summary: pd.DataFrame) -> str:
    """Figure 5's pool under each form of the hourglass control."""
    rows = ["| hourglass | stop | onset | runaway | final length (um) | passes | stop text |", "|" + " --- |" * 7]
    for r in summary.itertuples():
        rows.append(
            f"| {r.hourglass} | {r.stop_kind} | {_c(r.onset_concentration_mEq_l)} | "
            f"{_c(r.runaway_concentration_mEq_l)} | {r.final_length_um:.1f} | {r.passes:.0f} | {r.stop} |"
        )
    return "\n".join(rows)


NUMERICS = "numerics."  # the sensitivity inputs that are numerical choices, not physics
SHOWN_INPUTS = 5


def morris_table(indices: pd.DataFrame) -> str:
    """Per output and charge law: the inputs ranked by Morris mu* (with the bootstrap interval of the first), and the
    numerics' share: the largest mu* of a numerical input over the top input's mu*."""
    mu = indices[(indices.method == "morris") & (indices["index"] == "mu_star")]
    head = (
        "| output | law | samples used (failed) | inputs by mu* (per full range), largest first | "
        "numerics' share of the top mu* |"
    )
    rows = [head, "|" + " --- |" * 5]
    for (output, law), g in mu.groupby(["output", "charge_law"], sort=False):
        g = g[np.isfinite(g.value)].sort_values("value", ascending=False)
        used = f"{g.samples_used.iloc[0]:.0f} ({g.samples_failed.iloc[0]:.0f})" if len(g) else "-"
        if g.empty or g.value.iloc[0] <= 0.0:
            rows.append(f"| {output} | {law} | {used} | does not vary | - |")
            continue
        top = g.iloc[0]
        ranked = [f"**{top.input}** {top.value:.3g} [{top.conf_low:.3g}, {top.conf_high:.3g}]"]
        ranked += [f"{r.input} {r.value:.3g}" for r in g.iloc[1:SHOWN_INPUTS].itertuples()]
        numerics = g[g.input.str.startswith(NUMERICS)]
        share = (
            f"{numerics.value.iloc[0] / top.value:.0%} ({numerics.input.iloc[0].removeprefix(NUMERICS)})"
            if len(numerics)
            else "-"
        )
        rows.append(f"| {output} | {law} | {used} | {'; '.join(ranked)} | {share} |")
    return "\n".join(rows)


def _pct(value: float) -> str:
    return f"{100 * value:+.2f} %" if np.isfinite(value) else "-"


def annulus_table(table: pd.DataFrame) -> str:
    """The pressurised annulus: per pool model, B/A and fraction of the exact limit, the errors of the volume ratio and
    of the hoop stress at the hole at every spacing with the observed order of the finer pair, how far the GAG reach
    outside the lining; and, above the limit, how each spacing's run ended."""
    spacings = sorted(table.dx_um.unique(), reverse=True)
    orders = annulus.orders(table).set_index(["pool_model", "outer_ratio", "fraction", "quantity"])
    head = (
        "| pool | B/A | Pi / limit | volume ratio error: "
        + " / ".join(f"dx {d:g}" for d in spacings)
        + " (order) | hoop stress error: same spacings (order) | GAG beyond the lining, finest (um) |"
    )
    rows = [head, "|" + " --- |" * 6]
    below = table[(table.fraction < 1.0)]
    for (model, ratio, f), g in below.groupby(["pool_model", "outer_ratio", "fraction"], sort=True):
        g = g.set_index("dx_um").reindex(spacings)
        cells = []
        for quantity, error in (("volume_ratio", "volume_error"), ("lining_hoop_kPa", "lining_hoop_error")):
            key = (model, ratio, f, quantity)
            order = f"{orders.loc[key, 'order_fine']:.2f}" if key in orders.index else "-"
            cells.append(" / ".join(_pct(v) for v in g[error]) + f" ({order})")
        crossing = g.ring_crossing_um.iloc[-1]
        rows.append(
            f"| {model} | {ratio:g} | {f:g} | {cells[0]} | {cells[1]} | "
            + (f"{crossing:+.2f} |" if np.isfinite(crossing) else "- |")
        )
    above = table[table.fraction > 1.0]
    for (model, ratio), g in above.groupby(["pool_model", "outer_ratio"], sort=True):
        limit = g.limit_pressure_kPa.iloc[0]
        ends = []
        for r in g.sort_values("dx_um", ascending=False).itertuples():
            held = r.discrete_limit_kPa if r.beyond_end == "limit point" else r.largest_held_kPa
            what = "a STATE" if r.state else f"{r.beyond_end}, {held / limit:.4f} x the limit held"
            ends.append(f"dx {r.dx_um:g}: {what}")
        rows.append(
            f"| {model} | {ratio:g} | {g.fraction.iloc[0]:g} (exact {g.limit_kind.iloc[0]} {limit:.2f} kPa) | "
            + "; ".join(ends)
            + " | | |"
        )
    return "\n".join(rows)


def _value(value: float, digits: int = 3) -> str:
    return f"{value:.{digits}g}" if np.isfinite(value) else "-"


SWELLING_GCI_SHOWN = [  # the README's selection of gci.csv (quantity, walls, concentration or None: every J)
    ("concentration_at_volume_mEq_l", ("passive", "active"), None),
    ("tip_radial_stress_at_volume_kPa", ("passive",), None),
    ("tip_radial_stress_kPa", ("passive",), 150.0),
    ("volume_ratio", ("passive",), 150.0),
]


def swelling_gci_table(table: pd.DataFrame) -> str:
    """Figure 4's resolution study (the selection :data:`SWELLING_GCI_SHOWN` of gci.csv): per charge law, wall, case,
    quantity and where it is read (at a volume ratio J or a concentration), the value at every spacing, the observed
    order, the extrapolated value, the GCI of the finest spacing and the spacing at which the observed order puts a
    GCI of 5 %."""
    shown = np.zeros(len(table), dtype=bool)
    for quantity, walls, at in SWELLING_GCI_SHOWN:
        rows = (table.quantity == quantity) & table.model.isin(walls)
        shown |= (rows & (table["at"] == at)) if at is not None else rows
    table = table[shown]
    spacings = sorted(table.dx_um.unique(), reverse=True)
    names = {
        "concentration_at_volume_mEq_l": ("c holding J (mEq/l)", "J = {:g}"),
        "tip_radial_stress_at_volume_kPa": ("tip radial stress (kPa)", "J = {:g}"),
        "top_circ_stress_at_volume_kPa": ("top hoop stress (kPa)", "J = {:g}"),
        "tip_radial_stress_kPa": ("tip radial stress (kPa)", "{:g} mEq/l"),
        "top_circ_stress_kPa": ("top hoop stress (kPa)", "{:g} mEq/l"),
        "volume_ratio": ("pool volume ratio J", "{:g} mEq/l"),
    }
    head = (
        "| law | wall | case | quantity | at | "
        + " | ".join(f"dx = {dx:g} um" for dx in spacings)
        + " | observed order | extrapolated | GCI (finest) | dx for a GCI of 5 % |"
    )
    rows = [head, "|" + " --- |" * (9 + len(spacings))]
    order = table.assign(_q=table.quantity.map(list(names).index))
    order = order.sort_values(["charge_law", "_q", "model", "case", "at", "dx_um"], kind="stable")
    for (law, quantity, wall, case, at), g in order.groupby(
        ["charge_law", "quantity", "model", "case", "at"], sort=False
    ):
        values = g.set_index("dx_um").value
        first = g.sort_values("dx_um").iloc[0]
        finest = values.sort_index().iloc[:3]
        e = gci.estimate(finest.index, finest.to_numpy()) if len(finest) == 3 and finest.notna().all() else None
        if not np.isfinite(first.observed_order):
            order_text = "none: the differences grow" if e is not None and e.diverging else "-"
        else:
            order_text = f"{first.observed_order:.2f}" + ("" if first.order_in_range else " (outside 0.5-3)")
        gci_text = f"{100 * first.gci_fine:.1f} %" if np.isfinite(first.gci_fine) else "-"
        target = "reached" if np.isfinite(first.gci_fine) and first.gci_fine <= 0.05 else "-"
        if target == "-" and e is not None and np.isfinite(e.order):
            target = _um(e.spacing_for(0.05))
        label, where = names[quantity]
        cells = " | ".join(_value(values.get(dx, np.nan)) for dx in spacings)
        rows.append(
            f"| {law} | {wall} | {case} | {label} | {where.format(at)} | {cells} | {order_text} | "
            f"{_value(first.extrapolated)} | {gci_text} | {target} |"
        )
    return "\n".join(rows)


def figure4_runs_table(tips: pd.DataFrame) -> str:
    """Figure 4's runs per charge law and pool model: how many reach the top of the ramp, where the others' last
    equilibrium is, and the tip radial stress and pool volume ratio there."""
    rows = [
        "| law | pool | runs reaching the top of the ramp | last equilibrium of the others (mEq/l) | "
        "tip radial stress at each run's last equilibrium (kPa) | pool volume ratio J there |",
        "|" + " --- |" * 6,
    ]
    conv = tips[tips.stage == "converted"]
    top = conv.concentration_mEq_l.max()
    for (law, pool), g in conv.groupby(["charge_law", "pool_model"], sort=False):
        last = g.loc[g.groupby(["model", "pressure_mmHg", "case"]).concentration_mEq_l.idxmax()]
        short = last[last.concentration_mEq_l < top - 1e-9]
        ends = f"{short.concentration_mEq_l.min():g}-{short.concentration_mEq_l.max():g}" if len(short) else "-"
        J = last.pool_volume_change + 1.0
        tip = last.tip_radial_stress_kPa
        rows.append(
            f"| {law} | {pool} | {len(last) - len(short)} of {len(last)} (to {top:g} mEq/l) | {ends} | "
            f"{tip.min():.0f} to {tip.max():.0f} (tensile in {int((tip > 0).sum())}) | {J.min():.3g}-{J.max():.3g} |"
        )
    return "\n".join(rows)


def band_limit_table(band: pd.DataFrame, limit: float = 0.10) -> str:
    """Figure 4's bands: per charge law, wall, case and stress, the first concentration of the ramp at which the GCI
    of the finest spacing exceeds ``limit`` (or the three spacings give no order there), and the GCI at every step
    (``-``: a step that not every spacing reached)."""
    conv = band[(band.stage == "converted") & (band.dx_um == band.dx_um.min())]
    names = {"tip_radial_stress_kPa": "tip radial stress", "top_circ_stress_kPa": "top hoop stress"}
    levels = sorted(conv.concentration_mEq_l.unique())
    rows = [
        f"| law | wall | case | stress | band above {limit:.0%} from (mEq/l) | "
        + " | ".join(f"GCI at {c:g}" for c in levels)
        + " |",
        "|" + " --- |" * (5 + len(levels)),
    ]
    for (law, wall, case, quantity), g in conv.groupby(["charge_law", "model", "case", "quantity"], sort=True):
        g = g.sort_values("concentration_mEq_l")
        wide = g[~(g.gci_fine <= limit)]
        first = f"{wide.concentration_mEq_l.iloc[0]:g}" if len(wide) else "never"
        gci_at = g.set_index("concentration_mEq_l").gci_fine
        steps = [
            "-" if c not in gci_at.index else f"{100 * gci_at[c]:.0f} %" if np.isfinite(gci_at[c]) else "no order"
            for c in levels
        ]
        rows.append(f"| {law} | {wall} | {case} | {names[quantity]} | {first} | {' | '.join(steps)} |")
    return "\n".join(rows)


def figure4_claims_table(claims: pd.DataFrame) -> str:
    """Claims C6-C12 (every charge law and pool model): the verdict on figure 4's runs and across the resolution
    band, with the margin."""
    rows = ["| claim | law | pool | holds | margin (kPa) | at every spacing and extrapolated (margin, kPa) |"]
    rows.append("|" + " --- |" * 6)
    figure4 = claims[claims.claim_id.isin([f"C{k}" for k in range(6, 13)])]
    figure4 = figure4.assign(holds=figure4.holds.fillna("n/a"), across_band=figure4.across_band.fillna("n/a"))
    for r in figure4.itertuples():
        margin = f"{r.margin:+.0f}" if np.isfinite(r.margin) else "-"
        rows.append(f"| {r.claim_id} | {r.charge_law} | {r.pool_model} | {r.holds} | {margin} | {r.across_band} |")
    return "\n".join(rows)


SOURCES = {  # README marker -> (the result table's path pattern under results/, the function that writes it)
    "delamination-runs": ("delamination/summary.csv", runs_table),
    "delamination-gci": ("delamination/gci.csv", gci_table),
    "hourglass-variants": ("variants/hourglass_*_summary.csv", variants_table),
    "morris-ranking": ("sensitivity/morris/indices.csv", morris_table),
    "annulus-verification": ("verification/annulus.csv", annulus_table),
    "figure4-runs": ("swelling/tip_stress.csv", figure4_runs_table),
    "swelling-gci": ("swelling/gci.csv", swelling_gci_table),
    "figure4-bands": ("swelling/gci_band.csv", band_limit_table),
    "figure4-claims": ("claims.csv", figure4_claims_table),
}


def blocks(results: Path) -> dict[str, str]:
    """The tables that this run's results give, by the name of their README markers."""
    out = {}
    for name, (pattern, table) in SOURCES.items():
        paths = sorted(results.glob(pattern))
        if paths:
            out[name] = table(pd.concat([pd.read_csv(p) for p in paths], ignore_index=True))
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--results", type=Path, default=ROOT / "results", help="the run's results folder")
    ap.add_argument("--readme", type=Path, help="rewrite the tables between the markers of this README")
    args = ap.parse_args(argv)
    tables = blocks(args.results)
    if args.readme is None:
        print("\n\n".join(f"<!-- {name} -->\n{table}" for name, table in tables.items()))
        return 0
    text = args.readme.read_text()
    for name, table in tables.items():
        text = replace_block(text, table, name)
    args.readme.write_text(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
