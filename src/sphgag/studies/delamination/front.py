"""The pools' front (paper section 2.7): their seeded sectors, the damage candidates around them, the connectivity of
the particles damage converts, and the measures of growth (converted particles, delaminated length, islands).

**Candidates** (``candidates``, :data:`sphgag.studies.delamination.settings.CANDIDATE_RULES`): tissue particles of
the media in a pool's radial band (the reference radii of its seeded sector), not on a wall surface, within
``candidate_window_deg`` of the pool's current angular extent (the authors' script, ``window``), and by default
(``contact``, the paper's "radial stress at the tip of the pool") only those with a GAG particle of the pool within
1.5 dx in the reference configuration.

**Delaminated length**: the reference area converted by damage and connected to its pool (through the reference
neighbours within 1.5 dx among the pool's GAG particles, from its seeded ones) over the band's thickness. Converted
particles not connected to their pool are *islands*, counted apart (``islands``, ``island_particles``,
``island_distance_um``); ``converted_particles`` counts both.

**A damage pass** of eq. (2.28) on a converged state (:func:`damage_step`): the onset measure at the candidates, the
intact energy density, the damage state it makes, and the ruptured candidates become GAG particles of their pools
(:func:`with_ruptures`). The quasi-static growth (:mod:`.growth`) and the authors' explicit procedure
(:mod:`sphgag.studies.paper_procedure`) take their passes with it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from ...engine import forces
from ...engine.geometry import Sector
from ...engine.history import DAMAGED, SEEDED, HistoryMaterial, ParticleHistory
from ...engine.model import Model
from ...physics import damage
from .settings import CANDIDATE_RULES, CRITERIA, Settings

#: the contact distance in the reference configuration, in particle spacings: two particles within it touch (pools
#: merge, a candidate touches its pool, a converted particle is connected to its neighbour)
CONTACT_DX = 1.5


@dataclass(frozen=True)
class Islands:
    """Particles converted by damage (eq. 2.28, D = 1; section 2.7) that are not connected to their pool
    (:meth:`Front.islands`): ``count`` connected components of them, ``particles`` in all, and the reference distance
    [um] from the nearest of them to the nearest particle of its connected pool (NaN without islands)."""

    count: int = 0
    particles: int = 0
    distance_um: float = np.nan


@dataclass
class Front:
    """The pools' geometry: seeded sectors, candidates and the measures of growth.

    ``rule``: the candidate rule (:data:`sphgag.studies.delamination.settings.CANDIDATE_RULES`). ``adjacent``: the
    reference-neighbour graph, particles within :data:`CONTACT_DX` spacings in the reference configuration (a symmetric
    sparse matrix).
    """

    model: Model
    sectors: list[Sector]
    window_deg: float
    rule: str = "contact"

    def __post_init__(self):
        lay = self.model.layout
        surface = np.zeros(lay.n, dtype=bool)
        surface[lay.inner_surface] = surface[lay.outer_surface] = True
        self.interior = lay.pool_mask & ~surface
        self.bands = [(lay.radius >= s.r_range[0]) & (lay.radius <= s.r_range[1]) for s in self.sectors]
        self.centres = np.deg2rad([s.centre_angle_deg for s in self.sectors])
        self.thickness = np.array([s.radial_extent for s in self.sectors])
        pairs = cKDTree(lay.X).query_pairs(CONTACT_DX * lay.dx, output_type="ndarray")
        i, j = np.concatenate([pairs[:, 0], pairs[:, 1]]), np.concatenate([pairs[:, 1], pairs[:, 0]])
        self.adjacent = csr_matrix((np.ones(i.size, dtype=np.int8), (i, j)), shape=(lay.n, lay.n))

    @classmethod
    def of(cls, model: Model, sectors: list[Sector], settings: Settings) -> Front:
        """The front of a run with ``settings`` (its candidate window and rule)."""
        return cls(model, sectors, settings.candidate_window_deg, settings.candidates)

    def candidates(self, hist: ParticleHistory):
        """``(indices, pool)``: tissue particles of the media, off the surfaces, in a pool's radial band, within the
        window of its current angular extent and admitted by the candidate rule for that pool; ``pool`` is the
        nearest such pool (in angle)."""
        th = self.model.layout.theta
        w = np.deg2rad(self.window_deg)
        admits = CANDIDATE_RULES[self.rule].admits
        best = np.full(hist.n, np.inf)
        pool = np.full(hist.n, -1)
        for k, band in enumerate(self.bands):
            members = hist.members(k)
            lo, hi = th[members].min(), th[members].max()
            dist = np.maximum(lo - th, th - hi)
            ok = band & self.interior & ~hist.gag & (dist <= w) & (dist < best) & admits(self, hist, k)
            best[ok], pool[ok] = dist[ok], k
        idx = np.flatnonzero(pool >= 0)
        return idx, pool[idx]

    def touching(self, hist: ParticleHistory, pool: int) -> np.ndarray:
        """The particles (a mask) with a GAG particle of ``pool`` (seeded or converted) within the contact distance
        in the reference configuration."""
        return self.adjacent @ (hist.pool == pool).astype(np.int64) > 0

    def extent_deg(self, hist: ParticleHistory) -> np.ndarray:
        th = self.model.layout.theta
        return np.array([np.rad2deg(np.ptp(th[hist.members(k)])) for k in range(len(self.sectors))])

    def at_symmetry_edge(self, hist: ParticleHistory) -> bool:
        th = np.rad2deg(self.model.layout.theta[hist.gag])
        return bool(th.min() <= self.window_deg or th.max() >= 90.0 - self.window_deg)

    def at_layer(self, hist: ParticleHistory) -> bool:
        """A particle converted by damage touches (within the contact distance, reference positions) a particle
        outside the pool layers' interior: another layer or a free surface."""
        damaged = (hist.origin == DAMAGED).astype(np.int64)
        return bool(np.any((self.adjacent @ damaged > 0) & ~self.interior))

    def converted(self, hist: ParticleHistory):
        """``(total, interior, exterior)`` particles converted by damage (islands included); interior: on the side
        of its pool's seeded centre that faces the other pools (two or more pools; NaN for one)."""
        damaged = hist.origin == DAMAGED
        total = int(damaged.sum())
        if len(self.sectors) < 2:
            return total, np.nan, np.nan
        th = self.model.layout.theta
        inner = 0
        for k in range(len(self.sectors)):
            mine = np.flatnonzero(damaged & (hist.pool == k))
            towards = np.sign(np.mean([c for j, c in enumerate(self.centres) if j != k]) - self.centres[k])
            inner += int(np.sum(np.sign(th[mine] - self.centres[k]) == towards))
        return total, inner, total - inner

    def parts(self, hist: ParticleHistory, pool: int) -> tuple[np.ndarray, np.ndarray, int]:
        """``(connected, islands, count)`` of ``pool``: its GAG particles connected to its seeded ones through the
        reference-neighbour graph (:attr:`adjacent`) among its GAG particles, those that are not (indices), and the
        number of connected components of the latter."""
        mine = hist.members(pool)
        _, label = connected_components(self.adjacent[mine][:, mine], directed=False)
        attached = np.isin(label, label[hist.origin[mine] == SEEDED])
        return mine[attached], mine[~attached], np.unique(label[~attached]).size

    def delaminated_length(self, hist: ParticleHistory) -> float:
        """Length [um] of the delaminated arc: the reference area converted by damage and connected to its pool
        (:meth:`parts`) over its band's thickness; islands do not count."""
        V, damaged = self.model.layout.volume, hist.origin == DAMAGED
        length = 0.0
        for k, t in enumerate(self.thickness):
            connected = self.parts(hist, k)[0]
            length += V[connected[damaged[connected]]].sum() / t
        return float(length)

    def islands(self, hist: ParticleHistory) -> Islands:
        """The converted particles not connected to their pool (:meth:`parts`), over all pools."""
        X = self.model.layout.X
        count = particles = 0
        distance = np.inf
        for k in range(len(self.sectors)):
            connected, apart, n = self.parts(hist, k)
            if apart.size:
                count, particles = count + n, particles + apart.size
                distance = min(distance, float(cKDTree(X[connected]).query(X[apart])[0].min()))
        return Islands(count, particles, distance if count else np.nan)

    def merged(self, hist: ParticleHistory) -> bool:
        """Two pools touch: a particle of one has a particle of another within the contact distance (reference
        positions)."""
        return any(
            np.any(self.touching(hist, k) & (hist.pool >= 0) & (hist.pool != k)) for k in range(len(self.sectors))
        )


