"""What researchers look at: ParaView series read back against the states they came from, and the animations."""

import dataclasses

import numpy as np
import pandas as pd
import pytest

from sphgag.engine import geometry, measure
from sphgag.engine.history import HistoryMaterial
from sphgag.records import state
from sphgag.studies import artery
from sphgag.studies.delamination.growth import grow
from sphgag.studies.delamination.runs import save_snapshots
from sphgag.views import paraview

from .conftest import CI_NUMERICS, law_gag
from .test_delamination import settings


@pytest.fixture(scope="module")
def grown(ci_config, ci_wall, tmp_path_factory):
    """A short delamination run of the CI wall (damage at once, so that the pool grows in a few passes:
    :func:`tests.test_delamination.settings`), its snapshots saved as the pipeline saves them."""
    st = settings(ci_config)
    model = artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-views")
    gag = law_gag(ci_config)
    result = grow(model, ci_wall, [geometry.Sector(663.0, 45.0, 15.0, 3.0)], st, CI_NUMERICS, gag, model.props)
    path = tmp_path_factory.mktemp("views") / "snapshots.npz"
    save_snapshots(path, model, result.snapshots, {"run": "test"})
    return gag, path, result


def intact_wall(ci_config):
    return artery.bilayer_model(ci_config["bilayer"], CI_NUMERICS, name="test-views-export")


def test_a_paraview_series_reads_back_as_the_states_it_came_from(ci_config, grown, tmp_path):
    gag, path, result = grown
    model = intact_wall(ci_config)
    base = model.props
    frames = paraview.delamination_frames(model, path, gag, {"run": "test"})
    pvd = paraview.write_series(tmp_path / "run.pvd", frames)
    series = paraview.read_series(pvd)
    saved = state.load_series(path, {"run": "test"})
    assert len(series) == len(saved) == len(result.snapshots) > 1
    with np.load(path) as npz:
        stored_radial = [npz[f"s{k}_radial_stress_kPa"] for k in range(len(saved))]
    assert [f.time for f in series] == list(range(len(saved)))  # distinct times: ParaView's slider steps every state
    assert [f.data["pseudo_time"][0] for f in series] == [float(s.info["pseudo_time"]) for s in saved]
    for k, (frame, s) in enumerate(zip(series, saved)):
        d = frame.data
        assert set(paraview.FIELDS) <= set(d)
        np.testing.assert_array_equal(frame.x, s.x)
        np.testing.assert_array_equal(d["reference_position"][:, :2], model.layout.X)
        np.testing.assert_array_equal(d["displacement"][:, :2], s.x - model.layout.X)
        # the radial stress the run measured on its own converged state, recomputed from the saved one
        np.testing.assert_allclose(d["cauchy_rr_kPa"], stored_radial[k], rtol=1e-10, atol=1e-9)
        model.set_props(HistoryMaterial(base, s.history, gag))
        srr, stt, srt, J = measure.cauchy_polar(model.evaluate(s.x, s.load))
        model.set_props(base)
        np.testing.assert_array_equal(d["cauchy_tt_kPa"], stt)
        np.testing.assert_array_equal(d["cauchy_rt_kPa"], srt)
        np.testing.assert_array_equal(d["J"], J)
        np.testing.assert_array_equal(d["damage"], s.history.D)
        np.testing.assert_array_equal(d["origin"], s.history.origin)
        np.testing.assert_array_equal(d["pool"], s.history.pool)
        np.testing.assert_array_equal(d["layer"], model.layout.layer)
        c = s.load.material_value("concentration")
        np.testing.assert_array_equal(d["concentration_mEq_l"], np.where(s.history.gag, c, 0.0))
    assert series[-1].data["damage"].max() > 0.0  # the run grew: damage is in the series


def test_a_series_written_twice_is_the_same_bytes(ci_config, grown, tmp_path):
    gag, path, _ = grown
    frames = paraview.delamination_frames(intact_wall(ci_config), path, gag, {"run": "test"})
    a = paraview.write_series(tmp_path / "a" / "run.pvd", frames)
    b = paraview.write_series(tmp_path / "b" / "run.pvd", frames)
    for fa in sorted(a.parent.iterdir()):
        assert fa.read_bytes() == (b.parent / fa.name).read_bytes(), fa.name


