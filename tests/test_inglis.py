"""The exact pressurised-elliptical-hole field (sphgag.physics.inglis) checked against its defining equations."""

import numpy as np
import pytest

from sphgag.physics import inglis

P, MU, NU = 1.3, 2.0, 0.3
LAM = 2.0 * MU * NU / (1.0 - 2.0 * NU)
A = 1.5
RATIOS = (1.0, 2.0, 3.0)


def _stress(f):
    return np.stack([f["sxx"], f["sxy"], f["sxy"], f["syy"]], axis=-1).reshape(*np.shape(f["sxx"]), 2, 2)


def test_circle_reduces_to_lame():
    R = A
    th = np.linspace(0.0, 2.0 * np.pi, 13, endpoint=False) + 0.1
    for r in (R, 1.3 * R, 2.0 * R, 7.5 * R, 40.0 * R):
        x, y = r * np.cos(th), r * np.sin(th)
        f = inglis.field(x, y, R, R, P, MU, NU)
        s = P * (R / r) ** 2
        np.testing.assert_allclose(f["srr"], -s, rtol=1e-10, atol=1e-12 * s)
        np.testing.assert_allclose(f["stt"], s, rtol=1e-10, atol=1e-12 * s)
        np.testing.assert_allclose(f["srt"], 0.0, atol=1e-10 * s)
        ur = f["ux"] * np.cos(th) + f["uy"] * np.sin(th)
        ut = -f["ux"] * np.sin(th) + f["uy"] * np.cos(th)
        u0 = P * R * R / (2.0 * MU * r)
        np.testing.assert_allclose(ur, u0, rtol=1e-10)
        np.testing.assert_allclose(ut, 0.0, atol=1e-10 * u0)


