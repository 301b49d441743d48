"""The exact large-strain field of a circular swelling pool bonded in a matrix annulus (a verification reference).

Plane strain (``lz = 1``), radial symmetry: a disc of reference radius ``A`` of the GAG law (eq. 2.27 with the
contents' volumetric term of :func:`sphgag.physics.materials.convert_to_gag`) is bonded to an annulus ``A < R < B``
of the elastin-like matrix law (eqs. 2.18/2.21 without deposition stretch or fibres), and ``R = B`` is traction free.
Both are the engine's laws (:mod:`sphgag.physics.materials`, with its documented correction of eq. 2.18),

    ``W = mu/2 (lr^2 + lt^2 + 1 - 3) - mu ln J + U(J)  [- Pi (J - 1) in the pool]``,  ``J = lr lt``,

with ``U = lam/2 (ln J)^2`` for the matrix (eq. 2.21) and ``U = lam u(J)`` of the GAG's volumetric form
(:mod:`sphgag.physics.volumetric`, :attr:`Solid.volumetric`) in the pool, whose principal Cauchy stresses are
``sigma_rr = (mu (lr^2 - 1) + J U'(J))/J - Pi`` and likewise ``sigma_tt`` with ``lt`` (:func:`cauchy`). Swelling
(eqs. 2.25-2.26), by the charge law (:mod:`sphgag.physics.donnan`): a law that does not conserve the fixed charge
(``prescribed``) keeps ``Pi`` fixed; one that does (``conserved``) keeps the fixed charge ``c0`` per reference volume,
``Pi = RT (sqrt((c0/J)^2 + c*^2) - c*)`` (:func:`donnan_pressure`), ``c0`` being the concentration whose ``Pi`` at
``J = 1`` is the given pressure (the engine's laws at one load).

The pool deforms homogeneously, ``r = lp R``: its uniform hydrostatic stress satisfies equilibrium exactly and is
known in closed form. In the matrix, radial equilibrium ``dP_r/dR + (P_r - P_t)/R = 0`` (``P_r = dW/dlr``,
``P_t = dW/dlt``, ``lr = r'(R)``, ``lt = r/R``; equivalently ``d sigma_rr/dr + (sigma_rr - sigma_tt)/r = 0``) reads,
with ``s = ln R`` and the state ``(ln lt, ln lr)``,

    ``d ln lt/ds = lr/lt - 1``,
    ``d ln lr/ds = -lr (lr - lt) [mu (J + 1) + J^2 U''(J)] / (J [mu (lr^2 + 1) + J^2 U''(J)])``

(``J^2 U'' = lam (1 - ln J)`` for the matrix's ``lam/2 (ln J)^2``), scale free and regular as ``lam/mu -> oo`` (it
tends to the incompressible kinematics ``lr lt = 1``). It starts at ``R = A`` from ``lt = lp`` and the ``lr`` that
makes ``sigma_rr`` continuous with the pool's stress, and ``lp`` is the root of ``sigma_rr(B) = 0``. Exact: the
reduction to this ODE and its two boundary conditions; the numbers carry the ODE solver's error (DOP853, rtol 1e-11)
and root-finding to round-off.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from .donnan import GAS_CONSTANT, PAPER_LAW, charge_at, charge_law, pressure_at
from .volumetric import VOLUMETRIC_FORMS, VolumetricForm

RTOL, ATOL = 1e-11, 1e-12


@dataclass(frozen=True)
class Solid:
    """A neo-Hookean solid of eqs. (2.18)/(2.21): shear modulus ``mu``, and the volumetric term ``lam u(J)`` of the
    form ``volumetric`` (:data:`sphgag.physics.volumetric.VOLUMETRIC_FORMS`; ``lam`` [kPa] its small-strain bulk modulus
    U''(1): the Lame parameter of the elastin's ``lam/2 (ln J)^2``, ``log_squared``; for a pool the GAG contents'
    form); for a pool also the bath's mobile-ion concentration c* [mEq/l] and the temperature of eqs. (2.25-2.26)."""

    mu: float
    lam: float = 0.0
    bath_mEq_l: float = 300.0
    temperature_K: float = 310.0
    volumetric: str = "log_squared"

    def __post_init__(self):
        VOLUMETRIC_FORMS.lookup(self.volumetric)

    @property
    def form(self) -> VolumetricForm:
        """Its volumetric form (:mod:`sphgag.physics.volumetric`)."""
        return VOLUMETRIC_FORMS[self.volumetric]

    def bulk(self, J):
        """``(J U'(J), J^2 U''(J))`` of its volumetric term ``U = lam u(J)``: the Cauchy stress times J, and the
        stiffness of the radial equation (module docstring)."""
        _, du, d2u = self.form.terms(J, self.lam)
        return J * du, J * J * d2u

    @property
    def rt(self) -> float:
        """R T in kPa per mEq/l."""
        return GAS_CONSTANT * self.temperature_K / 1000.0

    @classmethod
    def of(cls, m) -> Solid:
        """A :class:`Solid` from itself, a dict of its fields, or a configuration section (``shear_modulus_kPa``,
        ``lame_lambda_kPa``, ``bath_concentration_mEq_l``, ``temperature_K``, ``volumetric``: the ``gag`` section's
        form, or the elastin's ``log_squared`` for a section without one; other keys ignored)."""
        if isinstance(m, cls):
            return m
        if "mu" in m:
            return cls(**{f.name: m[f.name] for f in fields(cls) if f.name in m})
        return cls(
            m["shear_modulus_kPa"],
            m.get("lame_lambda_kPa", 0.0),
            m.get("bath_concentration_mEq_l", 300.0),
            m.get("temperature_K", 310.0),
            m.get("volumetric", "log_squared"),
        )


