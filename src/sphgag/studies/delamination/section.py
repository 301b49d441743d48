"""The ``delamination`` configuration section (paper section 2.7, figures 5-7; config/schema.yaml): what every
delamination run shares, the pool sets grown, which set each figure shows, the resolution study and the
fracture-energy runs. One run's settings (its own sigma_cr, criterion and damage law) are
:class:`sphgag.studies.delamination.settings.Settings`."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from ...options import Options, file_name_problems
from ...physics.donnan import CHARGE_LAWS
from ...studies.wall_loading import BilayerCalibration
from ..artery import pool_placement_problems


@dataclass(frozen=True)
class Figures(Options):
    """Which pool set each figure (and its claims) shows: figure 5's set grown alone at every ``critical_stresses_kPa``
    (also the set of the resolution study), figure 6's sets of pools at one radius, figure 7's radially offset set."""

    fig5: str
    fig6: str | tuple
    fig7: str | tuple


@dataclass(frozen=True)
class Resolution(Options):
    """The resolution study: the pool sets ``pool_sets`` at the spacings ``dx_um``, at ``critical_stress_kPa``."""

    dx_um: tuple
    pool_sets: tuple


@dataclass(frozen=True)
class FractureEnergy(Options):
    """Figure 5's set grown with the damage law with a fracture energy G_c (``fracture_energies_J_m2``; with
    ``match_paper`` also at the G_c that eq. 2.28 as printed dissipates)."""

    fracture_energies_J_m2: tuple
    match_paper: bool


@dataclass(frozen=True)
class Delamination(Options):
    """The ``delamination`` section: the held lumen pressure, the critical stresses sigma_cr (figure 5's and every
    other set's), the onset criteria, the damage law's constants (eq. 2.28), the candidates, the concentration ramp
    and the caps of a run, the pool sets (:class:`sphgag.studies.artery.Pool` entries by set name), the figures' sets
    (:class:`Figures`), the resolution study (:class:`Resolution`) and the fracture-energy runs
    (:class:`FractureEnergy`)."""

    SECTION = "delamination"

    pressure_mmHg: float
    critical_stresses_kPa: tuple
    critical_stress_kPa: float
    criteria: tuple
    rupture_stretch_increment: float
    damage_law: str
    averaging_length_um: float
    candidates: str
    candidate_window_deg: float
    damage_tolerance: float
    concentration_step_mEq_l: float
    max_concentration_mEq_l: float
    max_concentration_by_law_mEq_l: Mapping
    max_passes: int
    max_extent_deg: float
    conversion_steps: int
    bisection_tolerance_mEq_l: float
    pool_sets: Mapping
    figures: Figures
    convergence: Resolution
    fracture_energy: FractureEnergy

    @classmethod
    def problems(cls, config) -> list[str]:
        """The figures' and the resolution study's sets exist (:meth:`pool_set_roles`), the held pressure has a saved
        state, the critical stresses and spacings give distinct file names, a law's ramp top names a charge law
        (:data:`sphgag.physics.donnan.CHARGE_LAWS`), and every pool lies inside the pool layers, off the symmetry
        edges."""
        de = config.get("delamination", {})
        if not de:
            return []
        problems = cls.pool_set_roles(de)
        if "pressure_mmHg" in de:
            problems += BilayerCalibration.unsaved(config, [("delamination.pressure_mmHg", de["pressure_mmHg"])])
        problems += file_name_problems("delamination", "critical_stresses_kPa", de.get("critical_stresses_kPa", []))
        problems += [
            f"delamination.max_concentration_by_law_mEq_l.{law} names no charge law ({', '.join(CHARGE_LAWS)})"
            for law in de.get("max_concentration_by_law_mEq_l", {})
            if law not in CHARGE_LAWS
        ]
        de_dx = [f"{v:g}" for v in de.get("convergence", {}).get("dx_um", [])]
        if len(set(de_dx)) < len(de_dx):
            problems.append(f"delamination.convergence.dx_um: {de_dx} repeat a file name (dx{{dx}}): make them differ")
        pools = {}
        for name, members in de.get("pool_sets", {}).items():
            pools.update({f"delamination.pool_sets.{name}[{k}]": pool for k, pool in enumerate(members)})
        return problems + pool_placement_problems(config, pools)

    @staticmethod
    def pool_set_roles(de: Mapping) -> list[str]:
        """Every figure's pool set (``delamination.figures``) and every set of the resolution study
        (``delamination.convergence.pool_sets``) exists in ``delamination.pool_sets``, and a set that figures 6-7
        share with figure 5 is run at their sigma_cr (figure 5's set runs at ``critical_stresses_kPa`` only)."""
        out, sets = [], de.get("pool_sets", {})
        fig5 = de.get("figures", {}).get("fig5")
        for role, names in de.get("figures", {}).items():
            for k, name in enumerate(names if isinstance(names, list) else [names]):
                key = f"delamination.figures.{role}" + (f"[{k}]" if isinstance(names, list) else "")
                if name not in sets:
                    out.append(
                        f"{key} = {name!r} is not a pool set of delamination.pool_sets ({', '.join(sets)}): "
                        f"figure {role.removeprefix('fig')} would have no set to show"
                    )
                elif role != "fig5" and name == fig5 and de["critical_stress_kPa"] not in de["critical_stresses_kPa"]:
                    out.append(
                        f"{key} = {name!r} is figure 5's set (delamination.figures.fig5), which runs at "
                        f"delamination.critical_stresses_kPa = {de['critical_stresses_kPa']}, not at "
                        f"delamination.critical_stress_kPa = {de['critical_stress_kPa']}: give the figure a set of "
                        "its own"
                    )
        for k, name in enumerate(de.get("convergence", {}).get("pool_sets", [])):
            if name not in sets:
                out.append(
                    f"delamination.convergence.pool_sets[{k}] = {name!r} is not a pool set of delamination.pool_sets "
                    f"({', '.join(sets)}): the resolution study would have no such set to grow"
                )
        return out
