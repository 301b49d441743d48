"""Configuration: load YAML, validate against the JSON schema, explain what is wrong.

Every key of ``config/config.yaml`` is declared in ``config/schema.yaml`` with
its type, range and description; unknown keys are errors (a typo must not be
silently ignored). :func:`validate` collects *all* problems and raises one
:class:`ConfigError` whose message names each bad key, its value, the
allowed range and what the key means.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import jsonschema
import yaml


class ConfigError(ValueError):
    """The configuration does not satisfy the schema."""


class _UniqueKeyLoader(yaml.SafeLoader):
    """A YAML loader that refuses duplicate keys (plain YAML lets the last one win silently)."""

    def construct_mapping(self, node, deep=False):
        seen = set()
        for key_node, _ in node.value:
            key = self.construct_object(key_node, deep=deep)
            if key in seen:
                raise ConfigError(
                    f"duplicate key {key!r} at line {key_node.start_mark.line + 1} of {key_node.start_mark.name}"
                )
            seen.add(key)
        return super().construct_mapping(node, deep)


def load_yaml(path) -> dict:
    """Read a YAML file; duplicate keys are an error."""
    with open(path) as fh:
        return yaml.load(fh, Loader=_UniqueKeyLoader) or {}


def _key(path) -> str:
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out or "<top level>"


def _subschema(schema: dict, path) -> dict:
    """The schema node of a config key (following ``$ref``s and the schemas of named entries)."""

    def resolve(node):
        while isinstance(node, dict) and "$ref" in node:
            node = schema["$defs"][node["$ref"].split("/")[-1]]
        return node

    node = resolve(schema)
    for part in path:
        if isinstance(part, int):
            node = resolve(node.get("items", {}))
        else:
            extra = node.get("additionalProperties")
            node = resolve(node.get("properties", {}).get(part, extra if isinstance(extra, dict) else {}))
    return node


def _describe(error: jsonschema.ValidationError, schema: dict) -> str:
    key = _key(error.absolute_path)
    node = _subschema(schema, error.absolute_path)
    if error.validator == "additionalProperties":
        allowed = ", ".join(sorted(error.schema.get("properties", {})))
        extra = sorted(set(error.instance) - set(error.schema.get("properties", {})))
        where = f"{key}." if error.absolute_path else ""
        return f"unknown key {', '.join(repr(where + e) for e in extra)} (allowed here: {allowed})"
    if error.validator == "required":
        missing = error.message.split("'")[1] if "'" in error.message else error.message
        where = f"{key}." if error.absolute_path else ""
        return f"missing key '{where}{missing}'"
    bounds = []
    for word, sym in (("minimum", ">="), ("exclusiveMinimum", ">"), ("maximum", "<="), ("exclusiveMaximum", "<")):
        if word in node:
            bounds.append(f"{sym} {node[word]}")
    allowed = f" (allowed: {node.get('type', 'value')} {' and '.join(bounds)})" if bounds else ""
    if "enum" in node:
        allowed = f" (allowed: one of {node['enum']})"
    desc = f" -- {node['description']}" if "description" in node else ""
    hint = ""
    if error.validator == "type" and isinstance(error.instance, str):
        try:
            value = float(error.instance)
        except ValueError:
            pass
        else:
            if "e" in error.instance.lower() and "." not in error.instance.lower().partition("e")[0]:
                # YAML 1.1 reads 1e-4 (no dot in the mantissa) as text
                hint = (
                    f" (YAML reads {error.instance} as text, not as the number {value!r}: write "
                    f"{_yaml_float(error.instance)})"
                )
            else:
                hint = f" (the number {value!r} was given as text: write it without quotes)"
    return f"{key} = {error.instance!r} is invalid: {error.message}{hint}{allowed}{desc}"


def _yaml_float(text: str) -> str:
    mantissa, _, exponent = text.lower().partition("e")
    if "." not in mantissa:
        mantissa += ".0"
    return mantissa + ("e" + exponent if exponent else "")


def typed_overrides(overrides):
    """The ``--config`` overrides with nested values read as YAML would read them in a file.

    Snakemake parses a nested ``--config section='{key: 0.001}'`` with YAML's base loader, which keeps
    every scalar as text; top-level values it already types itself and are left alone.
    """

    def typed(node):
        if isinstance(node, dict):
            return {k: typed(v) for k, v in node.items()}
        if isinstance(node, list):
            return [typed(v) for v in node]
        return yaml.safe_load(node) if isinstance(node, str) else node

    return {k: typed(v) if isinstance(v, (dict, list)) else v for k, v in dict(overrides or {}).items()}


def canonical(config):
    """The same configuration with every mapping's keys sorted (so that key order never matters)."""
    if isinstance(config, dict):
        return {k: canonical(config[k]) for k in sorted(config)}
    if isinstance(config, list):
        return [canonical(v) for v in config]
    return config


