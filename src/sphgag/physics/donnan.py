"""The charge laws of a GAG pool: how its Gibbs-Donnan swelling follows the pool's volume (eqs. 2.25-2.27).

The swelling pressure of a GAG particle is eq. (2.26) at its fixed-charge concentration c_FC,
``Pi = R T (sqrt(c_FC^2 + c*^2) - c*)`` (:func:`sphgag.physics.materials.swelling_pressure`). The load raises the
concentration ``c`` of the pool (per reference volume); a charge law says what c_FC is once the particle has the
volume ratio ``J`` (:meth:`ChargeLaw.concentration`):

* ``prescribed``, the paper's law as printed: c_FC = c at every J, so the particle carries the swelling pressure
  Pi(c) of the load (the property column ``PI`` of :mod:`sphgag.physics.materials`);
* ``conserved``, our documented deviation (mixture theory): the fixed charge stays in the particle, c_FC = c / J, so
  the Donnan pressure acts at the current concentration (the column ``FCD``, :func:`sphgag.physics.materials.donnan`).

A law is a :class:`ChargeLaw` (a :class:`sphgag.registry.Variant`) of the registry :data:`LAWS`, by its name in the
configuration (``gag.charge_laws``),
the pipeline's wildcard ``{law}`` and every pool table (column ``charge_law``). The schema's enumeration, the typed
GAG options (:class:`sphgag.physics.materials.Gag`), the engine's GAG material, the exact circular pool
(:mod:`sphgag.physics.cavity`), the pool models that carry it and the figures' titles are read from the registry, so
a new law whose fixed charge follows one of these two rules is one entry here (docs/contributing.md).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..registry import Registry, Variant


@dataclass(frozen=True)
class ChargeLaw(Variant):
    """A Donnan law of the GAG pools.

    name : the law's name (configuration, wildcard, column ``charge_law``).
    conserves_charge : the particle keeps its fixed charge, c_FC = c / J (the engine's column ``FCD``, with the Donnan
        pressure of eq. 2.26 evaluated in the Numba kernels at the particle's J); otherwise c_FC = c and the particle
        carries the prescribed swelling pressure Pi(c) of eqs. (2.25-2.26) (the column ``PI``).
    paper : the paper's law (the one to compare with the paper's panels); every other law is a deviation.
    title : the heading of the law's block in the figures.
    short : the law's label in a panel title or an axis label.

    It owns no configuration key of its own: the GAG options (``gag``) are every law's.
    """

    name: str
    conserves_charge: bool
    paper: bool
    title: str
    short: str

    def concentration(self, c, J):
        """The fixed-charge concentration c_FC [mEq/l] of eq. (2.26) at the volume ratio ``J`` of a particle loaded
        to ``c`` (per reference volume): ``c / J`` where the particle conserves its fixed charge, else ``c``."""
        return c / J if self.conserves_charge else c

    def reference_concentration(self, c_fc, J):
        """The load's concentration ``c`` (per reference volume) whose fixed-charge concentration at ``J`` is ``c_fc``:
        the inverse of :meth:`concentration`, ``J c_fc`` or ``c_fc``."""
        return J * c_fc if self.conserves_charge else c_fc


#: the registry of charge laws, by name, in the order the figures and tables show them (the paper's first)
LAWS: Registry[ChargeLaw] = Registry(
    "charge law",
    (
        ChargeLaw(
            "prescribed",
            conserves_charge=False,
            paper=True,
            title="prescribed charge law: Pi(c), eqs. 2.25-2.27 as printed (the paper's model: compare with the paper)",
            short="prescribed Pi(c), paper",
        ),
        ChargeLaw(
            "conserved",
            conserves_charge=True,
            paper=False,
            title="conserved charge law: Pi at the current concentration c/J (mixture theory; a deviation)",
            short="conserved charge, c/J",
        ),
    ),
)

#: the names of the registered laws (the schema's enumeration of ``gag.charge_laws``)
CHARGE_LAWS = LAWS.names

#: the name of the paper's law
PAPER_LAW = LAWS.paper.name


def charge_law(name: str) -> ChargeLaw:
    """The registered law ``name`` (ValueError naming the registered laws for any other)."""
    if not isinstance(name, str) or name not in LAWS:
        raise ValueError(f"unknown charge law {name!r}: one of {', '.join(LAWS)}")
    return LAWS[name]
