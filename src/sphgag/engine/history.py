"""What each particle has been through: its origin, damage and conversion to GAG (paper sections 2.6-2.7).

A :class:`ParticleHistory` is immutable (its arrays are read-only): every change
(a pool seeded, damage grown, a particle ruptured) returns a new history. The
material of a wall is then a pure function of ``(load, history)``
(:class:`HistoryMaterial`), so a model's cached property table can never be
stale: a new history means a new material object, installed with
:meth:`sphgag.engine.model.Model.set_props`, which clears the cache.

Per particle:

* ``origin``: :data:`TISSUE` (the wall as built), :data:`SEEDED` (a GAG pool of
  the configuration) or :data:`DAMAGED` (a tissue particle that ruptured and
  became GAG, section 2.7);
* ``pool``: the index of the pool a GAG particle belongs to (-1 for tissue);
* ``D``, ``onset_stretch`` and ``onset_energy``: the damage of eq. (2.28), and the radial
  stretch and intact energy density at its onset (NaN before onset; :mod:`sphgag.physics.damage`);
* ``converted_step``: the damage pass at which the particle became GAG (0 for
  seeded pools, -1 for tissue).

A GAG particle carries its pool's fixed-charge density, the load's
``concentration`` (eqs. 2.25-2.27).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, fields, replace

import numpy as np

from ..physics import damage, materials
from .loading import Load

TISSUE, SEEDED, DAMAGED = 0, 1, 2
ORIGINS = {TISSUE: "tissue", SEEDED: "seeded", DAMAGED: "damaged"}


def _frozen(a, dtype) -> np.ndarray:
    out = np.array(a, dtype=dtype)
    out.setflags(write=False)
    return out


@dataclass(frozen=True, eq=False)
class ParticleHistory:
    """Per-particle state that load paths do not undo (read-only arrays; see the module docstring)."""

    origin: np.ndarray
    pool: np.ndarray
    D: np.ndarray
    onset_stretch: np.ndarray
    converted_step: np.ndarray
    onset_energy: np.ndarray | None = None

    def __post_init__(self):
        if self.onset_energy is None:  # histories saved before the fracture-energy law
            object.__setattr__(self, "onset_energy", np.full(np.asarray(self.origin).size, np.nan))
        dtypes = dict(
            origin=np.int8, pool=np.int16, D=float, onset_stretch=float, converted_step=np.int64, onset_energy=float
        )
        n = np.asarray(self.origin).size
        for name, dtype in dtypes.items():
            value = _frozen(getattr(self, name), dtype)
            if value.shape != (n,):
                raise ValueError(f"history array {name} has shape {value.shape}, expected ({n},)")
            object.__setattr__(self, name, value)

    @classmethod
    def intact(cls, n: int) -> ParticleHistory:
        return cls(np.zeros(n), np.full(n, -1), np.zeros(n), np.full(n, np.nan), np.full(n, -1))

    @property
    def n(self) -> int:
        return self.origin.size

    @property
    def gag(self) -> np.ndarray:
        """Mask of GAG particles (seeded or converted by damage)."""
        return self.origin != TISSUE

    def members(self, pool: int) -> np.ndarray:
        return np.flatnonzero(self.pool == pool)

    def seed(self, pools) -> ParticleHistory:
        """The GAG pools of the configuration: ``pools[k]`` are the indices of pool ``k``'s particles."""
        origin, pool, step = self.origin.copy(), self.pool.copy(), self.converted_step.copy()
        for k, idx in enumerate(pools):
            idx = np.asarray(idx, dtype=np.int64)
            if np.any(origin[idx] != TISSUE):
                raise ValueError(f"pool {k} overlaps another pool")
            origin[idx], pool[idx], step[idx] = SEEDED, k, 0
        return replace(self, origin=origin, pool=pool, converted_step=step)

    def with_damage(self, D, onset_stretch, onset_energy=None) -> ParticleHistory:
        """The same history with new damage; refuses to let D decrease (eq. 2.28 is irreversible)."""
        D = np.asarray(D, dtype=float)
        if np.any(D < self.D):
            raise ValueError("damage never decreases")
        energy = self.onset_energy if onset_energy is None else onset_energy
        return replace(self, D=D, onset_stretch=onset_stretch, onset_energy=energy)

    def rupture(self, idx, pools, step: int) -> ParticleHistory:
        """Particles ``idx`` (tissue) become GAG particles of pools ``pools`` at damage pass ``step``."""
        idx = np.asarray(idx, dtype=np.int64)
        if np.any(self.gag[idx]):
            raise ValueError("only tissue particles can rupture")
        origin, pool, conv = self.origin.copy(), self.pool.copy(), self.converted_step.copy()
        origin[idx], pool[idx], conv[idx] = DAMAGED, pools, step
        return replace(self, origin=origin, pool=pool, converted_step=conv)

    # -- files ----------------------------------------------------------------
    def arrays(self) -> dict:
        """The arrays, keyed ``history_<name>`` (what :func:`sphgag.records.state.save` writes)."""
        return {f"history_{f.name}": getattr(self, f.name) for f in fields(self)}

    @classmethod
    def from_arrays(cls, data) -> ParticleHistory:
        return cls(**{f.name: data[f"history_{f.name}"] for f in fields(cls) if f"history_{f.name}" in data})

    def equals(self, other: ParticleHistory) -> bool:
        real = ("D", "onset_stretch", "onset_energy")
        return all(
            np.array_equal(getattr(self, f.name), getattr(other, f.name), equal_nan=f.name in real)
            for f in fields(self)
        )