# JSON Schema's "integer" accepts 30.0 and its "number" accepts True; in a config they are mistakes
# (``range(30.0)`` fails long after validation), so only Python ints are integers and bools are neither.
_TYPES = jsonschema.Draft202012Validator.TYPE_CHECKER.redefine_many(
    {
        "integer": lambda _, v: isinstance(v, int) and not isinstance(v, bool),
        "number": lambda _, v: isinstance(v, (int, float)) and not isinstance(v, bool),
    }
)
_Validator = jsonschema.validators.extend(jsonschema.Draft202012Validator, type_checker=_TYPES)


def _literal_problems(node, path=()) -> list[str]:
    """What JSON Schema cannot see: mapping keys that are not text (YAML reads ``1:`` as an integer) and
    non-finite numbers (``.nan`` and ``.inf`` pass every range check)."""
    out = []
    if isinstance(node, dict):
        for k, v in node.items():
            if not isinstance(k, str):
                out.append(f"key {_key(path + (str(k),))!r} must be a name, not a number: write '{k}' in quotes")
            out += _literal_problems(v, path + (str(k),))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += _literal_problems(v, path + (i,))
    elif isinstance(node, float) and not math.isfinite(node):
        out.append(f"{_key(path)} = {node} is not a finite number")
    return out


def _registries() -> dict:
    """The schema's enumerations that sphgag's registries (:class:`sphgag.registry.Registry`) define, by the path of
    their key (a list of names or one name): a new variant is an entry of its registry, and the configuration accepts
    it with no edit of the schema."""
    from .engine import hourglass
    from .physics import donnan
    from .studies import annulus
    from .studies.candidates import RULES
    from .studies.onset import CRITERIA
    from .studies.protocols import POOL_MODELS

    return {
        ("numerics", "hourglass"): hourglass.FORMS,
        ("gag", "charge_laws"): donnan.LAWS,
        ("swelling", "pool_models"): POOL_MODELS,
        ("swelling", "variant_pool_models"): POOL_MODELS,
        ("delamination", "criteria"): CRITERIA,
        ("delamination", "candidates"): RULES,
        ("verification", "circular_pool", "pool_models"): POOL_MODELS,
        ("verification", "annulus", "pool_models"): annulus.POOL_MODELS,
    }


def schema(schema_path) -> dict:
    """The schema at ``schema_path`` with the enumerations of sphgag's registries (:func:`_registries`), and each
    variant's title (the paper's marked) after its key's description."""
    out = load_yaml(schema_path)
    for path, registry in _registries().items():
        node = out
        for key in path:
            node = node["properties"][key]
        (node["items"] if "items" in node else node)["enum"] = list(registry)
        titles = "; ".join(f"{n}: {v.title}" + (" [the paper's]" if v.paper else "") for n, v in registry.items())
        node["description"] = f"{node.get('description', '')}. One of: {titles}"
    return out


