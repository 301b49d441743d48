"""The pipeline's jobs: one typed object between a Snakemake rule and the package.

A :class:`Kind` declares one kind of job once: its rule, its run key (the pattern of wildcards that names its files)
and the types of its wildcards. The rules take their paths from it (:meth:`Kind.output`, :attr:`Kind.log`,
:attr:`Kind.benchmark`, :attr:`Kind.provenance`), and the job's script enters it with :func:`run`, which gives a
:class:`Job`: the job's name (the rule and the run key, as every log line and record names it), its wildcards as
typed values (a critical stress is a float from the rule to the package, never text), its threads (the rule's,
:func:`sphgag.threads.use`), its log (:func:`sphgag.records.runlog.run`) and its provenance record
(:meth:`Job.record`). A script is then only what its job computes.

The job layer sets a job up and records it; it computes no number and reads no state, so it is no job's code input
(``workflow/code_inputs.py``, ``BOOKKEEPING``): a script loads its start states itself
(:func:`sphgag.records.state.load`, checked against the configuration slice its rule passes), and so depends on the
code that reads them.

The kinds are registered by rule name (:data:`KINDS`, :func:`kind`); a kind's rule that runs under several rules
(one script, two rules) gives each rule its own kind.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from types import MappingProxyType, SimpleNamespace

from .. import plugins, threads
from ..records import provenance, runlog

#: the types of the wildcards that carry numbers (every other wildcard is a name, kept as text); a key's text is the
#: number's ``:g`` form, so that the text in a file name and the value a job reads are one quantity
NUMBERS: Mapping[str, type] = MappingProxyType(
    {
        "sigma": float,
        "dx": float,
        "dedx": float,
        "width": float,
        "factor": int,
        "batch": int,
        "ratio": float,
        "length": float,
        "level": int,
    }
)


def flat(key: str) -> str:
    """The run key ``key`` ("{law}/{run}") as one file name ("{law}_{run}")."""
    return "_".join(PurePosixPath(key).parts)


@dataclass(frozen=True)
class Kind:
    """One kind of job: the rule ``rule`` and the run key ``key`` (a pattern of wildcards, "{law}/{pool}/...") that
    names its files and its runs. ``prefix`` names its runs (the rule's name unless given: two rules that run one
    computation share it)."""

    rule: str
    key: str
    prefix: str | None = None
    #: the name of its benchmark and provenance files and of its log folder (the rule's unless given: a rule that
    #: shares its files' names with another, e.g. one stage of a study)
    stem: str | None = None
    #: the pattern of its log, where it is not ``logs/<stem>/<key>.log`` (the logs of one study in one folder)
    log_path: str | None = None

    def output(self, folder: str, suffix: str) -> str:
        """The path pattern of one output: ``results/<folder>/<key><suffix>`` (results nest by the key's parts)."""
        return f"results/{folder}/{self.key}{suffix}"

    @property
    def files(self) -> str:
        """The stem of its files' names: ``stem`` or the rule."""
        return self.stem or self.rule

    @property
    def log(self) -> str:
        return self.log_path or f"logs/{self.files}/{self.key}.log"

    @property
    def benchmark(self) -> str:
        return f"results/benchmarks/{self.files}_{flat(self.key)}.tsv"

    @property
    def provenance(self) -> str:
        return f"results/provenance/{self.files}_{flat(self.key)}.json"

    def name(self, wildcards: Mapping) -> str:
        """The name of the run with ``wildcards``: the prefix and the flat key ("swell_prescribed_particles_...")."""
        return f"{self.prefix or self.rule}_{flat(self.key.format(**wildcards))}"

    def flat_output(self, folder: str, name: str, suffix: str) -> str:
        """The path pattern of one output named by the flat key: ``results/<folder>/<name>_<flat key><suffix>``."""
        return f"results/{folder}/{name}_{flat(self.key)}{suffix}"


#: the kinds of job, by rule name (:func:`register`)
KINDS: dict[str, Kind] = {}


def register(*new: Kind) -> None:
    """Add the kinds ``new`` to :data:`KINDS` (a rule has one kind)."""
    for k in new:
        if k.rule in KINDS and KINDS[k.rule] != k:
            raise ValueError(f"rule {k.rule!r} already has a kind of job: {KINDS[k.rule]}")
        KINDS[k.rule] = k


def kind(rule: str) -> Kind:
    """The kind of job of rule ``rule`` (KeyError naming the registered rules for any other)."""
    try:
        return KINDS[rule]
    except KeyError:
        raise KeyError(f"rule {rule!r} has no kind of job: one of {', '.join(sorted(KINDS))}") from None


def text(value) -> str:
    """The wildcard text of a number (its ``:g`` form, as :data:`NUMBERS` reads it back), or of each number of a list:
    the one place a number becomes part of a file name."""
    if isinstance(value, list | tuple):
        return [text(v) for v in value]
    return f"{value:g}"


def typed(wildcards: Mapping) -> SimpleNamespace:
    """The wildcards ``wildcards`` with their values typed (:data:`NUMBERS`; names stay text)."""
    return SimpleNamespace(**{k: NUMBERS.get(k, str)(v) for k, v in wildcards.items()})


@dataclass
class Job:
    """One running job of the pipeline (built by :func:`run`): its Snakemake object ``sm``, its name, its typed
    wildcards ``w``, its logger ``log`` and when it started."""

    sm: object
    name: str
    w: SimpleNamespace
    log: object = None
    started: float = field(default_factory=time.time)

    @property
    def params(self):
        return self.sm.params

    @property
    def input(self):
        return self.sm.input

    @property
    def output(self):
        return self.sm.output

    def record(self, params: dict, summary: dict | None = None, rule: str | None = None, outputs=None) -> dict:
        """The job's provenance record (the output ``provenance``): its rule, params, outputs (its rule's unless
        given) and ``summary``."""
        return provenance.write_record(
            self.sm.output.provenance,
            rule=rule or self.sm.rule,
            params=params,
            outputs=list(self.sm.output) if outputs is None else outputs,
            summary=summary,
            started=self.started,
        )


@contextmanager
def run(sm, name: str | None = None):
    """Enter the job of the Snakemake object ``sm``: its rule's threads, its log and its name: ``name`` if given, else
    its kind's (:func:`kind`), else, for a rule with no wildcards and no kind, the rule's; with the configuration's
    plug-ins registered (:mod:`sphgag.plugins`). Yields the :class:`Job`."""
    started = time.time()
    plugins.load_exported()  # the configuration's own variants (key plugins), in this job's process
    threads.use(sm.threads)
    name = name or (KINDS[sm.rule].name(sm.wildcards) if sm.rule in KINDS else sm.rule)
    with runlog.run(name, sm.log[0]) as log:
        yield Job(sm, name, typed(sm.wildcards), log, started)


from . import kinds  # noqa: E402, F401  (registers every kind of job)
