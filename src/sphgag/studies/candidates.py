"""Candidate rules of the delamination protocol (section 2.7): which intact particles the damage law of eq. (2.28)
tests against sigma_cr.

Every rule starts from the same set, the authors' script's (:meth:`sphgag.studies.delamination.front.Front.candidates`):
tissue particles of the media, off the wall surfaces, in a pool's radial band (the reference radii of its seeded
sector) and within ``delamination.candidate_window_deg`` of the pool's current angular extent. A rule admits a subset
of it, pool by pool. The paper compares "the radial stress at the tip of the pool" with sigma_cr (section 2.7): the
particles in contact with the pool (``contact``); the authors' script tests the whole window (``window``), so damage
can form islands ahead of a pool (docs/physics.md, "Damage candidates").

A rule is a :class:`CandidateRule` (a :class:`sphgag.registry.Variant`) of the registry :data:`CANDIDATE_RULES`. The
configuration's schema (``delamination.candidates``, :func:`sphgag.config.schema`) is built from the registry, so a new
rule is one function and one entry here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..engine.history import ParticleHistory
from ..registry import Registry, Variant


@dataclass(frozen=True)
class CandidateRule(Variant):
    """``admits(front, history, pool)``: the particles (a mask over all of them) that may be candidates of pool
    ``pool`` (an index of ``front.sectors``), within the window of :class:`sphgag.studies.delamination.front.Front`.
    ``title``: which particles; ``paper``: the rule of the paper's text. A rule owns no key beyond
    ``delamination.candidates`` (the window, ``delamination.candidate_window_deg``, is every rule's)."""

    name: str
    title: str
    admits: Callable[[object, ParticleHistory, int], np.ndarray]
    paper: bool = False


def anywhere(front, hist: ParticleHistory, pool: int) -> np.ndarray:
    """Every particle of the window (the authors' script)."""
    return np.ones(hist.n, dtype=bool)


def in_contact(front, hist: ParticleHistory, pool: int) -> np.ndarray:
    """The particles with a GAG particle of the pool (seeded or converted) within the contact distance in the
    reference configuration (:meth:`sphgag.studies.delamination.front.Front.touching`): the tip of the pool (the
    paper)."""
    return front.touching(hist, pool)


#: the registry of candidate rules, by name (``delamination.candidates``; the paper's first)
CANDIDATE_RULES: Registry[CandidateRule] = Registry(
    "candidate rule",
    (
        CandidateRule(
            "contact", "the particles touching the pool, within the window (the paper's text)", in_contact, paper=True
        ),
        CandidateRule("window", "every particle within the window of the pool (the authors' script)", anywhere),
    ),
)