def validate(config: dict, schema_path) -> dict:
    """Validate ``config`` against the schema at ``schema_path`` (:func:`schema`); return it or raise
    :class:`ConfigError`."""
    schema_ = schema(schema_path)
    if not isinstance(config, dict):
        raise ConfigError(f"invalid configuration: expected a mapping of sections, got {type(config).__name__}")
    problems = _literal_problems(config)
    if not problems:
        validator = _Validator(schema_)
        errors = sorted(validator.iter_errors(config), key=lambda e: list(map(str, e.absolute_path)))
        problems = [_describe(e, schema_) for e in errors] if errors else _consistency(config)
        if not problems:  # the sensitivity inputs refer to keys the checks above vouch for (e.g. figure 5's pool)
            problems = _sensitivity(config, schema_)
    if problems:
        lines = "\n".join(f"  - {p}" for p in problems)
        raise ConfigError(f"invalid configuration ({Path(schema_path).name}):\n{lines}")
    return config


def _empty_pools(config: dict) -> list[str]:
    """Pools that hold no particle of a pool layer (the media) at a resolution they are run at (too thin or too
    narrow for dx)."""
    from .studies import artery

    bil, out, layouts = config["bilayer"], [], {}
    sw, de = config.get("swelling", {}), config.get("delamination", {})
    runs = [(f"swelling.cases.{n}", pool, bil["dx_um"]) for n, pool in sw.get("cases", {}).items()]
    runs += [
        (f"swelling.cases.{n}", sw["cases"][n], dx)
        for n in config.get("swelling_convergence", {}).get("cases", [])
        for dx in config["swelling_convergence"]["dx_um"]
        if n in sw.get("cases", {})
    ]
    study = de.get("figures", {}).get("fig5")  # figure 5's set is also the set of the resolution study
    for name, pools in de.get("pool_sets", {}).items():
        spacings = [bil["dx_um"]] + (de["convergence"]["dx_um"] if name == study else [])
        runs += [(f"delamination.pool_sets.{name}[{k}]", pool, dx) for k, pool in enumerate(pools) for dx in spacings]
    for name, pool, dx in runs:
        if dx not in layouts:
            layouts[dx] = artery.bilayer_layout(dict(bil, dx_um=dx))
        if not artery.pool_sector(pool).members(layouts[dx], layer=layouts[dx].pool_layers).size:
            out.append(
                f"{name}: the pool holds no particle of a pool layer at dx = {dx:g} um (it is "
                f"{pool['radial_extent_um']:g} um by {pool['angular_extent_deg']:g} deg): make it larger than "
                "the particle spacing"
            )
    return sorted(set(out))


THINNEST_LAYER = 0.1  # a layer (or sub-layer) as thin as this fraction of the spacing still gets its own ring


