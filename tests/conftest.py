"""Shared fixtures: small layouts and models that compile and solve in seconds."""

from pathlib import Path

import numpy as np
import pytest

from sphgag import artery, config, geometry, kernel, materials
from sphgag.model import Model

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="session")
def full_config():
    return config.load_yaml(ROOT / "config" / "config.yaml")


@pytest.fixture(scope="session")
def ci_config():
    return config.load_yaml(ROOT / "config" / "ci.yaml")


@pytest.fixture(scope="session")
def mean_params(ci_config):
    return ci_config["mean"]


@pytest.fixture(scope="session")
def coarse_mean_model(ci_config):
    """Mean-behaviour model at the CI resolution (dx = 14 um)."""
    return artery.mean_model(ci_config["mean"], ci_config["numerics"], name="test-mean")


def lattice(n=14, spacing=1.0):
    """A free square patch of particles on a uniform lattice (for patch tests)."""
    g = np.arange(n) * spacing
    X, Y = np.meshgrid(g, g, indexing="ij")
    return np.column_stack([X.ravel(), Y.ravel()]), np.full(n * n, spacing * spacing)


class Lattice:
    """Minimal layout-like object for a free lattice patch."""

    def __init__(self, n=14, spacing=1.0):
        self.X, self.volume = lattice(n, spacing)
        self.theta = np.zeros(len(self.volume))
        self.dx = spacing
        self.n = len(self.volume)
        self.inner_surface = np.empty(0, dtype=np.int64)
        self.outer_radius = float(np.abs(self.X).max())


def isotropic_props(n, mu=10.0, lam=100.0, hourglass_modulus=10.0):
    p = materials.empty_props(n)
    p[:, materials.MU] = mu
    p[:, materials.LAM] = lam
    p[:, materials.HG_E] = hourglass_modulus
    return p


@pytest.fixture
def free_lattice_model():
    """Isotropic neo-Hookean lattice patch without symmetry planes (free body)."""
    lay = Lattice()
    nb = kernel.build_neighbours(lay.X, lay.volume, 2.5 * lay.dx, mirrors=())
    return Model("lattice", lay, nb, isotropic_props(lay.n), hourglass_alpha=50.0)


@pytest.fixture(scope="session")
def annulus_layout():
    return geometry.quarter_annulus([332.0, 444.0], 14.0)
