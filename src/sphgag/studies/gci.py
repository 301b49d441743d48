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

With four or more spacings, :func:`least_squares_uncertainty` follows Eca & Hoekstra (2014, "A procedure for the
estimation of the numerical uncertainty of CFD calculations based on grid refinement studies", J. Comput. Phys.
262:104-130) instead: least-squares fits of power series in ``h`` and a safety factor that depends on the observed
order and on the standard deviation of the fit (see that function for the rules and which of them could be checked).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.optimize import least_squares, minimize_scalar

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


# Eca & Hoekstra (2014), for a formal order of 2
LEAST_SQUARES_ORDER_RANGE = (0.5, 2.05)  # where the free-order fit is used, and Fs may be 1.25
LEAST_SQUARES_SAFETY_FACTORS = (1.25, 3.0)  # a "good" data set; any other
LEAST_SQUARES_ORDER_SEARCH = (1e-3, 10.0)  # where the free-order fit's p is sought
LEAST_SQUARES_FITS = ("power", "first", "second", "first_and_second")  # phi0 + alpha h^p, h, h^2; alpha1 h + alpha2 h^2


@dataclass(frozen=True)
class Uncertainty:
    """The numerical uncertainty of a value at its finest spacing ``h1`` by Eca & Hoekstra's (2014) procedure: the
    selected least-squares fit (one of :data:`LEAST_SQUARES_FITS`), its order (``p`` of the free-order fit, 1 or 2;
    NaN for the two-term fit), the extrapolated value ``phi0``, the fit's standard deviation ``sigma``, and the
    uncertainty ``U`` as a fraction of ``|phi1|`` (``uncertainty``) and in the units of the value
    (``uncertainty_abs``). ``observed_order`` is ``p`` of the free-order fit whichever fit was selected,
    ``data_range`` is ``Delta_phi`` and ``fit_at_h1`` the selected fit's value at ``h1``. NaN where the values are not
    all finite."""

    h1: float
    phi1: float
    fit: str
    order: float
    extrapolated: float
    std_dev: float
    uncertainty: float
    uncertainty_abs: float
    observed_order: float = np.nan
    safety_factor: float = np.nan
    data_range: float = np.nan
    fit_at_h1: float = np.nan
    weighted: bool = False


def _least_squares(columns: np.ndarray, phi: np.ndarray, weights):
    """The coefficients (the first the constant ``phi0``) of the least-squares fit of ``phi`` by the ``columns``, the
    fit's values at the spacings and its standard deviation: ``sqrt(sum r_i^2 / (n - k))``, or with ``weights``
    (summing to 1) ``sqrt(n sum w_i r_i^2 / (n - k))``, for ``n`` values, ``k`` coefficients and the residuals
    ``r_i``."""
    n, k = columns.shape
    scale = np.ones(n) if weights is None else np.sqrt(n * weights)
    coefficients = np.linalg.lstsq(columns * scale[:, None], phi * scale, rcond=None)[0]
    fitted = columns @ coefficients
    return coefficients, fitted, float(np.sqrt(np.sum((scale * (phi - fitted)) ** 2) / (n - k)))


def _power_fit(x: np.ndarray, phi: np.ndarray, weights):
    """The least-squares fit ``phi0 + alpha x^p`` with ``p`` free: linear in ``phi0`` and ``alpha`` at each ``p``, so
    its standard deviation is minimised over ``p`` alone, on a grid over :data:`LEAST_SQUARES_ORDER_SEARCH` refined
    by Brent's method between the grid's neighbours of its least, then polished by Levenberg-Marquardt in all three
    coefficients (kept where it lowers the standard deviation and stays in the search range). Returns ``p`` and
    :func:`_least_squares`'s triple."""
    n = x.size
    ones = np.ones(n)
    scale = np.ones(n) if weights is None else np.sqrt(n * weights)

    def linear(p: float):
        return _least_squares(np.column_stack([ones, x**p]), phi, weights)

    grid = np.linspace(*LEAST_SQUARES_ORDER_SEARCH, 1001)
    k = int(np.argmin([linear(p)[2] for p in grid]))
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]
    p = float(minimize_scalar(lambda q: linear(q)[2], bounds=(lo, hi), method="bounded").x)
    if linear(float(grid[k]))[2] < linear(p)[2]:
        p = float(grid[k])
    best = linear(p)
    polished = least_squares(
        lambda c: scale * (c[0] + c[1] * x ** c[2] - phi), [*best[0], p], method="lm", xtol=1e-15, ftol=1e-15
    )
    q = float(polished.x[2])
    if LEAST_SQUARES_ORDER_SEARCH[0] <= q <= LEAST_SQUARES_ORDER_SEARCH[1] and linear(q)[2] < best[2]:
        p, best = q, linear(q)
    return p, best


