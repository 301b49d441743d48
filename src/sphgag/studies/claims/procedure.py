"""The procedure claims: the features of figures 4-6 read on the authors' explicit procedure (P1-P4, target
``paper_procedure``) and figure 4 at equilibrium under the authors' settings (P5, target ``paper_settings``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from .. import paper_settings
from .evidence import Claim, Evidence, _yes

# -- the authors' explicit procedure beside the equilibria (target paper_procedure) ----------------------------------


def _read(e: Evidence, figure: str, quantity: str) -> pd.DataFrame:
    """The rows of the procedure's summary (sphgag.studies.paper_procedure.summary) of ``figure`` and ``quantity``."""
    t = e.procedure
    return t[(t.figure.astype(str) == figure) & (t.quantity == quantity)]


def _by_path(rows: pd.DataFrame):
    """``(path name, its rows)``: the equilibrium, then the explicit runs by step factor."""
    for path, g in rows.groupby(["path", "step_factor"], sort=False, dropna=False):
        name = "equilibrium" if path[0] == "equilibrium" else f"explicit x{path[1]:g}"
        yield name, g


def _residuals(g: pd.DataFrame) -> str:
    lo, hi = g.residual.min(), g.residual.max()
    return f"residual {lo:.2g}" if np.isclose(lo, hi) else f"residual {lo:.2g}-{hi:.2g}"


def p1_magnitudes(e: Evidence) -> list[Claim]:
    """The tip radial stress at 150 mEq/l is about 50-150 kPa in every pool (figure 4's magnitudes)."""
    out = []
    for path, g in _by_path(_read(e, "4", "tip_radial_stress_kPa")):
        v = g.value.to_numpy(dtype=float)
        margin = float(min(v.min() - 50.0, 150.0 - v.max()))
        claim = Claim(
            "P1",
            p1_magnitudes.__doc__.splitlines()[0],
            '"typically exceeding approximately 50 kPa" above 100 mEq/l; about 50-150 kPa at 150 mEq/l (figure 4)',
            f"{v.min():.0f} to {v.max():.0f} kPa over {len(v)} pools and walls ({_residuals(g)})",
            _yes(margin >= 0.0),
            "every pool and wall at 150 mEq/l within 50-150 kPa; the equilibrium at the procedure's spacing and "
            "temperature (paper_procedure)",
            margin=margin,
            path=path,
        )
        out.append(claim)
    return out


def _damage_rows(e: Evidence, quantity: str, figure: str = "5") -> pd.DataFrame:
    return _read(e, figure, quantity).sort_values("sigma_cr_kPa")


def p2_sawtooth(e: Evidence) -> list[Claim]:
    """The tip stress rises and drops repeatedly, a sawtooth (figure 5b)."""
    out = []
    for path, g in _by_path(_damage_rows(e, "teeth")):
        teeth = ", ".join(f"{r.sigma_cr_kPa:g} kPa {r.value:.0f} teeth" for r in g.itertuples())
        claim = Claim(
            "P2",
            p2_sawtooth.__doc__.splitlines()[0],
            "figure 5b (C14)",
            f"{teeth} (median {_residuals(g)})",
            _yes(len(g) and (g.value >= 2).all()),
            "at least two ruptures, each followed by a drop of the tip stress by > 10 % of sigma_cr before the next, "
            "in every run of figure 5's pool",
            path=path,
        )
        out.append(claim)
    return out


def p3_rate_ratio(e: Evidence) -> list[Claim]:
    """Raising sigma_cr from 30 to 60 kPa slows propagation more than twofold (figure 5b)."""
    out = []
    for path, g in _by_path(_damage_rows(e, "growth_rate_um_per_time")):
        lo, hi = g.iloc[0], g.iloc[-1]
        ratio = lo.value / hi.value if hi.value > 0 else np.inf
        rates = ", ".join(f"{r.sigma_cr_kPa:g} kPa {r.value:.3g} um" for r in g.itertuples())
        claim = Claim(
            "P3",
            p3_rate_ratio.__doc__.splitlines()[0],
            '"increases from sigma_cr = 30 kPa to 60 kPa reduce the rate of GAG propagation by more than two-fold" '
            "(figure 5b; C15)",
            f"{rates} per unit pseudo-time; ratio {ratio:.2f} (median {_residuals(g)})",
            _yes(ratio > 2.0) if len(g) > 1 else "n/a",
            "the mean rate of growth of the delaminated length (first rupture to the run's end) at the lowest sigma_cr "
            "over that at the highest exceeds 2",
            margin=float(ratio - 2.0) if len(g) > 1 else np.nan,
            path=path,
        )
        out.append(claim)
    return out


def p4_exterior_faster(e: Evidence) -> list[Claim]:
    """Two nearby pools grow faster outwards than towards each other (figure 6)."""
    rows = e.procedure_damage
    pairs = rows[rows.interior_particles.notna()] if rows is not None and len(rows) else rows
    out = []
    for factor, g in [] if pairs is None else pairs.groupby("step_factor", sort=True):
        found = []
        for (pool_set, sigma), run in g.groupby(["pool_set", "sigma_cr_kPa"], sort=False):
            run = run.reset_index(drop=True)  # where the interior side stops growing: the pools merge
            at = run.iloc[int(np.argmax(run.interior_particles.to_numpy() >= run.interior_particles.max()))]
            found.append((pool_set, sigma, at))
        text = ", ".join(
            f"{p} at {s:g} kPa: interior {at.interior_particles:.0f} / exterior {at.exterior_particles:.0f} at "
            f"pseudo-time {at.pseudo_time:.0f} (residual {at.residual:.2g})"
            for p, s, at in found
        )
        claim = Claim(
            "P4",
            p4_exterior_faster.__doc__.splitlines()[0],
            '"the rate of the exterior growth is faster" (figure 6; C16)',
            text,
            _yes(all(at.exterior_particles > at.interior_particles for *_, at in found)),
            "more exterior than interior converted particles where the interior side stops growing (the pools merge, "
            "as C16 reads it), in every pool-pair run",
            path=f"explicit x{factor:g}",
        )
        out.append(claim)
    return out


