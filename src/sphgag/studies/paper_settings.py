"""Figure 4's magnitudes against the authors' settings (target ``paper_settings``).

Our figure 4 tip radial stresses differ from the paper's by a factor of 4 to 20 (claim P1). The authors' script
(``../shared/notes/reference-implementation.md``) differs from our model in several settings besides its procedure:
spacing, kernel support, the hourglass penalty and its modulus while swelling, the GAG particles' material, the
temperature, the mass fractions, the lumen's control and where the tip is measured. ``config/script.yaml`` is the
authors' settings as a complete configuration; this module measures, at equilibrium, what each setting does.

Figure 4's protocol (:func:`sphgag.studies.convergence.swell_cases`: the passive or active wall at the section's lumen
pressure by the path of the pressure-diameter sweep, then each pool converted and swollen by
:func:`sphgag.studies.pool_swelling.swell_pool`, the paper's law Pi(c) of eqs. 2.25-2.27) is run under

* the script's configuration and ours (``setting = none``), and
* each configuration with one setting (a group of configuration keys, the section's ``settings``) switched to the
  other's value (``direction``: ``from_script``, the script's configuration with that setting ours; ``from_ours``,
  ours with that setting the script's).

:func:`ablation` reads figure 4's quantities at the section's concentrations: the tip radial stress (the tips of
``swelling.tip_probe``), the top hoop stress, the pool's volume ratio J, each with its residual; a state the path did
not reach in equilibrium gives no number (``equilibrium`` says why). :func:`steps` gives the step each setting makes
from the script's value to ours, read both ways.
"""

from __future__ import annotations

import copy
import logging
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
import yaml

from ..engine.numerics import Numerics
from ..options import Options
from ..physics.donnan import PAPER_LAW
from ..physics.materials import law_gag
from . import convergence

log = logging.getLogger("sphgag")

#: the two ends: the configuration of ``paper_settings.script_config`` and the running one
BASES = ("script", "ours")
#: the setting of a base configuration's own run (nothing switched)
NONE = "none"
#: the direction of a run with one setting switched, by its base
DIRECTIONS = {"script": "from_script", "ours": "from_ours"}
#: the columns of ``results/paper_settings/ablation.csv``
COLUMNS = [
    "setting",
    "direction",
    "case",
    "model",
    "charge_law",
    "concentration_mEq_l",
    "tip_radial_stress_kPa",
    "top_hoop_stress_kPa",
    "volume_ratio",
    "residual",
    "equilibrium",
    "pressure_mmHg",
    "particles",
]


@dataclass(frozen=True)
class PaperSettings(Options):
    """The ``paper_settings`` configuration section: the authors' configuration ``script_config`` (a complete
    configuration file, path relative to the working directory), the lumen pressure the walls are brought to,
    the pools ``cases`` of every run (and ``claim_cases``, those of the script's own run: claim P5), the walls
    ``models``, the concentrations figure 4's quantities are read at (steps of a ramp from 0 in
    ``concentration_step_mEq_l``), and the ``settings``: each a name and the dotted configuration keys it sets."""

    SECTION = "paper_settings"

    script_config: str
    pressure_mmHg: float
    cases: tuple
    claim_cases: tuple
    models: tuple
    concentrations_mEq_l: tuple
    concentration_step_mEq_l: float
    settings: Mapping

    @classmethod
    def problems(cls, config) -> list[str]:
        """The authors' configuration is a file; every setting's keys are keys of it and of ``config``; the cases are
        pools of both; the concentrations are steps of the ramp. (The file's own validation is
        :func:`sphgag.config.validate`'s, at the rules' parse time: workflow/rules/paper_settings.smk.)"""
        ps = config.get("paper_settings")
        if not ps:
            return []
        path = Path(ps["script_config"])
        if not path.is_file():
            return [f"paper_settings.script_config = {str(path)!r} is not a file (relative to the working directory)"]
        try:  # read, not validated: sphgag.config imports this module, and a job's code is what it imports
            script = yaml.safe_load(path.read_text()) or {}
        except (OSError, ValueError) as exc:
            return [f"paper_settings.script_config = {str(path)!r} cannot be read: {exc}"]
        problems = []
        for name, keys in ps["settings"].items():
            if name == NONE:
                problems.append(f"paper_settings.settings.{NONE}: the name is the base runs' (nothing switched)")
            for key in keys:
                for which, configuration in (("this configuration", config), (str(path), script)):
                    try:
                        get(configuration, key)
                    except KeyError:
                        problems.append(f"paper_settings.settings.{name}: {key!r} is not a key of {which}")
        for field in ("cases", "claim_cases"):
            for k, case in enumerate(ps[field]):
                for which, configuration in (("swelling.cases", config), (f"{path}'s swelling.cases", script)):
                    if case not in configuration.get("swelling", {}).get("cases", {}):
                        problems.append(f"paper_settings.{field}[{k}] = {case!r} is not a pool of {which}")
        step = ps["concentration_step_mEq_l"]
        for k, c in enumerate(ps["concentrations_mEq_l"]):
            if abs(c / step - round(c / step)) > 1e-9:
                problems.append(
                    f"paper_settings.concentrations_mEq_l[{k}] = {c:g} is not a step of the ramp "
                    f"(paper_settings.concentration_step_mEq_l = {step:g})"
                )
        return problems