def test_an_animation_shows_every_frames_stresses_and_partial_damage(ci_config, grown, tmp_path):
    """Each frame has its own colour range (a wall at 1/100 of the last frame's stresses is not drawn white), and
    tissue with 0 < D < 1 has a colour of its own."""
    from PIL import Image

    from sphgag.views import animation

    gag, path, _ = grown
    last = paraview.delamination_frames(intact_wall(ci_config), path, gag, {"run": "test"})[-1]
    quiet = dict(last.data, cauchy_rr_kPa=last.data["cauchy_rr_kPa"] / 100.0, damage=np.zeros_like(last.data["damage"]))
    tissue = np.flatnonzero(last.data["origin"] == 0)
    damaged = dict(last.data, damage=last.data["damage"].copy())
    box = animation.view([last])
    inside = (last.x[tissue, 0] > box[0]) & (last.x[tissue, 0] < box[1])
    inside &= (last.x[tissue, 1] > box[2]) & (last.x[tissue, 1] < box[3])
    damaged["damage"][tissue[inside][:20]] = 0.5
    frames = [paraview.Frame(0.0, last.x, quiet), paraview.Frame(1.0, last.x, damaged)]
    assert animation.stress_range(frames[0], box) == pytest.approx(
        animation.stress_range(dataclasses.replace(frames[1], data=dict(damaged, damage=quiet["damage"])), box) / 100
    )
    gif = animation.write(tmp_path / "run.gif", frames, "test")
    with Image.open(gif) as im:
        pixels = []
        for k in range(im.n_frames):
            im.seek(k)
            pixels.append(np.asarray(im.convert("RGB"), dtype=int).reshape(-1, 3))

    def saturated(rgb):  # strong reds or blues of the stress map
        return int(np.sum((np.abs(rgb[:, 0] - rgb[:, 2]) > 120) & (rgb.max(axis=1) - rgb.min(axis=1) > 120)))

    orange = np.array([0xD9, 0x5F, 0x02])
    for k, rgb in enumerate(pixels):
        assert saturated(rgb) > 200, k  # the quiet frame's stresses are visible too
    assert np.sum(np.all(np.abs(pixels[1] - orange) < 12, axis=1)) > 50  # partial damage, in its colour
    assert np.sum(np.all(np.abs(pixels[0] - orange) < 12, axis=1)) < 5  # and not where there is none


# --- the figures (sphgag.views.<family>), each drawn from small tables made here ------------------------------------

WALL_PRESSURES = (103.0, 145.0, 200.0)
DARK2 = ("#1b9e77", "#d95f02", "#7570b3")  # what figures 3 and 4 have always drawn 103, 145 and 200 mmHg in
SWELLING_CASES = {  # config/ci.yaml's pools
    "I": {"centre_radius_um": 663.0, "centre_angle_deg": 51.5, "radial_extent_um": 15.0, "angular_extent_deg": 3.0},
    "IV": {"centre_radius_um": 663.0, "centre_angle_deg": 51.5, "radial_extent_um": 15.0, "angular_extent_deg": 16.0},
}


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def _titles(fig) -> list[str]:
    """Every axes title of ``fig`` (centre and left)."""
    return [t for ax in fig.axes for t in (ax.get_title(), ax.get_title(loc="left")) if t]


def _concat(frames) -> pd.DataFrame:
    return pd.concat(frames, ignore_index=True)


def _hex(colour) -> str:
    import matplotlib.colors

    return matplotlib.colors.to_hex(colour)


def _particles(dx=8.0, r0=600.0, r1=720.0, border=680.0) -> pd.DataFrame:
    """A quarter annulus of particles as rule homeostasis writes them (particles.csv)."""
    r, th = np.meshgrid(np.arange(r0 + dx / 2, r1, dx), np.arange(0.0, np.pi / 2, dx / 660.0), indexing="ij")
    r, th = r.ravel(), th.ravel()
    return pd.DataFrame(
        dict(
            x_um=r * np.cos(th),
            y_um=r * np.sin(th),
            radius_um=r,
            theta_rad=th,
            volume_um2=dx * dx,
            layer=np.where(r < border, "media", "adventitia"),
        )
    )


def test_figure_1_draws_the_particles_the_kernel_and_the_composition():
    from sphgag.views import layout

    particles = _particles()
    fractions = {
        "media": {"elastin": 0.3, "smc": 0.6, "collagen": 0.1},
        "adventitia": {"elastin": 0.1, "collagen": 0.9},
    }
    fig = layout.fig1(particles, fractions, 2.0, 8.0)
    assert len(fig.axes) == 4
    titles = _titles(fig)
    assert titles[0] == f"(a) {len(particles)} particles, dx = 8 um"
    assert titles[1:] == ["(a) 6 deg sector\n(symbol area ~ volume)", "(b) spiky kernel, h = 2 dx", "(c) composition"]
    assert fig.axes[0].get_legend_handles_labels()[1] == [
        f"{layer} ({n})" for layer, n in particles.layer.value_counts().sort_index().items()
    ]


