"""Arterial models built from configuration slices (paper section 2.4, Tables 1-2).

A Snakemake rule passes exactly the parameters it depends on, as plain dictionaries (the ``mean``, ``bilayer`` and
``numerics`` sections of ``config/config.yaml``); the models take the numerics typed (:class:`sphgag.engine.numerics.
Numerics`, built once by the job) and read the bi-layered wall as typed options (:class:`Bilayer`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ..engine import geometry, history, kernel, quadrature
from ..engine.loading import Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import Options
from ..physics import materials


@dataclass(frozen=True)
class Fibre(Options):
    """Fung constants of a fibre family of the mean model (eq. 2.18): c1, c2 and its angle alpha to the axis."""

    c1_kPa: float
    c2: float
    angle_deg: float = 0.0


@dataclass(frozen=True)
class MeanFibres(Options):
    """The mean model's fibre families (Table 1): axial, circumferential and the +-diagonal pair."""

    axial: Fibre
    circumferential: Fibre
    diagonal: Fibre


@dataclass(frozen=True)
class Mean(Options):
    """The ``mean`` configuration section (section 2.4.1, Table 1): the mean-behaviour wall's geometry, particle
    spacing, elastin moduli (eq. 2.18), hourglass modulus E (eq. 2.14), axial stretch and fibre families."""

    SECTION = "mean"

    inner_radius_um: float
    outer_radius_um: float
    dx_um: float
    shear_modulus_kPa: float
    lame_lambda_kPa: float
    hourglass_modulus_kPa: float
    axial_stretch: float
    fibres: MeanFibres

    @classmethod
    def problems(cls, config) -> list[str]:
        """The wall's outer radius beyond its inner one, and the wall at least half a particle spacing thick."""
        problems = []
        m = config.get("mean", {})
        if m.get("outer_radius_um", 0) <= m.get("inner_radius_um", 0):
            problems.append(
                f"mean.outer_radius_um = {m.get('outer_radius_um')} must exceed "
                f"mean.inner_radius_um = {m.get('inner_radius_um')}"
            )
        elif {"inner_radius_um", "outer_radius_um", "dx_um"} <= set(m):
            if m["outer_radius_um"] - m["inner_radius_um"] < m["dx_um"] / 2:
                problems.append(
                    f"mean.outer_radius_um - mean.inner_radius_um = {m['outer_radius_um'] - m['inner_radius_um']:g} "
                    f"um must be at least half the particle spacing mean.dx_um = {m['dx_um']:g} um"
                )
        return problems


def mean_fibre_families(p: dict):
    """Fibre families of eq. (2.18) as ``(alpha_deg, c1, c2)``: axial, circumferential, +-diagonal."""
    f = p["fibres"]
    d = f["diagonal"]
    return (
        (0.0, f["axial"]["c1_kPa"], f["axial"]["c2"]),
        (90.0, f["circumferential"]["c1_kPa"], f["circumferential"]["c2"]),
        (d["angle_deg"], d["c1_kPa"], d["c2"]),
        (-d["angle_deg"], d["c1_kPa"], d["c2"]),
    )


def mean_model(p: dict, numerics: Numerics, name: str = "mean") -> Model:
    """Mean-behaviour model (section 2.4.1, Table 1) in its unloaded reference configuration."""
    layout = geometry.quarter_annulus([p["inner_radius_um"], p["outer_radius_um"]], p["dx_um"])
    nb = kernel.for_layout(layout, numerics.kernel_support_factor)
    props = materials.mean_behaviour(
        layout.n, p["shear_modulus_kPa"], p["lame_lambda_kPa"], mean_fibre_families(p), p["hourglass_modulus_kPa"]
    )
    return Model(name, layout, nb, props, **numerics.model_options())


# ---------------------------------------------------------------------------
# Bi-layered constrained-mixture model (section 2.4.2, Table 2)
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class FibreConstants(Options):
    """Fung constants of a fibre family (eq. 2.22) in tension and in compression; ``angle_deg`` is the diagonal
    collagen's angle alpha_0 to the axis (Table 2)."""

    c1_kPa: float
    c2: float
    c1_compression_kPa: float
    c2_compression: float
    angle_deg: float = 0.0