def get(config: Mapping, key: str):
    """The value of the dotted configuration key ``key`` (``KeyError`` naming it where it is not one)."""
    node = config
    for part in key.split("."):
        if not isinstance(node, Mapping) or part not in node:
            raise KeyError(f"{key!r} is not a key of the configuration")
        node = node[part]
    return node


def switched(config: Mapping, other: Mapping, keys) -> dict:
    """A copy of ``config`` with each dotted key of ``keys`` set to its value in ``other``."""
    out = copy.deepcopy(dict(config))
    for key in keys:
        *parents, leaf = key.split(".")
        node = out
        for part in parents:
            node = node[part]
        node[leaf] = copy.deepcopy(get(other, key))
    return out


def runs(section: Mapping) -> list[dict]:
    """Every run of the study: each base with nothing switched, then with each setting switched (``base``,
    ``setting``)."""
    return [dict(base=b, setting=s) for b in BASES for s in [NONE, *section["settings"]]]


def configuration(ours: Mapping, script: Mapping, base: str, setting: str) -> dict:
    """The configuration of one run: the ``base`` configuration (``script`` or ``ours``) with the keys of ``setting``
    (of ``ours``' ``paper_settings.settings``; :data:`NONE`: nothing) set to the other's values."""
    if base not in BASES:
        raise ValueError(f"base {base!r}: one of {', '.join(BASES)}")
    start, other = (script, ours) if base == "script" else (ours, script)
    keys = [] if setting == NONE else ours["paper_settings"]["settings"][setting]
    return switched(start, other, keys)


def run_params(ours: Mapping, script: Mapping, base: str, setting: str) -> dict:
    """What one run depends on (a rule's params; :func:`run` reads them): from its :func:`configuration`, the wall
    (spacing, ``bilayer``, ``numerics``, the homeostasis, the activation of the pressure-diameter path), the GAG
    under the paper's law (eqs. 2.25-2.27), the swelling protocol (:func:`sphgag.studies.pool_swelling.swell_pool`: a
    ramp from 0 to the highest of the section's concentrations in its steps, the lumen control and the hourglass
    factor), the pools (the section's ``cases``; ``claim_cases`` for the script's own run) and the probes. The
    section is ``ours``' (the running configuration's)."""
    ps = ours["paper_settings"]
    c = configuration(ours, script, base, setting)
    sw = c["swelling"]
    top, step = max(ps["concentrations_mEq_l"]), ps["concentration_step_mEq_l"]
    cases = ps["claim_cases"] if (base, setting) == ("script", NONE) else ps["cases"]
    return dict(
        dx=c["bilayer"]["dx_um"],
        bilayer=c["bilayer"],
        numerics=c["numerics"],
        homeostasis={k: v for k, v in c["homeostasis"].items() if k != "target_pressure_mmHg"},
        calibration={k: c["bilayer_calibration"][k] for k in ("activation_pressure_mmHg", "activation_steps")},
        pressure_mmHg=ps["pressure_mmHg"],
        gag=law_gag(c["gag"], PAPER_LAW),
        swelling=dict(
            conversion_steps=sw["conversion_steps"],
            max_concentration_mEq_l=float(top),
            concentration_points=int(round(top / step)) + 1,
            pool_model="particles",
            lumen_control=sw["lumen_control"],
            hourglass_factor=sw["hourglass_factor"],
        ),
        cases={name: sw["cases"][name] for name in dict.fromkeys(cases)},
        probe_length=sw["probe_length_um"],
        tip_probe=sw["tip_probe"],
    )


def run(params: Mapping, active: bool, name: str) -> pd.DataFrame:
    """Figure 4's protocol under one run's ``params`` (:func:`run_params`) in the passive or ``active`` wall: every
    pool's states (:func:`sphgag.studies.convergence.swell_cases`) measured (:func:`sphgag.studies.convergence.measure`,
    the tips of ``tip_probe``)."""
    p, numerics = params, Numerics.of(params["numerics"])
    states = convergence.swell_cases(
        p["dx"],
        p["bilayer"],
        numerics,
        p["homeostasis"],
        p["swelling"],
        p["gag"],
        p["cases"],
        p["pressure_mmHg"],
        p["calibration"],
        active,
        name,
    )
    wall = "active" if active else "passive"
    return convergence.measure(
        p["dx"],
        p["bilayer"],
        numerics,
        p["gag"],
        p["cases"],
        states,
        p["probe_length"],
        wall,
        name,
        tip_probe=p["tip_probe"],
    ).assign(charge_law=p["gag"]["charge_law"])


