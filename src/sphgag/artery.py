"""Arterial models built from configuration slices (paper section 2.4, Tables 1-2).

The builders take plain dictionaries (the ``mean`` and ``numerics`` sections
of ``config/config.yaml``) so that a Snakemake rule passes exactly the
parameters it depends on.
"""

from __future__ import annotations

from . import analytic, geometry, kernel, materials
from .model import Model


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


def mean_model(p: dict, numerics: dict, name: str = "mean") -> Model:
    """Mean-behaviour model (section 2.4.1, Table 1) in its unloaded reference configuration."""
    layout = geometry.quarter_annulus([p["inner_radius_um"], p["outer_radius_um"]], p["dx_um"])
    nb = kernel.for_layout(layout, numerics["kernel_support_factor"])
    props = materials.mean_behaviour(
        layout.n, p["shear_modulus_kPa"], p["lame_lambda_kPa"], mean_fibre_families(p), p["hourglass_modulus_kPa"]
    )
    return Model(name, layout, nb, props, numerics["hourglass_alpha"])


def mean_thick_wall(p: dict) -> analytic.ThickWallTube:
    """Exact incompressible thick-walled tube for the same strain energy (eq. 2.18)."""
    law = analytic.MeanBehaviour(p["shear_modulus_kPa"], mean_fibre_families(p))
    return analytic.ThickWallTube(law, p["inner_radius_um"], p["outer_radius_um"], p["axial_stretch"])
