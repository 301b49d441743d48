"""Whether a figure's text can be read: the pairs of text boxes that overlap, and the texts that leave the canvas (the
check every figure of the pipeline passes, figures 1 and 3-7 of the paper's among them: tests/test_overlap.py)."""

from __future__ import annotations

import json
import os
from contextlib import contextmanager
from pathlib import Path

import matplotlib.text

TOLERANCE_PX = 0.5  # boxes that share less than this (pixels, each way) only touch
CHECK_DIR = "SPHGAG_TEXT_CHECK"  # environment variable: a folder where style.save writes every figure's check


@contextmanager
def _recorded(texts: list):
    """While open, every text artist that draws itself is appended to ``texts`` with its window extent."""
    draw = matplotlib.text.Text.draw

    def recording(self, renderer):
        draw(self, renderer)
        if self.get_visible() and self.get_text().strip():
            texts.append((self, self.get_window_extent(renderer)))

    matplotlib.text.Text.draw = recording
    try:
        yield texts
    finally:
        matplotlib.text.Text.draw = draw


def drawn_texts(fig) -> list:
    """``(text artist, window extent)`` of every non-empty text ``fig`` draws (titles, axis and tick labels, legends,
    annotations, colour bars), as the canvas renders it: a tick label outside the axis' view is not drawn, so not
    listed."""
    with _recorded([]) as texts:
        fig.canvas.draw()
    return list({id(t): (t, box) for t, box in texts}.values())  # an artist drawn twice (a layout pass) counts once


def describe(text, ax=None) -> str:
    """A text artist in words: its string and where it is (the title of its axes ``ax``, by default the text's)."""
    ax = ax or text.axes
    if ax is None:
        return f"{type(text).__name__} {text.get_text()!r}"
    titles = [ax.get_title(loc) for loc in ("left", "center", "right")]
    name = next((t for t in [*titles, ax.get_ylabel(), ax.get_xlabel()] if t), "")
    return f"{type(text).__name__} {text.get_text()!r} in axes {name!r}"


def owners(fig) -> dict:
    """The axes of every text artist of ``fig`` that belongs to one (tick labels included), by the text's id."""
    return {id(t): ax for ax in fig.axes for t in ax.findobj(matplotlib.text.Text)}


def overlaps(fig) -> list[tuple[str, str]]:
    """The problems of ``fig``'s text, each a pair of descriptions (:func:`describe`): two texts whose boxes overlap
    by more than :data:`TOLERANCE_PX` both ways, or a text and "the canvas" when the text leaves the figure."""
    texts, of = drawn_texts(fig), owners(fig)
    canvas = fig.bbox
    found = []

    def name(text):
        return describe(text, of.get(id(text)))

    for i, (a, box_a) in enumerate(texts):
        if (
            box_a.x0 < canvas.x0 - TOLERANCE_PX
            or box_a.y0 < canvas.y0 - TOLERANCE_PX
            or box_a.x1 > canvas.x1 + TOLERANCE_PX
            or box_a.y1 > canvas.y1 + TOLERANCE_PX
        ):
            found.append((name(a), "the canvas"))
        for b, box_b in texts[i + 1 :]:
            width = min(box_a.x1, box_b.x1) - max(box_a.x0, box_b.x0)
            height = min(box_a.y1, box_b.y1) - max(box_a.y0, box_b.y0)
            if width > TOLERANCE_PX and height > TOLERANCE_PX:
                found.append((name(a), name(b)))
    return found


def record(fig, name: str) -> None:
    """Where the environment names a folder (:data:`CHECK_DIR`), write ``fig``'s problems there as ``<name>.json``
    (``name``: the figure's file; the pipeline's tests read them)."""
    folder = os.environ.get(CHECK_DIR)
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        out = Path(folder, f"{Path(name).as_posix().replace('/', '__')}.json")
        out.write_text(json.dumps({"figure": str(name), "overlaps": overlaps(fig)}, indent=1))
