"""The resolution study of delamination (``results/delamination/convergence.csv``): figure 5's pool grown from the
passive wall pressurised at each particle spacing, under every onset criterion (eq. 2.28, section 2.7)."""

from __future__ import annotations

import pandas as pd

from ...engine import solver
from ...engine.numerics import Numerics
from .. import artery, protocols
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
    """Rows of ``results/delamination/convergence.csv`` for one particle spacing: the one pool set of
    ``de["pool_sets"]`` (figure 5's, by any name) at ``critical_stress_kPa``, every onset criterion, from the passive
    wall pressurised at this spacing."""
    if len(de["pool_sets"]) != 1:
        raise ValueError(f"the resolution study runs one pool set, got {', '.join(de['pool_sets'])}")
    [(case, pools)] = de["pool_sets"].items()
    p = dict(bilayer, dx_um=float(dx))
    wall = artery.bilayer_model(p, numerics, name=name)
    h = protocols.homeostasis(wall, numerics, homeostasis)
    start = protocols.pressurise(wall, h.state, de["pressure_mmHg"], numerics)
    sectors = [artery.pool_sector(s) for s in pools]
    rows = []
    for criterion in de["criteria"]:
        settings = Settings.from_config(de, de["critical_stress_kPa"], criterion)
        model = artery.bilayer_model(p, numerics, name=name if len(de["criteria"]) == 1 else f"{name}_{criterion}")
        result = grow(
            model, solver.State(start.load, start.x, None, None), sectors, settings, numerics, gag, model.props
        )
        rows.append(labelled(result, case, settings, dx)[1].assign(particles=model.n))
    return pd.concat(rows, ignore_index=True)