def test_figure_1_shows_a_third_layer_in_the_order_of_the_wall():
    """A lamina between media and adventitia (a layer of the configuration, not of the code): its particles get a
    colour of their own and its composition a bar, in the wall's order."""
    from sphgag.views import layout, style

    particles = _particles()
    particles.loc[particles.radius_um.between(676.0, 684.0), "layer"] = "lamina"
    fractions = {
        "adventitia": {"elastin": 0.1, "collagen": 0.9},  # sorted keys, as the pipeline's canonical configuration
        "lamina": {"elastin": 1.0, "collagen": 0.0},
        "media": {"elastin": 0.3, "smc": 0.6, "collagen": 0.1},
    }
    fig = layout.fig1(particles, fractions, 2.0, 8.0, ["media", "lamina", "adventitia"])
    bars = fig.axes[3]
    assert [t.get_text() for t in bars.get_xticklabels()] == ["media", "lamina", "adventitia"]
    colours = {_hex(c.get_facecolor()[0]) for c in fig.axes[0].collections}
    assert len(colours) == 3 and _hex(style.LAYER_COLOURS["media"]) in colours


def test_figure_3c_finds_every_border_of_a_lamellar_wall():
    """The layers of a transmural profile from the lumen out, a name repeating (media, lamina, media, adventitia):
    figure 3c draws a line at each border."""
    from sphgag.views import wall

    names = ["media"] * 4 + ["lamina"] + ["media"] * 3 + ["adventitia"] * 2
    profile = pd.DataFrame(dict(radius_um=np.arange(10.0)[::-1], layer=names[::-1]))  # rows in any order
    runs = wall.layer_runs(profile)
    assert runs == [("media", 3.0), ("lamina", 4.0), ("media", 7.0), ("adventitia", 9.0)]


def _pressure_curve(scale=1.0) -> pd.DataFrame:
    """A pressure-diameter curve with its mean circumferential stretch and stress (calibrate_mean's columns)."""
    p = np.arange(0.0, 201.0, 10.0)
    stretch = 1.0 + scale * 0.4 * p / (p + 60.0)
    return pd.DataFrame(
        dict(
            pressure_mmHg=p,
            outer_diameter_um=700.0 * stretch,
            mean_circ_stretch=stretch,
            mean_circ_stress_kPa=1.5 * p * stretch,
        )
    )


def _transmural(pressures=WALL_PRESSURES) -> pd.DataFrame:
    """Transmural profiles (transmural.csv): exact and SPH, of the mean, passive and active models."""
    rows = []
    for model in ("mean", "passive", "active"):
        for p in pressures:
            for source, n in (("exact", 30), ("sph", 8)):
                r = np.linspace(640.0, 720.0, n)
                rows.append(
                    pd.DataFrame(
                        dict(
                            model=model,
                            pressure_mmHg=p,
                            source=source,
                            radius_um=r,
                            radial_stress_kPa=-p * 0.133 * (720.0 - r) / 80.0,
                            circ_stress_kPa=p * (1.0 + (720.0 - r) / 80.0),
                            layer=np.where(r < 690.0, "media", "adventitia"),
                        )
                    )
                )
    return pd.concat(rows, ignore_index=True)


def _lines_at(ax, y) -> int:
    """How many horizontal lines of ``ax`` lie at ``y``."""
    return sum(1 for line in ax.get_lines() if len(line.get_ydata()) == 2 and np.allclose(line.get_ydata(), [y, y]))


