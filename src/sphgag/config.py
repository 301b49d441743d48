"""Configuration: load YAML, validate against the JSON schema, explain what is wrong.

Every key of ``config/config.yaml`` is declared in ``config/schema.yaml`` with
its type, range and description; unknown keys are errors (a typo must not be
silently ignored). :func:`validate` collects *all* problems and raises one
:class:`ConfigError` whose message names each bad key, its value, the
allowed range and what the key means.

The relations between keys that a JSON schema cannot express (a pool inside the media, a pressure with a saved state,
values that name distinct files, ...) are checked by each section's typed options, beside the concept they configure
(:data:`SECTIONS`, :meth:`sphgag.options.Options.problems`), once the configuration satisfies the schema; the checks
the variants' registries own (pool models, onset criteria) are :func:`_variants`.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import jsonschema
import yaml

from .engine import forces, loading, measure
from .engine.geometry import Grading
from .engine.numerics import Numerics
from .options import key_text
from .physics import damage, donnan, volumetric
from .physics.materials import GagSection
from .studies import annulus, artery
from .studies.artery import Bilayer, Mean
from .studies.delamination import settings as delamination_settings
from .studies.delamination.section import Delamination
from .studies.paper_procedure import PaperProcedure
from .studies.paper_settings import PaperSettings
from .studies.pool_response import Sensitivity
from .studies.pool_swelling import POOL_MODELS
from .studies.pressure_diameter import Calibration
from .studies.sensitivity import SENSITIVITY_METHODS
from .studies.swelling import Swelling, SwellingConvergence
from .studies.verification import Verification
from .studies.wall_loading import BilayerCalibration, HomeostasisSettings


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
    key = key_text(error.absolute_path)
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
                out.append(f"key {key_text(path + (str(k),))!r} must be a name, not a number: write '{k}' in quotes")
            out += _literal_problems(v, path + (str(k),))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += _literal_problems(v, path + (i,))
    elif isinstance(node, float) and not math.isfinite(node):
        out.append(f"{key_text(path)} = {node} is not a finite number")
    return out


def _registries() -> dict:
    """The schema's enumerations that sphgag's registries (:class:`sphgag.registry.Registry`) define, by the path of
    their key (a list of names, one name, or a mapping's keys): a new variant is an entry of its registry, and the
    configuration accepts it with no edit of the schema."""
    return {
        ("numerics", "hourglass"): forces.HOURGLASS_FORMS,
        ("numerics", "stress_recovery"): measure.RECOVERIES,
        ("numerics", "lumen_load"): loading.LUMEN_LOADS,
        ("gag", "charge_laws"): donnan.CHARGE_LAWS,
        ("gag", "volumetric"): volumetric.VOLUMETRIC_FORMS,
        ("swelling", "pool_models"): POOL_MODELS,
        ("swelling", "variant_pool_models"): POOL_MODELS,
        ("delamination", "criteria"): delamination_settings.CRITERIA,
        ("delamination", "candidates"): delamination_settings.CANDIDATE_RULES,
        ("delamination", "damage_law"): damage.DAMAGE_LAWS,
        ("verification", "circular_pool", "pool_models"): POOL_MODELS,
        ("verification", "annulus", "pool_models"): annulus.ANNULUS_POOL_MODELS,
        ("verification", "profiles", "lumen_loads"): loading.LUMEN_LOADS,
        ("verification", "profiles", "recoveries"): measure.RECOVERIES,
        ("sensitivity", "methods"): SENSITIVITY_METHODS,
    }


def schema(schema_path) -> dict:
    """The schema at ``schema_path`` with the enumerations of sphgag's registries (:func:`_registries`), and each
    variant's title (the paper's marked) after its key's description."""
    out = load_yaml(schema_path)
    for path, registry in _registries().items():
        node = out
        for key in path:
            node = node["properties"][key]
        # a list's items, a mapping's keys (propertyNames) or the key's one value
        (node.get("items") or node.get("propertyNames") or node)["enum"] = list(registry)
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
        problems = [_describe(e, schema_) for e in errors] if errors else _consistency(config, schema_)
    if problems:
        lines = "\n".join(f"  - {p}" for p in problems)
        raise ConfigError(f"invalid configuration ({Path(schema_path).name}):\n{lines}")
    return config


def _pool_models(config: dict) -> list[str]:
    """Each pool model of the swelling runs (figure 4's and the variants') passes its own check
    (:meth:`sphgag.studies.pool_swelling.PoolModel.check`: it carries one of the configured charge laws), and a
    variant is not also one of figure 4's."""
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


def _delamination(config: dict) -> list[str]:
    """The section's damage law and each onset criterion pass their own checks (:meth:`sphgag.physics.damage.Law.check`:
    a law the section can grow by; :meth:`sphgag.studies.delamination.settings.OnsetCriterion.check`: one that
    averages does so over more than one particle at the coarsest spacing it is run at)."""
    de = config.get("delamination", {})
    if not de:
        return []
    law = damage.DAMAGE_LAWS.problems(config, "delamination.damage_law", de["damage_law"])
    return law + delamination_settings.CRITERIA.problems(config, "delamination.criteria", de["criteria"])


def _variants(config: dict) -> list[str]:
    """The checks the variants' registries own: the pool models' (:func:`_pool_models`), the onset criteria's
    (:func:`_delamination`) and the sensitivity methods' (their settings)."""
    methods = config.get("sensitivity", {}).get("methods", {})
    return (
        _pool_models(config)
        + _delamination(config)
        + SENSITIVITY_METHODS.problems(config, "sensitivity.methods", methods)
    )


#: the options of every section of the configuration, in its order: each checks the relations between its keys and
#: the rest of the configuration (:meth:`sphgag.options.Options.problems`)
SECTIONS = (
    Numerics,
    Grading,
    Mean,
    Calibration,
    Bilayer,
    HomeostasisSettings,
    BilayerCalibration,
    GagSection,
    Swelling,
    SwellingConvergence,
    Delamination,
    Verification,
    PaperProcedure,
    PaperSettings,
    Sensitivity,
)


def _consistency(config: dict, schema_: dict) -> list[str]:
    """Relations between keys that a JSON schema cannot express, checked by each section's options (:data:`SECTIONS`)
    and the variants (:func:`_variants`); the pools' particles are counted (which builds layouts) only for a
    configuration the other checks vouch for, and the sensitivity inputs, which refer to keys those checks vouch for
    (e.g. figure 5's pool), are checked last against their keys' ranges in ``schema_``."""
    problems = [p for options in SECTIONS for p in options.problems(config)] + _variants(config)
    if not problems and config.get("bilayer"):
        problems = artery.empty_pools(config)
    if not problems:
        problems = Sensitivity.input_problems(config, functools.partial(_subschema, schema_))
    return problems