def onset_measure(model: Model, ev, hist: ParticleHistory, cand: np.ndarray, settings: Settings) -> np.ndarray:
    """The radial Cauchy stress (eq. 2.10, current polar frame) the onset test of eq. (2.28) compares with sigma_cr,
    at the candidates, by the run's onset criterion (:data:`sphgag.studies.delamination.settings.CRITERIA`)."""
    return CRITERIA[settings.criterion].measure(model, ev, hist, cand, settings)


def intact_energy(model: Model, ev, base_props: np.ndarray) -> np.ndarray:
    """``W_0`` (eq. 2.23) of every particle with the undamaged material, at the state ``ev``."""
    W = np.empty(model.n)
    forces.energy_densities(ev.F, ev.load.axial_stretch, model.cth, model.sth, base_props, W)
    return W


def damage_step(model: Model, front: Front, settings: Settings, material: HistoryMaterial, ev, found):
    """The damage state (eq. 2.28) that the state ``ev`` makes from the history of ``material``, and the intact energy
    density ``W_0`` (eq. 2.23) of every particle there. ``found``: ``(candidates, their pools, their onset
    measures)``. Only candidates start to damage; GAG particles keep their ``D``."""
    hist, lay = material.history, model.layout
    cand, pools, sigma = found
    dmg = damage.DamageState(hist.D.copy(), hist.onset_stretch.copy(), hist.onset_energy.copy())
    radial = np.full(lay.n, -np.inf)
    radial[cand] = sigma
    W0 = intact_energy(model, ev, material.base(ev.load))
    band = np.full(lay.n, np.nan)
    band[cand] = front.thickness[pools]  # the band a pool's growth converts: its radial extent
    dmg.update(settings.law, cand, radial, damage.radial_stretch(ev.F, lay.theta), W0, band)
    dmg.D[hist.gag] = hist.D[hist.gag]
    return dmg, W0


def with_ruptures(hist: ParticleHistory, ruptured: np.ndarray, cand: np.ndarray, pools: np.ndarray, step: int):
    """``hist`` with the candidates ``ruptured`` become GAG particles of their pools (``pools``, per candidate) at
    damage pass ``step`` (section 2.7)."""
    if not ruptured.size:
        return hist
    owner = np.full(hist.n, -1)
    owner[cand] = pools
    return hist.rupture(ruptured, owner[ruptured], step)