def test_figure_3_draws_the_wall_models_in_the_colours_of_their_pressures():
    from sphgag.views import wall

    exact = _pressure_curve()
    states = exact.iloc[::2].reset_index(drop=True)
    bilayer_exact = {"passive": _pressure_curve(0.8), "active": _pressure_curve(0.6)}
    bilayer = _concat(
        [bilayer_exact[m].iloc[::2].assign(model=m) for m in ("passive", "active")],
    )
    fig = wall.fig3(states, exact, bilayer, bilayer_exact, _transmural(), 110.0)
    assert len(fig.axes) == 8
    assert _titles(fig) == [
        "(a) mean-behaviour model",
        "(a) bi-layered model",
        "(b) mean-behaviour model",
        "(c) bi-layered model",
    ]
    legend = fig.axes[7].get_legend()
    labels = [t.get_text() for t in legend.texts]
    assert labels[:3] == ["103 mmHg", "145 mmHg", "200 mmHg"]
    assert [_hex(h.get_color()) for h in legend.legend_handles[:3]] == list(DARK2)
    # the homeostatic pressure is the argument's (homeostasis.target_pressure_mmHg), on both pressure-diameter panels
    assert _lines_at(fig.axes[0], 110.0) == _lines_at(fig.axes[1], 110.0) == 1

    fig = wall.fig3a_mean(states, exact, 0.01, 120.0)
    assert len(fig.axes) == 2 and fig.axes[0].get_title() == "mean-behaviour model"
    assert _lines_at(fig.axes[0], 120.0) == 1 and _lines_at(fig.axes[0], 103.0) == 0

    fig = wall.fig3b(_transmural((90.0, 103.0)))
    assert len(fig.axes) == 2 and fig.axes[0].get_title() == "mean-behaviour model"
    legend = fig.axes[0].get_legend()
    assert [t.get_text() for t in legend.texts] == ["90 mmHg", "103 mmHg", "exact thick wall", "SPH (ring means)"]
    assert [_hex(h.get_color()) for h in legend.legend_handles[:2]] == list(DARK2[:2])  # any pressures, a colour each


def _tips(variants, models=("passive",), cases=tuple(SWELLING_CASES), pressures=(103.0, 200.0)) -> pd.DataFrame:
    """Figure 4's table (tip_stress.csv) for ``variants`` (charge law, pool model), ``models``, ``cases`` and
    ``pressures``: the intact wall, and the converted pool at four concentrations."""
    concentrations = (0.0, 50.0, 100.0, 150.0)
    rows = []
    for k, (law, pool) in enumerate(variants):
        for model in models:
            for case in cases:
                for p in pressures:
                    for stage, cs in (("intact", concentrations[:1]), ("converted", concentrations)):
                        for c in cs:
                            tip = (k + 1) * (c / 10.0 - 5.0) + p / 100.0
                            rows.append(
                                dict(
                                    charge_law=law,
                                    pool_model=pool,
                                    model=model,
                                    case=case,
                                    pressure_mmHg=p,
                                    stage=stage,
                                    concentration_mEq_l=c,
                                    tip_radial_stress_kPa=tip,
                                    tip_peak_radial_stress_kPa=1.5 * tip,
                                    top_circ_stress_kPa=200.0 + p + c,
                                    pool_volume_change=c / 300.0,
                                )
                            )
    return pd.DataFrame(rows)


def _fig4(tips, law):
    from sphgag.views import swelling

    cases = {name: SWELLING_CASES[name] for name in dict.fromkeys(tips.case)}
    return swelling.fig4(tips, _particles(), cases, 10.0, law, 150.0, WALL_PRESSURES, pool_layers=["media"])


def test_figure_4_is_laid_out_as_the_papers_for_one_law_in_figure_3s_colours():
    """One law a figure: (a) the pools, then a block per wall ((b) passive, (c) active; another pool model has blocks
    of its own), a tip radial and a top hoop row each, a column per pool; the paper's "~50 kPa above 100 mEq/l" on
    every tip radial stress panel."""
    from sphgag.views import overlap, swelling

    variants = [("prescribed", "particles"), ("prescribed", "cavity"), ("conserved", "particles")]
    tips = _tips(variants, models=("passive", "active"))
    fig = _fig4(tips, "prescribed")
    assert len(fig.axes) == (1 + 2 * 2 * 2) * len(SWELLING_CASES)  # (a), then tip and top per pool model and wall
    titles = _titles(fig)
    assert titles[:2] == ["(a) case I: 3 deg", "(a) case IV: 16 deg"]
    assert [t for t in titles if t[0] == "(" and "case" not in t] == [
        "(b) passive model",
        "(c) active model",
        "(d) passive model, pool as cavity",
        "(e) active model, pool as cavity",
    ]
    assert fig._suptitle.get_text().startswith("Figure 4: prescribed charge law")
    assert [fig.axes[k].get_ylabel() for k in (2, 4)] == [swelling.TIP, swelling.TOP]
    tip_panels = [ax for ax in fig.axes if ax.get_ylabel() == swelling.TIP or ax in fig.axes[3:4]]
    for ax in tip_panels:  # the paper's band: 50 kPa from 100 mEq/l
        assert any(list(line.get_ydata()) == [50.0, 50.0] for line in ax.lines), ax.get_ylabel()
    legend = fig.legends[0]
    colours = {t.get_text(): _hex(h.get_color()) for t, h in zip(legend.texts, legend.legend_handles)}
    assert colours["103 mmHg"] == DARK2[0] and colours["200 mmHg"] == DARK2[2]  # 200 mmHg as in figure 3
    assert swelling.PAPER_TIP_LABEL in colours
    assert overlap.overlaps(fig) == []
    fig = _fig4(tips, "conserved")
    assert len(fig.axes) == (1 + 2 * 2) * len(SWELLING_CASES)
    assert fig._suptitle.get_text().startswith("Figure 4: conserved charge law")