def least_squares_uncertainty(spacings, values) -> Uncertainty:
    """The :class:`Uncertainty` of the value at the finest of four or more spacings ``spacings`` (any order) by Eca &
    Hoekstra's (2014) least-squares procedure; a ValueError for fewer than four spacings or repeated ones.

    1. The fits (the abstract: "four types", "fitted to the data in the least-squares sense"; the paper's text could
       not be read here, so their equation numbers are not given): (a) ``phi0 + alpha h^p`` with ``p`` free,
       (b) ``phi0 + alpha h``, (c) ``phi0 + alpha h^2`` and (d) ``phi0 + alpha1 h + alpha2 h^2``, each fitted both
       unweighted and weighted by ``w_i = (1/h_i) / sum_j (1/h_j)`` (minimising ``sum w_i r_i^2``), the one of the two
       with the smaller standard deviation kept: ``sigma = sqrt(sum r_i^2 / (n - k))`` unweighted and
       ``sqrt(n sum w_i r_i^2 / (n - k))`` weighted, for the residuals ``r_i = phi_i - phi_fit(h_i)`` and ``k`` the
       fit's number of coefficients. Not confirmed: the weights and these standard deviations are cfdverify 0.0.3's
       (which cites the paper's Appendix B.1), but cfdverify multiplies the residuals by ``w_i``, not ``sqrt(w_i)``,
       so it minimises ``sum w_i^2 r_i^2`` and its weighted ``sigma`` is smaller than the formula's.
    2. The fit: (a) where its observed order lies in :data:`LEAST_SQUARES_ORDER_RANGE`, ``0.5 <= p < 2.05``; else the
       one of (b), (c) and (d) with the smallest standard deviation. Not confirmed: the paper's upper limit for (a)
       (cfdverify 0.0.3 takes ``p <= 2``) and whether (d) is a candidate above the range (cfdverify: only (b), (c)).
       ``p`` is sought in :data:`LEAST_SQUARES_ORDER_SEARCH` (an end of it where the best fit lies beyond).
    3. The error estimate ``eps = |phi1 - phi0|`` at the finest spacing and the data range
       ``Delta_phi = (max phi - min phi) / (n - 1)`` (eq. 19 as cfdverify numbers it).
    4. The safety factor (the abstract: it "depends on the observed order of grid convergence and on the standard
       deviation of the fit"): ``Fs = 1.25`` where fit (a) was used (``p`` in range) and ``sigma < Delta_phi``, else 3
       (cfdverify 0.0.3 takes ``p < 2.1`` here).
    5. The uncertainty: ``U = Fs eps + sigma + |phi1 - phi_fit(h1)|`` where ``sigma < Delta_phi`` (eq. 20), else
       ``U = 3 sigma / Delta_phi (eps + sigma + |phi1 - phi_fit(h1)|)`` (eq. 21; equation numbers as cfdverify cites
       them).

    For values ``phi0 + C h^p`` with ``p`` in range the fit is exact (``sigma = 0``) and ``U = 1.25 |phi1 - phi0|``,
    Celik et al.'s three-grid GCI (:func:`estimate`) in absolute terms: "the method reduces to the well known Grid
    Convergence Index" (the abstract). Values that all agree have no error: fit ``"constant"``, ``U = 0``.
    """
    h = np.asarray(spacings, dtype=float).ravel()
    phi = np.asarray(values, dtype=float).ravel()
    if h.size != phi.size:
        raise ValueError(f"as many spacings as values are needed, got {h.size} and {phi.size}")
    if h.size < 4:
        raise ValueError(f"the least-squares uncertainty needs at least four spacings, got {h.size}")
    order = np.argsort(h)
    h, phi = h[order], phi[order]
    if not (np.all(np.isfinite(h)) and h[0] > 0.0 and np.all(np.diff(h) > 0.0)):
        raise ValueError(f"the spacings must be positive and differ, got {h.tolist()}")
    h1, phi1 = float(h[0]), float(phi[0])
    nan = np.nan
    if not np.all(np.isfinite(phi)):
        return Uncertainty(h1, phi1, "", nan, nan, nan, nan, nan)
    n = h.size
    data_range = float((phi.max() - phi.min()) / (n - 1))
    if data_range == 0.0:
        return Uncertainty(h1, phi1, "constant", nan, phi1, 0.0, 0.0, 0.0, data_range=0.0, fit_at_h1=phi1)
    x = h / h1  # the fits' values and phi0 do not depend on the unit of h; this keeps x^p near 1
    weights = (1.0 / h) / np.sum(1.0 / h)
    ones = np.ones(n)
    # (a), unweighted and weighted: the one with the smaller standard deviation
    power = [(*_power_fit(x, phi, w), w is not None) for w in (None, weights)]
    p, (coefficients, fitted, sigma), weighted = min(power, key=lambda f: f[1][2])
    fit, fit_order = LEAST_SQUARES_FITS[0], p
    in_range = LEAST_SQUARES_ORDER_RANGE[0] <= p < LEAST_SQUARES_ORDER_RANGE[1]
    if not in_range:  # (b), (c), (d), unweighted and weighted: the smallest standard deviation
        columns = {
            "first": (np.column_stack([ones, x]), 1.0),
            "second": (np.column_stack([ones, x**2]), 2.0),
            "first_and_second": (np.column_stack([ones, x, x**2]), nan),
        }
        candidates = [
            (name, o, w is not None, _least_squares(c, phi, w))
            for name, (c, o) in columns.items()
            for w in (None, weights)
        ]
        fit, fit_order, weighted, (coefficients, fitted, sigma) = min(candidates, key=lambda c: c[3][2])
    phi0 = float(coefficients[0])
    eps = abs(phi1 - phi0)
    off_fit = abs(phi1 - float(fitted[0]))
    good, cautious = LEAST_SQUARES_SAFETY_FACTORS
    if sigma < data_range:  # eq. 20
        fs = good if in_range else cautious
        u = fs * eps + sigma + off_fit
    else:  # eq. 21
        fs = cautious
        u = cautious * sigma / data_range * (eps + sigma + off_fit)
    relative = u / abs(phi1) if phi1 != 0.0 else nan
    return Uncertainty(
        h1=h1,
        phi1=phi1,
        fit=fit,
        order=float(fit_order),
        extrapolated=phi0,
        std_dev=sigma,
        uncertainty=float(relative),
        uncertainty_abs=float(u),
        observed_order=p,
        safety_factor=fs,
        data_range=data_range,
        fit_at_h1=float(fitted[0]),
        weighted=weighted,
    )
