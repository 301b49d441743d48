"""A numerical variant of the study: figure 4's first pool and figure 5's pool run from the homeostatic state at one
setting of the numerics (target ``variants``: eq. 2.14 as printed beside the default, its energy form).

Each variant builds its own wall (homeostasis, figure 2b, and pressure control to the delamination pressure), since
the numerics change every state from the first. It then runs figure 4's protocol for the first pool of
``swelling.cases`` in that passive wall (GAG particles, the paper's charge law;
:func:`sphgag.studies.pool_swelling.swell_pool`, measured as rule pool_stresses measures) and grows figure 5's pool at
``delamination.critical_stress_kPa`` with the default onset criterion (:func:`sphgag.studies.delamination.growth.grow`).
"""

from __future__ import annotations

from dataclasses import dataclass

import pandas as pd

from ..engine.model import Model
from ..engine.numerics import Numerics
from . import artery
from .delamination.growth import grow
from .delamination.settings import Settings
from .delamination.tables import labelled
from .pool_swelling import pool_table, swell_pool
from .wall_loading import pressurised_wall


@dataclass
class Variant:
    """The tables of one variant: figure 4's pool (``swelling``, rows of pool_stresses) and figure 5's pool
    (``growth`` and ``summary``, rows of the delamination tables)."""

    swelling: pd.DataFrame
    growth: pd.DataFrame
    summary: pd.DataFrame


def run_variant(
    bilayer: dict,
    numerics: Numerics,
    homeostasis: dict,
    swelling: dict,
    de: dict,
    gag: dict,
    name: str = "variant",
) -> Variant:
    """Figure 4's first pool (``swelling``: the swelling settings with ``case`` and its ``pool``) and figure 5's pool
    set (``de``: the run settings with ``case``, its ``pools``, ``critical_stress_kPa`` and the default ``criterion``)
    at the numerics ``numerics``, from a wall of their own at ``de["pressure_mmHg"]`` (also the pressure figure 4's
    pool is swollen at here)."""
    _, start = pressurised_wall(bilayer, numerics, homeostasis, de["pressure_mmHg"], name)
    pool = artery.pool_sector(swelling["pool"])
    model = artery.bilayer_model(bilayer, numerics, name=f"{name}_swell", pool=pool, gag=gag)
    settings = {k: v for k, v in swelling.items() if k not in ("case", "pool", "probe_length_um")}
    states = swell_pool(model, start, numerics, dict(settings, pool_model="particles"))
    table = pool_table(model, states, pool, swelling["probe_length_um"], gag)
    table.insert(0, "case", swelling["case"])
    st = Settings.at_section(de, de["criterion"])
    grower: Model = artery.bilayer_model(bilayer, numerics, name=f"{name}_grow")
    result = grow(
        grower, start, [artery.pool_sector(s) for s in de["pools"]], st, numerics, gag, grower.props, run=f"{name}_grow"
    )
    growth, summary = labelled(result, de["case"], st, bilayer["dx_um"])
    return Variant(table, growth, summary)