def _thin_layers(config: dict) -> list[str]:
    """Layers (and sub-layers between ``aligned_radii_um``) thinner than a tenth of the largest particle spacing they
    are run at. Every layer gets at least one ring of particles (a lamina one particle thick is fine: the three-layer
    wall of tests/test_bilayer.py matches its exact tube); below a tenth its cell is a sliver (or, below round-off,
    nothing at all)."""
    out = []
    m = config.get("mean", {})
    if {"inner_radius_um", "outer_radius_um", "dx_um"} <= set(m) and m["outer_radius_um"] > m["inner_radius_um"]:
        if m["outer_radius_um"] - m["inner_radius_um"] < m["dx_um"] / 2:
            out.append(
                f"mean.outer_radius_um - mean.inner_radius_um = {m['outer_radius_um'] - m['inner_radius_um']:g} um "
                f"must be at least half the particle spacing mean.dx_um = {m['dx_um']:g} um"
            )
    bil = config.get("bilayer", {})
    if not {"inner_radius_um", "layers", "dx_um"} <= set(bil):
        return out
    spacings = [("bilayer.dx_um", bil["dx_um"])]
    spacings += [("swelling_convergence.dx_um", dx) for dx in config.get("swelling_convergence", {}).get("dx_um", [])]
    de_conv = config.get("delamination", {}).get("convergence", {})
    spacings += [("delamination.convergence.dx_um", dx) for dx in de_conv.get("dx_um", [])]
    source, dx = max(spacings, key=lambda item: item[1])
    from .studies.artery import Bilayer

    layers = []
    for k, (name, a, b) in enumerate(Bilayer.of(bil).bands()):
        edges = sorted({a, b, *(x for x in bil.get("aligned_radii_um", []) if a < x < b)})
        if len(edges) <= 2:  # one edge: the band is thinner than round-off
            layers.append((f"bilayer.layers[{k}].thickness_um ({name})", bil["layers"][k]["thickness_um"]))
        else:
            sub = [(f"the {name} sub-layer {lo:g}-{hi:g} um", hi - lo) for lo, hi in zip(edges, edges[1:])]
            layers += [(f"bilayer.aligned_radii_um: {text}", t) for text, t in sub]
    for name, thickness in layers:
        if thickness < THINNEST_LAYER * dx:
            out.append(
                f"{name} = {thickness:g} um is thinner than a tenth of the largest particle spacing it is run at "
                f"({source} = {dx:g} um)"
            )
    return out


def _wall(bil: dict) -> list[str]:
    """The layered wall of ``bilayer``: every layer named in ``layers`` has its mass fractions and orientations (and no
    others are given), the pool layers are layers of the wall, a layer has at most ``MAX_FAMILIES`` fibre families,
    and the aligned radii lie inside the wall."""
    from .physics.materials import MAX_FAMILIES

    problems, names = [], list(dict.fromkeys(band["name"] for band in bil.get("layers", [])))
    for key in ("mass_fractions", "orientations", "pool_layers"):
        given = bil.get(key, {})
        for name in given:
            if name not in names:
                problems.append(f"bilayer.{key}.{name} is not a layer of bilayer.layers ({', '.join(names)})")
        if key != "pool_layers":
            problems += [
                f"missing key 'bilayer.{key}.{n}': every layer of bilayer.layers needs it"
                for n in names
                if n not in given
            ]
    for name in names:
        frac, beta = bil.get("mass_fractions", {}).get(name, {}), bil.get("orientations", {}).get(name, {})
        families = 3 + int("smc" in frac) + int("circumferential" in beta)  # axial and +-diagonal collagen, ...
        if families > MAX_FAMILIES:
            problems.append(
                f"bilayer.mass_fractions.{name}.smc and bilayer.orientations.{name}.circumferential: a layer "
                f"carries at most {MAX_FAMILIES} fibre families (SMC or circumferential collagen, axial, two diagonal)"
            )
    from .studies.artery import bilayer_interfaces

    edges = bilayer_interfaces(bil)
    r_in, r_out = edges[0], edges[-1]
    for k, r in enumerate(bil.get("aligned_radii_um", [])):
        if not r_in < r < r_out:
            problems.append(f"bilayer.aligned_radii_um[{k}] = {r} is not inside the wall ({r_in:g}-{r_out:g} um)")
    return problems


def _pool_span(bil: dict, lo: float, hi: float) -> str | None:
    """``None`` if the radii ``lo``-``hi`` lie in one span of pool layers, else the spans as text."""
    from .studies import artery

    spans = artery.pool_spans(bil)
    if any(a <= lo and hi <= b for a, b in spans):
        return None
    return f"the pool layers {', '.join(bil['pool_layers'])} ({'; '.join(f'{a:g}-{b:g}' for a, b in spans)} um)"


