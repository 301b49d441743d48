"""A pool model of one file: the pool as a pressurised cavity whose wall keeps the configured hourglass form
(``numerics.hourglass``), where the shipped cavity switches to the energy form (:class:`sphgag.studies.pool_swelling.
CavityPool`)."""

from sphgag.physics import donnan
from sphgag.studies.pool_swelling import POOL_MODELS, CavityPool

REGISTRY = POOL_MODELS

VARIANT = CavityPool(
    "cavity_as_configured",
    "the pool as a pressurised cavity, its wall with the configured hourglass form (a test)",
    tuple(law.name for law in donnan.CHARGE_LAWS.values() if law.holds_pressure()),
    "cavity_as_configured",
    hourglass=None,
)
