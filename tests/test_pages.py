"""The documentation site's results pages (sphgag.views.pages): written from the tables alone."""

import pandas as pd

from sphgag.views import pages

CLAIMS = pd.DataFrame(
    dict(
        claim_id=["C1", "C6", "C6", "C6", "C8", "C8", "C18"],
        charge_law=["-", "prescribed", "conserved", "prescribed", "prescribed", "conserved", "prescribed"],
        pool_model=["-", "particles", "particles", "cavity", "particles", "particles", "particles"],
        holds=["yes", "yes", "no", "no", "no", "yes", None],
    )
).assign(statement="s", paper_value="p", our_value="o", criterion="c", margin=1.0, across_band="n/a")


def test_what_holds_is_read_per_law_for_the_paper_pool_with_the_general_claims():
    table = pages.holds_table(CLAIMS)
    assert "| prescribed | C1, C6 | C8 | C18 |" in table
    assert "| conserved | C1, C8 | C6 | - |" in table  # the cavity's C6 is not the paper's pool


def test_a_section_whose_table_was_not_made_names_the_target_that_makes_it(tmp_path):
    text = pages.page("swelling", {"tips": None, "claims": None}, "stamp")
    assert text.startswith("# Swelling (figure 4)\n\nstamp\n")
    assert "Not run: `snakemake resolution` makes it." in text and "Not run: `snakemake all` makes it." in text
    assert text.index("## Figures") > text.index("## Figure 4's runs")  # the tables first, then the figures


def test_every_page_is_written_with_its_figures_beside_it(tmp_path):
    figures, laws = {}, ["prescribed", "conserved"]
    for name, _ in pages.shown({f for _, shown, _ in pages.PAGES.values() for f in shown}, laws):
        figures[name] = tmp_path / name
        figures[name].write_bytes(b"png")
    assert {"fig4.png", "fig4_conserved.png", "fig7_conserved.png", "fig3.png"} <= set(figures)
    out = tmp_path / "results"
    stamp = pages.stamp("abc", {"files": ["config/ci.yaml"], "sha256": "f" * 64})
    pages.write(out, {"claims": CLAIMS}, figures, stamp, laws)
    assert sorted(p.stem for p in out.glob("*.md")) == sorted(pages.PAGES)
    index = (out / "index.md").read_text()
    assert "commit `abc`, configuration `config/ci.yaml` (sha256 `ffffffffffff`)" in index
    assert all((out / "figures" / name).read_bytes() == b"png" for name in figures)
    swelling = (out / "swelling.md").read_text()  # each law's figure 4, captioned with its law
    assert "![fig4: prescribed charge law" in swelling and "(figures/fig4.png)" in swelling
    assert "![fig4: conserved charge law" in swelling and "(figures/fig4_conserved.png)" in swelling


def test_the_authors_settings_are_answered_in_a_paragraph_and_a_table():
    """The swelling page's P5 section: each configuration's tip radial stress at 150 mEq/l, "no eq." where a path
    has none, and the settings ranked by their share of the difference, in words and in a table."""
    from .test_paper_settings import _ablation

    tips = {
        ("none", "script", "I"): 120.0,
        ("none", "ours", "I"): 400.0,
        ("lumen_control", "from_script", "I"): 300.0,
        ("lumen_control", "from_ours", "I"): 150.0,
        ("temperature", "from_script", "I"): float("nan"),
        ("temperature", "from_ours", "I"): 399.0,
    }
    text = pages.authors_settings(_ablation(tips))
    assert "the authors' settings (`config/script.yaml`) give a tip radial stress of passive I 120 kPa" in text
    assert "ours (`config/config.yaml`) passive I 400 kPa" in text
    assert "`lumen_control` (0.77)" in text and text.index("`lumen_control`") < text.index("| configuration")
    assert "| the authors', `temperature` ours | no eq. |" in text
    assert "| ours, `lumen_control` the authors' | 150 |" in text


def test_the_profile_verification_table_gives_every_spacing_and_the_observed_order():
    """One row per wall, pressure, load and reading: the errors coarse to fine, the order of the finer pair."""
    table = pd.DataFrame(
        dict(
            wall="mean",
            lumen_load="operator",
            recovery="traction",
            pressure_mmHg=103.0,
            dx_um=[7.0, 3.5],
            material_inner_radial_pct=0.0,
            material_outer_radial_pct=0.0,
            material_radial_max_pct=[4.0, 1.0],
            material_circ_rms_pct=[0.8, 0.4],
            residual=1e-6,
        )
    )
    text = pages.profiles_table(table)
    assert "| mean | 103 | operator | traction | 7 / 3.5 | +0.0 / +0.0 | +0.0 / +0.0 | 4.0 / 1.0 (2.00) |" in text
    assert text.endswith("0.8 / 0.4 (1.00) |")
