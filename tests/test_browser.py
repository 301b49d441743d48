"""The figures of the Snakemake report and of the documentation site's results pages as a real browser shows them:
headless Chromium (Debian's chromium and chromium-driver) through Selenium, on the CI run of ``workdir``; skipped
without them."""

import zipfile

import pytest

from .browser import chromium_driver, load_images, loaded, missing, one_colour, page_images
from .conftest import snakemake
from .test_pipeline import FIGURES, report_variable

pytestmark = pytest.mark.pipeline
if reason := missing():  # at collection: these tests alone then do not start the pipeline run (conftest.py)
    pytest.skip(reason, allow_module_level=True)


@pytest.fixture(scope="module")
def browser():
    """One headless Chromium for both tests."""
    driver = chromium_driver()
    yield driver
    driver.quit()


def assert_screenshot(png):
    """A PNG file was written and it is not blank (its pixels are not all one colour)."""
    assert png.stat().st_size > 0 and not one_colour(png), png


def test_every_image_of_the_report_loads_in_a_browser(browser, workdir, tmp_path):
    """``snakemake --report``, unzipped and opened in Chromium: the page's own images load, and every result whose
    MIME type is an image (the figures' PNGs and the animations, which the report shows on a click) loads from its
    ``data_uri`` with a nonzero natural size, as the browser reports it; the screenshot of the page is not blank."""
    report = workdir / "report_browser.zip"
    run = snakemake(workdir, "everything", "--report", str(report))
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    with zipfile.ZipFile(report) as z:
        z.extractall(tmp_path)
    page = tmp_path / report.stem / "report.html"  # the zip holds one folder named after it
    results = report_variable(page.read_text(), "results")
    images = {path: entry["data_uri"] for path, entry in results.items() if entry["mime_type"].startswith("image/")}
    assert {f for f in FIGURES if f.endswith(".png")} <= set(images), sorted(images)

    shot = tmp_path / "report.png"
    on_page = page_images(browser, page.as_uri(), shot)
    assert loaded(on_page) == on_page, on_page
    assert_screenshot(shot)
    shown = load_images(browser, list(images.values()))
    assert len(shown) == len(images), (len(shown), len(images))
    assert loaded(shown) == shown, [i for i in shown if i not in loaded(shown)]


def test_every_figure_of_the_results_pages_loads_in_a_browser(browser, workdir, tmp_path):
    """The CI run built the site (target docs, in everything); each of its results pages, opened in Chromium from
    ``site/``, shows its
    figures: at least one image on the results pages in all, every one complete with a nonzero natural size as the
    browser reports it, and a screenshot of each page that is not blank."""
    site = workdir / "site"  # built by the CI run of everything (target docs)
    assert (site / "index.html").is_file() and (site / "results" / "index.html").is_file()
    images = []
    for n, page in enumerate(sorted((site / "results").rglob("*.html"))):
        shot = tmp_path / f"results_{n}.png"
        on_page = page_images(browser, page.as_uri(), shot)
        assert loaded(on_page) == on_page, (page, [i for i in on_page if i not in loaded(on_page)])
        assert_screenshot(shot)
        images += on_page
    assert images, "no <img> on the results pages"