def _pool_set_roles(de: dict) -> list[str]:
    """Every figure's pool set (``delamination.figures``) and every set of the resolution study
    (``delamination.convergence.pool_sets``) exists in ``delamination.pool_sets``, and a set that figures 6-7 share
    with figure 5 is run at their sigma_cr (figure 5's set runs at ``critical_stresses_kPa`` only)."""
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
                    f"delamination.critical_stress_kPa = {de['critical_stress_kPa']}: give the figure a set of its own"
                )
    for k, name in enumerate(de.get("convergence", {}).get("pool_sets", [])):
        if name not in sets:
            out.append(
                f"delamination.convergence.pool_sets[{k}] = {name!r} is not a pool set of delamination.pool_sets "
                f"({', '.join(sets)}): the resolution study would have no such set to grow"
            )
    return out


def _pool_radii(pool: dict) -> tuple[float, float]:
    """Inner and outer reference radius [um] of a pool entry."""
    return (
        pool["centre_radius_um"] - pool["radial_extent_um"] / 2,
        pool["centre_radius_um"] + pool["radial_extent_um"] / 2,
    )


def _pool_angles(pool: dict) -> tuple[float, float]:
    """First and last angle [deg] of a pool entry."""
    half = pool["angular_extent_deg"] / 2
    return pool["centre_angle_deg"] - half, pool["centre_angle_deg"] + half


def _pool_models(config: dict) -> list[str]:
    """Each pool model of the swelling runs (figure 4's and the variants') passes its own check
    (:meth:`sphgag.studies.protocols.PoolModel.check`: it carries one of the configured charge laws), and a variant is
    not also one of figure 4's."""
    from .studies.protocols import POOL_MODELS

    swelling = config.get("swelling", {})
    problems = [
        p
        for key in ("pool_models", "variant_pool_models")
        for p in POOL_MODELS.problems(config, f"swelling.{key}", swelling.get(key, []))
    ]
    return problems + [
        f"swelling.variant_pool_models[{k}] = {name!r} is one of swelling.pool_models: it runs in target all already"
        for k, name in enumerate(swelling.get("variant_pool_models", []))
        if name in swelling.get("pool_models", [])
    ]


def _pressures(config: dict) -> list[str]:
    """The mean wall's radii, the calibration pressures below their sweep's top, and a saved state at every pressure a
    later stage starts from."""
    problems = []
    m = config.get("mean", {})
    if m.get("outer_radius_um", 0) <= m.get("inner_radius_um", 0):
        problems.append(
            f"mean.outer_radius_um = {m.get('outer_radius_um')} must exceed "
            f"mean.inner_radius_um = {m.get('inner_radius_um')}"
        )
    for section, key in (
        ("calibration", "transmural_pressures_mmHg"),
        ("bilayer_calibration", "state_pressures_mmHg"),
        ("bilayer_calibration", "activation_pressure_mmHg"),
    ):
        cal = config.get(section, {})
        top = cal.get("max_pressure_mmHg", 0)
        values = cal.get(key, [])
        for k, p in enumerate(values if isinstance(values, list) else [values]):
            if p > top:
                where = f"{section}.{key}" + (f"[{k}]" if isinstance(values, list) else "")
                problems.append(f"{where} = {p} exceeds {section}.max_pressure_mmHg = {top}")
    saved = config.get("bilayer_calibration", {}).get("state_pressures_mmHg", [])
    starts = [
        (f"swelling.pressures_mmHg[{k}]", p) for k, p in enumerate(config.get("swelling", {}).get("pressures_mmHg", []))
    ]
    if "pressure_mmHg" in config.get("delamination", {}):
        starts.append(("delamination.pressure_mmHg", config["delamination"]["pressure_mmHg"]))
    problems += [
        f"{key} = {p} has no saved state: it must be one of bilayer_calibration.state_pressures_mmHg = {saved}"
        for key, p in starts
        if p not in saved
    ]
    return problems