def test_figure_4_and_the_resolution_study_draw_a_third_charge_law():
    from sphgag.views import style, swelling

    laws = ["prescribed", "conserved", "ideal"]
    fig = _fig4(_tips([(law, "particles") for law in laws], cases=("IV",)), "ideal")
    assert len(fig.axes) == 1 + 2  # (a), then tip and top
    assert fig._suptitle.get_text() == "Figure 4: ideal charge law" == f"Figure 4: {style.law_title('ideal')}"

    table = _concat(
        [
            _tips([(law, "particles")], cases=("IV",), pressures=(103.0,))
            .query("stage == 'converted'")
            .assign(dx_um=dx)
            for law in laws
            for dx in (8.0, 6.0)
        ]
    )
    fig = swelling.swelling_convergence(table, laws)
    assert len(fig.axes) == 3 * len(laws)  # a row per quantity (tip, top, pool volume), a column per pool and law
    assert "case IV, passive\nideal" in _titles(fig)


def test_figure_4_draws_the_resolution_bands_and_the_tip_stress_against_pool_volume():
    """With the resolution study (three spacings, first-order synthetic values), the paper's block draws the
    extrapolated curve and a GCI band in cases I and IV, marks where the band first exceeds 10 %, and a last row
    plots the tip stress against the pool volume per spacing; without it the figure says the study has not run."""
    from matplotlib.collections import PolyCollection

    from sphgag.studies.resolution import swelling_band
    from sphgag.views import swelling

    variants = [("prescribed", "particles")]
    tips = _tips(variants, pressures=(103.0,))
    resolution = _concat(
        [
            _tips(variants, pressures=(103.0,)).assign(
                dx_um=h, tip_radial_stress_kPa=lambda t, h=h: t.tip_radial_stress_kPa * (1.0 + 0.1 * h)
            )
            for h in (3.0, 2.12, 1.5)
        ]
    )
    band = swelling_band(resolution, 103.0)
    cases = {name: SWELLING_CASES[name] for name in dict.fromkeys(tips.case)}
    args = (tips, _particles(), cases, 10.0, "prescribed", 150.0, WALL_PRESSURES)
    fig = swelling.fig4(*args, pool_layers=["media"], band=band, resolution=resolution)
    assert len(fig.axes) == (1 + 2 + 1) * len(cases)  # (a), tip and top, then tip against pool volume
    tip_axes = fig.axes[len(cases) : 2 * len(cases)]
    assert all(any(isinstance(c, PolyCollection) for c in ax.collections) for ax in tip_axes)
    assert swelling.EXTRAPOLATED in [t.get_text() for t in fig.legends[0].texts]
    assert any("GCI > 10%" in t.get_text() for ax in tip_axes for t in ax.texts)
    volume = fig.axes[-len(cases)]
    assert volume.get_xlabel() == "pool volume ratio J" and len(volume.lines) == 3 + 1  # a line per dx, and zero
    fig = swelling.fig4(*args, pool_layers=["media"])
    assert swelling.NOT_RUN in [t.get_text() for t in fig.legends[0].texts]


