"""What every figure family shares: the figures' style, palettes, the charge laws' and pool models' titles,
the check of a figure's data and its saving with provenance (no figure of its own)."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import seaborn as sns  # noqa: E402

from ..physics import donnan  # noqa: E402
from ..records.provenance import figure_metadata  # noqa: E402
from . import overlap  # noqa: E402

LAYER_COLOURS = {"media": "#3b6fb6", "adventitia": "#2e9e5b", "GAG": "#d1352b"}  # the paper's layers and the pools
GAG_CONCENTRATION = "GAG concentration (mEq/l)"
LAST_CONVERGED = "last converged state (run stopped)"


def _style():
    plt.rcParams.update(
        {
            "font.size": 9,
            "axes.labelsize": 9,
            "legend.fontsize": 8,
            "axes.spines.top": False,
            "axes.spines.right": False,
            "figure.dpi": 150,
            "savefig.bbox": "tight",
        }
    )


def distinct_colours(n: int, lead=()) -> list:
    """``n`` distinct colours: those of ``lead`` first, then the colours of Dark2 that ``lead`` does not have (hex, in
    Dark2's order), then evenly spaced hues (husl) for any beyond."""
    have = {matplotlib.colors.to_hex(c) for c in lead}
    dark2 = [c for c in map(matplotlib.colors.to_hex, plt.cm.Dark2.colors) if c not in have]
    colours = (list(lead) + dark2)[:n]
    return colours + sns.color_palette("husl", n - len(colours)).as_hex()


EXTRA_LAYER_COLOURS = ("#7570b3", "#e6ab02", "#a6761d", "#e7298a", "#666666")  # Dark2 without its greens and orange


def layer_colours(names) -> dict:
    """A colour per layer name of ``names`` (and ``GAG``): the paper's layers keep theirs (:data:`LAYER_COLOURS`), any
    other layer (a lamina) takes the next of :data:`EXTRA_LAYER_COLOURS` (none near the media's blue, the
    adventitia's green or the pools' red), then evenly spaced hues."""
    names = list(dict.fromkeys(names))
    extra = [n for n in names if n not in LAYER_COLOURS]
    spare = iter(distinct_colours(len(extra), lead=EXTRA_LAYER_COLOURS[: len(extra)]))
    return {**{n: LAYER_COLOURS.get(n) or next(spare) for n in names}, "GAG": LAYER_COLOURS["GAG"]}


def pressure_colours(pressures) -> dict:
    """A colour per distinct pressure [mmHg] of ``pressures`` (keys rounded to 1e-6 mmHg): Dark2 over the sorted
    pressures, so that a figure of the pressures 103, 145 and 200 mmHg draws them green, orange and purple."""
    levels = sorted({round(float(p), 6) for p in pressures})
    return dict(zip(levels, distinct_colours(len(levels))))


def pressure_colour(colours: dict, p):
    """The colour of pressure ``p`` [mmHg] in ``colours`` (:func:`pressure_colours`)."""
    return colours[round(float(p), 6)]


def palette(levels, colours: dict, label="{:g}".format) -> dict:
    """Seaborn palette of ``levels``: ``label(level)`` -> ``colours[level]`` where ``colours`` has the level, else
    the next unused colour of Dark2 (deterministic, in the order of ``levels``)."""
    spare = iter(c for c in sns.color_palette("Dark2").as_hex() if c not in colours.values())
    return {label(v): colours.get(v) or next(spare) for v in levels}


def long_measures(table: pd.DataFrame, measures: dict, id_vars) -> pd.DataFrame:
    """``table`` in long form: one row per value of a ``measures`` column (column -> (quantity, statistic)) that
    ``table`` has, with its ``quantity`` and ``statistic`` (the facets and line styles of a seaborn figure)."""
    long = table.melt(id_vars=id_vars, value_vars=[c for c in measures if c in table], var_name="column")
    long["quantity"] = long.column.map(lambda c: measures[c][0])
    long["statistic"] = long.column.map(lambda c: measures[c][1])
    return long


def style_legend(ax, loc="best", fontsize=7, **kws):
    """The seaborn legend of ``ax`` without a frame, in small type."""
    sns.move_legend(ax, loc, frameon=False, fontsize=fontsize, **kws)


# the Donnan laws of the pools (the registry sphgag.physics.donnan.CHARGE_LAWS, column charge_law of every pool table),
# as the figures name them (each law's title and short label): the paper's law is the one to compare with the
# paper's panels. A name the registry does not know is shown as itself.


def law_title(law: str) -> str:
    """The heading of a charge law: its title, or for a law the registry does not know "<law> charge law"."""
    known = donnan.CHARGE_LAWS.get(law)
    return known.title if known else f"{law} charge law"


def law_short(law: str) -> str:
    """The label of a charge law in a panel title or an axis label: its short label, or the name of a law the
    registry does not know."""
    known = donnan.CHARGE_LAWS.get(law)
    return known.short if known else law


def is_paper_law(law: str) -> bool:
    """Whether ``law`` is the paper's charge law (False for a law the registry does not know)."""
    known = donnan.CHARGE_LAWS.get(law)
    return bool(known and known.paper)


# the pool models of the swelling runs (sphgag.studies.pool_swelling.POOL_MODELS, column pool_model of the pool tables):
# ``particles`` is the paper's; the others are named beside their law in the figures
PAPER_POOL = "particles"


def variants(table: pd.DataFrame, laws) -> list[tuple[str, str]]:
    """The (charge law, pool model) pairs of ``table`` in the order of ``laws``, the paper's pool model first (a table
    without a column ``pool_model`` has the paper's only)."""
    pools = list(dict.fromkeys(table.pool_model)) if "pool_model" in table else [PAPER_POOL]
    pools = sorted(pools, key=lambda m: m != PAPER_POOL)
    have = set(zip(table.charge_law, table.pool_model if "pool_model" in table else [PAPER_POOL] * len(table)))
    return [(law, m) for law in laws for m in pools if (law, m) in have]


def paper_pool(table: pd.DataFrame) -> pd.DataFrame:
    """The rows of the paper's pool model (all rows of a table without a column ``pool_model``)."""
    return table[table.pool_model == PAPER_POOL] if "pool_model" in table else table


def variant_short(law: str, pool: str) -> str:
    """The label of one (charge law, pool model) pair: the law's, or, for another pool model, both names."""
    return law_short(law) if pool == PAPER_POOL else f"{law} law, pool as {pool}"


def save(fig, paths, description: str):
    """Save ``fig`` to every path (format from the suffix) with provenance metadata; where the environment asks for it,
    record the figure's text overlaps first (:func:`sphgag.views.overlap.record`, under the name of its PNG)."""
    overlap.record(fig, next((p for p in paths if str(p).endswith(".png")), paths[0]))
    for path in paths:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        meta = figure_metadata(description)
        if str(path).endswith(".png"):
            meta = {"Title": meta["Title"], "Software": meta["Creator"]}
        elif str(path).endswith(".pdf"):
            meta["CreationDate"] = None  # no timestamp: the same tables give the same bytes
        fig.savefig(path, metadata=meta)
    plt.close(fig)


def finite_or_raise(df: pd.DataFrame, columns, what: str):
    """Refuse to draw a figure from non-finite data."""
    bad = [c for c in columns if not np.isfinite(df[c].to_numpy(dtype=float)).all()]
    if bad:
        raise ValueError(f"{what}: non-finite values in {bad}; refusing to draw a figure from them")
