"""A pool model of one file: the pool as a pressurised cavity whose wall keeps the configured hourglass form
(``numerics.hourglass``) once converted, where the shipped cavity switches to the energy form
(:class:`sphgag.studies.pool_swelling.CavityPool`); a class of its own."""

from dataclasses import dataclass

from sphgag.studies.pool_swelling import POOL_MODELS, CavityPool

REGISTRY = POOL_MODELS


@dataclass(frozen=True)
class ConfiguredCavity(CavityPool):
    """A cavity that keeps ``numerics.hourglass`` once converted (``hourglass = None``)."""

    hourglass: str | None = None


VARIANT = ConfiguredCavity(
    "cavity_as_configured",
    "the pool as a pressurised cavity, its wall with the configured hourglass form (a test)",
    "cavity_as_configured",
)