def cauchy(lr, lt, solid: Solid, swelling=0.0):
    """Principal Cauchy stresses ``(sigma_rr, sigma_tt)`` of eqs. (2.21)/(2.27) at stretches ``lr, lt`` (``lz = 1``)
    under the swelling pressure ``swelling`` [kPa]: ``(mu (l^2 - 1) + J U'(J))/J - Pi`` (``J U' = lam ln J`` for
    ``lam/2 (ln J)^2``)."""
    J = lr * lt
    bulk = solid.bulk(J)[0]
    return (solid.mu * (lr * lr - 1.0) + bulk) / J - swelling, (solid.mu * (lt * lt - 1.0) + bulk) / J - swelling


def donnan_pressure(J, c0, solid: Solid):
    """Gibbs-Donnan pressure (eqs. 2.25-2.26) of the fixed charge ``c0`` [mEq/l, per reference volume] at ``J``."""
    return pressure_at(c0 / J, solid.bath_mEq_l, solid.rt)


def fixed_charge(pressure_kPa, solid: Solid):
    """The concentration whose Donnan pressure at ``J = 1`` is ``pressure_kPa``: the inverse of eq. (2.26)."""
    return charge_at(pressure_kPa, solid.bath_mEq_l, solid.rt)


def annulus_pressure_incompressible(stretch, A, B, mu):
    """Pressure in a hole of reference radius ``A`` expanded to ``a = stretch A`` in an incompressible neo-Hookean
    annulus ``A < R < B`` with a free outer surface (plane strain; exact):
    ``p / mu = 1/2 [ln(la^2 / lb^2) + lb^-2 - la^-2]``, ``la = a/A``, ``lb = b/B``, ``b^2 = B^2 + a^2 - A^2``.
    It rises monotonically to the saturation pressure ``mu ln(B/A)`` and never reaches it."""
    la = np.asarray(stretch, dtype=float)
    lb2 = 1.0 + (la * la - 1.0) * (A / B) ** 2
    return 0.5 * mu * (np.log(la * la / lb2) + 1.0 / lb2 - la**-2)


def infinite_cavity_pressure(stretch, mu):
    """Pressure in a cylindrical cavity expanded to ``a = stretch A`` in an infinite incompressible neo-Hookean solid
    (plane strain; exact): ``p = mu (ln l + (1 - l^-2)/2)``."""
    l = np.asarray(stretch, dtype=float)
    return mu * (np.log(l) + 0.5 * (1.0 - l**-2))


def _rhs(s, y, solid: Solid):
    lt, lr = np.exp(y)
    mu, J = solid.mu, np.exp(y[0] + y[1])
    k = float(solid.bulk(J)[1])  # J^2 U''(J)
    return [lr / lt - 1.0, -lr * (lr - lt) * (mu * (J + 1.0) + k) / (J * (mu * (lr * lr + 1.0) + k))]


def _increasing_root(f, x, step, tries=60):
    """Root of an increasing ``f``: bracket it by steps doubling away from ``x`` (halved where ``f`` fails), brentq."""
    fx = f(x)
    d = step if fx < 0.0 else -step
    for _ in range(tries):
        if fx == 0.0:
            return x
        y = x + d
        fy = f(y)
        if not np.isfinite(fy):
            d *= 0.5
        elif (fy > 0.0) != (fx > 0.0):
            return brentq(f, min(x, y), max(x, y), xtol=1e-14, rtol=1e-14)
        else:
            x, fx, d = y, fy, 2.0 * d
    raise RuntimeError("no sign change found")


