"""Arterial models built from configuration slices (paper section 2.4, Tables 1-2).

A Snakemake rule passes exactly the parameters it depends on, as plain dictionaries (the ``mean``, ``bilayer`` and
``numerics`` sections of ``config/config.yaml``); the bi-layered wall and the numerics are read as typed options
(:class:`Bilayer`, :class:`sphgag.engine.numerics.Numerics`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..engine import geometry, history, kernel
from ..engine.loading import Load
from ..engine.model import Model
from ..engine.numerics import Numerics
from ..options import Options
from ..physics import analytic, materials


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
    numerics = Numerics.of(numerics)
    layout = geometry.quarter_annulus([p["inner_radius_um"], p["outer_radius_um"]], p["dx_um"])
    nb = kernel.for_layout(layout, numerics.kernel_support_factor)
    props = materials.mean_behaviour(
        layout.n, p["shear_modulus_kPa"], p["lame_lambda_kPa"], mean_fibre_families(p), p["hourglass_modulus_kPa"]
    )
    return Model(name, layout, nb, props, **numerics.hourglass_control())


def mean_thick_wall(p: dict) -> analytic.ThickWallTube:
    """Exact incompressible thick-walled tube for the same strain energy (eq. 2.18)."""
    families = tuple(analytic.Family(1.0, a, c1, c2) for a, c1, c2 in mean_fibre_families(p))
    law = analytic.Mixture(p["shear_modulus_kPa"], families)
    return analytic.ThickWallTube.single(law, p["inner_radius_um"], p["outer_radius_um"], p["axial_stretch"])


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


def bilayer_families(p: Bilayer | dict, layer: str):
    """Fibre families of one layer as :class:`analytic.Family` (eqs. 2.22-2.23, Table 2).

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
        return analytic.Family(phi, alpha, col.c1_kPa, col.c2, col.c1_compression_kPa, col.c2_compression, pre.collagen)

    fams = []
    if "smc" in frac:
        fams.append(
            analytic.Family(frac["smc"], 90.0, smc.c1_kPa, smc.c2, smc.c1_compression_kPa, smc.c2_compression, pre.smc)
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


def bilayer_law(p: Bilayer | dict, layer: str, active: bool) -> analytic.Mixture:
    """Incompressible constituents of one layer at full pre-stretch, for the semi-analytical tube."""
    p = Bilayer.of(p)
    gr, gt, _ = elastin_prestretch(p)
    act = p.active
    return analytic.Mixture(
        mu=p.mass_fractions[layer]["elastin"] * p.elastin_shear_modulus_kPa,
        families=bilayer_families(p, layer),
        Gr=gr,
        Gt=gt,
        tmax=act.max_stress_kPa if (active and has_smc(p, layer)) else 0.0,
        lmax=act.stretch_max,
        lmin=act.stretch_min,
    )


def bilayer_tube(p: Bilayer | dict, active: bool) -> analytic.ThickWallTube:
    """Semi-analytical incompressible layered tube (same layers, constituents and pre-stretches)."""
    p = Bilayer.of(p)
    return analytic.ThickWallTube([(a, b, bilayer_law(p, name, active), name) for name, a, b in p.bands()], lz=1.0)


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


def pool_sector(case: dict) -> geometry.Sector:
    """A GAG pool from its configuration entry (centre, radial and angular extent)."""
    return geometry.Sector(
        case["centre_radius_um"], case["centre_angle_deg"], case["radial_extent_um"], case["angular_extent_deg"]
    )


def bilayer_layout(p: Bilayer | dict) -> geometry.Layout:
    """Particles of the layered wall: one band per entry of ``layers``, each split at the ``aligned_radii_um`` inside
    it (cell boundaries: the radial edges of GAG pools)."""
    p = Bilayer.of(p)
    radii, names = [p.inner_radius_um], []
    for name, a, b in p.bands():
        inside = sorted(r for r in p.aligned_radii_um if a < r < b)
        radii += [*inside, b]
        names += [name] * (len(inside) + 1)
    return geometry.quarter_annulus(radii, p.dx_um, layer_names=names, pool_layers=p.pool_layers)


def bilayer_model(
    p: Bilayer | dict,
    numerics: Numerics | dict,
    name: str = "bilayer",
    pool=None,
    gag: materials.Gag | dict | None = None,
) -> Model:
    """Bi-layered model (section 2.4.2, Table 2) in its in vivo reference configuration.

    The radii ``aligned_radii_um`` inside the media are cell boundaries of the
    particle layout (sub-layers of the media), so that a pool whose radial
    edges are among them has exactly its thickness at every resolution.

    With ``pool`` (a :class:`geometry.Sector`, or a list of them) and the ``gag``
    parameters, the material is a :class:`history.HistoryMaterial` on the path from
    the intact wall to the wall with those medial sectors seeded as GAG pools: the
    load's ``transition`` converts them and its ``concentration`` swells them.
    """
    numerics = Numerics.of(numerics)
    layout = bilayer_layout(p)
    nb = kernel.for_layout(layout, numerics.kernel_support_factor)
    material = BilayerMaterial(p, layout)
    if pool is not None:
        material = seeding(material, layout, [pool] if isinstance(pool, geometry.Sector) else list(pool), gag)
    return Model(name, layout, nb, material, **numerics.hourglass_control())


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
