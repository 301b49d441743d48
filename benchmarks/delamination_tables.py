"""The README's delamination numbers, generated from a finished run's tables (nothing typed by hand).

Reads, where they exist, ``results/delamination/summary.csv`` (figures 5-7, every charge law and onset measure),
``results/delamination/gci.csv`` (the resolution study's event concentrations with their uncertainty) and
``results/variants/hourglass_*_summary.csv`` (target ``variants``), and writes each as a Markdown table between the
README's markers ``<!-- delamination-runs -->``, ``<!-- delamination-gci -->`` and ``<!-- hourglass-variants -->``.

    python benchmarks/delamination_tables.py                    # print the tables
    python benchmarks/delamination_tables.py --readme README.md # rewrite them in the README
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd
from rule_resources import replace_block

from sphgag.studies import gci

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


def blocks(results: Path) -> dict[str, str]:
    """The tables that this run's results give, by the name of their README markers."""
    out = {}
    summary = results / "delamination" / "summary.csv"
    if summary.exists():
        out["delamination-runs"] = runs_table(pd.read_csv(summary))
    uncertainty = results / "delamination" / "gci.csv"
    if uncertainty.exists():
        out["delamination-gci"] = gci_table(pd.read_csv(uncertainty))
    variants = sorted((results / "variants").glob("hourglass_*_summary.csv"))
    if variants:
        out["hourglass-variants"] = variants_table(pd.concat([pd.read_csv(p) for p in variants], ignore_index=True))
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
