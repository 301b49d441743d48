"""One protocol for the variants of the model: charge laws, volumetric forms of the GAG contents, damage laws, onset
criteria, candidate rules, pool models and hourglass forms.

A variant is a small strategy object (:class:`Variant`) that holds its name (in the configuration, the pipeline's
wildcards and the tables' columns), its title (as the figures and the schema's descriptions name it), whether it is
the paper's (the one to compare with the paper's panels and claims), the configuration keys it owns with their
checks (:meth:`Variant.check`), and the behaviour it contributes (each kind's own methods). Each kind keeps its
variants in a :class:`Registry`: a read-only mapping name -> variant, in the order the figures and tables show them,
so ``tuple(REG)``, ``name in REG`` and ``REG[name]`` read it as a dict. The configuration's schema takes its
enumerations from the registries (:func:`sphgag.config.schema`), so a registered variant is accepted by name with no
edit of the schema (docs/contributing.md, "Variants").
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from typing import ClassVar, TypeVar


class Variant:
    """The protocol of a variant (a base for the frozen dataclasses of each kind; a class whose instances are built
    from a run's settings, as a damage law, registers itself with class attributes).

    name : the variant's name (configuration, wildcard, table column).
    title : how the figures (and the schema's descriptions) name it.
    paper : it is the paper's variant of its kind (one per registry); every other is a deviation.
    keys : the configuration keys it owns (dotted paths), which :meth:`check` vouches for.

    ``name``, ``title`` and ``paper`` are only declared here (each kind's dataclass holds them as fields, in its own
    order), so that a subclass's fields take no default from the base.
    """

    name: str
    title: str
    paper: bool
    keys: ClassVar[tuple[str, ...]] = ()

    def check(self, config: Mapping, key: str) -> None:
        """Raise ValueError naming the offending key and its allowed range where ``config`` (the whole
        configuration) does not suit this variant, named by the configuration key ``key`` (e.g.
        ``swelling.pool_models[1]``). Nothing to check by default."""


V = TypeVar("V")


class Registry(Mapping[str, V]):
    """The variants of one kind, by name, in the order of registration (the paper's first, by convention).

    ``kind``: what a variant is called in messages (``charge law``, ``pool model``...).
    """

    def __init__(self, kind: str, variants: Iterable[V] = ()):
        self.kind = kind
        self._variants: dict[str, V] = {}
        for v in variants:
            self.register(v)

    # -- the mapping ------------------------------------------------------------------------------------------------
    def __getitem__(self, name: str) -> V:
        return self._variants[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._variants)

    def __len__(self) -> int:
        return len(self._variants)

    def __repr__(self) -> str:
        return f"Registry({self.kind!r}: {', '.join(self._variants)})"

    # -- registration -----------------------------------------------------------------------------------------------
    def register(self, variant: V) -> V:
        """Add ``variant`` (ValueError for a name already registered, or a second paper's variant); returns it, so a
        class can register itself as a decorator."""
        name = variant.name
        if not isinstance(name, str) or not name:
            raise ValueError(f"a {self.kind} needs a name, got {name!r}")
        if name in self._variants:
            raise ValueError(f"{self.kind} {name!r} is registered already")
        if variant.paper and any(v.paper for v in self._variants.values()):
            raise ValueError(f"{self.kind} {name!r}: the paper's {self.kind} is {self.paper.name!r} already")
        self._variants[name] = variant
        return variant

    def unregister(self, name: str) -> V:
        """Remove the variant ``name`` and return it (a test's plug-in, undone)."""
        return self._variants.pop(name)

    @contextmanager
    def registered(self, variant: V) -> Iterator[V]:
        """``variant`` registered for the ``with`` block only (a test's plug-in)."""
        self.register(variant)
        try:
            yield variant
        finally:
            self.unregister(variant.name)

    # -- lookups ----------------------------------------------------------------------------------------------------
    def lookup(self, name) -> V:
        """The variant ``name`` (ValueError naming the registered ones for any other)."""
        if not isinstance(name, str) or name not in self._variants:
            raise ValueError(f"unknown {self.kind} {name!r}: one of {', '.join(self._variants)}")
        return self._variants[name]

    @property
    def names(self) -> tuple[str, ...]:
        """The registered names, in order (the schema's enumeration)."""
        return tuple(self._variants)

    @property
    def paper(self) -> V:
        """The paper's variant."""
        return next(v for v in self._variants.values() if v.paper)

    @property
    def titles(self) -> dict[str, str]:
        """Each variant's title, by name (the figures' and the schema's labels)."""
        return {name: v.title for name, v in self._variants.items()}

    def deviations(self) -> tuple[V, ...]:
        """The variants that are not the paper's, in order."""
        return tuple(v for v in self._variants.values() if not v.paper)

    def problems(self, config: Mapping, key: str, names) -> list[str]:
        """The messages of every registered variant of ``names`` (a name or a list of them, the value of the
        configuration key ``key``) whose :meth:`Variant.check` rejects ``config``."""
        listed = [(key, names)] if isinstance(names, str) else [(f"{key}[{k}]", n) for k, n in enumerate(names)]
        out = []
        for where, name in listed:
            if name in self._variants:
                try:
                    self._variants[name].check(config, where)
                except ValueError as exc:
                    out.append(str(exc))
        return out
