"""The ``verification`` configuration section: the closed-form checks of the pool stress field (docs/physics.md),
each configured beside its study."""

from __future__ import annotations

from dataclasses import dataclass

from ..options import Options
from .annulus import AnnulusVerification
from .crack import CrackVerification
from .inclusion import PoolVerification
from .swollen_pool import CircularPoolVerification
from .wall_profiles import ProfileVerification


@dataclass(frozen=True)
class Verification(Options):
    """The pressurised elliptical inclusion (:class:`PoolVerification`), the pressurised crack against Sneddon and
    Griffith (:class:`CrackVerification`), the circular pool at large strain (:class:`CircularPoolVerification`) and
    the pressurised annulus at the prescribed law's limit (:class:`AnnulusVerification`) and the walls' transmural
    stress (:class:`ProfileVerification`)."""

    SECTION = "verification"

    pool: PoolVerification
    crack: CrackVerification
    circular_pool: CircularPoolVerification
    annulus: AnnulusVerification
    profiles: ProfileVerification

    @classmethod
    def problems(cls, config) -> list[str]:
        """The problems of each check's configuration."""
        checks = (
            PoolVerification,
            CrackVerification,
            CircularPoolVerification,
            AnnulusVerification,
            ProfileVerification,
        )
        return [p for check in checks for p in check.problems(config)]