def _composition(config: dict) -> list[str]:
    """The layered wall (:func:`_wall`), each layer's mass fractions and orientations summing to 1, and the active
    tone's stretches in order."""
    bil = config.get("bilayer", {})
    problems = _wall(bil) if bil else []
    for layer, beta in bil.get("orientations", {}).items():
        if abs(sum(beta.values()) - 1.0) > 1e-6:
            problems.append(
                f"bilayer.orientations.{layer} must sum to 1 (beta factors of Table 2), got {sum(beta.values()):.6g}"
            )
    for layer, frac in bil.get("mass_fractions", {}).items():
        if abs(sum(frac.values()) - 1.0) > 1e-6:
            problems.append(f"bilayer.mass_fractions.{layer} must sum to 1, got {sum(frac.values()):.6g}")
    act = bil.get("active", {})
    if act and act.get("stretch_min", 0) >= act.get("stretch_max", 1):
        problems.append(
            f"bilayer.active.stretch_min = {act.get('stretch_min')} must be below "
            f"bilayer.active.stretch_max = {act.get('stretch_max')}"
        )
    return problems


def _swelling(config: dict) -> list[str]:
    """The pool models carry a configured charge law, and the resolution study's cases are pools of the sweeps."""
    sw = config.get("swelling", {})
    problems = _pool_models(config)
    sc = config.get("swelling_convergence", {})
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
    pp = config.get("paper_procedure", {})
    for k, name in enumerate(pp.get("cases", [])):
        if name not in sw.get("cases", {}):
            pools = ", ".join(sw.get("cases", {}))
            problems.append(f"paper_procedure.cases[{k}] = {name!r} is not a pool of swelling.cases ({pools})")
    for name in pp.get("pool_sets", {}):
        if name not in config.get("delamination", {}).get("pool_sets", {}):
            problems.append(f"paper_procedure.pool_sets.{name} is not a set of delamination.pool_sets")
    ramp_ = pp.get("swelling", {})
    if ramp_.get("stop_concentration_mEq_l", 0.0) > ramp_.get("max_concentration_mEq_l", float("inf")):
        problems.append(
            f"paper_procedure.swelling.stop_concentration_mEq_l = {ramp_['stop_concentration_mEq_l']:g} is above the "
            f"ramp's top, paper_procedure.swelling.max_concentration_mEq_l = {ramp_['max_concentration_mEq_l']:g}"
        )
    if "max_concentration_mEq_l" in sw and "concentration_points" in sw:
        top, points = sw["max_concentration_mEq_l"], sw["concentration_points"]
        ramp = [top * i / (points - 1) for i in range(points)]
        for k, c in enumerate(sc.get("gci_concentrations_mEq_l", [])):
            if not any(abs(v - c) < 1e-9 for v in ramp):
                steps = ", ".join(f"{v:g}" for v in ramp[1:])
                problems.append(
                    f"swelling_convergence.gci_concentrations_mEq_l[{k}] = {c:g} is not a step of the swelling ramp "
                    f"({steps} mEq/l)"
                )
    return problems


def _file_names(config: dict) -> list[str]:
    """Values that name files ({pressure}mmHg, dx{dx}, {sigma}kPa) give distinct names."""
    problems = []
    named = [
        ("bilayer_calibration", "state_pressures_mmHg"),
        ("calibration", "transmural_pressures_mmHg"),
        ("swelling", "pressures_mmHg"),
        ("swelling_convergence", "dx_um"),
        ("paper_procedure", "step_factors"),
        ("delamination", "critical_stresses_kPa"),
    ]
    for section, key in named:
        values = config.get(section, {}).get(key, [])
        names = [f"{v:g}" for v in values]
        for name in sorted({n for n in names if names.count(n) > 1}):
            same = [v for v, n in zip(values, names) if n == name]
            problems.append(f"{section}.{key}: {same} all give the file name '{name}': make them differ by more")
    de_dx = [f"{v:g}" for v in config.get("delamination", {}).get("convergence", {}).get("dx_um", [])]
    if len(set(de_dx)) < len(de_dx):
        problems.append(f"delamination.convergence.dx_um: {de_dx} repeat a file name (dx{{dx}}): make them differ")
    return problems


