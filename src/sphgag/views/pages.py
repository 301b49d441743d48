"""The pipeline's result tables as Markdown: the documentation site's results pages (``snakemake docs``) and the
README's generated blocks (``benchmarks/readme_tables.py``). Nothing here computes a number: every cell is read from
a table a rule wrote (its source in :data:`SECTIONS`), and every page is stamped with the commit and configuration
its tables came from.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ..physics.donnan import PAPER_LAW, charge_law
from ..studies import gci, paper_settings, resolution, wall_profiles
from ..studies.claims.procedure import P5_CONCENTRATION, P5_RANGE
from ..studies.claims.verdicts import markdown
from ..studies.sensitivity import MORRIS
from .names import LAW_FIGURES, law_figure


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
    mu = MORRIS.influence(indices)
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


def profiles_table(table: pd.DataFrame) -> str:
    """The walls' transmural stress (profiles.csv): per wall, pressure, lumen load and reading, the radial error at
    the inner and outer surfaces and the largest at any ring (% of P, at the rings' material points) and the hoop rms
    error (%) at every spacing, with the observed order of the finer pair."""
    orders = wall_profiles.orders(table).set_index(wall_profiles.KEYS)
    rows = [
        "| wall | P (mmHg) | lumen load | reading | dx (um) | inner radial (% of P) | outer radial | largest radial, "
        "any ring (order) | hoop rms, % (order) |",
        "|" + " --- |" * 9,
    ]
    for key, g in table.groupby(wall_profiles.KEYS, sort=False):
        g = g.sort_values("dx_um", ascending=False)
        o = orders.loc[key] if key in orders.index else pd.Series(dtype=float)
        cells = [
            " / ".join(f"{v:+.1f}" if signed else f"{v:.1f}" for v in g[column])
            + (f" ({o[column + '_order']:.2f})" if np.isfinite(o.get(column + "_order", np.nan)) else "")
            for column, signed in (
                ("material_inner_radial_pct", True),
                ("material_outer_radial_pct", True),
                ("material_radial_max_pct", False),
                ("material_circ_rms_pct", False),
            )
        ]
        wall, load, reading, P = key
        spacings = " / ".join(f"{d:g}" for d in g.dx_um)
        rows.append(f"| {wall} | {P:g} | {load} | {reading} | {spacings} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def annulus_table(table: pd.DataFrame) -> str:
    """The pressurised annulus: per pool model, B/A and fraction of the exact limit, the errors of the volume ratio and
    of the hoop stress at the hole at every spacing with the observed order of the finer pair, how far the GAG reach
    outside the lining; and, above the limit, how each spacing's run ended."""
    spacings = sorted(table.dx_um.unique(), reverse=True)
    orders = resolution.annulus_orders(table).set_index(["pool_model", "outer_ratio", "fraction", "quantity"])
    head = (
        "| pool | B/A | Pi / limit | volume ratio error: "
        + " / ".join(f"dx {d:g}" for d in spacings)
        + " (order) | hoop stress error: same spacings (order) | hoop stress recovered from the traction: same "
        + "(order) | GAG beyond the lining, finest (um) |"
    )
    rows = [head, "|" + " --- |" * 7]
    below = table[(table.fraction < 1.0)]
    for (model, ratio, f), g in below.groupby(["pool_model", "outer_ratio", "fraction"], sort=True):
        g = g.set_index("dx_um").reindex(spacings)
        cells = []
        for quantity, error in (
            ("volume_ratio", "volume_error"),
            ("lining_hoop_kPa", "lining_hoop_error"),
            ("lining_hoop_traction_kPa", "lining_hoop_traction_error"),
        ):
            key = (model, ratio, f, quantity)
            order = f"{orders.loc[key, 'order_fine']:.2f}" if key in orders.index else "-"
            cells.append(" / ".join(_pct(v) for v in g[error]) + f" ({order})")
        crossing = g.ring_crossing_um.iloc[-1]
        rows.append(
            f"| {model} | {ratio:g} | {f:g} | {cells[0]} | {cells[1]} | {cells[2]} | "
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
            + " | | | |"
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


def _claim_list(ids) -> str:
    return ", ".join(dict.fromkeys(ids)) or "-"


def holds_table(claims: pd.DataFrame, pool_model: str = "particles") -> str:
    """What holds and what does not: per charge law, the claims (of the pool model ``pool_model`` where a claim is
    about a pool) that hold, that do not, and that could not be judged (``n/a`` or not run)."""
    rows = ["| law | holds | does not hold | not judged |", "|" + " --- |" * 4]
    if "path" in claims:  # the claims on the equilibria (the procedure's are in procedure_table)
        claims = claims[claims.path.fillna("equilibrium") == "equilibrium"]
    general = claims[claims.charge_law == "-"]
    laws = [law for law in dict.fromkeys(claims.charge_law) if law != "-"]
    for law in laws:
        mine = pd.concat([general, claims[(claims.charge_law == law) & (claims.pool_model == pool_model)]])
        judged = mine.holds.fillna("n/a")
        rows.append(
            f"| {law} | {_claim_list(mine.claim_id[judged == 'yes'])} | {_claim_list(mine.claim_id[judged == 'no'])} "
            f"| {_claim_list(mine.claim_id[~judged.isin(['yes', 'no'])])} |"
        )
    return "\n".join(rows)


def gci_summary(table: pd.DataFrame, quantity: str = "concentration_at_volume_mEq_l") -> str:
    """Figure 4's uncertainty in one table: per charge law, wall and case, the GCI of the finest spacing of
    ``quantity`` (by default the concentration that holds each volume ratio J, the study's well-conditioned number),
    with its observed order."""
    dx = table.dx_um.min()
    rows = [
        f"| law | wall | case | J | value at dx = {dx:g} um | GCI | observed order | extrapolated |",
        "|" + " --- |" * 8,
    ]
    finest = table[(table.quantity == quantity) & (table.dx_um == dx)]
    for r in finest.sort_values(["charge_law", "model", "case", "at"]).itertuples():
        gci_text = f"{100 * r.gci_fine:.1f} %" if np.isfinite(r.gci_fine) else "no estimate"
        rows.append(
            f"| {r.charge_law} | {r.model} | {r.case} | {r.at:g} | {_value(r.value)} | {gci_text} | "
            f"{_value(r.observed_order, 2)} | {_value(r.extrapolated)} |"
        )
    return "\n".join(rows)


@dataclass(frozen=True)
class Section:
    """One section of a results page: its title, the table it is made from (a key of the tables a page reads), the
    function that writes it, and the target that makes the table where `all` does not."""

    title: str
    source: str
    render: Callable[[pd.DataFrame], str]
    target: str = "all"


def procedure_table(claims: pd.DataFrame) -> str:
    """The paper's features of figures 4-6 by the authors' explicit procedure beside the equilibrium (claims P1-P4):
    per feature and path, our numbers with the residual they were read at, and whether the feature holds."""
    rows = ["| feature | path | ours | holds |", "|" + " --- |" * 4]
    mine = claims[claims.claim_id.str.startswith("P")] if "path" in claims else claims.iloc[:0]
    for r in mine.itertuples():
        rows.append(f"| {r.claim_id}: {r.statement} | {r.path} | {r.our_value} | {r.holds} |")
    return "\n".join(rows)


def authors_settings(table: pd.DataFrame) -> str:
    """Figure 4 under the authors' settings (target paper_settings, claim P5) in a paragraph a reader can quote and
    a table: the tip radial stress at claim P5's concentration under each configuration and each one-setting switch
    (``results/paper_settings/ablation.csv``; "no eq." where the path has no equilibrium there), and the settings
    that account for most of the difference (:func:`sphgag.studies.paper_settings.ranked`)."""
    c, (lo, hi) = P5_CONCENTRATION, P5_RANGE
    at = table[np.isclose(table.concentration_mEq_l, c)]
    walls = list(dict.fromkeys(zip(at.model, at.case)))
    value = at.set_index(["setting", "direction", "model", "case"]).tip_radial_stress_kPa

    def tips(setting, direction):
        return [value.get((setting, direction, m, k), np.nan) for m, k in walls]

    def listed(values):
        return ", ".join(f"{m} {k} {_kpa(v)}" for (m, k), v in zip(walls, values))

    ranked = paper_settings.ranked(table, c).dropna(subset=["share"]).head(3)
    top = ", ".join(f"`{r.setting}` ({r.share:.2f})" for r in ranked.itertuples()) or "none could be ranked"
    text = (
        f"At {c:g} mEq/l and at equilibrium, the authors' settings (`config/script.yaml`) give a tip radial stress of "
        f"{listed(tips(paper_settings.NONE, 'script'))} kPa, ours (`config/config.yaml`) "
        f"{listed(tips(paper_settings.NONE, 'ours'))} kPa; the paper's figure 4 reads {lo:g}-{hi:g} kPa (claim P5). "
        f"The settings that account for most of the difference, by the median share of ours - the authors' that "
        f"their step makes (both directions, walls and pools): {top}."
    )
    rows = ["| configuration | " + " | ".join(f"{m} {k}" for m, k in walls) + " |", "|" + " --- |" * (len(walls) + 1)]
    names = {"script": "the authors'", "ours": "ours"}
    switched = {"from_script": "ours", "from_ours": "the authors'"}
    for base, direction in paper_settings.DIRECTIONS.items():
        rows.append(f"| {names[base]} | " + " | ".join(map(_kpa, tips(paper_settings.NONE, base))) + " |")
        for setting in dict.fromkeys(at.setting[at.direction == direction]):
            label = f"{names[base]}, `{setting}` {switched[direction]}"
            rows.append(f"| {label} | " + " | ".join(map(_kpa, tips(setting, direction))) + " |")
    return text + "\n\n" + "\n".join(rows)


def _kpa(value: float) -> str:
    return f"{value:.0f}" if np.isfinite(value) else "no eq."


def _claims_page(table: pd.DataFrame) -> str:
    return markdown(table)


# page -> (title, its figures (the stems of PNG names under figures/: a figure drawn once per charge law is shown once
# per law, :func:`shown`), its sections)
PAGES: dict[str, tuple[str, tuple[str, ...], tuple[Section, ...]]] = {
    "index": (
        "Results",
        ("fig1", "fig3", "fig4", "fig5", "fig6", "fig7"),
        (
            Section("What holds and what does not (the paper's pool of GAG particles)", "claims", holds_table),
            Section(
                "Figure 4's uncertainty: the concentration that holds a pool volume",
                "swelling_gci",
                gci_summary,
                "resolution",
            ),
        ),
    ),
    "claims": ("The paper's claims against our numbers", (), (Section("Claims", "claims", _claims_page),)),
    "swelling": (
        "Swelling (figure 4)",
        ("fig4",),
        (
            Section("Figure 4's runs", "tips", figure4_runs_table),
            Section("Claims C6-C12 across the resolution band", "claims", figure4_claims_table),
            Section("The paper's explicit procedure beside the equilibria (P1-P4)", "claims", procedure_table),
            Section("Figure 4 under the authors' settings (P5)", "paper_settings", authors_settings, "paper_settings"),
            Section(
                "Resolution study: observed order, extrapolation and GCI",
                "swelling_gci",
                swelling_gci_table,
                "resolution",
            ),
            Section("Where each band first exceeds 10 %", "swelling_band", band_limit_table, "resolution"),
        ),
    ),
    "delamination": (
        "Delamination (figures 5-7)",
        ("fig5", "fig6", "fig7"),
        (
            Section("Every run of figures 5-7", "delamination", runs_table),
            Section("Resolution study of the event concentrations", "delamination_gci", gci_table, "resolution"),
        ),
    ),
    "verification": (
        "Verification and variants",
        ("verification_pool",),
        (
            Section("The pressurised annulus", "annulus", annulus_table, "verification"),
            Section(
                "The walls' transmural stress against the exact thick wall", "profiles", profiles_table, "verification"
            ),
            Section("The hourglass control's forms on figure 5's pool", "variants", variants_table, "variants"),
            Section("Morris screening: which inputs decide the results", "morris", morris_table, "sensitivity"),
        ),
    ),
}


def stamp(commit: str, configuration: dict) -> str:
    """The line that says where a page's numbers came from."""
    files = ", ".join(f"`{f}`" for f in configuration["files"]) or "`config/config.yaml`"
    return (
        f"*Generated by `snakemake docs` from the tables of commit `{commit}`, configuration {files} "
        f"(sha256 `{configuration['sha256'][:12]}`). Every number on this page is read from those tables.*"
    )


def shown(stems, laws) -> list[tuple[str, str]]:
    """``(PNG name, caption)`` of the figures ``stems``: a figure of the paper's figures 4-7 once per charge law of
    ``laws`` (:func:`~sphgag.views.names.law_figure`: fig4.png, fig4_conserved.png), captioned with its law;
    any other once, captioned with its name."""
    out = []
    for stem in stems:
        if stem in LAW_FIGURES:
            out += [(f"{law_figure(stem, law)}.png", f"{stem}: {charge_law(law).title}") for law in laws]
        else:
            out.append((f"{stem}.png", stem))
    return out


def page(name: str, tables: dict[str, pd.DataFrame | None], header: str, laws=(PAPER_LAW,)) -> str:
    """The Markdown of results page ``name``: its title, the stamp ``header``, its sections (a section whose table
    was not made says which target makes it), then its figures (copied beside the page under figures/), those drawn
    once per charge law once for each of ``laws``, each captioned."""
    title, figures, sections = PAGES[name]
    out = [f"# {title}", "", header, ""]
    if name == "index":
        out += [f"- [{PAGES[p][0]}]({p}.md)" for p in PAGES if p != "index"] + [""]
    for s in sections:
        table = tables.get(s.source)
        body = s.render(table) if table is not None else f"Not run: `snakemake {s.target}` makes it."
        out += [f"## {s.title}", "", body, ""]
    if figures:
        out += ["## Figures", ""]
        out += [f"![{caption}](figures/{png})\n\n*{caption}*\n" for png, caption in shown(figures, laws)]
    return "\n".join(out)


def write(
    out_dir: Path, tables: dict[str, pd.DataFrame | None], figures: dict[str, Path], header: str, laws=(PAPER_LAW,)
) -> None:
    """Every page of :data:`PAGES` as ``out_dir/{page}.md``, with the figures they show copied from ``figures``
    (name -> path) into ``out_dir/figures`` (the paper's figures 4-7 once per charge law of ``laws``)."""
    (out_dir / "figures").mkdir(parents=True, exist_ok=True)
    for name in PAGES:
        (out_dir / f"{name}.md").write_text(page(name, tables, header, laws))
    for png in dict.fromkeys(png for _, stems, _ in PAGES.values() for png, _ in shown(stems, laws)):
        shutil.copyfile(figures[png], out_dir / "figures" / png)
