"""Text a reader can read: no two texts of a figure overlap and none leaves the canvas (sphgag.views.overlap), in a
figure made to fail and in every figure of the CI run (figures 1 and 3-7 and the studies' figures)."""

import json

import matplotlib.pyplot as plt
import pytest

from sphgag.views import overlap


def test_a_figure_with_text_over_text_and_off_the_canvas_is_named():
    fig, (left, right) = plt.subplots(1, 2, figsize=(4, 3))
    left.set_title("a title long enough to run into the next one", loc="left")
    right.set_title("the next title")
    left.text(0.5, 0.5, "over", transform=left.transAxes)
    left.text(0.52, 0.5, "overlapping", transform=left.transAxes)
    fig.text(0.98, 0.5, "off the canvas")
    found = overlap.overlaps(fig)
    plt.close(fig)
    over = "Text 'over' in axes 'a title long enough to run into the next one'"
    assert (over, over.replace("'over'", "'overlapping'")) in found, found
    assert ("Text 'off the canvas'", "the canvas") in found, found
    assert any("a title long" in a and "the next title" in b for a, b in found), found


def test_a_laid_out_figure_has_no_overlap():
    fig, axes = plt.subplots(2, 2, figsize=(6, 4), layout="constrained")
    for k, ax in enumerate(axes.flat):
        ax.plot([0, 1], [0, k], label=f"line {k}")
        ax.set(title=f"panel {k}", xlabel="x (um)", ylabel="y (kPa)")
        ax.legend()
    assert overlap.overlaps(fig) == []
    plt.close(fig)


def test_a_figure_records_its_check_where_the_environment_asks(tmp_path, monkeypatch):
    fig, ax = plt.subplots()
    ax.text(0.5, 0.5, "one")
    ax.text(0.5, 0.5, "two")
    overlap.record(fig, "figures/none.png")  # no folder named: nothing written
    monkeypatch.setenv(overlap.CHECK_DIR, str(tmp_path))
    overlap.record(fig, "figures/two.png")
    plt.close(fig)
    (written,) = tmp_path.glob("*.json")
    assert json.loads(written.read_text()) == {
        "figure": "figures/two.png",
        "overlaps": [["Text 'one' in axes ''", "Text 'two' in axes ''"]],
    }


@pytest.mark.pipeline
def test_no_figure_of_the_ci_run_has_text_over_text(workdir, text_checks):
    """Every figure the CI run of ``everything`` drew (every PNG under figures/ and every animation) was checked as it
    was saved, and none has two texts that overlap or a text off its canvas."""
    checks = [json.loads(p.read_text()) for p in sorted(text_checks.glob("*.json"))]
    checked = {c["figure"] for c in checks}
    drawn = {
        p.relative_to(workdir).as_posix() for ext in ("png", "gif") for p in (workdir / "figures").rglob(f"*.{ext}")
    }
    assert {"figures/fig4.png", "figures/fig4_conserved.png", "figures/fig7_conserved.png"} <= drawn
    assert drawn <= checked, sorted(drawn - checked)
    bad = [f"{c['figure']}: {a} / {b}" for c in checks for a, b in c["overlaps"]]
    assert not bad, "\n".join(bad)


def test_sigma_cr_labels_of_nearby_lines_share_one_label():
    """sigma_cr = 30, 40 and 60 kPa on a panel that spans thousands of kPa (a pool whose tip far exceeds them) are
    one label, not three stacked on each other; apart, each keeps its own."""
    from sphgag.views.delamination import sigma_labels

    fig, (wide, narrow) = plt.subplots(1, 2, figsize=(6, 3), layout="constrained")
    colours = {30.0: "C0", 40.0: "C1", 60.0: "C2"}
    for ax, top in ((wide, 5000.0), (narrow, 80.0)):
        ax.set_ylim(0.0, top)
        sigma_labels(ax, colours)
    assert [t.get_text() for t in wide.texts] == [" 30/40/60"]
    assert [t.get_text() for t in narrow.texts] == [" 30", " 40", " 60"]
    assert overlap.overlaps(fig) == []
    plt.close(fig)