def _stable_root(f, step=0.1, top=6.9):  # top: ln lp, J_pool up to 1e6
    """The first zero above 0 of the interface residual ``f(ln lp)``, negative at 0 for a swelling pool: the stable
    branch. ``f`` rises to a maximum (the limit point of a finite annulus) and falls beyond it; if that maximum is
    negative the pressure exceeds the limit pressure and there is no equilibrium (ValueError)."""
    a, fa = 0.0, f(0.0)
    if not fa < 0.0:
        return _increasing_root(f, 0.0, step)  # Pi <= the pool's stress at J = 1: it shrinks or stays
    while a < top:
        b = a + step
        fb = f(b)
        if not np.isfinite(fb):
            break
        if fb >= 0.0:
            return brentq(f, a, b, xtol=1e-14, rtol=1e-14)
        if fb < fa:  # past the maximum of f, which lies in [a - step, b]
            lo = max(a - step, 0.0)
            peak = minimize_scalar(lambda s: -f(s), bounds=(lo, b), method="bounded", options=dict(xatol=1e-10))
            if peak.fun < 0.0:
                return brentq(f, lo, peak.x, xtol=1e-14, rtol=1e-14)
            raise ValueError(
                f"no equilibrium: the pressure is above the limit pressure of this pool (the residual peaks at "
                f"sigma_rr(B) = {-peak.fun:.3g} kPa, J_pool = {np.exp(2.0 * peak.x):.3g}; pressure_for_volume_ratio "
                "gives the pressure-volume curve)"
            )
        a, fa = b, fb
    raise ValueError(f"no equilibrium found up to J_pool = {np.exp(2.0 * a):.3g}")


def _shoot(m: Solid, A, B, lp, traction, dense=False):
    """Integrate the matrix from ``R = A`` (``lt = lp``, ``sigma_rr = traction``) to ``B``: ``(sigma_rr(B), ode)``."""
    ln_lp = np.log(lp)  # sigma_rr(lr, lp) = traction, in x = ln lr (increasing in x where it matters):
    x = _increasing_root(
        lambda x: m.mu * np.expm1(2.0 * x) + float(m.bulk(lp * np.exp(x))[0]) - traction * lp * np.exp(x), -ln_lp, 0.5
    )
    ode = solve_ivp(
        _rhs, (np.log(A), np.log(B)), [ln_lp, x], "DOP853", rtol=RTOL, atol=ATOL, dense_output=dense, args=(m,)
    )
    if ode.status != 0 or not np.all(np.isfinite(ode.y[:, -1])):
        return np.nan, ode
    lt, lr = np.exp(ode.y[:, -1])
    return cauchy(lr, lt, m)[0], ode


@dataclass(frozen=True)
class CircularPool:
    """The solved pool: ``stretch`` lp = r/R of the pool, ``swelling_kPa`` the Pi acting in the swollen pool."""

    A: float
    B: float
    matrix: Solid
    gag: Solid
    law: str
    pressure_kPa: float
    stretch: float
    swelling_kPa: float
    ode: object = field(repr=False)

    @property
    def volume_ratio(self) -> float:
        """J_pool = lp^2 (the area ratio; lz = 1)."""
        return self.stretch**2

    @property
    def pool_stress_kPa(self) -> float:
        """The pool's uniform Cauchy stress sigma_rr = sigma_tt (eq. 2.27 with the contents' volumetric term)."""
        return float(cauchy(self.stretch, self.stretch, self.gag, self.swelling_kPa)[0])

    def field(self, R) -> dict:
        """``r``, ``sigma_rr``, ``sigma_tt`` (Cauchy, kPa) at reference radii ``0 <= R <= B``: the pool's for
        ``R < A``, the matrix's for ``R >= A`` (so ``R = A`` gives the matrix side of the interface)."""
        R = np.asarray(R, dtype=float)
        lt, lr = np.exp(self.ode.sol(np.log(np.clip(R, self.A, self.B))))
        srr, stt = cauchy(lr, lt, self.matrix)
        pool = R < self.A
        sp = self.pool_stress_kPa
        r = np.where(pool, self.stretch, lt) * R
        return dict(r=r, sigma_rr=np.where(pool, sp, srr), sigma_tt=np.where(pool, sp, stt))

    @property
    def interface_hoop_kPa(self) -> float:
        """Hoop stress on the matrix side of the interface, sigma_tt(A+)."""
        return float(self.field(self.A)["sigma_tt"])

    @property
    def outer_radius(self) -> float:
        """Current outer radius r(B)."""
        return float(self.field(self.B)["r"])


