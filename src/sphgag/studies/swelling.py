"""The configuration of figure 4 (paper section 2.6): the pools' conversion and swelling at a held lumen pressure
(the ``swelling`` section; :func:`sphgag.studies.pool_swelling.swell_pool`), and its resolution study (the
``swelling_convergence`` section; :mod:`sphgag.studies.convergence`)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from ..options import FANS_OUT, MEASUREMENT, Options, file_name_problems, role
from .artery import pool_placement_problems
from .wall_loading import BilayerCalibration


@dataclass(frozen=True)
class Swelling(Options):
    """The ``swelling`` section: the walls (``models``: passive, active), the pool models of figure 4 and of the
    variants, the saved states it starts from (``pressures_mmHg``), the conversion in ``conversion_steps``, the ramp of
    the fixed-charge concentration (``concentration_points`` from 0 to ``max_concentration_mEq_l``, eqs. 2.25-2.27),
    the size of the tip and top regions (``probe_length_um``) and how the tip is probed (``tip_probe``,
    :data:`sphgag.studies.pool_swelling.TIP_PROBES`), how the lumen is held while the pools swell (``lumen_control``,
    :data:`sphgag.studies.pool_swelling.LUMEN_CONTROLS`), the factor on the hourglass modulus of eq. (2.14) meanwhile
    (``hourglass_factor``) and the pools (``cases``, :class:`artery.Pool` entries by name)."""

    SECTION = "swelling"

    models: tuple = role(FANS_OUT)
    pool_models: tuple = role(FANS_OUT)
    variant_pool_models: tuple = role(FANS_OUT)
    pressures_mmHg: tuple = role(FANS_OUT)
    conversion_steps: int
    max_concentration_mEq_l: float
    concentration_points: int
    probe_length_um: float = role(MEASUREMENT)  # read where rule pool_stresses measures
    tip_probe: str = role(MEASUREMENT)
    lumen_control: str
    hourglass_factor: float
    cases: Mapping = role(FANS_OUT)

    @classmethod
    def problems(cls, config) -> list[str]:
        """Every pressure a saved state, each its own file name, and every pool inside the pool layers, off the
        symmetry edges."""
        sw = config.get("swelling", {})
        pressures = sw.get("pressures_mmHg", [])
        starts = [(f"swelling.pressures_mmHg[{k}]", p) for k, p in enumerate(pressures)]
        cases = {f"swelling.cases.{name}": pool for name, pool in sw.get("cases", {}).items()}
        return (
            BilayerCalibration.unsaved(config, starts)
            + file_name_problems("swelling", "pressures_mmHg", pressures)
            + pool_placement_problems(config, cases)
        )


@dataclass(frozen=True)
class SwellingConvergence(Options):
    """The ``swelling_convergence`` section, figure 4's resolution study: ``cases`` of the swelling sweeps, each wall
    and pool model, at the spacings ``dx_um`` and the lumen pressure ``pressure_mmHg``; figure 4's quantities read at
    the volume ratios ``volume_ratios`` and the concentrations ``gci_concentrations_mEq_l`` (steps of the ramp)."""

    SECTION = "swelling_convergence"

    dx_um: tuple
    cases: tuple
    models: tuple
    pool_models: tuple
    pressure_mmHg: float
    volume_ratios: tuple
    gci_concentrations_mEq_l: tuple

    @classmethod
    def problems(cls, config) -> list[str]:
        """The study's pool models and cases are those of the swelling sweeps, its concentrations steps of their
        ramp, and its spacings give distinct file names."""
        sw, sc, problems = config.get("swelling", {}), config.get("swelling_convergence", {}), []
        pools = sw.get("pool_models", []) + sw.get("variant_pool_models", [])
        for k, name in enumerate(sc.get("pool_models", [])):
            if name not in pools:
                problems.append(
                    f"swelling_convergence.pool_models[{k}] = {name!r} is not one of swelling.pool_models or "
                    f"swelling.variant_pool_models ({', '.join(pools)})"
                )
        for k, name in enumerate(sc.get("cases", [])):
            if name not in sw.get("cases", {}):
                problems.append(
                    f"swelling_convergence.cases[{k}] = {name!r} is not a pool of swelling.cases "
                    f"({', '.join(sw.get('cases', {}))})"
                )
        if "max_concentration_mEq_l" in sw and "concentration_points" in sw:
            top, points = sw["max_concentration_mEq_l"], sw["concentration_points"]
            ramp = [top * i / (points - 1) for i in range(points)]
            for k, c in enumerate(sc.get("gci_concentrations_mEq_l", [])):
                if not any(abs(v - c) < 1e-9 for v in ramp):
                    steps = ", ".join(f"{v:g}" for v in ramp[1:])
                    problems.append(
                        f"swelling_convergence.gci_concentrations_mEq_l[{k}] = {c:g} is not a step of the swelling "
                        f"ramp ({steps} mEq/l)"
                    )
        return problems + file_name_problems("swelling_convergence", "dx_um", sc.get("dx_um", []))
