"""The resolution study of delamination (``results/delamination/convergence.csv``): the study's pool sets (figure 5's
pool and a pair) grown from the passive wall pressurised at each particle spacing, under every onset criterion (eq.
2.28, section 2.7), and the discretisation error of the concentrations of their events (``gci.csv``,
:func:`sphgag.studies.resolution.delamination_gci`)."""

from __future__ import annotations

import pandas as pd

from ...engine.numerics import Numerics
from ...studies.wall_loading import pressurised_wall
from .. import artery
from .growth import grow
from .settings import Settings
from .tables import labelled


def convergence_study(
    dx: float,
    bilayer: dict,
    numerics: Numerics,
    homeostasis: dict,
    de: dict,
    gag: dict,
    name: str = "delamination_convergence",
) -> pd.DataFrame:
    """Rows of ``results/delamination/convergence.csv`` for one particle spacing: every pool set of ``de["pool_sets"]``
    at ``critical_stress_kPa``, every onset criterion, from the passive wall pressurised at this spacing."""
    p = dict(bilayer, dx_um=float(dx))
    _, start = pressurised_wall(p, numerics, homeostasis, de["pressure_mmHg"], name)
    rows = []
    for case, pools in de["pool_sets"].items():
        sectors = [artery.pool_sector(s) for s in pools]
        for criterion in de["criteria"]:
            settings = Settings.at_section(de, criterion)
            model = artery.bilayer_model(p, numerics, name=f"{name}_{case}_{criterion}")
            result = grow(model, start, sectors, settings, numerics, gag, model.props)
            rows.append(labelled(result, case, settings, dx)[1].assign(particles=model.n))
    return pd.concat(rows, ignore_index=True)