def test_the_verification_figures_draw_their_panels():
    from sphgag.views import verification

    b, pressure = 20.0, 10.0
    table = pd.DataFrame(
        [
            dict(
                aspect_ratio=ratio,
                b_over_dx=n,
                dx_um=b / n,
                semi_axis_b_um=b,
                pressure_kPa=pressure,
                tip_stress_kPa=pressure * (2 * ratio - 1) * (1 - 0.5 / n),
                reference_kPa=pressure * (2 * ratio - 1),
                rel_error=-0.5 / n,
                first_particle_rel_error=-1.0 / n,
                field_rms_error_kPa=pressure / n**2,
                traction_jump_kPa=pressure / n,
            )
            for ratio in (1.0, 2.0, 3.0)
            for n in (4.0, 8.0)
        ]
    )
    s, r = np.linspace(0.0, 2.0 * b, 10), np.linspace(0.2 * b, 2.0 * b, 10)
    profiles = _concat(
        [
            pd.DataFrame(
                dict(
                    profile="rings",
                    aspect_ratio=1.0,
                    b_over_dx=n,
                    radius_um=r,
                    radial_sph_kPa=-pressure,
                    circ_sph_kPa=pressure,
                    radial_exact_kPa=-pressure,
                    circ_exact_kPa=pressure,
                )
            )
            for n in (4.0, 8.0)
        ]
        + [
            pd.DataFrame(
                dict(
                    profile="axis",
                    aspect_ratio=ratio,
                    b_over_dx=n,
                    s_um=s,
                    hoop_exact_kPa=pressure * ratio,
                    hoop_sph_kPa=pressure * ratio * 0.9,
                )
            )
            for ratio in (1.0, 2.0, 3.0)
            for n in (4.0, 8.0)
        ]
    )
    fig = verification.verification_pool(table, profiles)
    assert len(fig.axes) == 4
    assert _titles(fig) == [
        "(a) circular inclusion: ring means",
        "(b) ahead of the tip: SPH (o), Inglis (-)",
        "(c) tip stress and first particle",
        "(d) field rms error, traction jump",
    ]

    circular = pd.DataFrame(
        [
            dict(pool_model=m, target_volume_ratio=j, dx_um=dx, volume_error=0.01 * dx, lining_error=0.02 * dx)
            for m in ("particles", "cavity")
            for j in (1.5, 2.0)
            for dx in (4.0, 3.0, 2.0)
        ]
    )
    circular.loc[circular.index[-1], ["volume_error", "lining_error"]] = np.nan  # a path that ended
    fig = verification.verification_circular_pool(circular)
    assert len(fig.axes) == 2
    assert _titles(fig) == ["(a) pool volume ratio", "(b) radius of the lining"]
    assert any("no equilibrium" in t.get_text() for t in fig.texts)

    crack = pd.DataFrame(
        [
            dict(
                dx_um=dx,
                nominal_half_length_um=a,
                half_length_um=a + dx / 4,
                critical_pressure_kPa=100.0 / np.sqrt(a),
                pressure_kPa=5.0,
                opening_area_um2=2 * np.pi * a**2 * 5.0 / 300.0,
                rel_error=0.1 * dx / a,
                area_rel_error=0.05 * dx / a,
                energy_rel_error=0.2 * dx / a,
            )
            for dx in (4.0, 2.0)
            for a in (40.0, 80.0)
        ]
    )
    fig = verification.verification_crack(crack, 300.0, 0.01, 50.0)
    assert len(fig.axes) == 3
    assert _titles(fig) == ["(a) onset of growth", "(b) opening before growth", "(c) errors against resolution"]


THREE_CRITERIA = ["averaged", "particle", "strain"]  # a third onset criterion, not (yet) in the registry


def test_the_criterion_styles_keep_the_first_two_and_tell_any_number_apart():
    from sphgag.views import delamination as views

    assert views.criterion_dashes(["averaged", "particle"]) == {"averaged": "", "particle": (3.7, 1.6)}
    assert views.criterion_colours(["averaged", "particle"]) == {"averaged": "k", "particle": "#d95f02"}
    names = [f"c{k}" for k in range(12)]
    dashes, colours = views.criterion_dashes(names), views.criterion_colours(names)
    assert list(dashes) == list(colours) == names
    assert len(set(dashes.values())) == len(set(map(_hex, colours.values()))) == len(names)


