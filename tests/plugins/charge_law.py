"""A charge law of one file: a class of its own, named ``ideal``, whose fixed charge stays in each particle
(c_FC = c / J: the conserved law's behaviour, which the engine's Donnan column evaluates)."""

from dataclasses import dataclass

from sphgag.physics.donnan import CHARGE_LAWS, ConservedCharge

REGISTRY = CHARGE_LAWS


@dataclass(frozen=True)
class IdealCharge(ConservedCharge):
    """The fixed charge conserved in each particle (c_FC = c / J), named ``ideal`` (a test)."""


VARIANT = IdealCharge(
    "ideal", paper=False, title="ideal charge law: the fixed charge conserved in each particle (a test)", short="ideal"
)