def circular_pool(A, B, matrix, gag, pressure_kPa, law=PAPER_LAW) -> CircularPool:
    """The pool of reference radius ``A`` in the annulus ``A < R < B`` swollen by ``pressure_kPa`` under the charge
    ``law`` (a name of :data:`sphgag.physics.donnan.CHARGE_LAWS`; ``prescribed``: Pi = pressure_kPa, eq. 2.27;
    ``conserved``: Pi(c0/J) with Pi(c0) = pressure_kPa, eq. 2.26). ``matrix``, ``gag``: :class:`Solid` or dicts
    (:meth:`Solid.of`). A finite annulus has a limit pressure, the maximum of the pressure-volume curve: above it there
    is no equilibrium (ValueError), below it the stable (smaller) pool of the two is returned."""
    charge = charge_law(law)
    m, g = Solid.of(matrix), Solid.of(gag)

    def swelling(lp):
        return float(charge.swelling_at(pressure_kPa, lp * lp, g.bath_mEq_l, g.rt))

    def residual(s):
        lp = np.exp(s)
        return _shoot(m, A, B, lp, cauchy(lp, lp, g, swelling(lp))[0])[0]

    lp = float(np.exp(_stable_root(residual)))
    ode = _shoot(m, A, B, lp, cauchy(lp, lp, g, swelling(lp))[0], dense=True)[1]
    return CircularPool(A, B, m, g, law, pressure_kPa, lp, swelling(lp), ode)


@dataclass(frozen=True)
class LimitPressure:
    """The largest pressure a pool of reference radius ``A`` in the annulus ``A < R < B`` holds in equilibrium:
    ``pressure_kPa`` at the pool volume ratio ``volume_ratio``; ``kind``: ``limit point`` (the pressure-volume curve
    has a maximum: beyond it the stable branch ends), ``saturation`` (the curve rises to an asymptote it never
    reaches, as the incompressible annulus to ``mu ln(B/A)``: then ``pressure_kPa`` is its value at
    ``volume_ratio`` = :data:`SATURATION_VOLUME_RATIO`, within a relative 1e-6 of the asymptote for these laws) or
    ``unbounded`` (the contents' own stress grows without bound, as the volumetric form ``hartmann_neff``'s: an
    equilibrium at every pressure, ``pressure_kPa`` and ``volume_ratio`` infinite)."""

    pressure_kPa: float
    volume_ratio: float
    kind: str


SATURATION_VOLUME_RATIO = 1e8  # where the pressure-volume curve is taken to have reached a saturation pressure


def limit_pressure(A, B, matrix, gag) -> LimitPressure:
    """The :class:`LimitPressure` of the prescribed law (eq. 2.27): the maximum over ``ln J`` of
    :func:`pressure_for_volume_ratio`, scanned in steps of 0.25 up to :data:`SATURATION_VOLUME_RATIO` and refined by
    a bounded scalar search around the largest sample. ``gag = Solid(0)``: an empty hole."""
    m, g = Solid.of(matrix), Solid.of(gag)

    def pressure(s):
        return pressure_for_volume_ratio(np.exp(s), A, B, m, g)

    top = np.log(SATURATION_VOLUME_RATIO)
    s = np.arange(0.0, top + 0.125, 0.25)
    p = np.array([pressure(x) for x in s])
    k = int(np.argmax(p))
    if p[-1] >= p[k] * (1.0 - 1e-9):  # still rising at the top, to round-off
        if p[-1] - p[-2] > 1e-6 * abs(p[-1]):  # and not levelling off: no largest pressure
            return LimitPressure(np.inf, np.inf, "unbounded")
        return LimitPressure(float(p[-1]), SATURATION_VOLUME_RATIO, "saturation")  # an asymptote
    peak = minimize_scalar(
        lambda x: -pressure(x), bounds=(s[max(k - 1, 0)], s[k + 1]), method="bounded", options=dict(xatol=1e-10)
    )
    return LimitPressure(float(-peak.fun), float(np.exp(peak.x)), "limit point")


def pressure_for_volume_ratio(J_target, A, B, matrix, gag, law=PAPER_LAW) -> float:
    """The swelling pressure [kPa] that gives the pool volume ratio ``J_target`` (prescribed law; under a law that
    conserves the fixed charge, ``conserved``, the pressure Pi(c0) at J = 1 of the fixed charge c0 that does). The
    interface traction is root-found at the known lp = sqrt(J_target), so the inverse is as exact as
    :func:`circular_pool`, on both sides of the limit point."""
    charge = charge_law(law)
    m, g = Solid.of(matrix), Solid.of(gag)
    lp = float(np.sqrt(J_target))
    t = _increasing_root(lambda t: _shoot(m, A, B, lp, t)[0], 0.0, 0.1 * m.mu)
    pi = float(cauchy(lp, lp, g)[0]) - t
    return float(charge.reference_pressure(pi, J_target, g.bath_mEq_l, g.rt))
