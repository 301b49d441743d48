"""The charge laws of a GAG pool: how its Gibbs-Donnan swelling follows the pool's volume (eqs. 2.25-2.27).

The swelling pressure of a GAG particle is eq. (2.26) at its fixed-charge concentration c_FC,
``Pi = R T (sqrt(c_FC^2 + c*^2) - c*)`` (:func:`swelling_pressure`). The load raises the concentration ``c`` of the
pool (per reference volume); a charge law says what c_FC is once the particle has the volume ratio ``J``
(:meth:`ChargeLaw.concentration`), and so what Pi is at every J:

* ``prescribed`` (:class:`PrescribedCharge`), the paper's law as printed: c_FC = c at every J, so the particle carries
  the swelling pressure Pi(c) of the load (the property column ``PI`` of :mod:`sphgag.physics.materials`);
* ``conserved`` (:class:`ConservedCharge`), our documented deviation (mixture theory): the fixed charge stays in the
  particle, c_FC = c / J, so the Donnan pressure acts at the current concentration (the column ``FCD``, evaluated
  with its derivative for the tangent at each particle's J by :func:`sphgag.physics.materials.donnan`).

A law is a :class:`ChargeLaw` (a :class:`sphgag.registry.Variant`) of the registry :data:`CHARGE_LAWS`, by its name in
the configuration (``gag.charge_laws``), the pipeline's wildcard ``{law}`` and every pool table (column
``charge_law``). It owns its behaviour: the concentration at J and its inverse, the swelling pressure at J of a pool
swollen to a given pressure (the exact circular pool, :mod:`sphgag.physics.cavity`) and the columns the engine's
property table carries it in (:meth:`ChargeLaw.engine_columns`, read by :mod:`sphgag.engine.history`). The schema's
enumeration, the typed GAG options (:class:`sphgag.physics.materials.Gag`), the pool models that carry it and the
figures' titles are read from the registry (docs/contributing.md).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..registry import Registry, Variant

GAS_CONSTANT = 8.314462618  # J / (mol K)


def swelling_pressure(c_fc, c_bath, temperature_K=310.0):
    """Gibbs-Donnan swelling pressure Pi = R T (sqrt(c_FC^2 + c*^2) - c*) in kPa (eqs. 2.25-2.26).

    Concentrations in mEq/l (= mol/m^3 for monovalent ions); R T in J/mol, so
    the product is in Pa; divided by 1000 for kPa.
    """
    c = np.asarray(c_fc, dtype=float)
    return GAS_CONSTANT * temperature_K * (np.sqrt(c * c + c_bath * c_bath) - c_bath) / 1000.0


def concentration_for_pressure(pi_kPa, c_bath, temperature_K=310.0):
    """The fixed-charge concentration [mEq/l] whose swelling pressure (eqs. 2.25-2.26) is ``pi_kPa``: the inverse of
    :func:`swelling_pressure`, ``c = sqrt((Pi / R T + c*)^2 - c*^2)``."""
    q = 1000.0 * np.asarray(pi_kPa, dtype=float) / (GAS_CONSTANT * temperature_K) + c_bath
    return np.sqrt(q * q - c_bath * c_bath)


def pressure_at(c_fc, c_bath, rt):
    """Eq. (2.26) with ``rt`` = R T in kPa per mEq/l: the Donnan pressure [kPa] of the concentration ``c_fc``."""
    return rt * (np.sqrt(c_fc**2 + c_bath * c_bath) - c_bath)


def charge_at(pressure_kPa, c_bath, rt):
    """The concentration whose Donnan pressure (:func:`pressure_at`) is ``pressure_kPa``: the inverse of eq. (2.26)."""
    q = pressure_kPa / rt + c_bath
    return np.sqrt(q * q - c_bath**2)


@dataclass(frozen=True)
class ChargeLaw(Variant):
    """A Donnan law of the GAG pools: how the fixed-charge concentration of eq. (2.26) follows a particle's volume.

    name : the law's name (configuration, wildcard, column ``charge_law``).
    paper : the paper's law (the one to compare with the paper's panels); every other law is a deviation.
    title : the heading of the law's block in the figures.
    short : the law's label in a panel title or an axis label.

    Its behaviour is its subclass's: :meth:`concentration` and its inverse :meth:`reference_concentration`, and
    :meth:`engine_columns`, how the engine's kernels evaluate it. It owns no configuration key of its own: the GAG
    options (``gag``) are every law's.
    """

    name: str
    paper: bool
    title: str
    short: str

    def concentration(self, c, J):
        """The fixed-charge concentration c_FC [mEq/l] of eq. (2.26) at the volume ratio ``J`` of a particle loaded
        to ``c`` (per reference volume)."""
        raise NotImplementedError

    def reference_concentration(self, c_fc, J):
        """The load's concentration ``c`` (per reference volume) whose fixed-charge concentration at ``J`` is ``c_fc``:
        the inverse of :meth:`concentration`."""
        raise NotImplementedError

    def engine_columns(self, c, c_bath, temperature_K):
        """How the engine's property table carries a GAG particle loaded to ``c`` (:func:`sphgag.physics.materials.
        convert_to_gag`): its constant swelling pressure (column ``PI``) and the fixed charge ``(c0, c_bath, T)``
        whose Donnan pressure the Numba kernels evaluate at the particle's J, with its derivative for the tangent
        (columns ``FCD``, ``CBATH``, ``RT``; None: no such term)."""
        raise NotImplementedError

    def swelling_at(self, pressure_kPa, J, c_bath, rt):
        """The swelling pressure [kPa] at ``J`` of a particle whose swelling pressure at ``J = 1`` is ``pressure_kPa``:
        eq. (2.26) at :meth:`concentration` of the charge that has it (``rt``: R T in kPa per mEq/l)."""
        return pressure_at(self.concentration(charge_at(pressure_kPa, c_bath, rt), J), c_bath, rt)

    def reference_pressure(self, pressure_kPa, J, c_bath, rt):
        """The swelling pressure at ``J = 1`` of a particle whose swelling pressure at ``J`` is ``pressure_kPa``: the
        inverse of :meth:`swelling_at`."""
        return pressure_at(self.reference_concentration(charge_at(pressure_kPa, c_bath, rt), J), c_bath, rt)

    def holds_pressure(self) -> bool:
        """Whether the swelling pressure is the load's at every J (c_FC = c): what a cavity under a prescribed
        pressure can carry (:class:`sphgag.studies.pool_swelling.CavityPool`)."""
        return self.concentration(1.0, 2.0) == 1.0


@dataclass(frozen=True)
class PrescribedCharge(ChargeLaw):
    """c_FC = c at every J: the particle carries the swelling pressure Pi(c) of the load (eqs. 2.25-2.27 as printed)."""

    def concentration(self, c, J):
        return c

    def reference_concentration(self, c_fc, J):
        return c_fc

    def engine_columns(self, c, c_bath, temperature_K):
        return float(swelling_pressure(c, c_bath, temperature_K)), None

    def swelling_at(self, pressure_kPa, J, c_bath, rt):
        return pressure_kPa  # eq. (2.26) at the charge of pressure_kPa, exactly

    def reference_pressure(self, pressure_kPa, J, c_bath, rt):
        return pressure_kPa


@dataclass(frozen=True)
class ConservedCharge(ChargeLaw):
    """c_FC = c / J: the particle keeps its fixed charge, and its Donnan pressure acts at the current concentration
    (mixture theory)."""

    def concentration(self, c, J):
        return c / J

    def reference_concentration(self, c_fc, J):
        return J * c_fc

    def engine_columns(self, c, c_bath, temperature_K):
        return 0.0, (c, c_bath, temperature_K)


#: the registry of charge laws, by name, in the order the figures and tables show them (the paper's first)
CHARGE_LAWS: Registry[ChargeLaw] = Registry(
    "charge law",
    (
        PrescribedCharge(
            "prescribed",
            paper=True,
            title="prescribed charge law: Pi(c), eqs. 2.25-2.27 as printed (the paper's model: compare with the paper)",
            short="prescribed Pi(c), paper",
        ),
        ConservedCharge(
            "conserved",
            paper=False,
            title="conserved charge law: Pi at the current concentration c/J (mixture theory; a deviation)",
            short="conserved charge, c/J",
        ),
    ),
)

#: the name of the paper's law
PAPER_LAW = CHARGE_LAWS.paper.name


def charge_law(name: str) -> ChargeLaw:
    """The registered law ``name`` (ValueError naming the registered laws for any other)."""
    if not isinstance(name, str) or name not in CHARGE_LAWS:
        raise ValueError(f"unknown charge law {name!r}: one of {', '.join(CHARGE_LAWS)}")
    return CHARGE_LAWS[name]