def swelling_load(base: Load, conversion: float, concentration: float) -> Load:
    """``base`` (a pressure-controlled state) with the pools' conversion fraction (the ``transition`` of
    :class:`HistoryMaterial`) and their GAG concentration (its ``concentration``, eqs. 2.25-2.27)."""
    return base.with_material(transition=float(conversion), concentration=float(concentration))


class HistoryMaterial:
    """Property table of a wall as a pure function of ``(load, history)``, on a path from ``before`` to ``after``.

    ``base(load)``: the intact wall's table (e.g. :class:`sphgag.studies.artery.BilayerMaterial`);
    ``gag``: the ``gag`` parameters of one run (eq. 2.27), with its Donnan law ``charge_law``
    (:data:`sphgag.physics.donnan.CHARGE_LAWS`, :func:`sphgag.physics.materials.law_gag`) gives GAG particles the
    columns of the load's concentration c it says (:meth:`sphgag.physics.donnan.ChargeLaw.engine_columns`): the
    swelling pressure Pi(c) (``prescribed``, eqs. 2.25-2.27 as printed), or the fixed charge c per reference volume,
    whose Donnan pressure acts at the current concentration c/J (``conserved``, :func:`sphgag.physics.materials.
    donnan`).
    The load's ``transition`` t in [0, 1] moves between the two histories (a load without one is at
    ``before``), so that the quasi-static solver can follow (and bisect) any change of history:

    * damage ``D = D_before + t (D_after - D_before)``, as ``(1 - D) W`` (:func:`sphgag.physics.damage.weaken`);
    * particles that are GAG in ``after`` but not in ``before`` follow the conversion
      homotopy of :func:`sphgag.physics.materials.convert_to_gag` with fraction ``t``, and their
      fixed charge rises with it, ``t c``;
    * GAG particles of ``before`` are GAG at the load's ``concentration`` c.

    Seeding a pool (figure 4) is the path from the intact history to the seeded one.
    """

    def __init__(
        self,
        base: Callable[[Load], np.ndarray],
        before: ParticleHistory,
        gag: materials.Gag | dict,
        after: ParticleHistory | None = None,
    ):
        self.base, self.gag = base, materials.Gag.of(gag)
        self.before, self.after = before, before if after is None else after
        if self.before.n != self.after.n:
            raise ValueError("the two histories have different particle counts")
        self.kept = np.flatnonzero(self.before.gag)
        self.converting = np.flatnonzero(self.after.gag & ~self.before.gag)

    @property
    def history(self) -> ParticleHistory:
        """The history at the end of the path (``transition = 1``)."""
        return self.after

    def settled(self) -> HistoryMaterial:
        """The same wall with the path completed: ``after`` becomes the history of both ends."""
        return HistoryMaterial(self.base, self.after, self.gag)

    def towards(self, after: ParticleHistory) -> HistoryMaterial:
        """A path from this material's final history to ``after``."""
        return HistoryMaterial(self.base, self.after, self.gag, after)

    def __call__(self, load: Load) -> np.ndarray:
        t = float(load.material_value("transition", 0.0))
        c = float(load.material_value("concentration", 0.0))
        out = self.base(load)
        D = self.before.D + t * (self.after.D - self.before.D)
        if np.any(D > 0.0):
            out = damage.weaken(out, D)
        g = self.gag
        for rows, fraction, charge in ((self.kept, 1.0, c), (self.converting, t, t * c)):
            if not rows.size or fraction == 0.0:
                continue
            # the law's columns: a constant Pi (PI), or a fixed charge the kernels evaluate at each J (FCD)
            pi, fixed = g.law.engine_columns(charge, g.bath_concentration_mEq_l, g.temperature_K)
            materials.convert_to_gag(
                out,
                rows,
                fraction,
                g.shear_modulus_kPa,
                g.hourglass_modulus_kPa,
                pi,
                kappa=g.lame_lambda_kPa,
                volumetric=g.volumetric,
                fixed_charge=fixed,
            )
        return out