def _delamination(config: dict) -> list[str]:
    """Every figure's pool set exists, and each onset criterion passes its own check
    (:meth:`sphgag.studies.onset.OnsetCriterion.check`: one that averages does so over more than one particle at the
    coarsest spacing it is run at)."""
    from .studies.onset import CRITERIA

    de = config.get("delamination", {})
    if not de:
        return []
    return _pool_set_roles(de) + CRITERIA.problems(config, "delamination.criteria", de["criteria"])


def _pool_placement(config: dict) -> list[str]:
    """Every pool (figure 4's cases, the delamination sets) lies inside one span of pool layers and off the symmetry
    edges (once the wall itself is sound)."""
    bil = config.get("bilayer", {})
    if not bil or _wall(bil):
        return []
    pools = {f"swelling.cases.{name}": pool for name, pool in config.get("swelling", {}).get("cases", {}).items()}
    for name, members in config.get("delamination", {}).get("pool_sets", {}).items():
        pools.update({f"delamination.pool_sets.{name}[{k}]": pool for k, pool in enumerate(members)})
    problems = []
    for name, pool in pools.items():
        lo, hi = _pool_radii(pool)
        if spans := _pool_span(bil, lo, hi):
            problems.append(f"{name}: radii {lo:g}-{hi:g} um leave {spans}")
        first, last = _pool_angles(pool)
        if first <= 0 or last >= 90:
            problems.append(f"{name}: angles {first:g}-{last:g} deg reach a symmetry edge (0 or 90 deg)")
    return problems


def _consistency(config: dict) -> list[str]:
    """Relations between keys that a JSON schema cannot express, one check per concern; the pools' particles are
    counted (which builds layouts) only for a configuration the other checks vouch for."""
    checks = (_pressures, _composition, _swelling, _file_names, _delamination, _pool_placement, _thin_layers)
    problems = [p for check in checks for p in check(config)]
    verification = config.get("verification", {})
    problems += _circular_pool(verification.get("circular_pool", {}))
    problems += _annulus(verification.get("annulus", {}))
    if not problems and config.get("bilayer"):
        problems += _empty_pools(config)
    return problems


def sensitivity_config_key(config: dict, path: str) -> tuple:
    """The configuration key a sensitivity input (a dotted path into
    :mod:`sphgag.studies.pool_response`'s scenario) sets: ``pool.*`` is figure 5's pool (the first of
    ``delamination.figures.fig5``'s set), the other sections are the configuration's own."""
    section, *rest = path.split(".")
    if section == "pool":
        return ("delamination", "pool_sets", config["delamination"]["figures"]["fig5"], 0, *rest)
    return (section, *rest)


def _bounds_text(node: dict) -> tuple[list, str]:
    tests, words = [], []
    for word, sym, ok in (
        ("minimum", ">=", lambda v, b: v >= b),
        ("exclusiveMinimum", ">", lambda v, b: v > b),
        ("maximum", "<=", lambda v, b: v <= b),
        ("exclusiveMaximum", "<", lambda v, b: v < b),
    ):
        if word in node:
            tests.append((ok, node[word]))
            words.append(f"{sym} {node[word]}")
    return tests, " and ".join(words)


def _circular_pool(vc: dict) -> list[str]:
    """The large-strain verification's annulus: at least twice the pool's radius, and particles small enough to
    put two rings in the pool."""
    problems = []
    where = "verification.circular_pool"
    A, B = vc.get("radius_um", 0.0), vc.get("outer_radius_um", 0.0)
    if B < 2.0 * A:
        problems.append(f"{where}.outer_radius_um = {B:g} must be at least twice {where}.radius_um = {A:g}")
    for k, dx in enumerate(vc.get("dx_um", [])):
        if dx > 0.5 * A:
            problems.append(f"{where}.dx_um[{k}] = {dx:g} must be at most half of {where}.radius_um = {A:g}")
    return problems