def _snapshots(steps=3, centre_deg=50.0, dx=6.0):
    """A run's ``*_snapshots.npz`` as :func:`sphgag.views.snapshots.read_snapshots` returns it: a pool of seeded
    GAG (origin 1) in a patch of wall, tissue beside it damaged and then converted (origin 2) as the run goes on."""
    r, th = np.meshgrid(np.arange(640.0, 712.0, dx), np.deg2rad(np.arange(40.0, 60.0, np.rad2deg(dx / 663.0))))
    r, th = r.ravel(), th.ravel()
    X = np.column_stack([r * np.cos(th), r * np.sin(th)])
    off = np.abs(np.rad2deg(th) - centre_deg)
    ring = np.abs(r - 663.0) < 8.0
    snap = dict(
        X=X,
        theta=th,
        volume=np.full(len(r), dx * dx),
        steps=np.arange(steps),
        concentrations=np.linspace(50.0, 150.0, steps),
    )
    for k in range(steps):
        origin = np.where(ring & (off < 1.0), 1, np.where(ring & (off < 1.0 + 0.6 * k), 2, 0))
        snap[f"s{k}_x"] = X * (1.0 + 0.002 * k)
        snap[f"s{k}_history_origin"] = origin
        snap[f"s{k}_history_pool"] = np.where(origin > 0, 0, -1)
        snap[f"s{k}_history_D"] = np.where((origin == 0) & ring & (off < 2.0 + 0.6 * k), 0.5, 0.0)
    return snap


def _growth(laws, cases, sigmas, criteria, steps=6):
    """Figures 5-7's tables: growth.csv and summary.csv of every run."""
    growth, summary = [], []
    for law in laws:
        for case in cases:
            for sigma in sigmas:
                for j, criterion in enumerate(criteria):
                    converted = np.maximum(np.arange(steps) - 2 - j, 0)
                    growth.append(
                        pd.DataFrame(
                            dict(
                                charge_law=law,
                                case=case,
                                sigma_cr_kPa=sigma,
                                criterion=criterion,
                                step=np.arange(steps),
                                pseudo_time=np.arange(steps, dtype=float),
                                concentration_mEq_l=np.minimum(50.0 * np.arange(1, steps + 1), 150.0),
                                delaminated_length_um=6.0 * converted,
                                tip_radial_stress_kPa=sigma * (0.5 + 0.3 * (np.arange(steps) % 3)),
                                converted_particles=converted,
                                converted_interior=converted // 2,
                                converted_exterior=converted - converted // 2,
                                snap=np.arange(steps) == steps - 1,
                            )
                        )
                    )
                    summary.append(
                        dict(
                            charge_law=law,
                            case=case,
                            sigma_cr_kPa=sigma,
                            criterion=criterion,
                            onset_concentration_mEq_l=100.0,
                            runaway_concentration_mEq_l=104.5,
                            final_length_um=6.0 * converted[-1],
                            merged=j == 0,
                            merge_step=4.0,
                            snaps=1,
                            stop_kind="merged" if j == 0 else "unstable",
                            stop="arrested",
                        )
                    )
    return _concat(growth), pd.DataFrame(summary)


# a lamellar wall: the snapshots grey each layer, the material key names each
WALL_LAYERS = [["media", 680.0], ["lamina", 681.0], ["media", 690.0], ["adventitia", 720.0]]


@pytest.mark.filterwarnings("error:constrained_layout not applied")  # panels wide enough for their titles
def test_figures_5_to_7_draw_three_onset_criteria_one_law_a_figure():
    from sphgag.views import delamination as views
    from sphgag.views import overlap

    laws, criteria = ["prescribed"], THREE_CRITERIA
    growth, summary = _growth(laws, ["single", "low", "high", "offset"], [40.0, 60.0], criteria)
    snap = _snapshots()

    fig = views.fig5(growth, summary, {c: snap for c in criteria}, "single", 40.0, criteria, "prescribed", WALL_LAYERS)
    titles = _titles(fig)
    assert [f"(b) {c} onset measure" in titles for c in criteria] == [True] * 3
    assert "(c) growth: onset (triangles),\nrunaway (lines)" in titles
    assert sum(t.startswith("(a) strain, 40 kPa\n") for t in titles) == 3  # a row of three states per criterion
    (growth_ax,) = [ax for ax in fig.axes if ax.get_title().startswith("(c) growth")]
    assert set(criteria) <= set(growth_ax.get_legend_handles_labels()[1])  # a line style per criterion
    tip = [ax for ax in fig.axes if ax.get_title() == "(b) averaged onset measure"][0]
    assert [views.PAPER_SIGMA] * 2 in [list(line.get_ydata()) for line in tip.lines]  # the paper's sigma_cr
    assert views.PAPER_SIGMA_LABEL in [t.get_text() for t in tip.get_legend().texts]
    (key,) = fig.legends
    assert [t.get_text() for t in key.get_texts()][:3] == ["intact media", "intact lamina", "intact adventitia"]
    assert overlap.overlaps(fig) == []

    fig = views.fig6(
        growth,
        summary,
        {(case, c): snap for case in ("low", "high") for c in criteria},
        ["low", "high"],
        criteria,
        "prescribed",
        WALL_LAYERS,
    )
    titles = _titles(fig)
    assert "(c) low: converted particles" in titles and "(c) high: converted particles" in titles
    assert sum(t.startswith("(b) high, strain: last\n") for t in titles) == 1  # the last state of the third criterion
    assert overlap.overlaps(fig) == []

    fig = views.fig7(growth, summary, {c: snap for c in criteria}, "offset", 40.0, criteria, "prescribed", WALL_LAYERS)
    (tip,) = [ax for ax in fig.axes if ax.get_title().startswith("(b) offset: tip radial stress")]
    colours = {_hex(line.get_color()) for line in tip.get_lines()[: len(criteria)]}
    assert colours == set(map(_hex, views.criterion_colours(criteria).values()))
    assert overlap.overlaps(fig) == []