@dataclass(frozen=True)
class Prestretch(Options):
    """Deposition stretches of Table 2: the elastin matrix's circumferential and axial G, SMC and collagen G."""

    elastin_circumferential: float
    elastin_axial: float
    smc: float
    collagen: float


@dataclass(frozen=True)
class Active(Options):
    """The active tone of eq. (2.24): T_max and the stretches of its maximum and of zero tone."""

    max_stress_kPa: float
    stretch_max: float
    stretch_min: float


THINNEST_LAYER = 0.1  # a layer (or sub-layer) as thin as this fraction of the spacing still gets its own ring


@dataclass(frozen=True)
class Bilayer(Options):
    """The ``bilayer`` configuration section (section 2.4.2, Table 2): the in vivo geometry, the particle spacing,
    the constituents' moduli, mass fractions, orientations, fibre constants, pre-stretches and active tone.

    ``layers`` are the wall's bands from the lumen outwards, each a ``{name, thickness_um}`` (a name may repeat: a
    lamellar media is ``media, lamina, media, ...``); ``pool_layers`` name the layers whose particles GAG pools convert
    and damage delaminates (the paper's media). ``mass_fractions[layer][constituent]`` and
    ``orientations[layer][direction]`` are read-only mappings by layer name."""

    SECTION = "bilayer"

    inner_radius_um: float
    layers: tuple
    pool_layers: tuple
    dx_um: float
    elastin_shear_modulus_kPa: float
    lame_lambda_kPa: float
    hourglass_modulus_kPa: float
    aligned_radii_um: tuple
    mass_fractions: Mapping
    orientations: Mapping
    collagen: FibreConstants
    smc: FibreConstants
    prestretch: Prestretch
    active: Active

    def bands(self) -> list[tuple[str, float, float]]:
        """``(name, R_a, R_b)`` of every band of ``layers``, from the lumen outwards (the in vivo geometry)."""
        out, r = [], self.inner_radius_um
        for band in self.layers:
            out.append((band["name"], r, r + band["thickness_um"]))
            r += band["thickness_um"]
        return out

    def layer_names(self) -> list[str]:
        """The distinct layer names, in the order of their first band."""
        return list(dict.fromkeys(name for name, _, _ in self.bands()))

    def pool_span_text(self, lo: float, hi: float) -> str | None:
        """``None`` if the radii ``lo``-``hi`` lie in one span of pool layers (:func:`pool_spans`), else the spans as
        text."""
        spans = pool_spans(self)
        if any(a <= lo and hi <= b for a, b in spans):
            return None
        return f"the pool layers {', '.join(self.pool_layers)} ({'; '.join(f'{a:g}-{b:g}' for a, b in spans)} um)"

    @classmethod
    def problems(cls, config) -> list[str]:
        """The layered wall (:meth:`wall_problems`), each layer's mass fractions and orientations (the beta factors
        of Table 2) summing to 1, the active tone's stretches (eq. 2.24) in order, and no layer thinner than
        :data:`THINNEST_LAYER` of the largest particle spacing it is run at (:meth:`thin_layers`)."""
        bil = config.get("bilayer", {})
        problems = cls.wall_problems(bil) if bil else []
        for layer, beta in bil.get("orientations", {}).items():
            if abs(sum(beta.values()) - 1.0) > 1e-6:
                problems.append(
                    f"bilayer.orientations.{layer} must sum to 1 (beta factors of Table 2), got "
                    f"{sum(beta.values()):.6g}"
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
        return problems + cls.thin_layers(config)

    @staticmethod
    def wall_problems(bil: Mapping) -> list[str]:
        """The layered wall of the ``bilayer`` section ``bil``: every layer named in ``layers`` has its mass fractions
        and orientations (and no others are given), the pool layers are layers of the wall, a layer has at most
        :data:`sphgag.physics.materials.MAX_FAMILIES` fibre families, and the aligned radii lie inside the wall."""
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
            if families > materials.MAX_FAMILIES:
                problems.append(
                    f"bilayer.mass_fractions.{name}.smc and bilayer.orientations.{name}.circumferential: a layer "
                    f"carries at most {materials.MAX_FAMILIES} fibre families (SMC or circumferential collagen, axial, "
                    "two diagonal)"
                )
        edges = bilayer_interfaces(bil)
        r_in, r_out = edges[0], edges[-1]
        for k, r in enumerate(bil.get("aligned_radii_um", [])):
            if not r_in < r < r_out:
                problems.append(f"bilayer.aligned_radii_um[{k}] = {r} is not inside the wall ({r_in:g}-{r_out:g} um)")
        return problems

    @classmethod
    def thin_layers(cls, config) -> list[str]:
        """Layers (and sub-layers between ``aligned_radii_um``) thinner than :data:`THINNEST_LAYER` of the largest
        particle spacing they are run at. Every layer gets at least one ring of particles (a lamina one particle thick
        is fine: the three-layer wall of tests/test_bilayer.py matches its exact tube); below a tenth its cell is a
        sliver (or, below round-off, nothing at all)."""
        bil = config.get("bilayer", {})
        if not {"inner_radius_um", "layers", "dx_um"} <= set(bil):
            return []
        spacings = [("bilayer.dx_um", bil["dx_um"])]
        sc = config.get("swelling_convergence", {})
        spacings += [("swelling_convergence.dx_um", dx) for dx in sc.get("dx_um", [])]
        de_conv = config.get("delamination", {}).get("convergence", {})
        spacings += [("delamination.convergence.dx_um", dx) for dx in de_conv.get("dx_um", [])]
        source, dx = max(spacings, key=lambda item: item[1])
        layers = []
        for k, (name, a, b) in enumerate(cls.of(bil).bands()):
            edges = sorted({a, b, *(x for x in bil.get("aligned_radii_um", []) if a < x < b)})
            if len(edges) <= 2:  # one edge: the band is thinner than round-off
                layers.append((f"bilayer.layers[{k}].thickness_um ({name})", bil["layers"][k]["thickness_um"]))
            else:
                sub = [(f"the {name} sub-layer {lo:g}-{hi:g} um", hi - lo) for lo, hi in zip(edges, edges[1:])]
                layers += [(f"bilayer.aligned_radii_um: {text}", t) for text, t in sub]
        return [
            f"{name} = {thickness:g} um is thinner than a tenth of the largest particle spacing it is run at "
            f"({source} = {dx:g} um)"
            for name, thickness in layers
            if thickness < THINNEST_LAYER * dx
        ]


def bilayer_interfaces(p: Bilayer | dict) -> list[float]:
    """Reference radii [R_in, the bands' borders, ..., R_out] of the in vivo (homeostatic) geometry."""
    bands = Bilayer.of(p).bands()
    return [bands[0][1]] + [b for _, _, b in bands]


def pool_spans(p: Bilayer | dict) -> list[tuple[float, float]]:
    """The radial spans ``(R_a, R_b)`` of ``pool_layers``: adjacent bands of pool layers join into one span (a pool
    must lie inside one of them)."""
    p = Bilayer.of(p)
    out = []
    for name, a, b in p.bands():
        if name not in p.pool_layers:
            continue
        if out and out[-1][1] == a:
            out[-1] = (out[-1][0], b)
        else:
            out.append((a, b))
    return out


def layer_at(p: Bilayer | dict, radius: float) -> str:
    """The name of the layer at the reference radius ``radius`` (the inner band at a border)."""
    bands = Bilayer.of(p).bands()
    return next((name for name, _, b in bands if radius <= b), bands[-1][0])


def has_smc(p: Bilayer | dict, layer: str) -> bool:
    """Whether ``layer`` holds smooth muscle (an ``smc`` mass fraction): its SMC family and active tone (eq. 2.24)."""
    return "smc" in Bilayer.of(p).mass_fractions[layer]


class FibreFamily(NamedTuple):
    """A fibre family of eqs. (2.22-2.23): mass fraction ``phi``, angle ``alpha_deg`` from the axial direction,
    constants ``(c1, c2)`` in tension and ``(c1m, c2m)`` in compression (None: the tension constants), deposition
    stretch ``prestretch`` (the fields of :class:`sphgag.physics.analytic.Family`, in its order)."""

    phi: float
    alpha_deg: float
    c1: float
    c2: float
    c1m: float | None = None
    c2m: float | None = None
    prestretch: float = 1.0


def bilayer_families(p: Bilayer | dict, layer: str) -> tuple[FibreFamily, ...]:
    """Fibre families of one layer (eqs. 2.22-2.23, Table 2).

    A layer with an ``smc`` mass fraction (the media) has SMC + circumferential collagen (phi_M^s, 90 deg, SMC
    constants, pre-stretch G_M^2); a layer with a ``circumferential`` orientation (the adventitia) has circumferential
    collagen (phi_A^c beta_A^theta). Every layer has axial collagen (phi^c beta^z) and two diagonal families
    (phi^c beta^d / 2 each, +-alpha_0). All collagen has the same constants and pre-stretch in every layer.
    """
    p = Bilayer.of(p)
    col, smc, pre = p.collagen, p.smc, p.prestretch
    frac, beta = p.mass_fractions[layer], p.orientations[layer]
    a0 = col.angle_deg

    def collagen(phi, alpha):
        return FibreFamily(phi, alpha, col.c1_kPa, col.c2, col.c1_compression_kPa, col.c2_compression, pre.collagen)

    fams = []
    if "smc" in frac:
        fams.append(
            FibreFamily(frac["smc"], 90.0, smc.c1_kPa, smc.c2, smc.c1_compression_kPa, smc.c2_compression, pre.smc)
        )
    if "circumferential" in beta:
        fams.append(collagen(frac["collagen"] * beta["circumferential"], 90.0))
    fams.append(collagen(frac["collagen"] * beta["axial"], 0.0))
    fams.append(collagen(frac["collagen"] * beta["diagonal"] / 2, a0))
    fams.append(collagen(frac["collagen"] * beta["diagonal"] / 2, -a0))
    return tuple(fams)


def elastin_prestretch(p: Bilayer | dict, fraction: float = 1.0):
    """(G_r, G_theta, G_z) of the elastin-dominated matrix a ``fraction`` of the way from 1 (G_r = 1/(G_t G_z))."""
    pre = Bilayer.of(p).prestretch
    gt = 1.0 + fraction * (pre.elastin_circumferential - 1.0)
    gz = 1.0 + fraction * (pre.elastin_axial - 1.0)
    return 1.0 / (gt * gz), gt, gz


class BilayerMaterial:
    """Property table of the bi-layered model as a function of the load's material parameters.

    ``prestretch`` in [0, 1] scales every deposition stretch from 1 to its Table 2 value
    (figure 2b); ``activation`` in [0, 1] scales the active tone T_max of the media (eq. 2.24).
    GAG pools and damage are the particles' history, layered on top by
    :class:`sphgag.engine.history.HistoryMaterial`.
    """

    def __init__(self, p: Bilayer | dict, layout: geometry.Layout):
        self.p = p = Bilayer.of(p)
        n = layout.n
        table = materials.empty_props(n)
        self.active = layout.layer_mask([name for name in layout.layer_names if has_smc(p, name)])
        for layer in layout.layer_names:
            rows = np.flatnonzero(layout.layer_mask(layer))
            table[rows, materials.MU] = p.mass_fractions[layer]["elastin"] * p.elastin_shear_modulus_kPa
            for k, f in enumerate(bilayer_families(p, layer)):
                materials.set_family(table, rows, k, f.phi, f.alpha_deg, f.c1, f.c2, f.c1m, f.c2m, f.prestretch)
            # eq. (2.23) weights the whole elastin energy (2.21), bulk term included, by phi^e
            table[rows, materials.LAM] = p.mass_fractions[layer]["elastin"] * p.lame_lambda_kPa
        table[:, materials.HG_E] = p.hourglass_modulus_kPa
        act = p.active
        table[:, materials.LMAX], table[:, materials.LMIN] = act.stretch_max, act.stretch_min
        self.target = materials.merge_identical_families(table)
        nf = int(self.target[:, materials.NFAM].max())
        self._fibre_g = [materials.FAM0 + k * materials.FAM_STRIDE + materials.GF for k in range(nf)]

    def __call__(self, load: Load) -> np.ndarray:
        s = load.material_value("prestretch", 1.0)
        a = load.material_value("activation", 0.0)
        out = self.target.copy()
        gr, gt, gz = elastin_prestretch(self.p, s)
        out[:, materials.GR], out[:, materials.GT], out[:, materials.GZ] = gr, gt, gz
        for col in self._fibre_g:
            out[:, col] = 1.0 + s * (self.target[:, col] - 1.0)
        out[self.active, materials.TACT] = a * self.p.active.max_stress_kPa
        return out


@dataclass(frozen=True)
class Pool(Options):
    """A GAG pool of the configuration (``swelling.cases``, ``delamination.pool_sets``): a sector of the wall by its
    centre (reference radius and angle) and its radial and angular extent."""

    centre_radius_um: float
    centre_angle_deg: float
    radial_extent_um: float
    angular_extent_deg: float

    def radii(self) -> tuple[float, float]:
        """Inner and outer reference radius [um]."""
        return (
            self.centre_radius_um - self.radial_extent_um / 2,
            self.centre_radius_um + self.radial_extent_um / 2,
        )

    def angles(self) -> tuple[float, float]:
        """First and last angle [deg]."""
        half = self.angular_extent_deg / 2
        return self.centre_angle_deg - half, self.centre_angle_deg + half


def pool_placement_problems(config, pools: Mapping) -> list[str]:
    """The pools ``pools`` (configuration entries by their key) each inside one span of pool layers of
    ``config["bilayer"]`` and off the symmetry edges (once the wall itself is sound: :meth:`Bilayer.wall_problems`)."""
    bil = config.get("bilayer", {})
    if not bil or Bilayer.wall_problems(bil):
        return []
    problems, wall = [], Bilayer.of(bil)
    for name, entry in pools.items():
        pool = Pool.of(entry)
        lo, hi = pool.radii()
        if spans := wall.pool_span_text(lo, hi):
            problems.append(f"{name}: radii {lo:g}-{hi:g} um leave {spans}")
        first, last = pool.angles()
        if first <= 0 or last >= 90:
            problems.append(f"{name}: angles {first:g}-{last:g} deg reach a symmetry edge (0 or 90 deg)")
    return problems


def empty_pools(config) -> list[str]:
    """Pools that hold no particle of a pool layer (the media) at a resolution they are run at (too thin or too
    narrow for dx): figure 4's cases at ``bilayer.dx_um`` and the resolution study's spacings, the delamination sets
    at ``bilayer.dx_um`` and figure 5's set (the set of the resolution study) at its spacings. This builds the layouts:
    check it only for a configuration whose other relations hold."""
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
            layouts[dx] = bilayer_layout(dict(bil, dx_um=dx))
        if not pool_sector(pool).members(layouts[dx], layer=layouts[dx].pool_layers).size:
            out.append(
                f"{name}: the pool holds no particle of a pool layer at dx = {dx:g} um (it is "
                f"{pool['radial_extent_um']:g} um by {pool['angular_extent_deg']:g} deg): make it larger than "
                "the particle spacing"
            )
    return sorted(set(out))


def pool_sector(case: dict) -> geometry.Sector:
    """A GAG pool from its configuration entry (centre, radial and angular extent)."""
    return geometry.Sector(
        case["centre_radius_um"], case["centre_angle_deg"], case["radial_extent_um"], case["angular_extent_deg"]
    )


def bilayer_layout(
    p: Bilayer | dict, pools=(), graded: geometry.Grading | dict | None = None, fitted: bool = False
) -> geometry.Layout:
    """Particles of the layered wall: one band per entry of ``layers``, each split at the ``aligned_radii_um`` inside
    it (cell boundaries: the radial edges of GAG pools). With ``pools`` (:class:`geometry.Sector`), their angular ends
    are cell boundaries and the spacing is graded around them (finest at their corners) by ``graded``
    (:class:`sphgag.engine.geometry.Grading`); without it, or with its uniform grading, the layout is the wall's own
    uniform one (a pool is the particles whose centres lie in its sector). ``fitted``: a ring of particles on every
    border between layers of different materials, shared by both (:mod:`sphgag.engine.quadrature`)."""
    p = Bilayer.of(p)
    radii, names = [p.inner_radius_um], []
    for name, a, b in p.bands():
        inside = sorted(r for r in p.aligned_radii_um if a < r < b)
        radii += [*inside, b]
        names += [name] * (len(inside) + 1)
    grading = None if graded is None else geometry.Grading.of(graded)
    columns = None
    if pools and grading is not None and not grading.uniform:
        columns = geometry.columns(geometry.Field(tuple(pools), p.dx_um, grading))
    return geometry.quarter_annulus(
        radii, p.dx_um, layer_names=names, pool_layers=p.pool_layers, columns=columns, fitted=fitted
    )


def bilayer_model(
    p: Bilayer | dict,
    numerics: Numerics,
    name: str = "bilayer",
    pool=None,
    gag: materials.Gag | dict | None = None,
    graded: geometry.Grading | dict | None = None,
    fitted: bool = False,
) -> Model:
    """Bi-layered model (section 2.4.2, Table 2) in its in vivo reference configuration.

    The radii ``aligned_radii_um`` inside the media are cell boundaries of the
    particle layout (sub-layers of the media), so that a pool whose radial
    edges are among them has exactly its thickness at every resolution.

    With ``pool`` (a :class:`geometry.Sector`, or a list of them) and the ``gag``
    parameters, the material is a :class:`history.HistoryMaterial` on the path from
    the intact wall to the wall with those medial sectors seeded as GAG pools: the
    load's ``transition`` converts them and its ``concentration`` swells them. With a non-uniform ``graded``
    (:mod:`sphgag.engine.geometry`) the layout is graded around the pools, their ends cell boundaries
    (:func:`bilayer_layout`).

    ``fitted``: particles on the media/adventitia border, shared by both layers, each layer's deformation gradient
    from its own side (:mod:`sphgag.engine.quadrature`; docs/physics.md, "Interface-fitted particles"); a wall without
    pools only, for now (a pool's boundary is not yet an interface of the layout).
    """
    pools = [] if pool is None else [pool] if isinstance(pool, geometry.Sector) else list(pool)
    if fitted and pools:
        raise ValueError(f"[{name}] interface-fitted particles do not yet place particles on a pool's boundary")
    layout = bilayer_layout(p, pools, graded, fitted)
    nb = kernel.for_layout(layout, numerics.kernel_support_factor)
    points = quadrature.build(layout, nb) if fitted else None
    material = BilayerMaterial(p, layout if points is None else points.layout)
    if pools:
        material = seeding(material, layout, pools, gag)
    return Model(name, layout, nb, material, points=points, **numerics.model_options())


def seeding(base, layout: geometry.Layout, sectors, gag: dict) -> history.HistoryMaterial:
    """The material path from the intact wall (``base``) to the wall with the particles of ``sectors`` in its pool
    layers (``layout.pool_layers``, the paper's media) seeded as GAG pools (pool k = sector k); a sector without such
    a particle is an error."""
    members = [s.members(layout, layer=layout.pool_layers) for s in sectors]
    for s, m in zip(sectors, members):
        if not m.size:
            raise ValueError(
                f"the pool {s} holds no particle of a pool layer ({', '.join(layout.pool_layers)}) at dx = "
                f"{layout.dx:g} um: make it larger than the particle spacing or move it into such a layer"
            )
    intact = history.ParticleHistory.intact(layout.n)
    return history.HistoryMaterial(base, intact, gag, after=intact.seed(members))


def carried(p: Bilayer | dict, x: np.ndarray, layout: geometry.Layout) -> np.ndarray:
    """The positions ``x`` of the wall ``p``'s own (uniform) layout, a state without pools, on ``layout`` (the same wall
    with its pools' ends as cell boundaries, graded around them): unchanged where the layouts are one, else the
    axisymmetric map of :func:`sphgag.engine.geometry.axisymmetric_positions`, a guess the first solve on ``layout``
    converges."""
    source = bilayer_layout(p)
    if source.n == layout.n and np.array_equal(source.X, layout.X):
        return x
    return geometry.axisymmetric_positions(source, x, layout)
