"""The grid convergence index of a result computed at three particle spacings (Celik, Ghia, Roache, Freitas, Coleman
& Raad 2008, "Procedure for estimation and reporting of uncertainty due to discretization in CFD applications",
J. Fluids Eng. 130:078001).

With spacings ``h1 < h2 < h3`` (fine, medium, coarse), ratios ``r21 = h2/h1`` and ``r32 = h3/h2``, and values
``phi1, phi2, phi3``, the observed order ``p`` solves (their eqs. 3-5)

    p = | ln|eps32 / eps21| + q(p) | / ln r21,     q(p) = ln( (r21^p - s) / (r32^p - s) ),

with ``eps32 = phi3 - phi2``, ``eps21 = phi2 - phi1`` and ``s = sign(eps32 / eps21)`` (``s < 0``: oscillatory
convergence), by fixed-point iteration. The extrapolated value is ``phi_ext = (r21^p phi1 - phi2) / (r21^p - 1)``
(eq. 6), the relative error ``e21 = |(phi1 - phi2) / phi1|`` and the fine-grid convergence index
``GCI21 = 1.25 e21 / (r21^p - 1)`` (eq. 8; the safety factor of three grids). Where monotone values have
``|eps32 / eps21| <= ln r32 / ln r21`` (the limit of ``phi0 + C h^p`` as p -> 0: the finer pair differs too much),
no positive order fits them: they are not in their asymptotic range, and no order is reported (``diverging``),
rather than the positive order the absolute values of eq. 3 would give.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

SAFETY_FACTOR = 1.25  # three grids (Celik et al. 2008)
CAUTIOUS_SAFETY_FACTOR = 3.0  # an observed order outside ORDER_RANGE (Roache 1998)
ORDER_RANGE = (0.5, 3.0)  # where an observed order is taken to be in its asymptotic range


@dataclass(frozen=True)
class Estimate:
    """The discretisation error of a value at its finest spacing ``h1``: the observed order, the extrapolated value
    and the fine-grid convergence index (a fraction of ``phi1``; NaN where the three values do not define them)."""

    h1: float
    phi1: float
    order: float
    extrapolated: float
    gci_fine: float
    oscillatory: bool = False
    diverging: bool = False  # the finer pair differs more than the coarser one: the values do not converge (yet)

    def spacing_for(self, gci: float) -> float:
        """The spacing at which the observed order says the fine-grid convergence index would be ``gci``."""
        if not (np.isfinite(self.order) and self.order > 0 and self.gci_fine > 0):
            return np.nan
        return float(self.h1 * (gci / self.gci_fine) ** (1.0 / self.order))


def estimate(spacings, values, max_iter: int = 200, tol: float = 1e-12) -> Estimate:
    """The :class:`Estimate` of the values ``values`` at three spacings ``spacings`` (any order)."""
    h = np.asarray(spacings, dtype=float)
    phi = np.asarray(values, dtype=float)
    if h.size != 3 or phi.size != 3:
        raise ValueError(f"the grid convergence index needs three spacings and three values, got {h.size}, {phi.size}")
    order = np.argsort(h)
    (h1, h2, h3), (phi1, phi2, phi3) = h[order], phi[order]
    if not (h1 < h2 < h3):
        raise ValueError(f"the three spacings must differ, got {h.tolist()}")
    if not np.all(np.isfinite(phi)):
        return Estimate(h1, phi1, np.nan, np.nan, np.nan)
    r21, r32 = h2 / h1, h3 / h2
    eps21, eps32 = phi2 - phi1, phi3 - phi2
    if eps21 == 0.0:  # the two finer values agree: no error to estimate at this precision
        return Estimate(h1, phi1, np.nan, phi1, 0.0 if eps32 == 0.0 else np.nan)
    if eps32 == 0.0:
        return Estimate(h1, phi1, np.nan, np.nan, np.nan)
    s = float(np.sign(eps32 / eps21))
    # phi = phi0 + C h^p with p > 0 has |eps32 / eps21| > ln r32 / ln r21 (its limit as p -> 0): below that the
    # differences do not shrink with the spacing as any positive order makes them
    if s > 0 and abs(eps32 / eps21) <= np.log(r32) / np.log(r21):
        return Estimate(h1, phi1, np.nan, np.nan, np.nan, False, diverging=True)
    p = abs(np.log(abs(eps32 / eps21))) / np.log(r21)
    for _ in range(max_iter):
        a, b = r21**p - s, r32**p - s
        if a <= 0.0 or b <= 0.0:
            return Estimate(h1, phi1, np.nan, np.nan, np.nan, s < 0)
        new = abs(np.log(abs(eps32 / eps21)) + np.log(a / b)) / np.log(r21)
        if abs(new - p) < tol:
            p = new
            break
        p = new
    if p <= 0.0:
        return Estimate(h1, phi1, np.nan, np.nan, np.nan, s < 0)
    growth = r21**p
    extrapolated = (growth * phi1 - phi2) / (growth - 1.0)
    gci = SAFETY_FACTOR * abs(eps21 / phi1) / (growth - 1.0) if phi1 != 0.0 else np.nan
    return Estimate(h1, phi1, float(p), float(extrapolated), float(gci), s < 0)


TIDY_RESULTS = ["observed_order", "extrapolated", "gci_fine", "order_in_range"]


def tidy(values: pd.DataFrame, keys) -> pd.DataFrame:
    """Per group of ``keys`` of the long table ``values`` (columns ``keys``, ``dx_um`` and ``value``), the
    :class:`Estimate` of its three finest spacings on every row of the group (:data:`TIDY_RESULTS`; NaN where the
    group has fewer than three finite values; no order, GCI 0 and the value itself where the two finest agree).
    Where the observed order lies outside :data:`ORDER_RANGE`, ``order_in_range`` is False and the GCI is Roache's
    cautious one: the safety factor :data:`CAUTIOUS_SAFETY_FACTOR` with the order clipped to that range."""
    out = []
    for _, group in values.groupby(list(keys), sort=False, dropna=False):
        group = group.sort_values("dx_um")
        finest = group[np.isfinite(group.value.to_numpy(dtype=float))].iloc[:3]
        e = estimate(finest.dx_um, finest.value) if len(finest) == 3 else None
        order, extrapolated, gci, in_range = np.nan, np.nan, np.nan, False
        if e is not None and not np.isfinite(e.order):  # the two finer values agree (else: no estimate)
            extrapolated, gci = e.extrapolated, e.gci_fine
        if e is not None and np.isfinite(e.order):
            order, extrapolated, gci = e.order, e.extrapolated, e.gci_fine
            in_range = ORDER_RANGE[0] <= e.order <= ORDER_RANGE[1]
            if not in_range:  # finest: sorted by spacing
                h, phi = finest.dx_um.to_numpy(dtype=float), finest.value.to_numpy(dtype=float)
                p = float(np.clip(e.order, *ORDER_RANGE))
                gci = CAUTIOUS_SAFETY_FACTOR * abs((phi[1] - phi[0]) / phi[0]) / ((h[1] / h[0]) ** p - 1.0)
        out.append(group.assign(observed_order=order, extrapolated=extrapolated, gci_fine=gci, order_in_range=in_range))
    columns = list(values.columns) + TIDY_RESULTS
    return pd.concat(out, ignore_index=True)[columns] if out else pd.DataFrame(columns=columns)
