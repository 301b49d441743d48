"""Particle layout, neighbour lists and corrected kernel gradients (eqs. 2.4-2.9)."""

import numpy as np
import pytest

from sphgag.engine import geometry, kernel


def test_volumes_sum_to_the_exact_area():
    lay = geometry.quarter_annulus([332.0, 444.0], 7.0)
    assert lay.n >= 1400
    assert lay.volume.sum() == pytest.approx(geometry.quarter_annulus_area(332.0, 444.0), rel=1e-13)


def test_surfaces_carry_rings_and_interfaces_are_cell_bounds():
    lay = geometry.quarter_annulus([646.8, 675.2, 687.0], 5.0, layer_names=("media", "adventitia"))
    assert lay.ring_radius[0] == pytest.approx(646.8)
    assert lay.ring_radius[-1] == pytest.approx(687.0)
    # the media/adventitia border is a cell boundary
    media = lay.layer_names.index("media")
    last_media_ring = max(k for k in range(len(lay.ring_radius)) if lay.layer[lay.ring_members(k)[0]] == media)
    assert lay.ring_cell[last_media_ring, 1] == pytest.approx(675.2)
    assert lay.ring_cell[last_media_ring + 1, 0] == pytest.approx(675.2)
    media_area = lay.volume[lay.layer_mask("media")].sum()
    assert media_area == pytest.approx(geometry.quarter_annulus_area(646.8, 675.2), rel=1e-12)


def test_particles_keep_off_the_symmetry_planes(annulus_layout):
    th = annulus_layout.theta
    assert th.min() > 0 and th.max() < np.pi / 2
    # equal arc spacing on every ring, close to dx
    for k in range(len(annulus_layout.ring_radius)):
        m = annulus_layout.ring_members(k)
        arc = np.diff(th[m]) * annulus_layout.ring_radius[k]
        assert np.ptp(arc) < 1e-9
        assert arc.mean() == pytest.approx(annulus_layout.dx, rel=0.15)


def test_spiky_kernel_is_normalised_in_2d():
    h = 3.0
    r = np.linspace(0, h, 20001)
    w = np.array([kernel.spiky(ri, h) for ri in r])
    assert np.trapezoid(2 * np.pi * r * w, r) == pytest.approx(1.0, rel=1e-6)
    dw = np.array([kernel.spiky_derivative(ri, h) for ri in r])
    assert np.allclose(dw[1:-1], np.gradient(w, r)[1:-1], atol=1e-6)


def test_neighbour_lists_are_symmetric_and_half_list_complete(annulus_layout):
    nb = kernel.for_layout(annulus_layout, 2.5)
    owner = np.repeat(np.arange(annulus_layout.n), nb.counts())
    plain = nb.mirror.min(axis=1) > 0
    pairs = set(zip(owner[plain], nb.nbr[plain]))
    assert all((j, i) in pairs for i, j in pairs)
    assert 2 * nb.pair_entry.size + nb.solo_entry.size == nb.n_entries
    assert np.all(owner[nb.pair_reverse] == nb.nbr[nb.pair_entry])
    assert np.all(nb.nbr[nb.pair_reverse] == owner[nb.pair_entry])


def test_corrected_gradients_are_first_order_complete(annulus_layout):
    """sum_j R_ij (x) V_j grad~xi_ij = I at every particle (eq. 2.7)."""
    nb = kernel.for_layout(annulus_layout, 2.5)
    owner = np.repeat(np.arange(annulus_layout.n), nb.counts())
    M = np.zeros((annulus_layout.n, 2, 2))
    np.add.at(M, owner, np.einsum("ea,eb->eab", nb.R, nb.a))
    assert np.abs(M - np.eye(2)).max() < 1e-12


def test_averaging_over_a_physical_length(annulus_layout):
    """The disc average keeps constants; for a linear field it is the value at the centroid of the particles in
    the disc, within a quarter spacing of the particle away from the surfaces (measured 0.17 dx at dx = 14 um,
    length 40 um); a length below the spacing is refused."""
    import pytest

    from sphgag.engine import measure

    lay = annulus_layout
    W = measure.averaging_matrix(lay, 40.0)
    assert np.allclose(W @ np.full(lay.n, 3.5), 3.5)
    r = np.linalg.norm(lay.X, axis=1)
    theta = np.arctan2(lay.X[:, 1], lay.X[:, 0])
    inside = (r > lay.inner_radius + 25) & (r < lay.outer_radius - 25) & (theta > 0.2) & (theta < 1.37)
    lin = 2.0 * lay.X[:, 0] - 0.5 * lay.X[:, 1]
    assert np.abs((W @ lin - lin)[inside]).max() <= 0.25 * lay.dx * np.hypot(2.0, 0.5)
    with pytest.raises(ValueError, match="averaging length"):
        measure.averaging_matrix(lay, 0.5)