def _annulus(va: dict) -> list[str]:
    """The annulus verification: particles small enough to put two rings in the hole."""
    where, A = "verification.annulus", va.get("radius_um", 0.0)
    return [
        f"{where}.dx_um[{k}] = {dx:g} must be at most half of {where}.radius_um = {A:g}"
        for k, dx in enumerate(va.get("dx_um", []))
        if dx > 0.5 * A
    ]


def _sensitivity(config: dict, schema: dict) -> list[str]:
    """Every sensitivity input names a number of the configuration that a sample may set (sections ``bilayer``,
    ``numerics``, ``homeostasis``, ``gag``, ``delamination`` and figure 5's ``pool``), and its range lies inside that
    key's own allowed range (and, for the pool, inside the media and away from the symmetry edges); the stated
    concentration is a step of the swelling ramp; Sobol takes no more inputs than there are."""
    se = config.get("sensitivity")
    if not se:
        return []
    out = []
    sections = ("bilayer", "numerics", "homeostasis", "gag", "delamination", "pool")
    for path, r in se["inputs"].items():
        name = f"sensitivity.inputs.{path}"
        if path.split(".")[0] not in sections or path.startswith("delamination.pool_sets"):
            out.append(
                f"{name}: an input is a number of one of the sections {', '.join(sections)} (pool: figure 5's pool)"
            )
            continue
        key = sensitivity_config_key(config, path)
        try:
            node = functools.reduce(lambda parent, part: parent[part], key, config)
        except (KeyError, IndexError, TypeError):
            node = None
        if isinstance(node, bool) or not isinstance(node, (int, float)):
            out.append(f"{name}: {_key(key)} is not a number of the configuration")
            continue
        tests, text = _bounds_text(_subschema(schema, key))
        for end in ("low", "high"):
            if not all(ok(r[end], b) for ok, b in tests):
                out.append(f"{name}.{end} = {r[end]} is outside the allowed range of {_key(key)} ({text})")
        if not r["low"] < r["high"]:
            out.append(f"{name}: low = {r['low']} must be below high = {r['high']}")
    de, bil = config["delamination"], config["bilayer"]
    pool = de["pool_sets"][de["figures"]["fig5"]][0]
    radius = se["inputs"].get("pool.centre_radius_um", {})
    for end in ("low", "high"):
        if end in radius:
            lo, hi = _pool_radii(dict(pool, centre_radius_um=radius[end]))
            if spans := _pool_span(bil, lo, hi):
                out.append(
                    f"sensitivity.inputs.pool.centre_radius_um.{end} = {radius[end]}: the pool ({lo:g}-{hi:g} um) "
                    f"leaves {spans}"
                )
    widths = [("sensitivity.map.angular_extents_deg", w) for w in se["map"]["angular_extents_deg"]]
    widths += [
        (f"sensitivity.inputs.pool.angular_extent_deg.{e}", se["inputs"].get("pool.angular_extent_deg", {}).get(e))
        for e in ("low", "high")
    ]
    for name, w in widths:
        if w is None:
            continue
        first, last = _pool_angles(dict(pool, angular_extent_deg=w))
        if first <= 0 or last >= 90:
            out.append(
                f"{name} = {w}: figure 5's pool (centre {pool['centre_angle_deg']:g} deg) would reach a symmetry edge"
            )
    from .studies.protocols import concentration_steps

    steps = concentration_steps(config["swelling"])
    if not any(math.isclose(c, se["concentration_mEq_l"]) for c in steps):
        steps = ", ".join(f"{c:g}" for c in steps)
        out.append(
            f"sensitivity.concentration_mEq_l = {se['concentration_mEq_l']} must be a step of the swelling ramp "
            f"({steps})"
        )
    if se["sobol"]["inputs"] > len(se["inputs"]):
        out.append(
            f"sensitivity.sobol.inputs = {se['sobol']['inputs']} exceeds the number of inputs ({len(se['inputs'])})"
        )
    return out
