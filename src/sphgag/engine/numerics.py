"""The numerical settings of a run (the ``numerics`` configuration section): the discretisation and the solver."""

from __future__ import annotations

from dataclasses import dataclass

from ..options import Options
from .solver import PathOptions, Solver


@dataclass(frozen=True)
class Numerics(Options):
    """``kernel_support_factor``: the kernel's support radius over the particle spacing (eq. 2.5);
    ``hourglass_alpha``: the hourglass penalty's alpha (eq. 2.14); ``hourglass``: its form
    (:data:`sphgag.engine.forces.HOURGLASS_FORMS`: ``paper``, eq. 2.14 as printed, or ``energy``, its energy form);
    ``tolerance``: the relative residual of a
    converged state; ``max_newton_iterations`` and ``max_bisections``: Newton's method per load step and the halvings
    of a step; ``reuse_factorisation``: chord steps with the last factorisation before refactorising;
    ``stress_recovery``: how the measurements read the stress (:data:`sphgag.engine.measure.RECOVERIES`: ``paper``,
    the kernel stress of eq. 2.10; ``volumetric``; ``traction``), with the equilibrium unchanged; ``lumen_load``: how
    the lumen pressure becomes particle forces (:data:`sphgag.engine.loading.LUMEN_LOADS`: ``surface`` or
    ``operator``)."""

    SECTION = "numerics"

    kernel_support_factor: float
    hourglass_alpha: float
    hourglass: str
    tolerance: float
    max_newton_iterations: int
    max_bisections: int
    reuse_factorisation: bool
    stress_recovery: str = "paper"
    lumen_load: str = "surface"

    def model_options(self) -> dict:
        """The numerical keywords of a :class:`sphgag.engine.model.Model`: the hourglass control (``hourglass_alpha``,
        ``hourglass``), the ``stress_recovery`` and the ``lumen_load``."""
        return dict(
            hourglass_alpha=self.hourglass_alpha,
            hourglass=self.hourglass,
            stress_recovery=self.stress_recovery,
            lumen_load=self.lumen_load,
        )

    def solver_options(self) -> PathOptions:
        """The options of the run's load paths (:class:`sphgag.engine.solver.PathOptions`): its tolerance, Newton
        iterations, bisections and factorisation reuse, no stall test."""
        return PathOptions(
            tol=self.tolerance,
            max_iter=self.max_newton_iterations,
            max_bisections=self.max_bisections,
            reuse=self.reuse_factorisation,
        )

    def solver(self, model) -> Solver:
        """A :class:`sphgag.engine.solver.Solver` of ``model`` with these options (an empty factorisation cache)."""
        return Solver(model, self.solver_options())