def ablation(tables: list[pd.DataFrame], concentrations, tolerance: float) -> pd.DataFrame:
    """``results/paper_settings/ablation.csv`` from the runs' tables (:func:`run`, each with its ``base`` and
    ``setting``): per run, wall and pool, at each of ``concentrations`` [mEq/l], figure 4's tip radial and top hoop
    stresses and the pool's volume ratio J with the state's residual; ``equilibrium`` is ``converged``, or why there
    is no number (the path ended below the concentration, or the state's residual exceeds ``tolerance``)."""
    rows = []
    for t in tables:
        for (base, setting, model, case), g in t.groupby(["base", "setting", "model", "case"], sort=False):
            path = g[g.stage == "converted"]
            last = g.iloc[-1]
            direction = base if setting == NONE else DIRECTIONS[base]
            for c in concentrations:
                at = path[np.isclose(path.concentration_mEq_l, c)]
                row = dict(
                    setting=setting,
                    direction=direction,
                    case=case,
                    model=model,
                    charge_law=last.charge_law,
                    concentration_mEq_l=float(c),
                    particles=int(last.particles),
                )
                values = dict(
                    tip_radial_stress_kPa=np.nan,
                    top_hoop_stress_kPa=np.nan,
                    volume_ratio=np.nan,
                    residual=np.nan,
                    pressure_mmHg=np.nan,
                )
                if not len(at):
                    reason = f"the path ends below it: {last.path_end}" + (
                        f", {last.end_reason}" if isinstance(last.end_reason, str) and last.end_reason else ""
                    )
                    rows.append(dict(row, **values, equilibrium=f"no equilibrium at {c:g} mEq/l ({reason})"))
                    continue
                s = at.iloc[-1]
                if not s.residual <= tolerance:
                    rows.append(dict(row, **values, equilibrium=f"not converged (residual {s.residual:.2g})"))
                    continue
                rows.append(
                    dict(
                        row,
                        tip_radial_stress_kPa=s.tip_radial_stress_kPa,
                        top_hoop_stress_kPa=s.top_circ_stress_kPa,
                        volume_ratio=s.pool_volume_change + 1.0,
                        residual=s.residual,
                        pressure_mmHg=s.pressure_mmHg,
                        equilibrium="converged",
                    )
                )
    return pd.DataFrame(rows, columns=COLUMNS)


def steps(table: pd.DataFrame, concentration: float, quantity: str = "tip_radial_stress_kPa") -> pd.DataFrame:
    """The step each setting makes from the script's value to ours in ``quantity`` at ``concentration``, per wall and
    pool, read both ways: ``from_script`` = (script's configuration, that setting ours) - (script's),
    ``from_ours`` = (ours) - (ours, that setting the script's); and ``share``: the step over the whole difference
    ours - script's (NaN where a state has no number)."""
    at = table[np.isclose(table.concentration_mEq_l, concentration)]
    value = at.set_index(["setting", "direction", "model", "case"])[quantity]
    rows = []
    for (model, case), g in at.groupby(["model", "case"], sort=False):
        base = {b: value.get((NONE, b, model, case), np.nan) for b in BASES}
        whole = base["ours"] - base["script"]
        for setting in dict.fromkeys(g.setting[g.setting != NONE]):
            for b, direction in DIRECTIONS.items():
                switched_value = value.get((setting, direction, model, case), np.nan)
                step = switched_value - base[b] if b == "script" else base[b] - switched_value
                rows.append(
                    dict(
                        setting=setting,
                        direction=direction,
                        model=model,
                        case=case,
                        concentration_mEq_l=float(concentration),
                        quantity=quantity,
                        step=step,
                        share=step / whole if whole else np.nan,
                        script=base["script"],
                        ours=base["ours"],
                    )
                )
    return pd.DataFrame(rows)


def ranked(table: pd.DataFrame, concentration: float) -> pd.DataFrame:
    """The settings by how much of the difference between the two configurations their step accounts for in the tip
    radial stress at ``concentration`` (:func:`steps`): per setting, the median over walls, pools and directions of
    ``share`` (the step over ours - the authors'; negative: a step away from ours) and of ``|step|``, the largest
    share first."""
    s = steps(table, concentration)
    if not len(s):
        return pd.DataFrame(columns=["setting", "abs_step_kPa", "share"])
    g = s.assign(abs_step_kPa=s.step.abs()).groupby("setting", sort=False)
    out = g.agg(abs_step_kPa=("abs_step_kPa", "median"), share=("share", "median")).reset_index()
    return out.sort_values("share", ascending=False, na_position="last").reset_index(drop=True)
