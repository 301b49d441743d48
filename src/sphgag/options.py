"""Typed options: sections of the validated configuration as small frozen dataclasses.

The package is entered with typed options: :class:`sphgag.engine.numerics.Numerics`,
:class:`sphgag.physics.materials.Gag` (one run's GAG), :class:`sphgag.studies.artery.Bilayer` and
:class:`sphgag.studies.delamination.settings.Settings` (one run's delamination settings). The pipeline keeps plain
dicts where rerun detection and provenance read them (Snakemake ``params``, the parameters a state file records). A
job builds its :class:`~sphgag.engine.numerics.Numerics` from them once, where it enters the package (its script, or
a study that reads a whole configuration: a sensitivity sample, a run under the authors' settings, the ParaView
export), and every function below takes them typed; the other options are built with ``of`` by the functions that
read them. A key the options do not know, or one they miss, raises naming it.

Every top-level section of the configuration has its options (``SECTION`` names it; :data:`sphgag.config.SECTIONS`
lists them), each in the module of the concept it configures. The relations between keys that the JSON schema cannot
express are checked beside them: :meth:`Options.problems` of each section's options reads the whole configuration
(once it satisfies the schema) and returns what is wrong, naming the keys; :func:`sphgag.config.validate` calls them
all.

**What a job reads.** A field of a section's options is, by default, a setting every job of the section reads. A field
declared with :func:`role` is not: a list the pipeline fans out over (:data:`FANS_OUT`: one job per value, its
wildcard), a key only a measurement reads (:data:`MEASUREMENT`), or a value shown beside the results and read by no
computation (:data:`REFERENCE`). :meth:`Options.job_settings` gives a job's slice of its section from these
declarations, so that the rules write no key filter of their own and a key read by no run reruns none.
"""

from __future__ import annotations

import typing
from collections.abc import Mapping
from dataclasses import MISSING, field, fields
from types import MappingProxyType

from .jobs import text

#: the roles of a section's keys that are not every job's settings (:func:`role`)
FANS_OUT, MEASUREMENT, REFERENCE = "fans out", "measurement", "reference"


def role(kind: str):
    """A field of a section's options that is no setting of its jobs: ``kind`` is :data:`FANS_OUT`, :data:`MEASUREMENT`
    or :data:`REFERENCE` (module docstring, "What a job reads")."""
    return field(metadata=dict(role=kind))


def _frozen(value):
    """Lists as tuples and mappings as read-only mappings, all the way down."""
    if isinstance(value, Mapping):
        return MappingProxyType({k: _frozen(v) for k, v in value.items()})
    if isinstance(value, list | tuple):
        return tuple(_frozen(v) for v in value)
    return value


def key_text(path) -> str:
    """A configuration key's path as text: ``section.key[index].key`` (``<top level>`` for the empty path)."""
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out or "<top level>"


def file_name_problems(section: str, key: str, values) -> list[str]:
    """The values of ``section.key`` that would give one file name (values name files by their wildcard text,
    :func:`sphgag.jobs.text`: pressures, spacings, step factors, critical stresses)."""
    problems, names = [], text(list(values))
    for name in sorted({n for n in names if names.count(n) > 1}):
        same = [v for v, n in zip(values, names) if n == name]
        problems.append(f"{section}.{key}: {same} all give the file name '{name}': make them differ by more")
    return problems


class Options:
    """Base of the typed options (frozen dataclasses): :meth:`of` builds one from a configuration section."""

    SECTION: typing.ClassVar[str] = ""

    @classmethod
    def problems(cls, config: Mapping) -> list[str]:
        """What is wrong with the relations between this section's keys and the rest of ``config``, a configuration
        that satisfies the schema (each message names the keys); none by default."""
        return []

    @classmethod
    def job_settings(cls, mapping: Mapping, *roles: str) -> dict:
        """The keys of the section ``mapping`` that a job of one run reads, in their order: its settings, and the keys
        of the roles ``roles`` (a measurement's job: :data:`MEASUREMENT`); not those it fans out over, nor references
        (:func:`role`)."""
        kinds = {f.name: f.metadata.get("role") for f in fields(cls)}
        return {k: v for k, v in mapping.items() if kinds[k] is None or kinds[k] in roles}

    @classmethod
    def keys_in(cls, mapping: Mapping) -> dict:
        """This class's keys out of the mapping ``mapping``, a section that holds them among others (a job that reads
        only these), in the order of its fields."""
        return {f.name: mapping[f.name] for f in fields(cls)}

    @classmethod
    def of(cls, value):
        """``value`` as options of this class: itself, or built from a mapping (:meth:`from_mapping`)."""
        return value if isinstance(value, cls) else cls.from_mapping(value, cls.SECTION)

    @classmethod
    def from_mapping(cls, mapping, where: str):
        """The options of the mapping ``mapping`` (named ``where`` in errors): every field's key and no other; a field
        whose type is itself :class:`Options` is built from its sub-mapping."""
        if not isinstance(mapping, Mapping):
            raise TypeError(f"{where}: expected a mapping of {cls.__name__}'s keys, got {type(mapping).__name__}")
        required = {f.name for f in fields(cls) if f.default is MISSING and f.default_factory is MISSING}
        known = {f.name for f in fields(cls)}
        unknown, missing = sorted(set(mapping) - known), sorted(required - set(mapping))
        if unknown or missing:
            problems = [f"unknown key {where}.{k}" for k in unknown] + [f"missing key {where}.{k}" for k in missing]
            raise ValueError(f"{cls.__name__}: {'; '.join(problems)}")
        hints = typing.get_type_hints(cls)
        values = {}
        for name, value in mapping.items():
            kind = hints[name]
            nested = isinstance(kind, type) and issubclass(kind, Options)
            values[name] = kind.from_mapping(value, f"{where}.{name}") if nested else _frozen(value)
        return cls(**values)