def test_a_snapshot_panel_is_framed_on_its_pool_and_says_so_when_the_pool_balloons():
    """Each snapshot is framed on its pools' current extent (true to scale, a scale bar), the pools covering at least
    a tenth of the panel; a pool swollen radially beyond the wall's thickness is framed on itself, and its title
    says so."""
    import matplotlib.pyplot as plt

    from sphgag.views import snapshots

    snap = _snapshots()
    for k in range(3):
        x0, x1, y0, y1 = snapshots.frame(snap, k)
        assert snapshots.ASPECT[0] <= (y1 - y0) / (x1 - x0) <= snapshots.ASPECT[1]
        assert snapshots.pool_fraction(snap, k) >= 0.1
        assert not snapshots.ballooned(snap, k)
    centre = snap["s2_x"][snap["s2_history_origin"] == 1].mean(axis=0)
    pool = snap["s2_history_origin"] > 0
    snap["s2_x"] = np.where(pool[:, None], centre + 12.0 * (snap["s2_x"] - centre), snap["s2_x"])  # ballooned
    assert snapshots.ballooned(snap, 2) and snapshots.pool_fraction(snap, 2) >= 0.1
    fig, ax = plt.subplots()
    snapshots.snapshot_panel(ax, snap, 2, WALL_LAYERS, "(a) run")
    assert ax.get_title(loc="left").endswith(snapshots.BALLOONED)
    assert ax.get_aspect() == 1.0 and ax.get_xlim() == pytest.approx(snapshots.frame(snap, 2)[:2])
    plt.close(fig)


def test_the_sensitivity_figures_draw_a_panel_per_output_method_and_law():
    from sphgag.views import sensitivity as views

    laws = ["prescribed", "conserved", "ideal"]
    inputs = ["gag.shear_modulus_kPa", "bilayer.dx_um", "delamination.critical_stress_kPa"]
    rows = []
    for law in laws:
        for output in ("tip_radial_stress_kPa", "final_length_um"):
            for method, indices in (("morris", ("mu_star", "sigma")), ("sobol", ("S1", "ST"))):
                for k, name in enumerate(inputs):
                    for index in indices:
                        v = 0.1 * (k + 1)
                        rows.append(
                            dict(
                                charge_law=law,
                                output=output,
                                method=method,
                                input=name,
                                index=index,
                                value=v,
                                conf_low=0.8 * v,
                                conf_high=1.2 * v,
                                samples_used=8,
                                samples_missing=0,
                            )
                        )
    fig = views.sensitivity(pd.DataFrame(rows), laws)
    assert len(fig.axes) == 2 * 2 * len(laws)
    assert _titles(fig)[:3] == ["Morris: prescribed Pi(c), paper", "Morris: conserved charge, c/J", "Morris: ideal"]

    states = list(views.MAP_COLOURS)
    table = pd.DataFrame(
        [
            dict(charge_law=law, sigma_cr_kPa=s, angular_extent_deg=w, concentration_mEq_l=c, state=states[k % 4])
            for law in laws
            for s in (40.0, 60.0)
            for k, (w, c) in enumerate((w, c) for w in (3.0, 16.0) for c in (50.0, 100.0, 150.0))
        ]
    )
    swelling = _tips([("prescribed", "particles")]).assign(limit_concentration_mEq_l=np.nan, path_end="complete")
    swelling.loc[swelling.case == "IV", "limit_concentration_mEq_l"] = 120.0
    fig = views.delamination_map(table, swelling, {"I": 3.0, "IV": 16.0}, 103.0, laws)
    assert len(fig.axes) == len(laws) * 2
    assert _titles(fig)[-1] == "ideal\nsigma_cr = 60 kPa"
