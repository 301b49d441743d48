"""The evidence the claims are judged on (:class:`Evidence`: the pipeline's tables and the configuration that made
them), a claim's row (:class:`Claim`) and the helpers the claims of every figure share.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

#: the paper's pool model (sphgag.studies.pool_swelling.POOL_MODELS): the pool's GAG particles carry eq. (2.27)
PAPER_POOL = "particles"


@dataclass
class Claim:
    claim_id: str
    statement: str
    paper_value: str
    our_value: str
    holds: str  # yes | no | n/a | not run (its evidence is made by a target that has not run)
    criterion: str
    charge_law: str = "-"  # a pool claim's Donnan law (sphgag.physics.donnan.CHARGE_LAWS); "-": no pool
    pool_model: str = "-"  # a pool claim's pool model (sphgag.studies.pool_swelling.POOL_MODELS); "-": no pool
    margin: float = np.nan  # the criterion's smallest slack in its unit (kPa for C6-C12): > 0 where it holds
    across_band: str = "-"  # C6-C12: the verdict and margin at every spacing of the resolution study and extrapolated
    path: str = "equilibrium"  # how the states were reached: equilibrium, or the authors' explicit procedure (P1-P4)


@dataclass(frozen=True)
class Evidence:
    """What the claims read: the pipeline's tables (rule claims' inputs) and the configuration that made them.

    Calibration: ``mean`` (mean_pressure_diameter.csv), ``bilayer`` (bilayer_pressure_diameter.csv), ``activation``
    (activation_summary.csv), ``layers`` (homeostasis/layers.csv), ``transmural``. Pools: ``tips``
    (swelling/tip_stress.csv), ``growth`` and ``delamination`` (delamination/growth.csv and summary.csv, the paper's
    damage law), with ``cases`` (each swelling pool's angular extent), ``max_concentration`` of the swelling runs,
    the onset ``criteria`` (the first is the default) and the pool sets' roles ``figures`` (``delamination.figures``).
    Other targets: ``sensitivity`` (sensitivity/samples.csv, target ``sensitivity``), ``resolution`` and ``band``
    (swelling/convergence.csv and gci_band.csv, target ``resolution``: figure 4's resolution study at
    ``study_pressure``, :func:`across_band`), ``procedure`` (paper_procedure/summary.csv, target
    ``paper_procedure``: the authors' explicit procedure, :data:`PROCEDURE`; ``procedure_damage``, its damage runs'
    rows, paper_procedure/damage.csv), ``paper_settings`` (paper_settings/ablation.csv, target ``paper_settings``:
    figure 4 under the authors' settings, :func:`p5_authors_settings`); :data:`TARGETS` names the target that
    makes each of these, for the rows of a claim whose evidence is missing.
    """

    mean: pd.DataFrame | None = None
    bilayer: pd.DataFrame | None = None
    activation: pd.DataFrame | None = None
    layers: pd.DataFrame | None = None
    transmural: pd.DataFrame | None = None
    tips: pd.DataFrame | None = None
    growth: pd.DataFrame | None = None
    delamination: pd.DataFrame | None = None
    cases: dict = field(default_factory=dict)
    max_concentration: float | None = None
    criteria: tuple = ()
    figures: dict = field(default_factory=dict)
    sensitivity: pd.DataFrame | None = None
    resolution: pd.DataFrame | None = None
    band: pd.DataFrame | None = None
    study_pressure: float | None = None
    procedure: pd.DataFrame | None = None
    procedure_damage: pd.DataFrame | None = None
    paper_settings: pd.DataFrame | None = None

    def of_law(self, law: str, pool_model: str = PAPER_POOL) -> Evidence:
        """The evidence of one charge law and pool model: its rows of the pool tables (columns ``charge_law`` and,
        where a table has it, ``pool_model``)."""
        pools = {
            k: of_law(getattr(self, k), law, pool_model)
            for k in ("tips", "growth", "delamination", "sensitivity", "resolution", "band")
            if getattr(self, k) is not None
        }
        return replace(self, **pools)

    def not_run(self, claim: Claim, evidence: str) -> Claim:
        """``claim`` (its id, statement and criterion) as the row of a claim whose ``evidence`` (a field) is missing:
        the target that makes it has not run."""
        return replace(claim, our_value=f"not run: `snakemake {TARGETS[evidence]}`", holds="not run")


#: the evidence the default target does not make, by the Evidence field that holds it, and the target that makes it
TARGETS = {
    "sensitivity": "sensitivity",
    "resolution": "resolution",
    "band": "resolution",
    "procedure": "paper_procedure",
    "procedure_damage": "paper_procedure",
    "paper_settings": "paper_settings",
}


def _yes(flag) -> str:
    return "yes" if bool(flag) else "no"


def _hoop_range(profile: pd.DataFrame) -> float:
    s = profile.circ_stress_kPa
    return float((s.max() - s.min()) / s.mean())


def _size_groups(table: pd.DataFrame, ordered: list) -> list[pd.DataFrame]:
    """Per model and pressure, the rows indexed by case in the pool-size order ``ordered``: the groups with more than
    one pool."""
    groups = [g.set_index("case") for _, g in table.groupby(["model", "pressure_mmHg"])]
    groups = [g.loc[[c for c in ordered if c in g.index]] for g in groups]
    return [g for g in groups if len(g) > 1]


def _monotone_groups(table: pd.DataFrame, ordered: list, holds) -> tuple[int, int]:
    """(groups where ``holds(rows ordered by pool size)``, groups with more than one pool) per model and pressure."""
    groups = _size_groups(table, ordered)
    return sum(bool(holds(g)) for g in groups), len(groups)


def _group_slack(table: pd.DataFrame, ordered: list, slack) -> float:
    """The smallest ``slack(rows ordered by pool size)`` over the model-pressure groups with more than one pool."""
    return min((float(slack(g)) for g in _size_groups(table, ordered)), default=np.nan)


def last_converged(tips: pd.DataFrame) -> pd.DataFrame:
    """Each swelling run's last converged state (its highest concentration), in the table's order: a run that found
    no equilibrium beyond some concentration ends there, below the requested maximum."""
    conv = tips[tips.stage == "converted"]
    last = conv.groupby(["model", "pressure_mmHg", "case"]).concentration_mEq_l.idxmax()
    return conv[conv.index.isin(last)]


def at_highest(top: pd.DataFrame, max_concentration: float | None) -> str:
    """Where the claims read "the highest concentration": the requested one if every run reached it, else each run's
    last converged state."""
    ends = top.concentration_mEq_l
    if max_concentration is None or np.allclose(ends, max_concentration):
        return f"at {ends.max():g} mEq/l"
    short = int((ends < max_concentration - 1e-9).sum())
    return (
        f"at each run's last converged state ({ends.min():g}-{ends.max():g} mEq/l; {short}/{len(ends)} runs found "
        f"no equilibrium up to {max_concentration:g})"
    )


def _runs(growth: pd.DataFrame, case: str, criterion: str):
    return {
        s: g.sort_values("step")
        for s, g in growth[(growth.case == case) & (growth.criterion == criterion)].groupby("sigma_cr_kPa")
    }


def _found(claims, e: Evidence) -> list[Claim]:
    """The claims of ``claims`` that ``e`` has the data for."""
    return [c for c in (claim(e) for claim in claims) if c is not None]


def of_law(table: pd.DataFrame, law: str, pool_model: str = PAPER_POOL) -> pd.DataFrame:
    """The rows of one charge law (column ``charge_law``) and pool model (column ``pool_model``, where the table has
    one: the delamination tables have the paper's only)."""
    rows = table.charge_law == law
    if "pool_model" in table:
        rows &= table.pool_model == pool_model
    return table[rows]