#: the paper's figure 4-6 features by the authors' explicit procedure (target paper_procedure), one row per path
PROCEDURE = [p1_magnitudes, p2_sawtooth, p3_rate_ratio, p4_exterior_faster]
#: the equilibrium's claim of each procedure claim that has one (its verdict stands beside the explicit paths')
PROCEDURE_EQUILIBRIUM = {"P2": "C14", "P3": "C15", "P4": "C16"}


def procedure_claims(e: Evidence, found: list[Claim]) -> list[Claim]:
    """The procedure claims (:data:`PROCEDURE`, the paper's law and pool): the equilibrium's own verdict where
    ``found`` (the claims of the paper's law) has its counterpart, then every explicit path's; ``not run`` until
    target paper_procedure has run."""

    def bare(k, fn, our_value="", holds="", path="equilibrium"):
        return Claim(f"P{k + 1}", fn.__doc__.splitlines()[0], "", our_value, holds, "", path=path)

    if e.procedure is None:
        return [e.not_run(bare(k, fn), "procedure") for k, fn in enumerate(PROCEDURE)]
    equilibrium = {c.claim_id: c for c in found}
    out = []
    for k, fn in enumerate(PROCEDURE):
        no_run = "n/a: the configuration runs none of its pools (paper_procedure.cases, paper_procedure.pool_sets)"
        rows = fn(e) or [bare(k, fn, our_value=no_run, holds="n/a", path="explicit")]
        twin = PROCEDURE_EQUILIBRIUM.get(rows[0].claim_id)
        if twin in equilibrium:
            c = equilibrium[twin]
            verdict = dict(our_value=f"{twin}: {c.our_value}", holds=c.holds, criterion=f"as {twin}: {c.criterion}")
            rows.insert(0, replace(rows[0], **verdict, margin=c.margin, path="equilibrium"))
        out += rows
    return out


# -- figure 4 under the authors' settings (target paper_settings) ---------------------------------------------------

#: claim P5's range of the tip radial stress [kPa] (P1's reading of figure 4) and the concentration it is read at
P5_RANGE, P5_CONCENTRATION = (50.0, 150.0), 150.0


def p5_authors_settings(e: Evidence) -> Claim:
    """Figure 4's magnitudes follow from the authors' settings."""
    criterion = (
        f"the authors' configuration (config/script.yaml) gives every pool's and wall's tip radial stress within "
        f"{P5_RANGE[0]:g}-{P5_RANGE[1]:g} kPa at {P5_CONCENTRATION:g} mEq/l, each at equilibrium; the settings are "
        "ranked by the median share of the difference ours - authors' that their step makes (both directions, cases "
        "and walls of the ablation)"
    )
    paper = (
        '"typically exceeding approximately 50 kPa" above 100 mEq/l; about 50-150 kPa at 150 mEq/l '
        "(figure 4, as P1 reads it)"
    )
    bare = Claim("P5", p5_authors_settings.__doc__.splitlines()[0], paper, "", "", criterion)
    if e.paper_settings is None:
        return e.not_run(bare, "paper_settings")
    t = e.paper_settings
    at = t[np.isclose(t.concentration_mEq_l, P5_CONCENTRATION)]
    script = at[(at.setting == paper_settings.NONE) & (at.direction == "script")]
    ours = at[(at.setting == paper_settings.NONE) & (at.direction == "ours")]
    if not len(script):
        missing = f"n/a: no state of the authors' configuration at {P5_CONCENTRATION:g} mEq/l"
        return replace(bare, our_value=missing, holds="n/a")
    v = script.tip_radial_stress_kPa.to_numpy(dtype=float)
    missing = int(np.isnan(v).sum())
    margin = float(min(np.nanmin(v) - P5_RANGE[0], P5_RANGE[1] - np.nanmax(v))) if missing < len(v) else np.nan
    each = ", ".join(f"{r.model} {r.case} {r.tip_radial_stress_kPa:.0f}" for r in script.itertuples())
    theirs = f"authors' configuration: {each} kPa (residual <= {script.residual.max():.1g})"
    if missing:
        theirs += f"; {missing} state(s) without equilibrium"
    if len(ours):
        theirs += "; ours: " + ", ".join(f"{r.model} {r.case} {r.tip_radial_stress_kPa:.0f}" for r in ours.itertuples())
    top = paper_settings.ranked(t, P5_CONCENTRATION).dropna(subset=["share"]).head(3)
    if len(top):
        theirs += "; the settings that account for most of the difference (median share of ours - authors', step): "
        theirs += ", ".join(f"{r.setting} {r.share:+.2f} ({r.abs_step_kPa:.0f} kPa)" for r in top.itertuples())
    return replace(bare, our_value=theirs, holds=_yes(missing == 0 and margin >= 0.0), margin=margin)