@pytest.mark.parametrize("ratio", RATIOS)
def test_boundary_traction_is_the_pressure(ratio):
    a, b = A, A / ratio
    t = np.linspace(0.0, 2.0 * np.pi, 50, endpoint=False) + 0.013
    x, y = a * np.cos(t), b * np.sin(t)
    n = np.stack([x / a**2, y / b**2], axis=-1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    f = inglis.field(x, y, a, b, P, MU, NU)
    traction = np.einsum("kij,kj->ki", _stress(f), n)
    np.testing.assert_allclose(traction, -P * n, rtol=0, atol=1e-8 * P)
    # the polar components must be consistent with the Cartesian ones
    er = np.stack([x, y], axis=-1) / np.hypot(x, y)[:, None]
    np.testing.assert_allclose(np.einsum("ki,kij,kj->k", er, _stress(f), er), f["srr"], atol=1e-12 * P * ratio)


@pytest.mark.parametrize("ratio", (1.0, 2.0, 3.0, 5.0))
def test_tip_hoop_stress_is_inglis(ratio):
    a, b = A, A / ratio
    expected = P * (2.0 * ratio - 1.0)
    assert inglis.tip_hoop_stress(a, b, P) == pytest.approx(expected, rel=1e-14)
    f = inglis.field(np.array([a]), np.array([0.0]), a, b, P, MU, NU)
    assert f["syy"][0] == pytest.approx(expected, rel=1e-10)
    assert f["stt"][0] == pytest.approx(expected, rel=1e-10)
    assert f["sxx"][0] == pytest.approx(-P, rel=1e-10)
    # and at the end of the minor axis the hoop stress is p (2 b/a - 1)
    g = inglis.field(np.array([0.0]), np.array([b]), a, b, P, MU, NU)
    assert g["sxx"][0] == pytest.approx(P * (2.0 / ratio - 1.0), rel=1e-10, abs=1e-10 * P)


@pytest.mark.parametrize("ratio", RATIOS)
def test_stresses_decay_like_inverse_square(ratio):
    a, b = A, A / ratio
    th = np.array([0.0, 0.4, 1.1, np.pi / 2, 2.5, 4.0])
    mags = []
    for r in (100.0 * a, 1000.0 * a):
        f = inglis.field(r * np.cos(th), r * np.sin(th), a, b, P, MU, NU)
        mags.append(np.sqrt(f["sxx"] ** 2 + f["syy"] ** 2 + 2 * f["sxy"] ** 2) * r * r)
    assert np.all(mags[0] > 0.1 * P * a * b)
    np.testing.assert_allclose(mags[0], mags[1], rtol=1e-2)


def _exterior_points(a, b, n, seed):
    rng = np.random.default_rng(seed)
    th = rng.uniform(0.0, 2.0 * np.pi, n)
    s = rng.uniform(1.05, 3.0, n)  # scaled elliptical radius, off the boundary
    return s * a * np.cos(th), s * b * np.sin(th)


@pytest.mark.parametrize("ratio", RATIOS)
def test_equilibrium_and_hooke(ratio):
    a, b = A, A / ratio
    x, y = _exterior_points(a, b, 8, seed=int(10 * ratio))
    h = 1e-4 * b
    f = inglis.field(x, y, a, b, P, MU, NU)
    fxp, fxm = (inglis.field(x + s, y, a, b, P, MU, NU) for s in (h, -h))
    fyp, fym = (inglis.field(x, y + s, a, b, P, MU, NU) for s in (h, -h))

    def dx(k):
        return (fxp[k] - fxm[k]) / (2 * h)

    def dy(k):
        return (fyp[k] - fym[k]) / (2 * h)

    # equilibrium: div sigma = 0, relative to p / b
    div_x = dx("sxx") + dy("sxy")
    div_y = dx("sxy") + dy("syy")
    scale = P / b
    assert np.max(np.abs(div_x)) < 1e-6 * scale
    assert np.max(np.abs(div_y)) < 1e-6 * scale
    # guard: the individual derivatives are not trivially zero
    assert np.max(np.abs(dx("sxx"))) > 1e-3 * scale

    # compatibility: stresses are Hooke's law (plane strain) of the displacement gradient
    exx, eyy = dx("ux"), dy("uy")
    exy = 0.5 * (dy("ux") + dx("uy"))
    tr = exx + eyy
    smax = np.max(np.abs(np.stack([f["sxx"], f["syy"], f["sxy"]])))
    np.testing.assert_allclose(2 * MU * exx + LAM * tr, f["sxx"], rtol=0, atol=1e-6 * smax)
    np.testing.assert_allclose(2 * MU * eyy + LAM * tr, f["syy"], rtol=0, atol=1e-6 * smax)
    np.testing.assert_allclose(2 * MU * exy, f["sxy"], rtol=0, atol=1e-6 * smax)


@pytest.mark.parametrize("ratio", RATIOS)
def test_displacement_single_valued_and_decays(ratio):
    a, b = A, A / ratio
    # continuity across the axes (where sqrt(z^2 - 4 R^2 m) changes branch)
    eps = 1e-9 * a
    for x0, y0, dxv, dyv in (
        (0.0, 2.0 * b, eps, 0.0),
        (0.0, -1.5 * b, eps, 0.0),
        (-2.0 * a, 0.0, 0.0, eps),
        (1.2 * a, 0.0, 0.0, eps),
    ):
        f1 = inglis.field(np.array([x0 + dxv]), np.array([y0 + dyv]), a, b, P, MU, NU)
        f2 = inglis.field(np.array([x0 - dxv]), np.array([y0 - dyv]), a, b, P, MU, NU)
        for k in ("ux", "uy", "sxx", "syy", "sxy"):
            assert abs(f1[k][0] - f2[k][0]) < 1e-6 * P * max(1.0, a / MU), (k, x0, y0)
    # displacement around a closed loop returns to its start (no dislocation)
    th = np.linspace(0.0, 2.0 * np.pi, 721)
    f = inglis.field(3 * a * np.cos(th), 3 * a * np.sin(th), a, b, P, MU, NU)
    assert abs(f["ux"][0] - f["ux"][-1]) < 1e-12 * P * a / MU
    assert abs(f["uy"][0] - f["uy"][-1]) < 1e-12 * P * a / MU
    # decay like 1/r (no net force on the hole, so no logarithmic term)
    ang = np.array([0.0, 0.7, np.pi / 2, 2.2, 3.5])
    ru = {}
    for r in (10.0 * a, 100.0 * a, 1000.0 * a):
        g = inglis.field(r * np.cos(ang), r * np.sin(ang), a, b, P, MU, NU)
        ru[r] = np.hypot(g["ux"], g["uy"]) * r
    np.testing.assert_allclose(ru[100.0 * a], ru[1000.0 * a], rtol=1e-3)
    np.testing.assert_allclose(ru[10.0 * a], ru[1000.0 * a], rtol=5e-2)
    assert np.max(ru[1000.0 * a]) > 0.1 * P * a * b / MU  # not trivially zero


def test_rejects_bad_axes():
    with pytest.raises(ValueError):
        inglis.field(np.array([3.0]), np.array([0.0]), 1.0, 2.0, P, MU, NU)
